"""Tracing: runs each requested algorithm over symbolic inputs and packages the result as a
`Function` (signature + expression DAG) for the emitter, the FLOP counter and the templates."""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Dict, Tuple

from . import chain_loop, differentiate, lane_functions, project
from ..graph import expr as ex
from ..graph.reassociate import reassociate
from ..algorithms import (aba, centroidal, contact_dynamics, crba, forward_dynamics, frames, jacobian,
                          kinematics, osc, rnea)
from ..views import coupled
from ..views.scalar import TracedModel


class TraceError(ValueError):
    """The robot cannot be traced for a function (e.g. a structurally singular mass matrix)."""


@dataclass(frozen=True)
class Argument:
    name: str
    rows: int
    cols: int
    doc: str

    @property
    def size(self):
        return self.rows * self.cols


@dataclass(frozen=True)
class Function:
    """One generated function: `outputs[k]` is written from `values[outputs[k].name]`, a tuple of
    rows·cols expressions in column-major order, all nodes of `graph`; an entry None is not written
    (the upper triangle of mass_matrix_lower)."""
    name: str
    doc: str
    inputs: Tuple[Argument, ...]
    outputs: Tuple[Argument, ...]
    values: Dict[str, Tuple[ex.Expr, ...]]
    graph: ex.Graph
    computes: str = ""    # the quantity it equals: its own name, or a lane function's scalar namesake
    schedule: str = ""    # the view it was traced on and why, when passes/schedule.py chose one
    lanes: object = None  # views/limb_lanes.LaneLayout of a lane function (lane_functions.py), else None
    solve: object = None  # passes/looped_solve.LoopedSolve: `values` are its terms, a loop solves them
    # (output name, entries): entries no loop after it reads, neither stored nor cleared (a looped
    # solve's terms: LoopedSolve.unread)
    unread: Tuple[Tuple[str, Tuple[int, ...]], ...] = ()

    def traced_arguments(self):
        """The arguments whose entries `values` holds: the outputs, or a looped solve's terms."""
        return self.outputs if self.solve is None else self.solve.terms

    def output_exprs(self):
        """All written traced entries in signature order (column-major within each argument)."""
        return [e for arg in self.traced_arguments() for e in self.values[arg.name] if e is not None]

    def __hash__(self):
        return hash((self.name, self.inputs, self.outputs))


def _columns(vectors):
    """Column-major flattening of a list of column vectors."""
    return tuple(x for col in vectors for x in col)


def _matrix(rows, cols):
    """Column-major flattening of a matrix given as rows (cols given: there may be no rows)."""
    return tuple(rows[r][c] for c in range(cols) for r in range(len(rows)))


def _input_args(robot, nf):
    return {
        "q": Argument("q", robot.nq, 1, "configuration (position, quaternion w x y z, joints)"
                      if robot.floating_base else "joint positions"),
        "v": Argument("v", robot.nv, 1, "velocity (trunk ω, v in trunk coordinates, joint rates)"
                      if robot.floating_base else "joint velocities"),
        "a": Argument("a", robot.nv, 1, "acceleration (trunk ω̇, R_W^0 p̈, joint accelerations)"
                      if robot.floating_base else "joint accelerations"),
        "tau": Argument("tau", robot.n_joints, 1, "joint torques / forces"),
        "f": Argument("f", 3, nf, "foot forces, world frame, one column per foot"),
        "ground_mass": Argument("ground_mass", 1, 1, "ground inertia of the big-ground-inertia "
                                "approximation (paper 001 Eq. 43)"),
        "restitution": Argument("restitution", 1, 1, "restitution coefficient e in [0, 1] of the "
                                "impact: J v⁺ = −e J v⁻"),
    }


