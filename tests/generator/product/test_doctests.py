"""The doctested examples of the product's helper functions (identifiers, C++ literals, constants)."""
import doctest
import sys

from rbdc_cli import ROOT

sys.path.insert(0, str(ROOT / "generator"))
from rbdcgen.backend import emit, names
from rbdcgen.commands import verify  # noqa: E402


def load_tests(loader, tests, pattern):
    tests.addTests(doctest.DocTestSuite(emit))
    tests.addTests(doctest.DocTestSuite(names))
    tests.addTests(doctest.DocTestSuite(verify))
    return tests
