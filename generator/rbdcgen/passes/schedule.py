"""Which form a quantity is evaluated in, decided by cost (docs/performance.md, "The fastest form by
default"): the scalar tree, the robot's isomorphic limbs in SIMD lanes, (forward- and
contact-dynamics derivatives) a looped solve with SIMD across the right-hand sides
(looped_solve.py), (forward dynamics) the articulated-body algorithm (algorithms/aba.py), or
(mass_matrix_factor) the factorisation as a loop (looped_factor.py), or (mass_matrix) the CRBA as a
loop over the bodies (looped_crba.py), or (the RNEA's derivatives) their recursion as a loop over the
bodies (looped_rnea_derivatives.py), or (the OSC recursions) J̄ᵀ's columns as a loop (looped_osc.py),
or (a fixed-base chain's ∂q̈) M⁻¹ times ∂τ's low-rank blocks (looped_solve.low_rank_applies), or (a
fixed-base chain's RNEA and forward dynamics) one loop along the chain (chain_loop.py).
The quantity is the same;
only how it is evaluated changes, so the function keeps its plain name and its doc gains one line
that says the choice and its numbers.

The cost is the arithmetic instructions the body issues: every operation node once, a lane operation
being one vector instruction for all limbs, the sum over the lanes two (a horizontal add of four), a
looped solve's row update one per looped_solve.SIMD_DOUBLES columns; straight-line code past
FRONT_END_LIMIT instructions (less what a large loop's own code takes of it) and the tree loops' and
the factor's instructions weigh more, as measured (`cost`), and each cycle of the form's critical
path (graph/latency.py) weighs LATENCY_WEIGHT instructions more: a form whose work waits in one long
chain is slower than its count says. Where the unrolled factor is past looped_factor.UNROLL_LIMIT,
the unrolled CRBA past looped_crba.UNROLL_LIMIT, the unrolled RNEA derivatives past
looped_rnea_derivatives.UNROLL_LIMIT, the feet's unrolled force terms past
looped_feet_forces.UNROLL_LIMIT, or the OSC's unrolled columns past looped_osc.UNROLL_LIMIT, `auto`
does not trace the forms that unroll it (tracing them alone would take minutes) when another form
exists. A scene may force a form (`schedule: scalar`, `limb_lanes`, `looped_solve`, `aba`,
`looped_factor`, `looped_crba`, `looped_rnea`, `lanes_looped_rnea`, `looped_feet`, `looped_osc`,
`low_rank` or `chain_loop`) where the function has it."""

from __future__ import annotations

import time
from dataclasses import replace

from ..algorithms import aba
from ..algorithms.forward_dynamics import dof_parents
from ..graph import expr as ex
from ..graph.latency import critical_path
from ..views.coupled import tree_view
from ..views import limbs, origins, turns
from ..views.limbs import LimbError
from . import (body_tree, chain_loop, lane_functions, looped_crba, looped_factor, looped_feet_forces, looped_osc,
               looped_rnea_derivatives, looped_solve, singular_mass)
from .trace import signature, trace_function

_LANE_SUM_INSTRUCTIONS = 2  # log2(LANES) horizontal additions


def instructions(fn):
    """Arithmetic instructions of fn's live DAG (a lane operation issues once), and of its looped
    solve."""
    return straight_line_instructions(fn) + (fn.solve.instructions() if fn.solve is not None else 0)


def straight_line_instructions(fn):
    """Arithmetic instructions of fn's traced, straight-line part."""
    return _straight_line_counts(fn)[0]


def _instructions(node):
    """The arithmetic instructions the body issues for one node."""
    if node.op == "lane_sum":
        return _LANE_SUM_INSTRUCTIONS
    return 0 if node.op in ("const", "sym", "lane_get") else 1


def _straight_line_counts(fn):
    """(arithmetic instructions, lane instructions among them) of fn's traced, straight-line part."""
    count = lanes = 0
    for node in ex.reachable(fn.output_exprs()):
        n = _instructions(node)
        count += n
        lanes += n if node.lane or node.op == "lane_sum" else 0
    return count, lanes


def beside_sines(fn):
    """fn's straight-line arithmetic instructions, counted as its schedule line counts them, that wait
    on no joint sine or cosine: all a core could run during `joint_sincos`, which every other one
    waits on (docs/performance.md, "The sines' latency in series"; tools/trig_latency.py)."""
    waits = set()
    count = 0
    for node in ex.reachable(fn.output_exprs()):
        if node.op in ("sin", "cos") or any(a.id in waits for a in node.args):
            waits.add(node.id)
        else:
            count += _instructions(node)
    return count


