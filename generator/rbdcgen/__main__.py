"""`python3 -m rbdcgen` (what the ./rbdc launcher runs)."""
import sys

from .commands.cli import main

sys.exit(main())
