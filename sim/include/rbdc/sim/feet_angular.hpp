// Angular velocity Jacobians of the bodies carrying the feet: ω_k^W = J_ω,k v (world coordinates).
// With them a force at the contact point C_k = p_fk − r ẑ_C (Eqs. 32-33) becomes the force at the
// foot point plus its moment, and v_Ck = v_fk + ω_k × (C_k − p_fk). Only rotations are computed, so
// the generated dynamics (which give linear feet rows only) can use them too.
#pragma once

#include "rbdc/model.hpp"

namespace rbdc::sim {

class FeetAngularJacobian {
 public:
  explicit FeetAngularJacobian(const Model& model);  ///< floating base, revolute joints
  /// Rows 3k…3k+2 map v = (ω_B, v_B, q̇) to the world angular velocity of foot k's body.
  /// q: nq (quaternion w x y z at 3…6). Jw: 3·n_feet × nv.
  void compute(const double* q, MatrixX& Jw);

 private:
  Model model_;
  std::vector<Matrix3> W_R_body_;  // per body, rotation only
};

}  // namespace rbdc::sim