def _spec(robot, nf, nc):
    """name → (doc, input names, [(output name, rows, cols, doc)], trace(m) → {name: values});
    nf feet, nc of them in contact."""
    nv, nj = robot.nv, robot.n_joints
    contact_rows = "rows 3k + r: contact k (the scene's contacts in the robot's foot order), world axis r"

    def osc_outputs(result):
        Lam, JbarT, b = result
        return {"Lambda": _matrix(Lam, 6), "JbarT": _matrix(JbarT, nj), "b": tuple(b)}

    def osc_terms(result):
        Lam, columns, b = result
        return {"Lambda": _matrix(Lam, 6), "columns": columns, "b": tuple(b)}

    osc_out = osc.output_specs(nj)
    return {
        "feet_positions": (
            "World positions of the feet (paper 000 Eqs. 16-18).", ("q",),
            [("p", 3, nf, "foot positions, world frame, one column per foot")],
            lambda m: {"p": _columns(kinematics.feet_positions(m))}),
        "feet_velocities": (
            "World linear velocities of the feet.", ("q", "v"),
            [("pdot", 3, nf, "foot velocities, world frame, one column per foot")],
            lambda m: {"pdot": _columns(kinematics.feet_velocities(m))}),
        "feet_jacobian": (
            "Stacked feet Jacobian J (paper 000 Alg. 6, App. B).", ("q",),
            [("J", 3 * nf, nv, "feet Jacobian, world-frame foot velocities from v")],
            lambda m: {"J": _matrix(jacobian.feet_jacobian(m), nv)}),
        "quadratic_velocity_terms": (
            "Quadratic velocity terms c (paper 000 Alg. 2).", ("q", "v"),
            [("c", nv, 1, "Coriolis and centrifugal terms")],
            lambda m: {"c": rnea.quadratic_velocity_terms(m)}),
        "gravity_terms": (
            "Gravity terms g (paper 000 Alg. 3).", ("q",),
            [("g", nv, 1, "gravity terms")],
            lambda m: {"g": rnea.gravity_terms(m)}),
        "bias": (
            "Bias c + g in one pass (inverse dynamics at a = 0, without the acceleration terms).",
            ("q", "v"),
            [("cg", nv, 1, "quadratic velocity and gravity terms c + g")],
            lambda m: {"cg": rnea.bias(m)}),
        "feet_force_terms": (
            "Generalised forces of the world foot forces (paper 000 Alg. 4).", ("q", "f"),
            [("tau_e", nv, 1, "τ_e = Jᵀ f")],
            lambda m: {"tau_e": rnea.feet_force_terms(m)}),
        "inverse_dynamics": (
            "Inverse dynamics M a + c + g (RNEA, paper 000 Algs. 2-3).", ("q", "v", "a"),
            [("tau", nv, 1, "generalised forces M a + c + g")],
            lambda m: {"tau": rnea.inverse_dynamics(m)}),
        "mass_matrix": (
            "Joint-space inertia matrix M (CRBA, paper 000 Alg. 5).", ("q",),
            [("M", nv, nv, "mass matrix, full symmetric")],
            lambda m: {"M": _matrix(crba.mass_matrix(m), nv)}),
        "body_transforms": (
            "Each body's transform X_λ(i)^i = X_J X_T from q (the looped CRBA's input, "
            "passes/looped_crba.py).", ("q",),
            [("X", 12, robot.nb - 1, "column k: the (k + 1)-th body in depth-first order (crba.depth_first_order), "
                                     "its E row-major (parent → body coordinates), then r (its origin in "
                                     "parent coordinates)")],
            lambda m: {"X": crba.body_transforms(m)}),
        "mass_matrix_lower": (
            "Joint-space inertia matrix M (CRBA, paper 000 Alg. 5), its lower triangle only (n(n+1)/2 "
            "stores instead of n²): for Eigen's M.selfadjointView<Eigen::Lower>() and its LDLᵀ/LLᵀ.",
            ("q",),
            [("M", nv, nv, crba.LOWER_TRIANGLE_DOC)],
            lambda m: {"M": crba.lower_triangle(_matrix(crba.mass_matrix(m), nv), nv)}),
        "mass_matrix_factor": (
            "M = Lᵀ D L over the tree's dofs (CRBA + the sparse factorisation forward_dynamics uses).",
            ("q",),
            [("L", nv, nv, "unit lower triangular; zero except at each dof's ancestors in the tree"),
             ("D", nv, 1, "pivots, the diagonal of D"),
             ("D_inv", nv, 1, "their inverses, so that a solve multiplies")],
            lambda m: forward_dynamics.factor_outputs(*forward_dynamics.mass_matrix_factor(m),
                                                      forward_dynamics.dof_parents(m.robot))),
        "mass_matrix_factor_terms": (
            "M's entries the sparse factorisation reads (the looped factor's input, "
            "passes/looped_factor.py).",
            ("q",),
            [("L", forward_dynamics.factor_entries(robot), 1,
              "M's entries at each dof's tree ancestors, packed (forward_dynamics.packed_factor)"),
             ("D", nv, 1, "M's diagonal")],
            lambda m: forward_dynamics.factor_terms(m)),
        "forward_dynamics": (
            "Forward dynamics: solves M a = Sᵀτ + τ_e − c − g (CRBA + sparse LDLᵀ, or the "
            "articulated-body algorithm where that is cheaper: the schedule line says which).",
            ("q", "v", "tau", "f"),
            [("a", nv, 1, "acceleration")],
            lambda m: {"a": forward_dynamics.forward_dynamics(m)}),
        "forward_dynamics_aba": (
            "Forward dynamics: solves M a = Sᵀτ + τ_e − c − g (the articulated-body algorithm).",
            ("q", "v", "tau", "f"),
            [("a", nv, 1, "acceleration")],
            lambda m: {"a": aba.forward_dynamics_aba(m)}),
        "step_terms": (
            "Everything one contact evaluation of the simulator needs at (q, v, τ), in one pass "
            "with shared kinematics: feet, their Jacobian rows, the factor M = Lᵀ D L and the "
            "acceleration without foot forces (sim/include/rbdc/sim/dynamics.hpp).",
            ("q", "v", "tau"),
            [("p", 3, nf, "foot positions, world frame, one column per foot"),
             ("pdot", 3, nf, "foot velocities, world frame, one column per foot"),
             ("omega", 3, nf, "angular velocity of each foot's body, world frame"),
             ("J", 3 * nf, nv, "feet Jacobian, world-frame foot velocities from v"),
             ("Jw", 3 * nf, nv, "angular rows of the feet's bodies, world frame (omega = Jw v)"),
             ("L", nv, nv, "unit lower triangular; zero except at each dof's ancestors in the tree"),
             ("D", nv, 1, "pivots, the diagonal of D"),
             ("D_inv", nv, 1, "their inverses, so that a solve multiplies"),
             ("a", nv, 1, "acceleration without foot forces, M⁻¹(Sᵀτ − c − g)")],
            lambda m: {"p": _columns(kinematics.feet_positions(m)),
                       "pdot": _columns(kinematics.feet_velocities(m)),
                       "omega": _columns(kinematics.feet_angular_velocities(m)),
                       "J": _matrix(jacobian.feet_jacobian(m), nv),
                       "Jw": _matrix(jacobian.feet_angular_jacobian(m), nv),
                       **forward_dynamics.factor_outputs(*forward_dynamics.mass_matrix_factor(m),
                                                         forward_dynamics.dof_parents(m.robot)),
                       "a": forward_dynamics.free_acceleration(m)}),
        "osc_open_chain": (
            "Trunk operational-space Λ, J̄ᵀ, b with measured foot forces (paper 001 Table 1).",
            ("q", "v", "f"), osc_out,
            lambda m: osc_outputs(osc.osc_open_chain(m))),
        "osc_closed_chain": (
            "Trunk operational-space Λ, J̄ᵀ, b with feet in contact (paper 001 Table 2).",
            ("q", "v", "ground_mass"), osc_out,
            lambda m: osc_outputs(osc.osc_closed_chain(m))),
        **{name + "_terms": (
            "The traced part of %s in its looped form (passes/looped_osc.py)." % name,
            inputs, osc.terms_specs(robot.nb),
            lambda m, algorithm=algorithm: osc_terms(algorithm(m, looped=True)))
           for name, inputs, algorithm in (("osc_open_chain", ("q", "v", "f"), osc.osc_open_chain),
                                           ("osc_closed_chain", ("q", "v", "ground_mass"), osc.osc_closed_chain))},
        "contact_dynamics": (
            "Rigid-contact dynamics of the scene's contact feet: a and λ of M a − Jᵀλ = Sᵀτ − c − g, "
            "J a = −J̇v (Schur complement, damped proximal Delassus solve; docs/runtime.md).",
            ("q", "v", "tau"),
            [("a", nv, 1, "acceleration"),
             ("lambda", 3 * nc, 1, "contact forces on the feet, world; " + contact_rows)],
            lambda m: dict(zip(("a", "lambda"), contact_dynamics.contact_dynamics(m)))),
        "impulse_dynamics": (
            "Impulse dynamics of a touchdown of the scene's contact feet: v⁺ and Λ of "
            "M (v⁺ − v) = JᵀΛ, J v⁺ = −e J v (docs/runtime.md).",
            ("q", "v", "restitution"),
            [("v_plus", nv, 1, "velocity after the impact"),
             ("impulse", 3 * nc, 1, "contact impulses, world; " + contact_rows)],
            lambda m: dict(zip(("v_plus", "impulse"), contact_dynamics.impulse_dynamics(m)))),
    }


