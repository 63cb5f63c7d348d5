// Independent coordinates of a coupled model and the projection of the dynamics (coupling.hpp).
#include "rbdc/coupling.hpp"

#include <Eigen/Cholesky>
#include <limits>
#include <stdexcept>
#include <string>

#include "rbdc/bias_terms.hpp"
#include "rbdc/crba.hpp"

namespace rbdc {
namespace {

void check_size(const char* what, Eigen::Index size, int expected) {
  if (size != expected) {
    throw std::invalid_argument(std::string(what) + " has " + std::to_string(size) + " entries, expected " +
                                std::to_string(expected));
  }
}

}  // namespace

int CoupledCoordinates::num_joints() const {
  int n = 0;
  for (size_t i = 1; i < follower.size(); ++i) n += follower[i] ? 0 : 1;
  return n;
}

CoupledCoordinates coupled_coordinates(const Model& model) {
  CoupledCoordinates c;
  const size_t nb = static_cast<size_t>(model.nb);
  c.follower.assign(nb, false);
  c.q_index.assign(nb, 0);
  c.v_index.assign(nb, 0);
  for (const Coupling& k : model.couplings) c.follower[static_cast<size_t>(k.follower)] = true;
  c.nq = model.floating_base ? 7 : 0;
  c.nv = model.root_dofs();
  for (size_t i = 1; i < nb; ++i) {
    if (c.follower[i]) continue;
    c.q_index[i] = c.nq++;
    c.v_index[i] = c.nv++;
  }
  for (const Coupling& k : model.couplings) {
    c.q_index[static_cast<size_t>(k.follower)] = c.q_index[static_cast<size_t>(k.leader)];
    c.v_index[static_cast<size_t>(k.follower)] = c.v_index[static_cast<size_t>(k.leader)];
  }
  return c;
}

MatrixX coupling_matrix(const Model& model) {
  const CoupledCoordinates c = coupled_coordinates(model);
  MatrixX G = MatrixX::Zero(model.nv, c.nv);
  for (int k = 0; k < model.root_dofs(); ++k) G(k, k) = 1;
  for (int i = 1; i < model.nb; ++i) {
    G(model.joints[static_cast<size_t>(i)].v_index, c.v_index[static_cast<size_t>(i)]) = 1;
  }
  for (const Coupling& k : model.couplings) {
    const int row = model.joints[static_cast<size_t>(k.follower)].v_index;
    G(row, c.v_index[static_cast<size_t>(k.leader)]) = k.multiplier;
  }
  return G;
}

VectorX expand_configuration(const Model& model, const VectorRef& q) {
  const CoupledCoordinates c = coupled_coordinates(model);
  check_size("q", q.size(), c.nq);
  VectorX q_tree(model.nq);
  if (model.floating_base) q_tree.head<7>() = q.head<7>();
  for (int i = 1; i < model.nb; ++i) {
    q_tree[model.joints[static_cast<size_t>(i)].q_index] = q[c.q_index[static_cast<size_t>(i)]];
  }
  for (const Coupling& k : model.couplings) {
    q_tree[model.joints[static_cast<size_t>(k.follower)].q_index] =
        k.multiplier * q[c.q_index[static_cast<size_t>(k.leader)]] + k.offset;
  }
  return q_tree;
}

VectorX independent_configuration(const Model& model, const VectorRef& q_tree) {
  const CoupledCoordinates c = coupled_coordinates(model);
  check_size("q", q_tree.size(), model.nq);
  VectorX q(c.nq);
  if (model.floating_base) q.head<7>() = q_tree.head<7>();
  for (int i = 1; i < model.nb; ++i) {
    if (!c.follower[static_cast<size_t>(i)]) {
      q[c.q_index[static_cast<size_t>(i)]] = q_tree[model.joints[static_cast<size_t>(i)].q_index];
    }
  }
  return q;
}

VectorX independent_velocity(const Model& model, const VectorRef& v_tree) {
  const CoupledCoordinates c = coupled_coordinates(model);
  check_size("v", v_tree.size(), model.nv);
  VectorX v(c.nv);
  v.head(model.root_dofs()) = v_tree.head(model.root_dofs());
  for (int i = 1; i < model.nb; ++i) {
    if (!c.follower[static_cast<size_t>(i)]) {
      v[c.v_index[static_cast<size_t>(i)]] = v_tree[model.joints[static_cast<size_t>(i)].v_index];
    }
  }
  return v;
}

VectorX coupled_forward_dynamics(const Model& model, Data& data, const VectorRef& q, const VectorRef& v,
                                 const VectorRef& tau, const Matrix3X& f_world) {
  const CoupledCoordinates c = coupled_coordinates(model);
  check_size("v", v.size(), c.nv);
  check_size("tau", tau.size(), c.num_joints());
  const MatrixX G = coupling_matrix(model);
  const VectorX q_tree = expand_configuration(model, q);
  const VectorX v_tree = G * v;
  VectorX rhs = G.transpose() * (feet_force_terms(model, data, q_tree, f_world) -
                                 quadratic_velocity_terms(model, data, q_tree, v_tree) -
                                 gravity_terms(model, data, q_tree));
  rhs.tail(c.num_joints()) += tau;  // S'ᵀτ': the independent joints follow the root's dofs
  const MatrixX M = G.transpose() * mass_matrix(model, data, q_tree) * G;
  const Eigen::LLT<MatrixX> llt(M);
  if (llt.info() != Eigen::Success) return VectorX::Constant(c.nv, std::numeric_limits<double>::quiet_NaN());
  return llt.solve(rhs);
}

}  // namespace rbdc
