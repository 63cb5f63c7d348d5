// Paper 000 Alg. 6 and App. B (Eqs. B1-B3).
#include "rbdc/jacobian.hpp"

#include "argument_checks.hpp"
#include "rbdc/kinematics.hpp"
#include "tree_helpers.hpp"

namespace rbdc {

const MatrixX& feet_jacobian(const Model& model, Data& data, const VectorRef& q) {
  detail::check_q("feet_jacobian", model, data, q);
  world_transforms(model, data, q);
  // J_feet ← 0
  data.J.setZero();
  // for k = 1 … m
  for (size_t k = 0; k < model.feet.size(); ++k) {
    //   i ← φ(k)
    const Foot& foot = model.feet[k];
    const int i = foot.body;
    //   for j ∈ κ(i): J_feet,kj ← X_j^i S_j   (Eq. B3)
    detail::body_jacobian(model, data, i, data.J_foot);
    //   J_feet,k ← X_i^fk J_feet,k
    data.J_foot_at_point.noalias() = detail::foot_transform(foot) * data.J_foot;
    // World linear rows: R_fk^W times the linear block (the foot frame has body i's orientation).
    const Matrix3 world_R_body =
        detail::rotation_of(data.X_world[static_cast<size_t>(i)]).transpose();
    data.J.middleRows<3>(3 * static_cast<Eigen::Index>(k)).noalias() =
        world_R_body * data.J_foot_at_point.bottomRows<3>();
  }
  return data.J;
}

const MatrixX& feet_jacobian_contact(const Model& model, Data& data, const VectorRef& q,
                                     const std::vector<Matrix3>& world_R_contact) {
  detail::check_size("feet_jacobian_contact", "world_R_contact",
                     static_cast<Eigen::Index>(world_R_contact.size()),
                     static_cast<Eigen::Index>(model.feet.size()));
  feet_jacobian(model, data, q);
  // Rotate each block row into its contact frame: R_W^Ck = (R_Ck^W)ᵀ (Eq. 33 without the offset).
  for (size_t k = 0; k < model.feet.size(); ++k) {
    const Eigen::Index row = 3 * static_cast<Eigen::Index>(k);
    data.J_contact.middleRows<3>(row).noalias() =
        world_R_contact[k].transpose() * data.J.middleRows<3>(row);
  }
  return data.J_contact;
}

}  // namespace rbdc