def _whole_body_spec(robot, nf, n_frames):
    """The whole-body controller's functions (scene.WHOLE_BODY; issue 21), as _spec; n_frames is the
    number of frames the scene lists (docs/generated_api.md, "Frames and centroidal quantities")."""
    nv = robot.nv
    centroidal_specs = centroidal.specs(nv)

    # m.frame_values / m.frame_rows: the traced frames' results in the scene's frame order (the lane
    # model's lane frames taken apart), so the same builders serve the lane functions
    def placements(m):
        rotations, positions = (m.frame_values(x) for x in frames.frame_placements(m))
        return {"R": tuple(x for R in rotations for c in range(3) for x in (R[0][c], R[1][c], R[2][c])),
                "p": _columns(positions)}

    def pair(names, result):
        return {name: _columns(values) for name, values in zip(names, result)}

    def pair_matrices(names, result):
        return {name: _matrix(rows, nv) for name, rows in zip(names, result)}

    return {
        "frame_placements": (
            "Placements of the scene's frames: W_R_F and the origin (paper 000 Eqs. 15-18).", ("q",),
            [("R", 3, 3 * n_frames, "frame k's rotation frame → world in columns 3k … 3k+2"),
             ("p", 3, n_frames, "frame origins, world frame, one column per frame")],
            placements),
        "frame_velocities": (
            "Spatial velocities (ω; v) of the scene's frames at their origins.", ("q", "v"),
            [("v_local", 6, n_frames, "frame axes (Pinocchio's LOCAL, rows angular first)"),
             ("v_world", 6, n_frames, "world axes (LOCAL_WORLD_ALIGNED, rows angular first)")],
            lambda m: pair(("v_local", "v_world"), map(m.frame_values, frames.frame_velocities(m)))),
        "frame_jacobians": (
            "6 × nv Jacobians of the scene's frames (paper 000 Eq. B3 moved to the frame).", ("q",),
            [("J_local", 6 * n_frames, nv, "rows 6k … 6k+5: frame k's J, frame axes (J v = v_local)"),
             ("J_world", 6 * n_frames, nv, "rows 6k … 6k+5: frame k's J, world axes (J v = v_world)")],
            lambda m: pair_matrices(("J_local", "J_world"), map(m.frame_rows, frames.frame_jacobians(m)))),
        "frame_bias_accelerations": (
            "J̇v of the scene's frames: their accelerations at a = 0.", ("q", "v"),
            [("spatial", 6, n_frames, "J̇_local v: spatial acceleration, frame axes"),
             ("classical", 6, n_frames, "J̇_world v: (ω̇; p̈ of the origin), world axes")],
            lambda m: pair(("spatial", "classical"), map(m.frame_values, frames.frame_bias_accelerations(m)))),
        "feet_bias_accelerations": (
            "J̇v of the feet: each foot point's classical acceleration at a = 0, world frame.",
            ("q", "v"),
            [("Jdot_v", 3, nf, "one column per foot, world frame")],
            lambda m: {"Jdot_v": _columns(m.feet_values(frames.feet_bias_accelerations(m)))}),
        "center_of_mass": centroidal_specs["center_of_mass"] + (centroidal.center_of_mass_outputs,),
        "center_of_mass_jacobian": centroidal_specs["center_of_mass_jacobian"] + (
            lambda m: {"J_c": _matrix(centroidal.center_of_mass_jacobian(m), nv)},),
        "centroidal_momentum_matrix": centroidal_specs["centroidal_momentum_matrix"] + (
            lambda m: {"A_G": _matrix(centroidal.centroidal_momentum_matrix(m), nv)},),
        "centroidal_bias": centroidal_specs["centroidal_bias"] + (
            lambda m: {"Adot_v": tuple(centroidal.centroidal_bias(m))},),
        "mass_matrix_inverse": (
            "M⁻¹ from the sparse factor M = Lᵀ D L (CRBA, paper 000 Alg. 5).", ("q",),
            [("M_inv", nv, nv, "inverse mass matrix, full symmetric")],
            lambda m: {"M_inv": _matrix(forward_dynamics.mass_matrix_inverse(m), nv)}),
    }


