"""Which view a quantity is traced on, decided by cost (docs/performance.md, "The fastest form by
default"): the scalar tree, or the robot's isomorphic limbs in SIMD lanes. The algorithm is the
same; only how it is evaluated changes, so the function keeps its plain name and its doc gains one
line that says the choice and its numbers.

The cost is the arithmetic instructions the body issues: every operation node once, a lane
operation being one vector instruction for all limbs, the sum over the lanes two (a horizontal
add of four). A scene may force a view (`schedule: scalar` or `schedule: limb_lanes`)."""

from __future__ import annotations

from dataclasses import replace

from ..graph import expr as ex
from ..views.limbs import LimbError, isomorphic_limbs
from . import lane_functions, singular_mass
from .trace import trace_function

_LANE_SUM_INSTRUCTIONS = 2  # log2(LANES) horizontal additions


def instructions(fn):
    """Arithmetic instructions of fn's live DAG (a lane operation issues once)."""
    count = 0
    for node in ex.reachable(fn.output_exprs()):
        if node.op == "lane_sum":
            count += _LANE_SUM_INSTRUCTIONS
        elif node.op not in ("const", "sym", "lane_get"):
            count += 1
    return count


def scheduled_function(robot, scene, name):
    """`name` traced on the view the scene's schedule asks for, or by cost under `auto`."""
    lane_name = lane_functions.LANE_NAME.get(name)
    if lane_name is None or scene.schedule == "scalar":
        return trace_function(robot, scene, name)
    try:
        isomorphic_limbs(robot)
    except LimbError:
        if scene.schedule == "limb_lanes":
            raise
        return trace_function(robot, scene, name)
    lanes = trace_function(robot, scene, lane_name)
    if scene.schedule == "limb_lanes":
        return _as(lanes, name, lanes.doc, "limb lanes, as the scene asks")
    scalar = trace_function(robot, scene, name)
    cost_scalar, cost_lanes = instructions(scalar), instructions(lanes)
    if cost_lanes >= cost_scalar:
        return replace(scalar, schedule="scalar tree: %d arithmetic instructions, limb lanes %d"
                       % (cost_scalar, cost_lanes))
    return _as(lanes, name, scalar.doc, "limb lanes (the %d isomorphic limbs in SIMD lanes, the trunk "
               "scalar): %d arithmetic instructions, scalar tree %d" % (ex.LANES, cost_lanes, cost_scalar))


def _as(lanes, name, doc, why):
    """The lane function under the plain name."""
    return replace(lanes, name=name, doc=doc, schedule=why)


def trace_scene(robot, scene):
    """All functions of the scene, each on its scheduled view: its quantities in the order of
    scene.QUANTITIES, then its derivatives in the order of scene.DERIVATIVES."""
    names = singular_mass.applicable(robot, scene, scene.quantities_for(robot) + scene.derivatives_for(robot))
    return [scheduled_function(robot, scene, name) for name in names]
