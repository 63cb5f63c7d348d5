// DynamicsModel on the runtime's reference algorithms (any robot loaded from URDF).
#include <Eigen/Core>

#include "rbdc/crba.hpp"
#include "rbdc/forward_dynamics.hpp"
#include "rbdc/inverse_dynamics.hpp"
#include "rbdc/jacobian.hpp"
#include "rbdc/kinematics.hpp"
#include "rbdc/sim/dynamics.hpp"
#include "rbdc/sim/feet_angular.hpp"
#include "rbdc/sim/tree_ltdl.hpp"

namespace rbdc::sim {
namespace {

class RuntimeDynamics final : public DynamicsModel {
 public:
  explicit RuntimeDynamics(const Model& model)
      : model_(model), data_(model_), angular_(model_), dof_parents_(rbdc::sim::dof_parents(model_)), f_(Matrix3X::Zero(3, static_cast<int>(model.feet.size()))) {}

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

  void mass_matrix_factor(const double* q, TreeLtdl& factor) override {
    factor.factorise(rbdc::mass_matrix(model_, data_, Eigen::Map<const VectorX>(q, model_.nq)));
  }
  void mass_matrix(const double* q, MatrixX& M) override {
    M = rbdc::mass_matrix(model_, data_, Eigen::Map<const VectorX>(q, model_.nq));
  }
  void bias_forces(const double* q, const double* v, double* h) override {
    Eigen::Map<VectorX>(h, model_.nv) =
        inverse_dynamics(model_, data_, Eigen::Map<const VectorX>(q, model_.nq),
                         Eigen::Map<const VectorX>(v, model_.nv), VectorX::Zero(model_.nv));
  }
  void feet_jacobian(const double* q, MatrixX& J) override {
    J = rbdc::feet_jacobian(model_, data_, Eigen::Map<const VectorX>(q, model_.nq));
  }
  void feet_angular_jacobian(const double* q, MatrixX& Jw) override { angular_.compute(q, Jw); }
  const std::vector<int>& dof_parents() const override { return dof_parents_; }

 private:
  Model model_;
  Data data_;
  FeetAngularJacobian angular_;
  std::vector<int> dof_parents_;
  Matrix3X f_;  // forward_dynamics takes a Matrix3X, not a map
};

}  // namespace

std::unique_ptr<DynamicsModel> make_runtime_dynamics(const Model& model) {
  return std::make_unique<RuntimeDynamics>(model);
}

}  // namespace rbdc::sim
