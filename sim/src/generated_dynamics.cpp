// DynamicsModel on the committed generated code: generated/mini_cheetah/full.hpp and, for
// rbdc-sim --rotors full, generated/mini_cheetah_rotors/full.hpp (the same robot with MIT's rotors).
#include "mini_cheetah/full.hpp"
#include "mini_cheetah_rotors/full.hpp"
#include "rbdc/sim/dynamics.hpp"
#include "rbdc/sim/feet_angular.hpp"
#include "rbdc/sim/tree_ltdl.hpp"
#include "rbdc/sim/robot.hpp"

namespace rbdc::sim {
namespace {

// One generated robot and scene as static members: a namespace cannot be a template argument.
#define RBDC_SIM_GENERATED_API(Name, ns, label)                                                       \
  struct Name {                                                                                    \
    static constexpr int nq = ns::nq, nv = ns::nv, n_feet = ns::n_feet;                            \
    using MassMatrix = ns::MassMatrix<double>;                                                     \
    using FeetJacobian = ns::FeetJacobian<double>;                                                 \
    static const char* name() { return label; }                                                    \
    static void feet_positions(const double* q, double* p) { ns::feet_positions<double>(q, p); }   \
    static void feet_velocities(const double* q, const double* v, double* pd) {                    \
      ns::feet_velocities<double>(q, v, pd);                                                       \
    }                                                                                              \
    static void forward_dynamics(const double* q, const double* v, const double* tau,              \
                                 const double* f, double* a) {                                     \
      ns::forward_dynamics<double>(q, v, tau, f, a);                                               \
    }                                                                                              \
    static void mass_matrix(const double* q, double* M) { ns::mass_matrix<double>(q, M); }         \
    static void mass_matrix_factor(const double* q, double* L, double* D, double* D_inv) {         \
      ns::mass_matrix_factor<double>(q, L, D, D_inv);                                              \
    }                                                                                              \
    static void bias(const double* q, const double* v, double* h) { ns::bias<double>(q, v, h); }   \
    static void feet_jacobian(const double* q, double* J) { ns::feet_jacobian<double>(q, J); }     \
  };
RBDC_SIM_GENERATED_API(MiniCheetah, rbdc_gen::mini_cheetah::full, "generated")
RBDC_SIM_GENERATED_API(MiniCheetahRotors, rbdc_gen::mini_cheetah_rotors::full, "generated (rotors)")
#undef RBDC_SIM_GENERATED_API

template <class Gen>
class GeneratedDynamics final : public DynamicsModel {
 public:
  // The angular rows need only the joint frames; they come from the URDF the code was generated from
  // (the rotors change no frame).
  GeneratedDynamics() : GeneratedDynamics(load_robot(default_urdf())) {}
  explicit GeneratedDynamics(const Model& model) : angular_(model), dof_parents_(rbdc::sim::dof_parents(model)) {}
  int nq() const override { return Gen::nq; }
  int nv() const override { return Gen::nv; }
  int n_feet() const override { return Gen::n_feet; }
  std::string name() const override { return Gen::name(); }

  void feet_state(const double* q, const double* v, double* p_feet, double* v_feet) override {
    Gen::feet_positions(q, p_feet);
    Gen::feet_velocities(q, v, v_feet);
  }

  void forward_dynamics(const double* q, const double* v, const double* tau, const double* f_feet,
                        double* a) override {
    Gen::forward_dynamics(q, v, tau, f_feet, a);
  }

  void mass_matrix(const double* q, MatrixX& M) override {
    Gen::mass_matrix(q, M_.data());
    M = M_;
  }
  // The generated factor: the CRBA and the factorisation unrolled, no M to copy and factor here.
  void mass_matrix_factor(const double* q, TreeLtdl& factor) override {
    Gen::mass_matrix_factor(q, L_.data(), D_.data(), D_inv_.data());
    factor.assign(L_.data(), D_.data(), D_inv_.data());
  }
  void bias_forces(const double* q, const double* v, double* h) override { Gen::bias(q, v, h); }
  void feet_jacobian(const double* q, MatrixX& J) override {
    Gen::feet_jacobian(q, J_.data());
    J = J_;
  }
  void feet_angular_jacobian(const double* q, MatrixX& Jw) override { angular_.compute(q, Jw); }
  const std::vector<int>& dof_parents() const override { return dof_parents_; }

 private:
  FeetAngularJacobian angular_;
  std::vector<int> dof_parents_;
  typename Gen::MassMatrix M_, L_;
  Eigen::Matrix<double, Gen::nv, 1> D_, D_inv_;
  typename Gen::FeetJacobian J_;
};

}  // namespace

std::unique_ptr<DynamicsModel> make_generated_dynamics() {
  return std::make_unique<GeneratedDynamics<MiniCheetah>>();
}

std::unique_ptr<DynamicsModel> make_generated_rotor_dynamics() {
  return std::make_unique<GeneratedDynamics<MiniCheetahRotors>>();
}

}  // namespace rbdc::sim
