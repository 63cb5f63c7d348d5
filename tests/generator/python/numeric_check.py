"""Random states and evaluation of traced functions against the Python reference."""

import math
import os
import random
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "generator"))
DATA = os.path.join(HERE, "..", "data")

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
    }


def evaluate(fn, state):
    """{output name: column-major list of floats} for a traced Function; 0 where it writes
    nothing (the upper triangle of mass_matrix_lower), as the verify harness's zeroed buffers."""
    values = iter(ex.evaluate(fn.output_exprs(), state))
    return {arg.name: [0.0 if e is None else next(values) for e in fn.values[arg.name]]
            for arg in fn.outputs}


def flatten_columns(vectors):
    return [x for col in vectors for x in col]


def flatten_matrix(rows):
    return [rows[r][c] for c in range(len(rows[0])) for r in range(len(rows))]


def max_relative_error(got, want):
    scale = max(1.0, max(abs(x) for x in want))
    return max(abs(g - w) for g, w in zip(got, want)) / scale


_CONSTANT = re.compile(r"Scalar\([^)]*\)")
# joint_trig.sin[i] / .cos[i]: one trig operation each (joint_sincos computes them all at once).
_OPERATOR = re.compile(r" [-+*/] |(?:^|[(\s])-(?=[\w(])|\b(?:sin|cos|sqrt)\(|\bjoint_trig\.(?:sin|cos)\[")


def operator_count(statement):
    """Operations on the right-hand side of one emitted statement (none in a marker comment)."""
    if statement.startswith("//"):
        return 0
    return len(_OPERATOR.findall(_CONSTANT.sub("C", statement.split("=", 1)[1])))
