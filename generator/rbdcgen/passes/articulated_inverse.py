"""The articulated-body recursion on a fixed-base chain (rbdc_gen/articulated_inverse.hpp): M⁻¹ whole
(rbdc_gen::articulated_inverse) for forward_dynamics_derivatives' low-rank form
(looped_solve.low_rank_applies; docs/performance.md, "M⁻¹ by the articulated-body recursion"), the ABA
run for every unit torque at once, O(n²) multiply-adds on a chain, where the looped CRBA, the factor
M = Lᵀ D L and Zᵀ D⁻¹ Z (looped_inverse.py) take O(n³); and forward dynamics as one O(n) loop
(rbdc_gen::articulated_forward_dynamics; has_looped_form; "Forward dynamics as one loop"): the RNEA's
c + g − Jᵀf in the root's coordinates, then the recursion, the traced part only the bodies' transforms."""

from __future__ import annotations

from dataclasses import dataclass
from typing import ClassVar, Tuple

from ..algorithms.crba import depth_first_order
from . import body_tree
from .body_tree import ACCUMULATE, APPLY, CROSS, PROJECTION, SPATIAL_CROSS, STEP_OVERHEAD
from .trace import with_loop

HEADER = "rbdc_gen/articulated_inverse.hpp"
TERMS = "forward_dynamics_chain_terms"  # forward_dynamics' looped form: the transforms and gravity
DOT8 = (8, 7)               # x · y padded to 8
OUTER = (36, 36)            # P + U wᵀ, P's 6 columns of 6
# Each body leaves first: U = I^C S − P S − U_c k with c = Sᵀ U_c, k = D_c⁻¹ c; D = Sᵀ(I^C S − P S) +
# armature − c k; a's column (f − Sᵀ p^A − c a_c) D⁻¹ and p^A + U_c a_c; P + U_c w_cᵀ; w = D⁻¹ U (the
# vectors 8 wide: their padding is computed too).
BODY_LEAVES_FIRST = (APPLY, (48, 40), DOT8, (1, 0), (0, 8), DOT8, (1, 2), (8, 8),
                     DOT8, (2, 2), (8, 8), (48, 48), (8, 0))
BODY_ROOT_FIRST = (DOT8, DOT8, (1, 2), (8, 8))  # a − wᵀ p − (wᵀ S_above) a_above; p + S_above a_above
BELOW = (13, 11)            # a column below the body, leaves first: Sᵀ p^A, D⁻¹ u, p^A + U m
ABOVE = (6, 6)              # a column from the body on, root first: m − wᵀ a, or a + S q̈
# The RNEA at q̈ = 0 before the recursion, per body: v + S q̇; (v_λ × S) q̇; a_λ + that; I a + v ×* I v;
# the force's sum and τ − Sᵀ(it) as the recursion asks for it. Per foot: p0 + E0ᵀ offset, p × f, and
# the wrench off its body's force.
BODY_RNEA = ((6, 6), SPATIAL_CROSS, (6, 0), (0, 6), APPLY, APPLY, SPATIAL_CROSS, (0, 6), (0, 6), PROJECTION, (0, 1))
FOOT = ((9, 9), CROSS, (0, 6))


