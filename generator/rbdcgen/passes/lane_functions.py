"""Functions traced with the isomorphic limbs in SIMD lanes (views/limb_lanes.py): the same
outputs as their scalar namesakes, emitted only when a scene lists them (scene.LANE_QUANTITIES)."""

from __future__ import annotations

from . import differentiate, lane_contact_derivatives, lane_derivatives
from ..algorithms import aba, centroidal, contact_dynamics, crba, forward_dynamics, osc, rnea
from ..views.limb_lanes import LaneModel, contact_lanes, feet_shape, frame_shapes
from ..views.limbs import isomorphic_limbs, limb_groups, quadruped_groups

# derivative function → the trace of its lane function: its own on the lane model (the analytic RNEA
# recursion: a limb's composites summed over the lanes where they join the trunk's), or for ∂a the
# same method with the solves of limb columns apart (lane_derivatives.py)
DERIVATIVES = {"inverse_dynamics_derivatives": differentiate.inverse_dynamics_derivatives,
               "bias_derivatives": differentiate.bias_derivatives,
               "gravity_derivatives": differentiate.gravity_derivatives,
               "forward_dynamics_derivatives": lane_derivatives.forward_dynamics_derivatives}
# centroidal function → its trace on the lane model, outputs in the full robot's columns
CENTROIDAL = {
    "center_of_mass": centroidal.center_of_mass_outputs,
    "center_of_mass_jacobian": lambda m: {"J_c": _full_columns(m, centroidal.center_of_mass_jacobian(m))},
    "centroidal_momentum_matrix": lambda m: {"A_G": _full_columns(m, centroidal.centroidal_momentum_matrix(m))},
    "centroidal_bias": lambda m: {"Adot_v": tuple(centroidal.centroidal_bias(m))}}
# the frame functions: traced on the lane model by their scalar builders (views/limb_lanes.lane_frames;
# m.frame_values and m.frame_rows put the lane frames' results in the scene's frame order)
FRAMES = ("frame_placements", "frame_velocities", "frame_jacobians", "frame_bias_accelerations")
# the same for the feet's J̇v (m.feet_values: the lane feet's results as the kept feet's)
FEET = ("feet_bias_accelerations",)
# contact function → its trace on the lane model, one contact foot per limb (LaneDelassus)
CONTACT = {
    "contact_dynamics": lambda m: _contact_outputs(m, ("a", "lambda"), contact_dynamics.contact_dynamics),
    "impulse_dynamics": lambda m: _contact_outputs(m, ("v_plus", "impulse"), contact_dynamics.impulse_dynamics)}
# M⁻¹ with the limbs' columns in lanes (forward_dynamics.lane_mass_matrix_inverse)
INVERSE = {"mass_matrix_inverse": lambda m: {"M_inv": _columns(forward_dynamics.lane_mass_matrix_inverse(m))}}
# the traced terms of contact_dynamics_derivatives' looped form (looped_solve.py), one contact foot
# per limb as CONTACT
CONTACT_TERMS = {"contact_dynamics_derivative_terms": lane_contact_derivatives.contact_dynamics_derivative_terms}
# the same for forward_dynamics_derivatives' looped solve: its right-hand sides and M's factor
SOLVE_TERMS = {"forward_dynamics_derivative_terms": lane_derivatives.forward_dynamics_derivative_terms,
               "forward_dynamics_derivative_loop_terms": lane_derivatives.forward_dynamics_derivative_loop_terms}
# function → its lane function whose limb pairs carry a second quantity in their spare lanes 2-3, and
# what it is. Not the derivatives: their tangents are non-zero where either quantity's is, so
# packed they cost more (humanoid32's ∂q̈ terms with rnea.pair_step: 54 804 → 55 444 instructions).
PAIRED = {"bias": "bias_paired_lanes", "inverse_dynamics": "inverse_dynamics_paired_lanes",
          "mass_matrix": "mass_matrix_paired_lanes", "mass_matrix_lower": "mass_matrix_lower_paired_lanes"}
