"""rbdcgen: the rbdc generator. IR → traced expression DAG → straight-line C++ (see
docs/generator_core.md)."""

__version__ = "0.1.0"