@dataclass(frozen=True)
class ArticulatedInverse:
    """articulated_inverse writing M⁻¹ whole (column-major nv × nv) into `output`, the same array
    looped_inverse.LoopedInverse would write (∂a/∂τ), so that the low-rank product reads it alike,
    and a = M⁻¹r into solve_a from the terms' r (Sᵀτ + Jᵀf − c − g); with `unit_columns` False,
    articulated_forward_dynamics writing a into `output` from the terms' transforms and gravity, the
    inputs v, τ and f (forward_dynamics' looped form; `feet`: each foot's table body and offset);
    `comparison`: (its multiplications, those of the looped CRBA, factor and Zᵀ D⁻¹ Z), for the banner."""
    robot: object
    comparison: Tuple[int, int] = (0, 0)
    output: str = "da_dtau"
    simd_doubles: int = 4  # columns per vector instruction the cost model assumes (looped_solve.SIMD_DOUBLES)
    unit_columns: bool = True
    terms: Tuple = ()  # without unit_columns, the traced terms' outputs (X, g) it reads
    feet: Tuple = ()
    pays: ClassVar[bool] = True  # as a LoopedInverse that is taken
    headers: ClassVar[Tuple[str, ...]] = (body_tree.HEADER, HEADER)

    def _pieces(self):
        """(per-body pieces, per-column pieces), each (multiplications, additions), by trip count; the
        chain's body i on dof i − 1."""
        nb = self.robot.nb
        nv = nb - 1
        bodies, columns = body_tree.root_frame_pieces(self.robot), []
        if not self.unit_columns:
            bodies += list(BODY_RNEA) * nv + list(FOOT) * len(self.feet)
        for i in range(nb - 1, 0, -1):  # leaves first
            bodies += ([ACCUMULATE] if i < nb - 1 else []) + list(BODY_LEAVES_FIRST)
            columns += [BELOW] * (nv - i) if self.unit_columns else []  # the columns after the body's own
        for i in range(2, nb):  # root first: the first body's a is its own
            bodies += BODY_ROOT_FIRST
            columns += [ABOVE] * (2 * (nv - i) + 1) if self.unit_columns else []  # m − wᵀ a from i on, a + S q̈ after
        columns += [(ABOVE[0], 0)] * (nv - 1) if self.unit_columns else []  # the first body's a: S q̈
        return bodies, columns

    def operations(self):
        pieces = [piece for part in self._pieces() for piece in part]
        return {"mul": sum(m for m, _ in pieces), "add": sum(a for _, a in pieces),
                "div": self.robot.nb - 1, "neg": (self.robot.nb - 1) * self.unit_columns + 3 * (not self.unit_columns)}

    def instructions(self):
        """Per body as the tree loops count theirs (looped_crba.LoopedCrba: the larger of the two counts,
        a step's overhead each); per column, SIMD across the columns, a load and a multiply-add per
        multiplication, simd_doubles columns at a time (as looped_inverse.LoopedInverse)."""
        bodies, columns = self._pieces()
        per_body = max(sum(m for m, _ in bodies), sum(a for _, a in bodies)) + STEP_OVERHEAD * 2 * self.robot.nb
        return per_body + 2 * sum(m for m, _ in columns) // self.simd_doubles

    def cost(self):
        return body_tree.LOOP_WEIGHT * self.instructions()

    def loops(self):
        """The tree's table, then the loop (the low-rank product's RNEA loop reads the same table and a)."""
        nb, nv = self.robot.nb, self.robot.nv
        if not self.unit_columns:
            nf = len(self.feet)
            bodies = ", ".join(str(body) for body, _ in self.feet) or "0"
            offsets = ", ".join("{%s}" % (", ".join(repr(float(o[r])) for _, o in self.feet) or "0.0")
                                for r in range(3))
            return [body_tree.table(self.robot), f"RBDC_TABLE ChainFeet<{nf}> feet{{{{{bodies}}}, {{{offsets}}}}};",
                    f"articulated_forward_dynamics<Scalar, {nb}, {nv}, {nf}>(tree, feet, solve_X, solve_g, v, tau, f, "
                    f"{self.output});"]
        return [body_tree.table(self.robot), f"alignas(64) Scalar solve_a[{nv}];",
                f"articulated_inverse<Scalar, {nb}, {nv}>(tree, solve_X, solve_r, {self.output}, solve_a);"]

    def emission(self, terms_name):
        return ("forward dynamics as one loop: %s writes the %d bodies' transforms, articulated_forward_dynamics "
                "runs the RNEA's c + g − Jᵀf and the articulated-body recursion over a table of the tree"
                % (terms_name, self.robot.nb - 1))


def has_looped_form(robot, name):
    """forward_dynamics on a fixed-base chain (body_tree.fixed_base_chain)."""
    return name == "forward_dynamics" and body_tree.fixed_base_chain(robot)


def looped_function(robot, scene, name):
    """forward_dynamics in its looped form: the traced transforms and gravity, with
    articulated_forward_dynamics."""
    position = {body: k for k, body in enumerate(depth_first_order(robot))}
    feet = tuple((position[foot.body], tuple(foot.offset)) for foot in scene.feet_for(robot))
    return with_loop(robot, scene, name, TERMS, lambda terms, _: ArticulatedInverse(
        robot=robot, output="a", unit_columns=False, terms=terms.outputs, feet=feet))
