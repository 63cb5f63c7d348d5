"""A fixed-base chain's dynamics as one loop in the root's coordinates (rbdc_gen/articulated_inverse.hpp;
docs/performance.md, "A chain's dynamics as one loop"): the traced part writes only the bodies'
transforms and gravity; chain_inverse_dynamics runs the RNEA (inverse_dynamics, bias,
quadratic_velocity_terms), articulated_forward_dynamics the RNEA's c + g − Jᵀf and then the
articulated-body recursion (forward_dynamics), v and a carried along the chain in registers, the rest
SIMD across the bodies. Straight-line code folds the constants but grows past the instruction cache
with the chain (chain100's forward dynamics: 317 KB); the loop folds nothing, so on a short chain the
straight-line code wins by cost."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar, Tuple

from . import articulated_inverse, body_tree, differentiate, trace  # trace reads TERMS here: imported, not from-imported

# The quantities with the form: (Velocity, Acceleration, Gravity) of the bodies' forces, as
# articulated_detail::body_forces takes them (forward dynamics: at q̈ = 0, then the recursion).
FORCES = {"forward_dynamics": (True, False, True), "inverse_dynamics": (True, True, True),
          "bias": (True, False, True), "quadratic_velocity_terms": (True, False, False)}
TERMS = {name: name + "_chain_terms" for name in FORCES}  # each body's transform, and gravity
SIMD_DOUBLES = 2  # bodies per vector instruction the cost model assumes for the pieces SIMD across them (cost)


def terms_spec(robot, signature_inputs):
    """trace.py's entries for TERMS: name → (doc, input names, outputs, trace(m))."""
    return {terms: ("The traced part of %s in its chain-loop form (passes/chain_loop.py): each body's "
                    "transform, and gravity in root coordinates." % name, signature_inputs[name],
                    [("X", 12, robot.nb - 1, "each body's transform, as body_transforms writes it"),
                     ("g", 3, 1, "gravity in root coordinates")],
                    differentiate.transforms_and_gravity)
            for name, terms in TERMS.items()}


def has_looped_form(robot, name):
    """The quantities of FORCES on a fixed-base chain (body_tree.fixed_base_chain)."""
    return name in FORCES and body_tree.fixed_base_chain(robot)


@dataclass(frozen=True)
class ChainLoop:
    """The loop of `name` over the chain, reading the terms' X and g and the function's inputs,
    writing its output `output`; `feet` (forward dynamics): each foot's table body and offset."""
    robot: object
    name: str
    output: str
    terms: Tuple = ()
    feet: Tuple = ()
    headers: ClassVar[Tuple[str, ...]] = (body_tree.HEADER, articulated_inverse.HEADER)

    def _pieces(self):
        """(pieces along the chain, pieces SIMD across the bodies, per-column pieces), each
        (multiplications, additions), by trip count."""
        if self.name == "forward_dynamics":
            return articulated_inverse.forward_dynamics_pieces(self.robot, len(self.feet), False)
        velocity, acceleration, _ = FORCES[self.name]
        return articulated_inverse.body_force_pieces(self.robot, velocity, acceleration, 0) + ([],)

    def operations(self):
        pieces = [piece for part in self._pieces() for piece in part]
        return {"mul": sum(m for m, _ in pieces), "add": sum(a for _, a in pieces),
                "div": self.robot.nb - 1 if self.name == "forward_dynamics" else 0,
                "neg": 3 if FORCES[self.name][2] else 0}

    def instructions(self):
        along, across, columns = self._pieces()
        return articulated_inverse.loop_instructions(along + across, columns, self.robot.nb)

    def cost(self):
        """As the other loops' (body_tree.LOOP_WEIGHT), the pieces SIMD across the bodies at SIMD_DOUBLES
        bodies an instruction (2, not AVX2's 4: their loads and stores come with them). Counted whole,
        the RNEA's loop lost to the straight-line code by cost on a 50-link chain, where it ran 12 % (ID)
        and 38 % (bias) faster; counted at 4, it won on a 30-link chain's ID, 7 % slower there. Measured
        on Zen 5, clang 14 (docs/performance.md, "A chain's dynamics as one loop")."""
        along, across, columns = self._pieces()
        simd = max(sum(m for m, _ in across), sum(a for _, a in across)) // SIMD_DOUBLES
        return body_tree.LOOP_WEIGHT * (articulated_inverse.loop_instructions(along, columns, self.robot.nb) + simd)

    def loops(self):
        nb, nv = self.robot.nb, self.robot.nv
        if self.name != "forward_dynamics":
            velocity, acceleration, gravity = (body_tree.cpp_bool(flag) for flag in FORCES[self.name])
            a = "a" if FORCES[self.name][1] else "nullptr"
            return [body_tree.table(self.robot),
                    f"chain_inverse_dynamics<Scalar, {nb}, {nv}, {velocity}, {acceleration}, {gravity}>(tree, solve_X, "
                    f"solve_g, v, {a}, {self.output});"]
        return [body_tree.table(self.robot), articulated_inverse.feet_table(self.feet),
                f"articulated_forward_dynamics<Scalar, {nb}, {nv}, {len(self.feet)}>(tree, feet, solve_X, solve_g, v, "
                f"tau, f, {self.output});"]

    def emission(self, terms_name):
        loop = ("articulated_forward_dynamics runs the RNEA's c + g − Jᵀf and the articulated-body recursion"
                if self.name == "forward_dynamics" else "chain_inverse_dynamics runs the RNEA")
        return "one loop along the chain: %s writes the %d bodies' transforms, %s over a table of the tree" % (
            terms_name, self.robot.nb - 1, loop)


def looped_function(robot, scene, name):
    """`name` in its chain-loop form: the traced transforms and gravity, with the loop."""
    feet = articulated_inverse.chain_feet(robot, scene) if name == "forward_dynamics" else ()
    return trace.with_loop(robot, scene, name, TERMS[name], lambda terms, outputs: ChainLoop(
        robot=robot, name=name, output=outputs[0].name, terms=terms.outputs, feet=feet))
