"""`python3 -m rbdcgen` (what the ./rbdc launcher runs)."""
import sys

from .cli import main

sys.exit(main())
