"""`python -m app` is the `rasterlab` command."""
import sys

from app.launcher import main

sys.exit(main())