# Straight-line code runs from the op cache while it is short; past FRONT_END_LIMIT arithmetic
# instructions each further one costs 1 + FRONT_END_PENALTY (fetched and decoded on every call). A
# large loop's own code (loop_code) takes its share of the limit.
# Measured on an AMD EPYC (Zen 5), clang 14, per counted instruction: 0.084 ns for arm7's ∂τ (3 366),
# 0.165-0.185 ns for the Mini Cheetah's (6 806), humanoid32's (25 023) and Talos's (46 718).
FRONT_END_LIMIT = 3400
# A lane form whose straight-line part is longer is not emitted, for its compile time. Long lane code
# is cut into blocks as scalar code is (backend/blocks.py), and then g++ 12 -O3 takes about 0.45 ms
# per straight-line lane instruction: humanoid32's ∂q̈ terms (21 828) 9.2 s in 30 blocks (32 s as one
# function), TALOS's (39 500) 18.2 s in 49 (120 s): at this limit a header stays near 15 s, a
# quarter below issue 20's 20 s, and TALOS's ∂q̈ keeps the looped RNEA form (its lane terms measured
# 2.6 % faster, but its full + derivatives headers in one TU took 54.7 s against 46.8 s and the 60 s
# limit).
LANE_CODE_LIMIT = 32000
FRONT_END_PENALTY = 1.4
# A lane instruction past the limit costs this much more again: its EVEX encoding is longer, and long
# lane code passes its values between blocks through memory. Measured (Zen 5, clang 14) on
# humanoid32's ∂τ once the regrouped inertias (views/regrouped.py) had made its lane form 13 231
# instructions, 73 % of them lane ones: 2.6-2.9 µs against 2.2-2.3 µs for the looped RNEA
# derivatives (cost 30 112), where the scalar penalty alone had costed it 26 994 and chosen it.
LANE_FRONT_END_EXTRA = 1.4


# What a cycle of a form's critical path costs, in instructions. Fitted (least squares, no constant) to
# five pairs of forward-dynamics forms timed against each other (Zen 5, clang 14, the peer harness;
# docs/performance.md, "Forms chosen by their critical path too"): per call, 0.29 cycles an
# instruction and 0.80 a cycle of path, 2.7 instructions a cycle: arm7's and iiwa14's ABA 45 and 33 ns slower than their
# factor, Panda's factor 48 ns faster than its ABA, the Mini Cheetah's lanes 7 ns slower than its ABA
# in lanes, and 5 ns slower once both add their sums in their terms' order of arrival
# (graph/reassociate.py). 2.5, within the fit's error, keeps that last choice. It also charges the
# limb pairs' lane rotations, which cross the vector's halves on every body's chain: humanoid32's ID
# paired, 6 % fewer instructions on a path of 284 cycles against 241, took 4 % longer; TALOS's, 19 %
# fewer on 316 against 263, 37 % less (its lanes' code past FRONT_END_LIMIT). A loop's own chain is not
# traced: a looped form is charged its traced part's path or the scalar tree's, whichever is longer
# (`_figures`).
LATENCY_WEIGHT = 2.5


def cost(fn, counts, path):
    """What `auto` minimises, in units of one short straight-line instruction: the straight-line part
    (`counts`: _straight_line_counts) with the front-end penalty on what the code holds past
    FRONT_END_LIMIT, the loops' code counted in (more for the share of lane instructions), the loops
    weighted by what each of their instructions was measured to cost (their `cost()`), and
    LATENCY_WEIGHT a cycle of the critical path charged to the form (`path`)."""
    n, lanes = counts
    loops = fn.solve.cost() if fn.solve is not None else 0
    penalty = FRONT_END_PENALTY + LANE_FRONT_END_EXTRA * lanes / max(1, n)
    return round(n + penalty * max(0, n + loop_code(fn.solve) - FRONT_END_LIMIT) + loops + LATENCY_WEIGHT * path)


def loop_code(solve):
    """The loops' own code, as straight-line instructions: the looped RNEA derivatives', alone or
    under a looped solve (15-29 KB; the other loops take 1-5 KB, left out). A call streams whatever
    part of its code the front end cannot hold, the loops' as well as the traced part: Panda's ∂q̈
    terms ran 230-250 ns and its ∂ID in the looped form 593-636 ns, one after the other 1 035-1 072 ns
    (docs/performance.md, "A loop's code in the front end's budget")."""
    rnea = solve if isinstance(solve, looped_rnea_derivatives.LoopedRneaDerivatives) else getattr(solve, "rnea", None)
    return looped_rnea_derivatives.CODE if rnea is not None else 0


