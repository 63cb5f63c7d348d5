// DynamicsModel on generated/mini_cheetah/full.hpp (compiled only when that target exists;
// otherwise generated_dynamics_none.cpp provides the factory).
#include "mini_cheetah/full.hpp"
#include "rbdc/sim/dynamics.hpp"

namespace rbdc::sim {
namespace {

namespace gen = rbdc_gen::mini_cheetah::full;

class GeneratedDynamics final : public DynamicsModel {
 public:
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
};

}  // namespace

std::unique_ptr<DynamicsModel> make_generated_dynamics() { return std::make_unique<GeneratedDynamics>(); }

}  // namespace rbdc::sim