def _lookup(robot, scene, name):
    """(doc, input names, output specs, build) of function `name` for this robot and scene."""
    nf, nc = len(scene.feet_for(robot)), len(scene.contacts_for(robot))
    scalar = {**_spec(robot, nf, nc), **_whole_body_spec(robot, nf, len(scene.frames_for(robot))),
              **differentiate.spec(robot, nf, nc)}
    spec = {**scalar, **lane_functions.spec(robot, scalar),
            **chain_loop.terms_spec(robot, {name: scalar[name][1] for name in chain_loop.TERMS})}
    if name not in spec:
        raise KeyError("unknown function '%s'" % name)
    return _in_frame_axes(scene, name, spec[name])


# The frame functions' output in each single-axes choice of the scene key frame_axes.
FRAME_AXES_OUTPUT = {"frame_velocities": {"local": "v_local", "world": "v_world"},
                     "frame_jacobians": {"local": "J_local", "world": "J_world"},
                     "frame_bias_accelerations": {"local": "spatial", "world": "classical"}}


def _in_frame_axes(scene, name, entry):
    """A frame function's entry with only the output of the scene's frame_axes (the other one's
    work then falls to DCE); any other entry as it is."""
    keep = FRAME_AXES_OUTPUT.get(lane_functions.SCALAR.get(name, name), {}).get(scene.frame_axes)
    if keep is None:
        return entry
    doc, inputs, outputs, build = entry
    return doc, inputs, [o for o in outputs if o[0] == keep], lambda m: {keep: build(m)[keep]}


