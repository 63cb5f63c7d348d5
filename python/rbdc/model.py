"""rbdc.Model: a robot loaded by the C++ runtime, with the runtime's algorithms as numpy methods named
as the C++ functions (mass_matrix(q), inverse_dynamics(q, v, a), ...). Every method takes one state or
a batch (a leading dimension N), float64 or float32, any strides, and `out=` / `threads=` keywords;
the batch loop runs in C++ threads without the GIL. docs/python.md."""
import warnings
from pathlib import Path

from ._native import load_runtime

_runtime = load_runtime()
ModelError = _runtime.ModelError  # the loader's refusal, message "<file>:<line>: <element>: <problem>"


class ModelWarning(UserWarning):
    """A repair or an ignored fault of the loader ("<file>:<line>: <element>: <problem>")."""


def _shape(rows, cols):
    return f"({rows}, {cols})" if cols != 1 else ("()" if rows == 1 else f"({rows},)")


def _method(name, inputs, outputs, doc):
    names = [i[0] for i in inputs]

    def method(self, *args, out=None, threads=0, **kwargs):
        given = list(args) + [kwargs.pop(n) for n in names[len(args):] if n in kwargs]
        if kwargs or len(given) != len(names):
            raise TypeError(f"{name}() takes ({', '.join(names)}); got {len(args)} positional and "
                            f"{sorted(kwargs) or 'no other'} keyword arguments")
        return self._impl.call(name, tuple(given), out, threads)

    lines = [f"{name}({', '.join(names)}, *, out=None, threads=0) -> {', '.join(o[0] for o in outputs)}", "",
             doc, "", "Arguments (one state, or N states with a leading dimension):"]
    lines += [f"  {n}: {_shape(r, c)}, {d}" for n, r, c, d in inputs]
    lines += ["Returns:"] + [f"  {n}: {_shape(r, c)}, {d}" for n, r, c, d in outputs]
    method.__name__, method.__doc__ = name, "\n".join(lines)
    return method


class Model:
    """A robot as the runtime holds it. Create with Model.from_urdf."""

    def __init__(self, impl, source):
        self._impl = impl
        self.source = source  # path and loading options, for rbdc.compile(model)
        for name, inputs, outputs, doc in impl.algorithms():
            setattr(self, name, _method(name, inputs, outputs, doc).__get__(self))

    @classmethod
    def from_urdf(cls, path, base="floating", topology=None, mimic="couple", root=None, lock=None):
        """Loads and validates a URDF (or a standalone topology .yaml) as `rbdc-info` does: a floating
        base unless base="fixed"; `topology` an overlay fixing numbering and feet; `mimic` 'couple'
        (the runtime then works in tree coordinates, follower angles included), 'lock' or
        'independent'; `root` a root link; `lock` {joint: value} joints welded at a position. The
        loader's warnings become ModelWarning; a refusal raises ModelError with the loader's
        message (file:line). docs/model.md."""
        if base not in ("floating", "fixed"):
            raise ValueError(f"rbdc.Model.from_urdf: base must be 'floating' or 'fixed', not {base!r}")
        if not Path(path).is_file():
            raise FileNotFoundError(f"rbdc.Model.from_urdf: {path} does not exist")
        impl, messages = _runtime.load(str(path), base == "floating", str(topology or ""), mimic,
                                       root or "", dict(lock or {}))
        for message in messages:
            warnings.warn(message, ModelWarning, stacklevel=2)
        return cls(impl, {"path": str(path), "base": base, "topology": topology, "mimic": mimic,
                          "root": root, "lock": lock})

    name = property(lambda self: self._impl.name)
    floating_base = property(lambda self: self._impl.floating_base)
    nq = property(lambda self: self._impl.nq)
    nv = property(lambda self: self._impl.nv)
    nb = property(lambda self: self._impl.nb)
    n_joints = property(lambda self: self._impl.n_joints)
    n_feet = property(lambda self: self._impl.n_feet)
    joint_names = property(lambda self: self._impl.joint_names)
    body_names = property(lambda self: self._impl.body_names)
    foot_names = property(lambda self: self._impl.foot_names)
    gravity = property(lambda self: self._impl.gravity)
    default_ground_mass = property(lambda self: self._impl.default_ground_mass)

    def algorithms(self):
        """The method names (the runtime's algorithms)."""
        return [row[0] for row in self._impl.algorithms()]

    def __repr__(self):
        return (f"rbdc.Model({self.name!r}, nq={self.nq}, nv={self.nv}, n_joints={self.n_joints}, "
                f"n_feet={self.n_feet}, {'floating' if self.floating_base else 'fixed'} base)")
