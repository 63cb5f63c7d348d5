#include "rbdc/data.hpp"

namespace rbdc {

// M_llt is sized in the initialiser list: move-assigning a fresh LLT would copy its
// not-yet-set status field (undefined behaviour that UBSan reports).
Data::Data(const Model& model) : M_llt(model.nv) {
  const size_t nb = static_cast<size_t>(model.nb);
  const Eigen::Index nv = model.nv;
  const Eigen::Index n_feet = static_cast<Eigen::Index>(model.feet.size());
  const Eigen::Index n_joints = model.num_joints();

  X_up.assign(nb, Matrix6::Identity());
  X_root.assign(nb, Matrix6::Identity());
  X_world.assign(nb, Matrix6::Identity());
  v.assign(nb, Vector6::Zero());
  feet_position = Matrix3X::Zero(3, n_feet);
  world_R_foot.assign(static_cast<size_t>(n_feet), Matrix3::Identity());
  feet_velocity = Matrix3X::Zero(3, n_feet);
  feet_bias_acceleration = Matrix3X::Zero(3, n_feet);

  a_body.assign(nb, Vector6::Zero());
  f_body.assign(nb, Vector6::Zero());
  f_ext.assign(nb, Vector6::Zero());
  f_rotor.assign(nb, Vector6::Zero());
  c = VectorX::Zero(nv);
  g = VectorX::Zero(nv);
  tau_e = VectorX::Zero(nv);
  tau = VectorX::Zero(nv);

  Ic.assign(nb, Matrix6::Zero());
  M = MatrixX::Zero(nv, nv);

  J_foot = Matrix6X::Zero(6, nv);
  J_foot_at_point = Matrix6X::Zero(6, nv);
  J = MatrixX::Zero(3 * n_feet, nv);
  J_contact = MatrixX::Zero(3 * n_feet, nv);

  const Eigen::Index n_frames = static_cast<Eigen::Index>(model.frames.size());
  world_R_frame.assign(model.frames.size(), Matrix3::Identity());
  frame_position = Matrix3X::Zero(3, n_frames);
  frame_velocity_local = Matrix6X::Zero(6, n_frames);
  frame_velocity_world = Matrix6X::Zero(6, n_frames);
  frame_jacobian_local.assign(model.frames.size(), Matrix6X::Zero(6, nv));
  frame_jacobian_world.assign(model.frames.size(), Matrix6X::Zero(6, nv));
  frame_bias_spatial = Matrix6X::Zero(6, n_frames);
  frame_bias_classical = Matrix6X::Zero(6, n_frames);

  com_jacobian = Matrix3X::Zero(3, nv);
  A_G = Matrix6X::Zero(6, nv);

  a = VectorX::Zero(nv);
  M_inverse = MatrixX::Zero(nv, nv);

  IA.assign(nb, Matrix6::Zero());
  beta.assign(nb, Vector6::Zero());
  zeta.assign(nb, Vector6::Zero());
  B.assign(nb, Matrix6X::Zero(6, n_joints));
  osc.JbarT = Matrix6X::Zero(6, n_joints);
}

}  // namespace rbdc
