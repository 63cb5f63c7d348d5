// Operational frames: Eqs. 13-18, 19 and B3 of paper 000 with the frame transform X_i^F in place of
// the foot's X_i^fk (which is the pure-translation special case).
#include "rbdc/frames.hpp"

#include <stdexcept>

#include "argument_checks.hpp"
#include "rbdc/kinematics.hpp"
#include "tree_helpers.hpp"

namespace rbdc {

using detail::frame_transform;
using detail::rotation_of;

namespace {

/// diag(R, R) x: a spatial vector from frame axes to world axes (the point stays the frame origin).
Vector6 to_world_axes(const Matrix3& world_R_frame, const Vector6& x) {
  Vector6 out;
  out << world_R_frame * x.head<3>(), world_R_frame * x.tail<3>();
  return out;
}

/// R_F^W (frame → world coordinates) = (R_W^F)ᵀ with R_W^F = E_F R_W^i (Eq. 17 with X_i^F).
Matrix3 world_R_frame(const Data& data, const Frame& frame) {
  return (frame.rotation * rotation_of(data.X_world[static_cast<size_t>(frame.body)])).transpose();
}

}  // namespace

int frame_index(const Model& model, const std::string& name) {
  for (size_t k = 0; k < model.frames.size(); ++k) {
    if (model.frames[k].name == name) return static_cast<int>(k);
  }
  throw std::invalid_argument("model '" + model.name + "' has no frame '" + name + "'");
}

const Matrix3X& frame_placements(const Model& model, Data& data, const VectorRef& q) {
  detail::check_q("frame_placements", model, data, q);
  world_transforms(model, data, q);
  for (size_t k = 0; k < model.frames.size(); ++k) {
    const Frame& frame = model.frames[k];
    const Matrix6& X_W_i = data.X_world[static_cast<size_t>(frame.body)];
    // p_F = p_i + R_i^W r_F                                 (Eqs. 16-18)
    data.frame_position.col(static_cast<Eigen::Index>(k)) =
        detail::origin_of(X_W_i) + rotation_of(X_W_i).transpose() * frame.translation;
    data.world_R_frame[k] = world_R_frame(data, frame);
  }
  return data.frame_position;
}

const Matrix6X& frame_velocities(const Model& model, Data& data, const VectorRef& q, const VectorRef& v) {
  detail::check_qv("frame_velocities", model, data, q, v);
  kinematics(model, data, q, v);
  world_transforms(model, data, q);
  for (size_t k = 0; k < model.frames.size(); ++k) {
    const Frame& frame = model.frames[k];
    const Eigen::Index col = static_cast<Eigen::Index>(k);
    // v_F = X_i^F v_i                                      (Eq. 13 carried to the frame)
    const Vector6 v_F = frame_transform(frame) * data.v[static_cast<size_t>(frame.body)];
    data.frame_velocity_local.col(col) = v_F;
    data.frame_velocity_world.col(col) = to_world_axes(world_R_frame(data, frame), v_F);
  }
  return data.frame_velocity_world;
}

const std::vector<Matrix6X>& frame_jacobians(const Model& model, Data& data, const VectorRef& q) {
  detail::check_q("frame_jacobians", model, data, q);
  world_transforms(model, data, q);
  for (size_t k = 0; k < model.frames.size(); ++k) {
    const Frame& frame = model.frames[k];
    //   J_i ← [X_j^i S_j]_{j ∈ κ(i)}                        (Eq. B3)
    detail::body_jacobian(model, data, frame.body, data.J_foot);
    //   J_F ← X_i^F J_i;  world-aligned: diag(R_F^W, R_F^W) J_F
    Matrix6X& local = data.frame_jacobian_local[k];
    local.noalias() = frame_transform(frame) * data.J_foot;
    const Matrix3 R = world_R_frame(data, frame);
    data.frame_jacobian_world[k].topRows<3>().noalias() = R * local.topRows<3>();
    data.frame_jacobian_world[k].bottomRows<3>().noalias() = R * local.bottomRows<3>();
  }
  return data.frame_jacobian_world;
}

const Matrix6X& frame_bias_accelerations(const Model& model, Data& data, const VectorRef& q,
                                         const VectorRef& v) {
  detail::check_qv("frame_bias_accelerations", model, data, q, v);
  kinematics(model, data, q, v);
  world_transforms(model, data, q);
  //   a_i at a = 0                                          (Eq. 19)
  detail::bias_accelerations(model, data, v);
  for (size_t k = 0; k < model.frames.size(); ++k) {
    const Frame& frame = model.frames[k];
    const Eigen::Index col = static_cast<Eigen::Index>(k);
    const size_t i = static_cast<size_t>(frame.body);
    //   a_F ← X_i^F a_i,  v_F ← X_i^F v_i;  classical: (ω̇_F; a_F,lin + ω_F × v_F) in world axes
    const Matrix6 X_F = frame_transform(frame);
    const Vector6 a_F = X_F * data.a_body[i];
    const Vector6 v_F = X_F * data.v[i];
    data.frame_bias_spatial.col(col) = a_F;
    data.frame_bias_classical.col(col) =
        to_world_axes(world_R_frame(data, frame), detail::classical_acceleration(a_F, v_F));
  }
  return data.frame_bias_classical;
}

}  // namespace rbdc
