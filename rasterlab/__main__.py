"""`python -m rasterlab` is the `rasterlab` command."""
import sys

from rasterlab import main

sys.exit(main())
