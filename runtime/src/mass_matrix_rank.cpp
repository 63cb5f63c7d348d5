#include "rbdc/mass_matrix_rank.hpp"

#include <cmath>
#include <sstream>

#include "rbdc/crba.hpp"
#include "rbdc/data.hpp"

namespace rbdc {

namespace {

// The joint behind dof k.
std::string dof_label(const Model& model, int k) {
  if (k < model.root_dofs()) return "floating-base dof " + std::to_string(k);
  const size_t i = static_cast<size_t>(k - model.root_dofs() + 1);
  return "joint '" + model.joints[i].name + "' (dof " + std::to_string(k) + ")";
}

// Why dof k moves no inertia of its own, where it is plain: its body is a massless leaf.
std::string cause(const Model& model, int k) {
  if (k >= model.root_dofs()) {
    const size_t i = static_cast<size_t>(k - model.root_dofs() + 1);
    const Body& b = model.bodies[i];
    if (model.children[i].empty() && b.mass == 0 && b.inertia_com.isZero(0)) {
      return "body '" + b.name + "' is a moving leaf with zero mass";
    }
  }
  return "its motion moves no inertia that the dofs after it cannot move as well";
}

}  // namespace

std::string mass_matrix_singularity(const Model& model) {
  Data data(model);
  VectorX q = VectorX::Zero(model.nq);
  if (model.floating_base) q(3) = 1;  // identity quaternion (w x y z)
  const int first_joint = model.floating_base ? 7 : 0;
  for (int k = first_joint; k < model.nq; ++k) q(k) = std::sin(k - first_joint + 1.0);
  MatrixX H = mass_matrix(model, data, q);
  const VectorX diagonal = H.diagonal();
  for (Eigen::Index k = H.rows() - 1; k >= 0; --k) {  // Lᵀ D L, leaves first (Featherstone's LTDL)
    if (!(H(k, k) > kSingularPivot * diagonal(k))) {
      std::ostringstream s;
      s << "the mass matrix is singular: " << dof_label(model, static_cast<int>(k)) << " has pivot "
        << H(k, k) << " ≤ " << kSingularPivot << " · M_kk = " << kSingularPivot * diagonal(k) << " ("
        << cause(model, static_cast<int>(k)) << ")";
      return s.str();
    }
    for (Eigen::Index i = k - 1; i >= 0; --i) {
      const double ratio = H(k, i) / H(k, k);
      for (Eigen::Index j = i; j >= 0; --j) H(i, j) -= ratio * H(k, j);
      H(k, i) = ratio;
    }
  }
  return "";
}

}  // namespace rbdc
