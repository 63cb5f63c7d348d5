// DynamicsModel on the runtime's reference algorithms (any robot loaded from URDF).
#include <Eigen/Core>

#include "rbdc/crba.hpp"
#include "rbdc/forward_dynamics.hpp"
#include "rbdc/inverse_dynamics.hpp"
#include "rbdc/jacobian.hpp"
#include "rbdc/kinematics.hpp"
#include "rbdc/sim/dynamics.hpp"
#include "rbdc/sim/tree_ltdl.hpp"

namespace rbdc::sim {
namespace {

class RuntimeDynamics final : public DynamicsModel {
 public:
  explicit RuntimeDynamics(const Model& model)
      : model_(model), data_(model_), dof_parents_(rbdc::sim::dof_parents(model_)), f_(Matrix3X::Zero(3, static_cast<int>(model.feet.size()))) {}

  int nq() const override { return model_.nq; }
  int nv() const override { return model_.nv; }
  int n_feet() const override { return static_cast<int>(model_.feet.size()); }
  std::string name() const override { return "runtime"; }

  void feet_state(const double* q, const double* v, double* p_feet, double* v_feet) override {
    const Eigen::Map<const VectorX> qm(q, model_.nq), vm(v, model_.nv);
    Eigen::Map<Matrix3X>(p_feet, 3, n_feet()) = feet_positions(model_, data_, qm);
    Eigen::Map<Matrix3X>(v_feet, 3, n_feet()) = feet_velocities(model_, data_, qm, vm);
  }

  void forward_dynamics(const double* q, const double* v, const double* tau, const double* f_feet,
                        double* a) override {
    f_ = Eigen::Map<const Matrix3X>(f_feet, 3, n_feet());
    Eigen::Map<VectorX>(a, model_.nv) = rbdc::forward_dynamics(
        model_, data_, Eigen::Map<const VectorX>(q, model_.nq), Eigen::Map<const VectorX>(v, model_.nv),
        Eigen::Map<const VectorX>(tau, model_.nv - model_.root_dofs()), f_);
  }

  void mass_matrix(const double* q, MatrixX& M) override {
    M = rbdc::mass_matrix(model_, data_, Eigen::Map<const VectorX>(q, model_.nq));
  }
  void step_terms(const double* q, const double* v, const double* tau, StepTerms& terms,
                  TreeLtdl& factor) override {
    terms.resize(model_.nv, n_feet());
    const Eigen::Map<const VectorX> qm(q, model_.nq), vm(v, model_.nv);
    feet_state(q, v, terms.p_feet.data(), terms.v_feet.data());
    terms.J = feet_jacobian(model_, data_, qm);
    angular_rows(qm, terms.Jw);
    for (int k = 0; k < n_feet(); ++k) terms.omega_feet.col(k) = terms.Jw.middleRows<3>(3 * k) * vm;
    factor.factorise(rbdc::mass_matrix(model_, data_, qm));
    f_.setZero();
    terms.a_free = rbdc::forward_dynamics(model_, data_, qm, vm,
                                          Eigen::Map<const VectorX>(tau, model_.nv - model_.root_dofs()), f_);
  }
  const std::vector<int>& dof_parents() const override { return dof_parents_; }

 private:
  // Angular rows of the feet's bodies (world): ω_B is in trunk coordinates, so its columns are the
  // trunk axes; a revolute joint j adds its world axis W_R_j a_j (X_W^j's rotation is j_R_W).
  void angular_rows(const VectorRef& q, MatrixX& Jw) {
    const std::vector<Matrix6>& X = world_transforms(model_, data_, q);
    Jw.setZero();
    for (int k = 0; k < n_feet(); ++k) {
      const int body = model_.feet[static_cast<size_t>(k)].body;
      if (model_.floating_base) Jw.block<3, 3>(3 * k, 0) = X[0].topLeftCorner<3, 3>().transpose();
      for (int j : model_.support[static_cast<size_t>(body)]) {
        const Joint& joint = model_.joints[static_cast<size_t>(j)];
        if (j == 0 || joint.type != JointType::Revolute) continue;
        Jw.block<3, 1>(3 * k, joint.v_index) = X[static_cast<size_t>(j)].topLeftCorner<3, 3>().transpose() * joint.axis;
      }
    }
  }

  Model model_;
  Data data_;
  std::vector<int> dof_parents_;
  Matrix3X f_;  // forward_dynamics takes a Matrix3X, not a map
};

}  // namespace

std::unique_ptr<DynamicsModel> make_runtime_dynamics(const Model& model) {
  return std::make_unique<RuntimeDynamics>(model);
}

}  // namespace rbdc::sim
