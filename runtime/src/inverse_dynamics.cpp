// Full RNEA: paper 000 Eqs. 19-23 with the joint accelerations added to Eq. 19 and gravity as the
// fictitious base acceleration of Alg. 3.
#include "rbdc/inverse_dynamics.hpp"

#include "argument_checks.hpp"
#include "rbdc/kinematics.hpp"
#include "rotors.hpp"
#include "tree_helpers.hpp"

namespace rbdc {

const VectorX& inverse_dynamics(const Model& model, Data& data, const VectorRef& q,
                                const VectorRef& v, const VectorRef& a) {
  detail::check_qv("inverse_dynamics", model, data, q, v);
  detail::check_size("inverse_dynamics", "a", a.size(), model.nv);
  kinematics(model, data, q, v);
  const Vector6& v0 = data.v[0];
  // a_0 ← a[0:6] + (0, -ω̃_0 v_0) - (0, R_W^0 g_W): the trunk's spatial acceleration from its
  // classical one (Alg. 2), biased by gravity (Alg. 3). A fixed base only keeps the gravity part.
  data.a_body[0] << Vector3::Zero(), -detail::rotation_of(data.X_world[0]) * model.gravity;
  if (model.floating_base) {
    data.a_body[0] += a.head<6>();
    data.a_body[0].tail<3>() -= v0.head<3>().cross(v0.tail<3>());
  }
  // f_0 ← I_0 a_0 + v_0 ⊗ I_0 v_0
  data.f_body[0] = model.inertia[0] * data.a_body[0] + crf(v0) * model.inertia[0] * v0;
  // for i = 1 … nb-1
  for (int i = 1; i < model.nb; ++i) {
    const size_t ui = static_cast<size_t>(i);
    const size_t j = static_cast<size_t>(model.parent[ui]);
    const int vi_index = model.joints[ui].v_index;
    const Vector6& S = model.motion_subspace[ui];
    const Vector6& vi = data.v[ui];
    const Matrix6& Ii = model.inertia[ui];
    //   a_i ← X_j^i a_j + S_i q̈_i + v_i * S_i q̇_i
    data.a_body[ui] = data.X_up[ui] * data.a_body[j] + S * a[vi_index] + crm(vi) * S * v[vi_index];
    //   f_i ← I_i a_i + v_i ⊗ I_i v_i                       (Eq. 20)
    data.f_body[ui] = Ii * data.a_body[ui] + crf(vi) * Ii * vi;
    //   rotor i on body j (rotors.hpp)
    if (model.has_rotors) {
      data.f_rotor[ui] = detail::rotor_wrench(model, ui, data.v[j], data.a_body[j], v[vi_index], a[vi_index]);
    }
  }
  // for i = nb-1 … 1: τ_i ← S_iᵀ f_i; f_j ← f_j + (X_j^i)ᵀ f_i; then τ_0 ← S_0ᵀ f_0
  detail::inward_force_pass(model, data, data.tau);
  // Armature: reflected inertia on M's diagonal only, τ_i += armature_i q̈_i.
  if (model.has_armature) {
    for (int i = 1; i < model.nb; ++i) {
      const Joint& joint = model.joints[static_cast<size_t>(i)];
      data.tau[joint.v_index] += joint.armature * a[joint.v_index];
    }
  }
  return data.tau;
}

}  // namespace rbdc
