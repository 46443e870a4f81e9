"""`python -m rockingwall`: the command line (rockingwall.cli)."""
import sys

from .cli import main

sys.exit(main())
