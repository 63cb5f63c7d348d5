"""rbdc from Python: the reference runtime (rbdc.Model) and the generated code (rbdc.compile), with
numpy arrays of one state or of many, and rbdc.dask for batches on a Dask cluster. docs/python.md."""
from .compiled import compile
from .model import Model, ModelError, ModelWarning

__all__ = ["Model", "ModelError", "ModelWarning", "compile"]
