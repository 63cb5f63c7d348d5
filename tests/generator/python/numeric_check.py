"""Random states, evaluation of traced functions against the Python reference, and a serial chain
of any length."""

import math
import os
import random
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "generator"))
DATA = os.path.join(HERE, "..", "data")

from dataclasses import replace  # noqa: E402

from rbdcgen.frontend.ir import Actuator, Rotor, load_ir  # noqa: E402
from rbdcgen.graph import expr as ex  # noqa: E402


def random_state(robot, nf, seed):
    rng = random.Random(seed)
    q = [rng.uniform(-1.0, 1.0) for _ in range(robot.nq)]
    if robot.floating_base:
        quat = [rng.gauss(0, 1) for _ in range(4)]
        norm = math.sqrt(sum(x * x for x in quat))
        q[3:7] = [x / norm for x in quat]
    return {
        "q": q,
        "v": [rng.uniform(-2.0, 2.0) for _ in range(robot.nv)],
        "a": [rng.uniform(-3.0, 3.0) for _ in range(robot.nv)],
        "tau": [rng.uniform(-5.0, 5.0) for _ in range(robot.n_joints)],
        "f": [rng.uniform(-20.0, 20.0) for _ in range(3 * nf)],
        "ground_mass": [rng.uniform(10.0, 1e3)],
        "restitution": [rng.uniform(0.0, 1.0)],
    }


def evaluate(fn, state):
    """{output name: column-major list of floats} for a traced Function; 0 where it writes
    nothing (the upper triangle of mass_matrix_lower), as the verify harness's zeroed buffers."""
    values = iter(ex.evaluate(fn.output_exprs(), state))
    return {arg.name: [0.0 if e is None else next(values) for e in fn.values[arg.name]]
            for arg in fn.traced_arguments()}


def flatten_columns(vectors):
    return [x for col in vectors for x in col]


def flatten_matrix(rows):
    return [rows[r][c] for c in range(len(rows[0])) for r in range(len(rows))]


def max_relative_error(got, want):
    scale = max(1.0, max(abs(x) for x in want))
    return max(abs(g - w) for g, w in zip(got, want)) / scale


def assert_agree(test, got, want, tolerance=1e-12, **labels):
    """Each output of `want` (evaluate's {name: values}) within `tolerance` of `got`'s
    (max_relative_error), one subTest per output with `labels`."""
    for output in want:
        with test.subTest(output=output, **labels):
            test.assertLess(max_relative_error(got[output], want[output]), tolerance)


_CONSTANT = re.compile(r"Scalar\([^)]*\)")
# joint_trig.sin[i] / .cos[i]: one trig operation each (joint_sincos computes them all at once).
_OPERATOR = re.compile(r" [-+*/] |(?:^|[(\s])-(?=[\w(])|\b(?:sin|cos|sqrt)\(|\bjoint_trig\.(?:sin|cos)\[")


def operator_count(statement):
    """Operations on the right-hand side of one emitted statement (none in a marker comment)."""
    if statement.startswith("//"):
        return 0
    return len(_OPERATOR.findall(_CONSTANT.sub("C", statement.split("=", 1)[1])))


def chain(links):
    """A fixed-base serial chain of `links` revolute joints about x, y, z in turn (the IR)."""
    body = {"com": [0.0, 0.0, 0.05], "inertia_com": [[2e-3, 0, 0], [0, 2e-3, 0], [0, 0, 1e-3]], "mass": 0.5}
    joint = {"lower": None, "upper": None, "rotation": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]}
    bodies = [dict(body, name="base")] + [dict(body, name="link%d" % i) for i in range(1, links + 1)]
    joints = [dict(joint, name="root", type="fixed", parent=-1, axis=[0, 0, 0], translation=[0, 0, 0],
                   q_index=0, v_index=0)]
    for i in range(1, links + 1):
        joints.append(dict(joint, name="j%d" % i, type="revolute", parent=i - 1,
                           axis=[1.0 if k == i % 3 else 0.0 for k in range(3)], translation=[0, 0, 0.1],
                           q_index=i - 1, v_index=i - 1))
    nb = links + 1
    return load_ir({"format": "rbdc-ir-1", "name": "chain", "nb": nb, "floating_base": False,
                    "gravity": [0, 0, -9.81], "bodies": bodies, "joints": joints, "nq": links,
                    "nv": links, "lambda": [i - 1 for i in range(1, nb)],
                    "feet": [{"name": "tip", "body": links, "offset": [0, 0, 0.1]}],
                    "PRED": [i - 1 for i in range(1, nb)], "SUCC": list(range(1, nb)),
                    "kappa": [list(range(1, i + 1)) for i in range(nb)],
                    "mu": [[i + 1] if i + 1 < nb else [] for i in range(nb)],
                    "nu": [list(range(i, nb)) for i in range(nb)]})


def geared(robot, joint=1):
    """`robot` with a geared rotor on `joint` (a tree with rotors: the loops over bodies do not apply)."""
    rotor = Rotor(gear_ratio=6.0, mass=0.1, inertia=((1e-4, 0, 0), (0, 1e-4, 0), (0, 0, 2e-4)),
                  rotation=((1, 0, 0), (0, 1, 0), (0, 0, 1)), translation=(0, 0, 0), axis=(0, 0, 1))
    joints = list(robot.joints)
    joints[joint] = replace(joints[joint], actuator=Actuator(armature=0.0, rotor=rotor))
    return replace(robot, joints=tuple(joints))
