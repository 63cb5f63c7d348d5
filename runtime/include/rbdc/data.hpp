// The workspace of the runtime algorithms. A Data is sized once from a Model (every vector and
// matrix is allocated in the constructor) so that no algorithm call touches the heap. Results of
// the algorithms live here; each algorithm also returns a const reference to its result.
// Frames and ordering: docs/conventions.md; what each algorithm fills: docs/runtime.md.
#pragma once

#include <Eigen/Cholesky>
#include <vector>

#include "rbdc/model.hpp"

namespace rbdc {

using Matrix3X = Eigen::Matrix<double, 3, Eigen::Dynamic>;
using Matrix6X = Eigen::Matrix<double, 6, Eigen::Dynamic>;
/// Read-only vector argument: binds to VectorX, segments and maps without a copy.
using VectorRef = Eigen::Ref<const VectorX>;

/// Trunk operational-space quantities of paper 001 (Eq. 28 / Eq. 48):
///   Lambda · a_trunk + b = JbarT · τ + f_t,
/// with a_trunk = a[0:6] = (ω̇_B, R_W^0 p̈_W) and f_t a wrench on the trunk at its origin, all in
/// trunk coordinates.
struct OscQuantities {
  Matrix6 Lambda = Matrix6::Zero();  ///< Λ_t (6 × 6)
  Matrix6X JbarT;                    ///< J̄_tᵀ restricted to the actuated joints (6 × n_joints)
  Vector6 b = Vector6::Zero();       ///< b_t (6)
};

struct Data {
  explicit Data(const Model& model);

  // --- Kinematics (paper 000 Alg. 1, Eqs. 9-18, 37), index = body ------------------------------
  std::vector<Matrix6> X_up;     ///< X_λ(i)^i; X_up[0] is the identity
  std::vector<Matrix6> X_root;   ///< X_0^i (Eq. 12); X_root[0] is the identity
  std::vector<Matrix6> X_world;  ///< X_W^i (Eq. 15); X_world[0] = X_W^0 (Eq. 14)
  std::vector<Vector6> v;        ///< body spatial velocities v_i, body coordinates (Eq. 13)
  Matrix3X feet_position;        ///< column k: foot k's position in the world (Eq. 18)
  std::vector<Matrix3> world_R_foot;  ///< foot k's orientation: foot → world coordinates (Eq. 17)
  Matrix3X feet_velocity;        ///< column k: foot k's linear velocity, world coordinates (Eq. 37)
  Matrix3X feet_bias_acceleration;  ///< column k: J̇_k v, foot k's acceleration at a = 0, world

  // --- Recursive Newton-Euler passes (Algs. 2-4) -----------------------------------------------
  std::vector<Vector6> a_body;   ///< body spatial accelerations a_i of the current pass
  std::vector<Vector6> f_body;   ///< body wrenches f_i of the current pass
  std::vector<Vector6> f_ext;    ///< external wrench on body i at its origin, body coordinates
  std::vector<Vector6> f_rotor;  ///< wrench of joint i's rotor, rotor coordinates (zero without)
  VectorX c;                     ///< quadratic velocity terms (Alg. 2), nv
  VectorX g;                     ///< gravity terms (Alg. 3), nv
  VectorX tau_e;                 ///< external wrench terms (Alg. 4), nv
  VectorX tau;                   ///< inverse dynamics M a + c + g, nv

  // --- Joint-space inertia (Alg. 5) --------------------------------------------------------------
  std::vector<Matrix6> Ic;       ///< composite-rigid-body inertias I_ci (Eq. 26)
  MatrixX M;                     ///< joint-space inertia matrix, nv × nv, full symmetric

  // --- Feet Jacobian (Alg. 6, App. B) ------------------------------------------------------------
  Matrix6X J_foot;               ///< one foot's block row X_j^i S_j in body coordinates (6 × nv)
  Matrix6X J_foot_at_point;      ///< the same at the foot point, X_i^fk · J_foot (6 × nv)
  MatrixX J;                     ///< feet Jacobian, world coordinates (3·n_feet × nv)
  MatrixX J_contact;             ///< feet Jacobian, contact-frame coordinates (3·n_feet × nv)

  // --- Operational frames (rbdc/frames.hpp), column or entry k = model.frames[k] -----------------
  std::vector<Matrix3> world_R_frame;  ///< frame k's orientation: frame → world coordinates
  Matrix3X frame_position;             ///< column k: frame k's origin in the world
  Matrix6X frame_velocity_local;       ///< column k: (ω; v) of frame k at its origin, frame axes
  Matrix6X frame_velocity_world;       ///< the same in world axes (still at the frame origin)
  std::vector<Matrix6X> frame_jacobian_local;  ///< 6 × nv each: J_k v = frame_velocity_local
  std::vector<Matrix6X> frame_jacobian_world;  ///< 6 × nv each: J_k v = frame_velocity_world
  Matrix6X frame_bias_spatial;    ///< column k: J̇_k v of the local Jacobian (spatial, frame axes)
  Matrix6X frame_bias_classical;  ///< column k: J̇_k v of the world-aligned one (classical, world)

  // --- Centroidal quantities (rbdc/centroidal.hpp), world axes --------------------------------------
  Vector3 com = Vector3::Zero();            ///< centre of mass
  Vector3 com_velocity = Vector3::Zero();   ///< its velocity
  Matrix3X com_jacobian;                    ///< 3 × nv: com_velocity = com_jacobian v
  Matrix6X A_G;                             ///< centroidal momentum matrix (6 × nv): h_G = A_G v
  Vector6 centroidal_bias = Vector6::Zero();  ///< Ȧ_G v, the rate of h_G at a = 0

  // --- Forward dynamics (Eq. 43) -----------------------------------------------------------------
  VectorX a;                     ///< generalised acceleration, nv
  Eigen::LLT<MatrixX> M_llt;     ///< Cholesky factor of M, sized nv
  MatrixX M_inverse;             ///< M⁻¹ (mass_matrix_inverse), nv × nv

  // --- Operational space (paper 001 Tables 1-2) --------------------------------------------------
  std::vector<Matrix6> IA;       ///< articulated inertias I_i^A (or Ĩ_i^A)
  std::vector<Vector6> beta;     ///< articulated bias forces β_i^A (or β̃_i^A)
  std::vector<Vector6> zeta;     ///< velocity-product accelerations ζ_i (Eq. 29)
  std::vector<Matrix6X> B;       ///< B_ik: column k-1 holds joint k's coupling (6 × n_joints)
  OscQuantities osc;             ///< output of osc_open_chain / osc_closed_chain
  // The closed-form references keep their own workspace: OscReferenceData in rbdc/osc.hpp.
};

}  // namespace rbdc
