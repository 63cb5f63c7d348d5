// DynamicsModel on the committed generated code: generated/mini_cheetah/{full,simulation}.hpp and,
// for rbdc-sim --rotors full, generated/mini_cheetah_rotors/ (the same robot with MIT's rotors).
// The contact step takes everything from one step_terms call (scene `simulation`).
#include "mini_cheetah/full.hpp"
#include "mini_cheetah/simulation.hpp"
#include "mini_cheetah_rotors/full.hpp"
#include "mini_cheetah_rotors/simulation.hpp"
#include "rbdc/sim/dynamics.hpp"
#include "rbdc/sim/tree_ltdl.hpp"
#include "rbdc/sim/robot.hpp"

namespace rbdc::sim {
namespace {

// One generated robot (scenes full and simulation) as static members: a namespace cannot be a
// template argument.
#define RBDC_SIM_GENERATED_API(Name, ns, sim_ns, label)                                              \
  struct Name {                                                                                    \
    static constexpr int nq = ns::nq, nv = ns::nv, n_feet = ns::n_feet;                            \
    using MassMatrix = ns::MassMatrix<double>;                                                     \
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
    static void step_terms(const double* q, const double* v, const double* tau, StepTerms& t,      \
                           double* L, double* D, double* D_inv) {                                  \
      sim_ns::step_terms<double>(q, v, tau, t.p_feet.data(), t.v_feet.data(), t.omega_feet.data(), \
                                 t.J.data(), t.Jw.data(), L, D, D_inv, t.a_free.data());           \
    }                                                                                              \
  };
RBDC_SIM_GENERATED_API(MiniCheetah, rbdc_gen::mini_cheetah::full, rbdc_gen::mini_cheetah::simulation,
                       "generated")
RBDC_SIM_GENERATED_API(MiniCheetahRotors, rbdc_gen::mini_cheetah_rotors::full,
                       rbdc_gen::mini_cheetah_rotors::simulation, "generated (rotors)")
#undef RBDC_SIM_GENERATED_API

template <class Gen>
class GeneratedDynamics final : public DynamicsModel {
 public:
  // M's factor has the sparsity of the URDF the code was generated from (the rotors add no dof).
  GeneratedDynamics() : GeneratedDynamics(load_robot(default_urdf())) {}
  explicit GeneratedDynamics(const Model& model) : dof_parents_(rbdc::sim::dof_parents(model)) {}
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
  // One generated pass: the CRBA, the factorisation, c + g and the feet share their kinematics.
  void step_terms(const double* q, const double* v, const double* tau, StepTerms& terms,
                  TreeLtdl& factor) override {
    terms.resize(Gen::nv, Gen::n_feet);
    Gen::step_terms(q, v, tau, terms, L_.data(), D_.data(), D_inv_.data());
    factor.assign(L_.data(), D_.data(), D_inv_.data());
  }
  const std::vector<int>& dof_parents() const override { return dof_parents_; }

 private:
  std::vector<int> dof_parents_;
  typename Gen::MassMatrix M_, L_;
  Eigen::Matrix<double, Gen::nv, 1> D_, D_inv_;
};

}  // namespace

std::unique_ptr<DynamicsModel> make_generated_dynamics() {
  return std::make_unique<GeneratedDynamics<MiniCheetah>>();
}

std::unique_ptr<DynamicsModel> make_generated_rotor_dynamics() {
  return std::make_unique<GeneratedDynamics<MiniCheetahRotors>>();
}

}  // namespace rbdc::sim
