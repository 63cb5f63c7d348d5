#include "print_dynamics.hpp"

#include <iomanip>

#include "rbdc/rbdc.hpp"

namespace rbdc::tools {

VectorX documented_configuration(const Model& model) {
  VectorX q = VectorX::Zero(model.nq);
  const int first = model.floating_base ? 7 : 0;
  if (model.floating_base) q.head<7>() << 0, 0, 0.3, 1, 0, 0, 0;
  const double leg_pose[3] = {0.0, -0.8, 1.6};
  for (int j = 0; j < model.num_joints(); ++j) q[first + j] = leg_pose[j % 3];
  return q;
}

VectorX documented_velocity(const Model& model) {
  VectorX v(model.nv);
  for (int k = 0; k < model.nv; ++k) v[k] = 0.1 * (k % 5 + 1) * (k % 2 ? -1 : 1);
  return v;
}

void print_dynamics(const Model& model, const VectorX& q, const VectorX& v, std::ostream& out) {
  Data data(model);
  const Eigen::IOFormat rows(6, 0, " ", "\n", "  ", "");
  out << std::setprecision(6);
  out << "v = (" << v.transpose() << ")\n";
  out << "M (mass_matrix, CRBA) =\n" << mass_matrix(model, data, q).format(rows) << "\n";
  out << "c (quadratic_velocity_terms) =\n" << quadratic_velocity_terms(model, data, q, v).transpose().format(rows) << "\n";
  out << "g (gravity_terms) =\n" << gravity_terms(model, data, q).transpose().format(rows) << "\n";
  out << "feet positions (world, one row per foot) =\n"
      << feet_positions(model, data, q).transpose().format(rows) << "\n";
  out << "feet Jacobian (world, 3 rows per foot) =\n" << feet_jacobian(model, data, q).format(rows) << "\n";
}

}  // namespace rbdc::tools