def _figures(traced):
    """{form: (instructions, critical path, cost)} of the traced forms. A looped form's path is at
    least the scalar tree's: its loops run the same algorithm's chain, one iteration after another
    (without this a 2-link arm's 25-instruction factor would lose to a loop for its path)."""
    figures = {}
    for form, fn in traced.items():
        counts = _straight_line_counts(fn)
        path = critical_path(fn)
        if fn.solve is not None and "scalar" in figures:
            path = max(path, figures["scalar"][1])
        figures[form] = (counts[0] + (fn.solve.instructions() if fn.solve is not None else 0), path,
                         cost(fn, counts, path))
    return figures


def _forms(robot, scene, name):
    """{form: how to trace it} for every form of `name` this robot allows, the scalar tree first."""
    forms = {"scalar": lambda: trace_function(robot, scene, name)}
    lane_name = lane_functions.LANE_NAME.get(name)
    if lane_name is not None and _lanes_apply(robot, scene, name):
        forms["limb_lanes"] = lambda: _as(trace_function(robot, scene, lane_name), name)
        if name in lane_functions.PAIRED and any(g.spare_lanes for g in limbs.limb_groups(robot)):
            forms["paired_lanes"] = lambda: _as(trace_function(robot, scene, lane_functions.PAIRED[name]), name)
    if looped_solve.has_looped_form(robot, name):
        forms["looped_solve"] = lambda: looped_solve.looped_function(robot, scene, name)
        lane_terms = lane_functions.LANE_NAME.get(looped_solve.TERMS[name])
        if lane_terms is not None and _lanes_apply(robot, scene, looped_solve.TERMS[name]):
            forms["lanes_looped_solve"] = lambda: looped_solve.looped_function(robot, scene, name, lane_terms)
    if name == "forward_dynamics" and aba.applies(robot):
        forms["aba"] = lambda: _as(trace_function(robot, scene, "forward_dynamics_aba"), name)
        if _lanes_apply(robot, scene, "forward_dynamics_aba"):
            forms["aba_lanes"] = lambda: _as(trace_function(robot, scene, "forward_dynamics_aba_lanes"), name)
    if chain_loop.has_looped_form(robot, name):
        forms["chain_loop"] = lambda: chain_loop.looped_function(robot, scene, name)
    if looped_factor.has_looped_form(robot, name):
        forms["looped_factor"] = lambda: looped_factor.looped_function(robot, scene, name)
    if looped_crba.has_looped_form(robot, name):
        forms["looped_crba"] = lambda: looped_crba.looped_function(robot, scene, name)
    if looped_factor.has_looped_form(robot, name) and looped_crba.has_looped_form(robot, "mass_matrix"):
        forms["looped_crba"] = lambda: looped_factor.looped_function(robot, scene, name, crba=True)
    if looped_rnea_derivatives.has_looped_form(robot, name):
        forms["looped_rnea"] = lambda: looped_rnea_derivatives.looped_function(robot, scene, name)
    if looped_feet_forces.has_looped_form(robot, name):
        forms["looped_feet"] = lambda: looped_feet_forces.looped_function(robot, scene, name)
    if looped_osc.has_looped_form(robot, name):
        forms["looped_osc"] = lambda: looped_osc.looped_function(robot, scene, name)
    if name in looped_solve.LOOP_TERMS and body_tree.applies(tree_view(robot)):  # coupled: projected
        forms["looped_rnea"] = lambda: looped_solve.looped_function(robot, scene, name, rnea=True)
        loop_terms = looped_solve.LOOP_TERMS[name]
        if not robot.couplings and _lanes_apply(robot, scene, loop_terms):
            forms["lanes_looped_rnea"] = lambda: looped_solve.looped_function(
                robot, scene, name, lane_functions.LANE_NAME[loop_terms], rnea=True)
    if name in looped_solve.LOOP_TERMS and body_tree.applies(robot):
        forms["looped_crba"] = lambda: looped_solve.looped_function(robot, scene, name, factor=True)
    if looped_solve.low_rank_applies(robot, scene, name):
        forms["low_rank"] = lambda: looped_solve.looped_function(robot, scene, name, low_rank=True)
    return forms


def _lanes_apply(robot, scene, name):
    """Whether the lane function of `name` applies (lane_functions.available); a scene that forces
    limb lanes gets the reason when not."""
    try:
        lane_functions.available(robot, scene, name)
        return True
    except LimbError:
        if scene.schedule == "limb_lanes":
            raise
        return False