_MOTION = "a pair's accelerations in lanes 0-1, its velocities in 2-3, so that one transform and one inertia product serve both"
_COLUMNS = "a pair body's column of M in lanes 0-1, a child's in 2-3, so that one walk to the root serves both"
PAIRED_WORDS = {"bias": _MOTION, "inverse_dynamics": _MOTION, "mass_matrix": _COLUMNS, "mass_matrix_lower": _COLUMNS}
# lane function → the function it equals
SCALAR = {**{lanes: name for name, lanes in PAIRED.items()},
          "bias_lanes": "bias", "inverse_dynamics_lanes": "inverse_dynamics",
          "mass_matrix_lanes": "mass_matrix", "mass_matrix_lower_lanes": "mass_matrix_lower",
          "forward_dynamics_lanes": "forward_dynamics", "forward_dynamics_aba_lanes": "forward_dynamics_aba",
          "osc_open_chain_lanes": "osc_open_chain",
          **{name + "_lanes": name for name in DERIVATIVES}, **{name + "_lanes": name for name in CENTROIDAL},
          **{name + "_lanes": name for name in FRAMES + FEET}, **{name + "_lanes": name for name in CONTACT},
          **{name + "_lanes": name for name in INVERSE},
          **{name + "_lanes": name for name in CONTACT_TERMS}, **{name + "_lanes": name for name in SOLVE_TERMS}}
# function → its lane function
LANE_NAME = {scalar: lanes for lanes, scalar in SCALAR.items() if lanes not in PAIRED.values()}
# lane functions with the foot forces as lane inputs
WITH_FEET = ("forward_dynamics_lanes", "forward_dynamics_aba_lanes", "forward_dynamics_derivatives_lanes", "osc_open_chain_lanes",
             "contact_dynamics_lanes", "impulse_dynamics_lanes", "feet_bias_accelerations_lanes",
             "contact_dynamics_derivative_terms_lanes", "forward_dynamics_derivative_terms_lanes",
             "forward_dynamics_derivative_loop_terms_lanes")


# functions whose lane form takes any groups of isomorphic limbs (views/limbs.limb_groups: a humanoid's
# legs and arms in pairs, the spine scalar); the others need the quadruped's four limbs of the trunk
ANY_GROUPS = ("bias", "inverse_dynamics", "mass_matrix", "mass_matrix_lower", "forward_dynamics", "forward_dynamics_aba",
              "inverse_dynamics_derivatives", "bias_derivatives", "gravity_derivatives", "forward_dynamics_derivative_terms",
              "forward_dynamics_derivative_loop_terms")


def model(robot, scene, zero_inputs, name):
    """The traced model of lane function `name`: the spine and one lane limb per group."""
    groups = limb_groups(robot) if SCALAR[name] in ANY_GROUPS else quadruped_groups(robot)
    return LaneModel(robot, scene, groups, zero_inputs, feet=name in WITH_FEET, frames=SCALAR[name] in FRAMES,
                     pair_streams=name in PAIRED.values())


def available(robot, scene, name):
    """LimbError if the lane form of `name` does not apply to this robot and scene: the functions
    outside ANY_GROUPS need the quadruped's limbs (isomorphic_limbs), those with foot forces
    (WITH_FEET) the same feet on every limb of a group (feet_shape), a frame function the same frames on every limb
    (views/limb_lanes.frame_shapes), the contact functions one kept foot and at most one contact per
    limb (contact_lanes), the feet's J̇v the same feet on every limb (feet_shape)."""
    if name in ANY_GROUPS:
        groups = limb_groups(robot)
        if LANE_NAME[name] in WITH_FEET:
            for group in groups:
                feet = [foot for foot in scene.feet_for(robot) if any(foot.body in limb for limb in group.limbs)]
                feet_shape(robot.name, feet, group.limbs)
        return
    limbs = isomorphic_limbs(robot)
    if name in FRAMES:
        frame_shapes(scene.frames_for(robot), limbs)
    if name in CONTACT or name in CONTACT_TERMS:
        contact_lanes(scene.feet_for(robot), scene.contacts_for(robot), limbs)
    if name in FEET:
        feet_shape(robot.name, scene.feet_for(robot), limbs)


