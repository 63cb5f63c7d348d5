// rbdc's side of generated_vs_pinocchio: the generated code of one robot, scenes `full` (ID, c + g,
// g, M, FD) and `derivatives` (∂ID, ∂FD). Compiled per robot with `-include <robot.hpp>`, written by
// generated_vs_pinocchio.sh, which includes the robot's two scene headers and defines
// peer_robot::{full, derivatives, name}. Inputs are the generated code's fixed-size Eigen types.
#include <stdexcept>
#include <string>

#include "generated_vs_pinocchio.hpp"
#include "rbdc/model.hpp"

namespace peer {
namespace {

namespace full = peer_robot::full;
namespace derivatives = peer_robot::derivatives;
constexpr int nv = full::nv, nj = full::n_joints;

struct FixedState {
  full::ConfigVector<double> q;
  full::TangentVector<double> v, a;
  full::JointVector<double> tau;
};

/// forward_dynamics_derivatives' outputs; taken through its raw-pointer overload because the Eigen
/// overload's ∂a/∂τ type is MassMatrix when nv = n_joints (fixed base), a plain Matrix otherwise.
struct FdDerivatives {
  full::MassMatrix<double> da_dq, da_dv;
  Eigen::Matrix<double, nv, nj> da_dtau;
  Eigen::Matrix<double, nv, 3 * full::n_feet> da_df;
};

const full::FeetMatrix<double> kNoForces = full::FeetMatrix<double>::Zero();

void fd_derivatives(const FixedState& s, FdDerivatives& o) {
  derivatives::forward_dynamics_derivatives(s.q.data(), s.v.data(), s.tau.data(), kNoForces.data(), o.da_dq.data(),
                                            o.da_dv.data(), o.da_dtau.data(), o.da_df.data());
}

class GeneratedSide final : public Side {
 public:
  Outputs outputs(const State& state) const override {
    const FixedState s = convert(state);
    full::TangentVector<double> tau, cg, g, a;
    full::MassMatrix<double> M, dtau_dq, dtau_dv;
    FdDerivatives fd;
    full::inverse_dynamics(s.q, s.v, s.a, tau);
    full::bias(s.q, s.v, cg);
    full::gravity_terms(s.q, g);
    full::mass_matrix(s.q, M);
    full::forward_dynamics(s.q, s.v, s.tau, kNoForces, a);
    derivatives::inverse_dynamics_derivatives(s.q, s.v, s.a, dtau_dq, dtau_dv);
    fd_derivatives(s, fd);
    return {tau, cg, g, a, M, dtau_dq, dtau_dv, fd.da_dq, fd.da_dv, fd.da_dtau};
  }

  void register_benchmarks(const std::vector<State>& states) const override {
    auto S = std::make_shared<std::vector<FixedState>>();
    for (const State& s : states) S->push_back(convert(s));
    // Outputs live in the closure; their data pointer escapes and memory is clobbered so that no
    // store is dropped.
    add_benchmark("rbdc/ID", [S, tau = full::TangentVector<double>()](int k) mutable {
      const FixedState& s = (*S)[k];
      full::inverse_dynamics(s.q, s.v, s.a, tau);
      benchmark::DoNotOptimize(tau.data());
      benchmark::ClobberMemory();
    });
    add_benchmark("rbdc/c+g", [S, cg = full::TangentVector<double>()](int k) mutable {
      const FixedState& s = (*S)[k];
      full::bias(s.q, s.v, cg);
      benchmark::DoNotOptimize(cg.data());
      benchmark::ClobberMemory();
    });
    add_benchmark("rbdc/g", [S, g = full::TangentVector<double>()](int k) mutable {
      full::gravity_terms((*S)[k].q, g);
      benchmark::DoNotOptimize(g.data());
      benchmark::ClobberMemory();
    });
    add_benchmark("rbdc/M", [S, M = full::MassMatrix<double>()](int k) mutable {
      full::mass_matrix((*S)[k].q, M);
      benchmark::DoNotOptimize(M.data());
      benchmark::ClobberMemory();
    });
    add_benchmark("rbdc/FD", [S, a = full::TangentVector<double>()](int k) mutable {
      const FixedState& s = (*S)[k];
      full::forward_dynamics(s.q, s.v, s.tau, kNoForces, a);
      benchmark::DoNotOptimize(a.data());
      benchmark::ClobberMemory();
    });
    add_benchmark("rbdc/dID", [S, dq = full::MassMatrix<double>(), dv = full::MassMatrix<double>()](int k) mutable {
      const FixedState& s = (*S)[k];
      derivatives::inverse_dynamics_derivatives(s.q, s.v, s.a, dq, dv);
      benchmark::DoNotOptimize(dq.data());
      benchmark::ClobberMemory();
    });
    add_benchmark("rbdc/dFD", [S, fd = FdDerivatives()](int k) mutable {
      fd_derivatives((*S)[k], fd);
      benchmark::DoNotOptimize(fd.da_dq.data());
      benchmark::ClobberMemory();
    });
  }

 private:
  static FixedState convert(const State& s) { return {s.q, s.v, s.a, s.tau}; }
};

}  // namespace

std::unique_ptr<Side> generated_side(const rbdc::Model& m) {
  if (m.nq != full::nq || m.nv != nv || m.num_joints() != nj) {
    throw std::runtime_error(std::string("the generated code of ") + peer_robot::name +
                             " does not have the model's nq, nv, joints (" + std::to_string(m.nq) + ", " +
                             std::to_string(m.nv) + ", " + std::to_string(m.num_joints()) + ")");
  }
  return std::make_unique<GeneratedSide>();
}

const char* generated_robot() { return peer_robot::name; }

}  // namespace peer
