"""contact_dynamics_derivatives' traced terms (differentiate.contact_dynamics_derivative_terms, the part
its looped form does not loop over) on the lane model, one contact foot per limb (docs/performance.md,
"Contact derivatives with the terms in limb lanes"). The same method and the same terms in the full
robot's layout; what the lanes change is where each term comes from:
- r₁, the forward-dynamics residual's derivatives at placeholder a and f, is the analytic recursion on
  the lane model, as for forward_dynamics_derivatives_lanes (limb k's columns in lane k);
- r₂, the derivatives of the lane foot's J a + J̇v (feet_motion_derivatives) on the lane model, so
  lane k holds contact k's derivative along limb k's coordinates (along another limb's it is zero);
- Z = L⁻ᵀJᵀ, D⁻¹Z, A and the damped factor are LaneDelassus's (Z and D⁻¹Z: contact k's column is
  lane k of the lane columns, LaneDelassus.half_solves), M's factor the lane factor's entries;
- the placeholders take the lane contact_dynamics' a and λ (λ in the lanes: the lane foot's force)."""

from __future__ import annotations

from . import differentiate
from ..algorithms import contact_dynamics as cd
from ..algorithms import forward_dynamics as fd
from ..algorithms.feet_motion_derivatives import feet_acceleration_derivatives
from ..graph import expr as ex
from ..graph import spatial as sp
from ..views.limb_lanes import contact_lanes, lane_column_order
from ..views.limbs import isomorphic_limbs


def contact_dynamics_derivative_terms(m):
    """The terms of differentiate.contact_dynamics_derivative_terms for the lane model m (feet=True)."""
    full = m.full
    lanes = contact_lanes(m.kept_feet, m.contacts, m.limbs)

    def delassus(model):
        return cd.LaneDelassus(model, lanes)

    system = delassus(m)
    dq, dv = (m.scatter_matrix(rows) for rows in differentiate.residual_derivatives(m))
    r2_q, r2_v = (_contact_columns(m, lanes, differentiate.column_major(rows))
                  for rows in feet_acceleration_derivatives(m, m.feet[:1]))
    r1_columns, r2_columns = differentiate.contact_columns(full, dq, dv, r2_q, r2_v)
    L, inv_diag = fd.mass_matrix_factor(m)
    terms = differentiate.contact_terms(r1_columns, r2_columns, system, *system.half_solves(m),
                                        fd.packed_factor(m.scatter_matrix(L), fd.dof_parents(full)),
                                        m.scatter(inv_diag), column_order(full))
    return differentiate.at_contact_solution(m, terms, delassus)


def column_order(robot):
    """The places of the terms' right-hand-side columns (limb_lanes.lane_column_order)."""
    return lane_column_order(robot, isomorphic_limbs(robot), differentiate.contact_column_dofs(robot))


def _contact_columns(m, lanes, tangents):
    """r₂'s columns along the full robot's q (or v) tangents from the lane foot's (`tangents`:
    column-major, 3 rows per direction of the reduced tree): contact c (lane k)
    takes lane k, in the full column of the reduced direction in lane k; zero along the other limbs."""
    columns = [sp.zeros(3 * len(lanes)) for _ in range(m.full.nv)]
    for d in range(m.robot.nv):
        for c, k in enumerate(lanes):
            column = list(columns[m.full_index(d, k)])
            column[3 * c:3 * c + 3] = [ex.lane_get(tangents[3 * d + r], k) for r in range(3)]
            columns[m.full_index(d, k)] = column
    return columns