def signature(robot, scene, name):
    """(doc, input Arguments, output Arguments) of function `name`, without tracing it."""
    doc, input_names, output_specs, _ = _lookup(robot, scene, name)
    args = _input_args(robot, len(scene.feet_for(robot)))
    inputs = tuple(args[n] for n in input_names if n not in scene.zero_inputs)
    return doc, inputs, tuple(Argument(*spec) for spec in output_specs)


def trace_function(robot, scene, name, known_inputs=None):
    """Traces one function of the scene into a fresh graph; `known_inputs` ({name: floats}, scalar
    functions only) traces those inputs as constants: the function evaluated by folding."""
    nf, nc = len(scene.feet_for(robot)), len(scene.contacts_for(robot))
    doc, input_names, output_specs, build = _lookup(robot, scene, name)
    tree = coupled.tree_view(robot)
    if tree is not robot:  # mimic couplings: trace on the tree, then project (passes/project.py)
        build = {**_spec(tree, nf, nc), **differentiate.spec(tree, nf, nc)}[name][3]
    args = _input_args(robot, nf)
    zero = tuple(n for n in scene.zero_inputs if n in input_names)
    with ex.Graph() as graph:
        lanes = name in lane_functions.SCALAR
        m = (lane_functions.model(robot, scene, zero, name) if lanes
             else TracedModel(robot, scene, zero_inputs=zero, known_inputs=known_inputs))
        try:
            values = project.traced_values(robot, name, m, build, output_specs)
        except ZeroDivisionError:
            raise TraceError(
                "robot '%s': %s divides by a pivot that is exactly zero: a joint moves no mass "
                "(a massless body, or a massless subtree, on a moving joint)" % (robot.name, name)
            ) from None
        outputs = tuple(Argument(n, r, c, d) for n, r, c, d in output_specs)
        for arg in outputs:
            if len(values[arg.name]) != arg.size:
                raise AssertionError("%s: output %s has %d entries, expected %d"
                                     % (name, arg.name, len(values[arg.name]), arg.size))
        flat = iter(ex.absorb_negations(reassociate([e for arg in outputs for e in values[arg.name] if e is not None])))
        values = {arg.name: tuple(None if e is None else next(flat) for e in values[arg.name])
                  for arg in outputs}
    inputs = tuple(args[n] for n in input_names if n not in zero)
    return Function(name=name, doc=doc, inputs=inputs, outputs=outputs, values=values, graph=graph,
                    computes=lane_functions.SCALAR.get(name, name), lanes=m.layout() if lanes else None)



def with_loop(robot, scene, name, terms_name, loop):
    """`name` in a looped form: the traced function `terms_name` (the same inputs) writes what the
    loop `loop(terms, outputs)` reads (the Function's `solve`: passes/looped_*.py); the function keeps
    the signature of `name`."""
    doc, inputs, outputs = signature(robot, scene, name)
    terms = trace_function(robot, scene, terms_name)
    assert terms.inputs == inputs
    return replace(terms, name=name, doc=doc, outputs=outputs, computes=name, solve=loop(terms, outputs))
