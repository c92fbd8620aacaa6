"""`python -m app` is the `rasterlab` command."""
import sys

from app.cli import main

sys.exit(main())
