#include "rbdc/derivatives.hpp"

namespace rbdc {

DerivativeData::DerivativeData(const Model& model) {
  const size_t nb = static_cast<size_t>(model.nb);
  const Eigen::Index nv = model.nv;
  const Eigen::Index n_feet3 = 3 * static_cast<Eigen::Index>(model.feet.size());

  dtau_dq = MatrixX::Zero(nv, nv);
  dtau_dv = MatrixX::Zero(nv, nv);
  dbias_dq = MatrixX::Zero(nv, nv);
  dbias_dv = MatrixX::Zero(nv, nv);
  dg_dq = MatrixX::Zero(nv, nv);
  da_dq = MatrixX::Zero(nv, nv);
  da_dv = MatrixX::Zero(nv, nv);
  da_dtau = MatrixX::Zero(nv, model.num_joints());
  da_df = MatrixX::Zero(nv, n_feet3);
  dpdot_dq = MatrixX::Zero(n_feet3, nv);
  dtau_e_dq = MatrixX::Zero(nv, nv);

  dX_motion.assign(nb, Vector6::Zero());
  dv_body.assign(nb, Vector6::Zero());
  da_body.assign(nb, Vector6::Zero());
  df_body.assign(nb, Vector6::Zero());
  df_rotor.assign(nb, Vector6::Zero());
  direction_q = VectorX::Zero(nv);
  direction_v = VectorX::Zero(nv);
  zero_nv = VectorX::Zero(nv);
  tau_column = VectorX::Zero(nv);
}

}  // namespace rbdc