def spec(robot, scalar_specs):
    """trace.py's function table for the lane functions (same shape as trace._spec); `scalar_specs`:
    the scalar functions' table (derivatives included) the lane functions take their signatures from."""
    nv = robot.nv
    table = {
        **_in_lanes(scalar_specs, DERIVATIVES),
        **_in_lanes(centroidal.specs(nv), CENTROIDAL),
        **_in_lanes(scalar_specs, {name: scalar_specs[name][3] for name in FRAMES + FEET}),
        **_in_lanes(scalar_specs, CONTACT),
        **_in_lanes(scalar_specs, INVERSE),
        **_in_lanes(scalar_specs, CONTACT_TERMS),
        **_in_lanes(scalar_specs, SOLVE_TERMS),
        **_in_lanes(scalar_specs, {"forward_dynamics_aba": lambda m: {"a": m.scatter(aba.forward_dynamics_aba(m))}}),
        "bias_lanes": (
            "Bias c + g in one pass (inverse dynamics at a = 0), the four isomorphic limbs' passes "
            "evaluated together in SIMD lanes, the trunk scalar; equals bias.",
            ("q", "v"),
            [("cg", nv, 1, "quadratic velocity and gravity terms c + g")],
            lambda m: {"cg": m.scatter(rnea.bias(m))}),
        "inverse_dynamics_lanes": (
            "Inverse dynamics M a + c + g (RNEA, paper 000 Algs. 2-3), the four isomorphic limbs' "
            "passes evaluated together in SIMD lanes, the trunk scalar; equals inverse_dynamics.",
            ("q", "v", "a"),
            [("tau", nv, 1, "generalised forces M a + c + g")],
            lambda m: {"tau": m.scatter(rnea.inverse_dynamics(m))}),
        "mass_matrix_lanes": (
            "Joint-space inertia matrix M (CRBA, paper 000 Alg. 5), the four isomorphic limbs' "
            "passes evaluated together in SIMD lanes, the trunk scalar; equals mass_matrix.",
            ("q",),
            [("M", nv, nv, "mass matrix, full symmetric")],
            lambda m: {"M": _columns(m.scatter_matrix(crba.mass_matrix(m)))}),
        "mass_matrix_lower_lanes": (
            "The lower triangle of M (CRBA, paper 000 Alg. 5), the four isomorphic limbs' passes "
            "evaluated together in SIMD lanes, the trunk scalar; equals mass_matrix_lower.",
            ("q",),
            [("M", nv, nv, crba.LOWER_TRIANGLE_DOC)],
            lambda m: {"M": crba.lower_triangle(_columns(m.scatter_matrix(crba.mass_matrix(m))), nv)}),
        "forward_dynamics_lanes": (
            "Forward dynamics: solves M a = Sᵀτ + τ_e − c − g (CRBA + sparse LDLᵀ), the four "
            "isomorphic limbs' passes and their rows of the factorisation evaluated together in SIMD "
            "lanes, the trunk scalar; equals forward_dynamics.",
            ("q", "v", "tau", "f"),
            [("a", nv, 1, "acceleration")],
            lambda m: {"a": m.scatter(forward_dynamics.forward_dynamics(m))}),
        "osc_open_chain_lanes": (
            "Trunk operational-space Λ, J̄ᵀ, b with measured foot forces (paper 001 Table 1), the four "
            "isomorphic limbs' inward passes evaluated together in SIMD lanes, the trunk scalar; "
            "equals osc_open_chain.",
            ("q", "v", "f"),
            osc.output_specs(robot.n_joints),
            lambda m: _osc_outputs(m, osc.osc_open_chain(m))),
    }
    for name, paired in PAIRED.items():  # the same trace on a model with pair_streams
        doc, inputs, outputs, trace = table[LANE_NAME[name]]
        table[paired] = (doc + " In a limb pair, %s." % PAIRED_WORDS[name], inputs, outputs, trace)
    return table


def _in_lanes(specs, traces):
    """The lane function of each scalar function in `traces` (name → its lane trace): its scalar
    namesake's doc, inputs and outputs (`specs`: name → (doc, inputs, outputs, …))."""
    return {name + "_lanes": (specs[name][0] + " The four isomorphic limbs in SIMD lanes, the trunk "
                              "scalar; equals %s." % name,) + tuple(specs[name][1:3]) + (trace,)
            for name, trace in traces.items()}


def _contact_outputs(m, names, function):
    """A contact function's joint-space output scattered to the full robot, its contact rows (scalar
    already, in contact order) as they are."""
    lanes = contact_lanes(m.kept_feet, m.contacts, m.limbs)
    x, rows = function(m, lambda model: contact_dynamics.LaneDelassus(model, lanes))
    return {names[0]: m.scatter(x), names[1]: tuple(rows)}


def _osc_outputs(m, result):
    """Λ_t and b_t (trunk quantities: the limbs' lanes already summed into them) and J̄_tᵀ with
    its limb joint columns scattered to the full robot's joints."""
    Lam, JbarT, b = result
    return {"Lambda": _columns(Lam), "JbarT": _columns(m.scatter_joint_columns(JbarT)), "b": tuple(b)}


def _full_columns(m, rows):
    """Column-major entries of a matrix (rows) over the reduced tree's dofs as the full robot's: the
    root columns as they are, the lane limb's joint columns scattered to every limb."""
    root = m.robot.root_dofs
    joints = m.scatter_joint_columns(tuple(tuple(row[root:]) for row in rows))
    return _columns([tuple(row[:root]) + joints[r] for r, row in enumerate(rows)])


def _columns(rows):
    """Column-major entries of a matrix given as (non-empty) rows."""
    return tuple(rows[r][c] for c in range(len(rows[0])) for r in range(len(rows)))