# The parts some forms unroll, too large to trace past a limit: (whether the robot is past it, what
# the part costs, quantity → its forms that unroll the part). Those forms are left untraced where
# another form remains (the loops, the articulated-body algorithm).
_UNROLLED_PARTS = (
    (looped_factor.unrolled_too_large,
     lambda robot: "its factorisation alone: %d multiply-adds" % looped_factor.factor_multiply_adds(dof_parents(robot)),
     {"mass_matrix_factor": ("scalar",), "forward_dynamics": ("scalar",),
      "forward_dynamics_derivatives": ("scalar", "looped_solve", "lanes_looped_solve", "looped_rnea", "lanes_looped_rnea")}),
    (looped_crba.unrolled_too_large,
     lambda robot: "its CRBA: %d body-ancestor steps" % looped_crba.ancestor_steps(robot),
     {"mass_matrix": ("scalar",), "mass_matrix_lower": ("scalar",), "mass_matrix_factor": ("scalar", "looped_factor"),
      "forward_dynamics": ("scalar",),
      "forward_dynamics_derivatives": ("scalar", "looped_solve", "lanes_looped_solve", "looped_rnea", "lanes_looped_rnea")}),
    (looped_rnea_derivatives.unrolled_too_large,
     lambda robot: "its recursion: %d body-ancestor steps" % looped_rnea_derivatives.ancestor_steps(robot),
     {**{name: ("scalar", "limb_lanes") for name in looped_rnea_derivatives.TERMS},
      **{name: ("scalar", "looped_solve", "lanes_looped_solve") for name in looped_solve.LOOP_TERMS}}),
    (looped_feet_forces.unrolled_too_large,
     lambda robot: "its entries: %d dof-ancestor pairs on the feet's paths" % looped_feet_forces.path_pairs(robot),
     {looped_feet_forces.NAME: ("scalar",)}),
    (looped_osc.unrolled_too_large,
     lambda robot: "its columns: %d body-ancestor steps" % looped_osc.ancestor_steps(robot),
     {name: ("scalar", "limb_lanes") for name in looped_osc.NAMES}))


# A forced schedule → the forms that satisfy it, in order of preference (limb lanes: the contact
# derivatives' lane terms under their looped solve too; the looped RNEA derivatives: the feet's force
# terms looped as well, as in ∂q̈'s looped solve).
_FORCED = {"limb_lanes": ("limb_lanes", "lanes_looped_solve"), "looped_rnea": ("looped_rnea", "looped_feet")}

_SHORT = {"scalar": "scalar tree", "limb_lanes": "limb lanes",
          "paired_lanes": "limb lanes with the pairs' spare lanes used", "looped_solve": "looped solve",
          "lanes_looped_solve": "limb lanes and a looped solve",
          "lanes_looped_rnea": "limb lanes and looped RNEA derivatives",
          "aba": "articulated-body algorithm", "aba_lanes": "articulated-body algorithm in limb lanes", "looped_factor": "looped factor", "looped_crba": "looped CRBA",
          "looped_rnea": "looped RNEA derivatives", "looped_feet": "looped feet force terms",
          "looped_osc": "looped operational-space columns", "low_rank": "low-rank product",
          "chain_loop": "one loop along the chain"}
_DETAIL = {"scalar": "", "limb_lanes": " (the %d isomorphic limbs in SIMD lanes, the trunk scalar)" % ex.LANES,
           "paired_lanes": "",  # a quadruped has no pairs
           "looped_solve": " (the solve's right-hand sides in SIMD across columns)",
           "lanes_looped_solve": " (the terms traced with the %d isomorphic limbs in SIMD lanes, the "
                                 "solve's right-hand sides in SIMD across columns)" % ex.LANES,
           "lanes_looped_rnea": " (M's factor and the terms traced with the %d isomorphic limbs in SIMD lanes, "
                                "∂τ a loop over the bodies, the solve's right-hand sides in SIMD across columns)" % ex.LANES,
           "aba": " (O(n); the scalar tree is CRBA + the sparse LᵀDL factor)",
           "aba_lanes": " (the %d isomorphic limbs in SIMD lanes, the trunk scalar)" % ex.LANES,
           "looped_factor": " (the sparse LᵀDL factorisation a loop)",
           "looped_crba": " (a loop over the bodies, the tree's constants in a table)",
           "looped_rnea": " (a loop over the bodies, the tree's constants in a table)",
           "looped_feet": " (a loop over the dof tree's ancestor pairs)",
           "looped_osc": " (J̄ᵀ's columns a loop over the bodies' descendants, the tree's constants in a table)",
           "low_rank": " (M⁻¹ times ∂τ's low-rank blocks by running sums along the chain, ∂τ never formed)",
           "chain_loop": " (in the root's coordinates, the tree's constants in a table)"}


