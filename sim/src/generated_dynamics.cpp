// DynamicsModel on generated/mini_cheetah/full.hpp (compiled only when that target exists;
// otherwise generated_dynamics_none.cpp provides the factory).
#include "mini_cheetah/full.hpp"
#include "rbdc/sim/dynamics.hpp"
#include "rbdc/sim/feet_angular.hpp"
#include "rbdc/sim/tree_ltdl.hpp"
#include "rbdc/sim/robot.hpp"

namespace rbdc::sim {
namespace {

namespace gen = rbdc_gen::mini_cheetah::full;

class GeneratedDynamics final : public DynamicsModel {
 public:
  // The angular rows need only the joint frames; they come from the URDF the code was generated from.
  GeneratedDynamics() : GeneratedDynamics(load_robot(default_urdf())) {}
  explicit GeneratedDynamics(const Model& model) : angular_(model), dof_parents_(rbdc::sim::dof_parents(model)) {}
  int nq() const override { return gen::nq; }
  int nv() const override { return gen::nv; }
  int n_feet() const override { return gen::n_feet; }
  std::string name() const override { return "generated"; }

  void feet_state(const double* q, const double* v, double* p_feet, double* v_feet) override {
    gen::feet_positions<double>(q, p_feet);
    gen::feet_velocities<double>(q, v, v_feet);
  }

  void forward_dynamics(const double* q, const double* v, const double* tau, const double* f_feet,
                        double* a) override {
    gen::forward_dynamics<double>(q, v, tau, f_feet, a);
  }

  void mass_matrix(const double* q, MatrixX& M) override {
    gen::mass_matrix<double>(q, M_.data());
    M = M_;
  }
  void bias_forces(const double* q, const double* v, double* h) override {
    static constexpr double zero[gen::nv] = {};
    gen::inverse_dynamics<double>(q, v, zero, h);
  }
  void feet_jacobian(const double* q, MatrixX& J) override {
    gen::feet_jacobian<double>(q, J_.data());
    J = J_;
  }
  void feet_angular_jacobian(const double* q, MatrixX& Jw) override { angular_.compute(q, Jw); }
  const std::vector<int>& dof_parents() const override { return dof_parents_; }

 private:
  FeetAngularJacobian angular_;
  std::vector<int> dof_parents_;
  gen::MassMatrix<double> M_;
  gen::FeetJacobian<double> J_;
};

}  // namespace

std::unique_ptr<DynamicsModel> make_generated_dynamics() { return std::make_unique<GeneratedDynamics>(); }

}  // namespace rbdc::sim