# The lane forms' words for a robot whose limbs in lanes are not the quadruped's (limbs.groups_in_words).
_LANE_FORMS = {"limb_lanes": " (%s; the rest scalar)", "aba_lanes": " (%s; the rest scalar)",
               "paired_lanes": " (%s; the rest scalar; %s)",
               "lanes_looped_solve": " (the terms traced with %s, the solve's right-hand sides in SIMD across columns)",
               "lanes_looped_rnea": " (M's factor and the terms traced with %s, ∂τ a loop over the bodies, the "
                                    "solve's right-hand sides in SIMD across columns)"}


def scheduled_function(robot, scene, name):
    """`name` traced in the form the scene's schedule asks for, or by cost under `auto` (each form
    traced; the fewest arithmetic instructions wins, the scalar tree on a tie)."""
    forms = _forms(robot, scene, name)
    if len(forms) == 1 or scene.schedule == "scalar":
        return forms["scalar"]()
    forced = next((form for form in _FORCED.get(scene.schedule, (scene.schedule,)) if form in forms), None)
    if forced is not None:
        return replace(forms[forced](), schedule="%s, as the scene asks" % _SHORT[forced])
    if scene.schedule != "auto":  # a form this function does not have: the scalar tree
        return forms["scalar"]()
    untraced = []
    for too_large, cost_of, unrolled_by in _UNROLLED_PARTS:
        unrolling = unrolled_by.get(name, ())
        if too_large(robot) and any(form not in unrolling for form in forms):
            for form in unrolling:
                if forms.pop(form, None) is not None:
                    untraced.append("%s not traced (%s)" % (_SHORT[form], cost_of(robot)))
    traced = {form: trace() for form, trace in forms.items()}
    for form in [f for f in traced if f in _LANE_FORMS and len(traced) > 1]:
        lane_code = straight_line_instructions(traced[form])
        if lane_code > LANE_CODE_LIMIT:
            del traced[form]
            untraced.append("%s not emitted (%d straight-line instructions in lanes, past %d)"
                            % (_SHORT[form], lane_code, LANE_CODE_LIMIT))
    figures = _figures(traced)
    best = min(figures, key=lambda form: figures[form][2])  # dicts keep order: the scalar tree wins a tie
    others = ", ".join(["%s %d (path %d, cost %d)" % ((_SHORT[form],) + figures[form]) for form in figures
                        if form != best] + untraced)
    detail = _detail(robot, best, name)
    return replace(traced[best], doc=signature(robot, scene, name)[0],
                   schedule="%s%s: %d arithmetic instructions (critical path %d cycles, cost %d), %s"
                   % ((_SHORT[best], detail) + figures[best] + (others,)))


def _detail(robot, form, name):
    """The schedule line's words on `form`: the lane forms say which limbs are in lanes (the paired
    form also what the pairs' spare lanes carry)."""
    groups = limbs.groups_in_words(robot) if form in _LANE_FORMS else None
    if groups is None:
        return _DETAIL[form]
    return _LANE_FORMS[form] % ((groups, lane_functions.PAIRED_WORDS[name]) if form == "paired_lanes" else groups)


def _as(form, name):
    """Another form's function (a lane function, forward_dynamics_aba) under the plain name, counted
    as the quantity it computes."""
    return replace(form, name=name, computes=name)


def traced_tree(robot):
    """The robot a scene's functions are traced on: each body's coordinates turned about its joint axis
    (views/turns.py), then its origin slid along it (views/origins.py): the same functions, fewer
    operations."""
    return origins.slid(turns.turned(robot))


def trace_scene(robot, scene, progress=None):
    """All functions of the scene, each on its scheduled view: its quantities in the order of
    scene.QUANTITIES, then its derivatives in the order of scene.DERIVATIVES. `progress(function,
    seconds)`, if given, hears of each as it is done. They are traced on traced_tree(robot)."""
    robot = traced_tree(robot)
    names = singular_mass.applicable(robot, scene, scene.quantities_for(robot) + scene.derivatives_for(robot))
    functions = []
    for name in names:
        start = time.monotonic()
        functions.append(scheduled_function(robot, scene, name))
        if progress is not None:
            progress(functions[-1], time.monotonic() - start)
    return functions
