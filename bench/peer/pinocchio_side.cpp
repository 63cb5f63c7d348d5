// Pinocchio 3's side of generated_vs_pinocchio: robot-independent (pinocchio::Model is dynamic), so
// compiled once and linked into every robot's binary. Header-only Pinocchio: its algorithms are
// instantiated here and inlined into their benchmark loops. States are mapped to Pinocchio's
// conventions once (pinocchio_conventions.hpp) and its outputs mapped back to rbdc's.
#include <pinocchio/algorithm/aba-derivatives.hpp>
#include <pinocchio/algorithm/aba.hpp>
#include <pinocchio/algorithm/crba.hpp>
#include <pinocchio/algorithm/rnea-derivatives.hpp>
#include <pinocchio/algorithm/rnea.hpp>
#include <pinocchio/multibody/data.hpp>

#include <cstdio>

#include "generated_vs_pinocchio.hpp"
#include "pinocchio_conventions.hpp"

namespace peer {
namespace {

/// A state in Pinocchio's coordinates: its a is the spatial base acceleration a − drift, `bias_a` is
/// −drift (where `rnea` gives rbdc's c + g), tau is nv long with zero base entries.
struct PinState {
  VectorX q, v, a, bias_a, tau;
};

/// M, Minv: Pinocchio fills the upper triangle only.
MatrixX symmetric(MatrixX X) {
  X.triangularView<Eigen::StrictlyLower>() = X.transpose();
  return X;
}

class PinocchioSide final : public Side {
 public:
  PinocchioSide(const rbdc::Model& m, const std::string& urdf) : m_(m) {
    std::string note;
    pin_ = pinocchio_model(urdf, m.floating_base, &note);
    if (!note.empty()) std::printf("%s\n", note.c_str());
    if (pin_.nv != m.nv) {
      throw std::runtime_error("nv differs: rbdc " + std::to_string(m.nv) + ", Pinocchio " + std::to_string(pin_.nv) +
                               " (mimic joints? Pinocchio loads them independent: --independent-mimic)");
    }
    map_ = map_indices(m, pin_);
  }

  Outputs outputs(const State& s) const override {
    const PinState p = convert(s);
    pinocchio::Data d(pin_);
    Outputs o;
    o.tau = from_pin_v(map_, pinocchio::rnea(pin_, d, p.q, p.v, p.a));
    o.cg = from_pin_v(map_, pinocchio::rnea(pin_, d, p.q, p.v, p.bias_a));
    o.g = from_pin_v(map_, pinocchio::computeGeneralizedGravity(pin_, d, p.q));
    o.M = from_pin_m(map_, symmetric(pinocchio::crba(pin_, d, p.q)));
    o.a = from_pin_v(map_, pinocchio::aba(pin_, d, p.q, p.v, p.tau)) + drift(m_, s.v);
    pinocchio::computeRNEADerivatives(pin_, d, p.q, p.v, p.a);
    o.dtau_dq = from_pin_m(map_, d.dtau_dq);
    o.dtau_dv = from_pin_m(map_, d.dtau_dv);
    // drift depends on v only, and not on the joint rates: ∂a/∂q and the joint columns of ∂a/∂v are
    // the same in both conventions.
    pinocchio::computeABADerivatives(pin_, d, p.q, p.v, p.tau);
    o.da_dq = from_pin_m(map_, d.ddq_dq);
    o.da_dv = from_pin_m(map_, d.ddq_dv);
    o.da_dtau = from_pin_m(map_, symmetric(d.Minv)).rightCols(m_.num_joints());
    return o;
  }

  void register_benchmarks(const std::vector<State>& states) const override {
    auto S = std::make_shared<std::vector<PinState>>();
    for (const State& s : states) S->push_back(convert(s));
    const pinocchio::Model& pin = pin_;
    // Each benchmark has its own Data, allocated here; the result's data pointer escapes and memory
    // is clobbered so that no store is dropped.
    auto data = [&] { return std::make_shared<pinocchio::Data>(pin); };
    add_benchmark("pin/ID", [&pin, S, d = data()](int k) {
      const PinState& s = (*S)[k];
      benchmark::DoNotOptimize(pinocchio::rnea(pin, *d, s.q, s.v, s.a).data());
      benchmark::ClobberMemory();
    });
    add_benchmark("pin/c+g", [&pin, S, d = data()](int k) {
      const PinState& s = (*S)[k];
      benchmark::DoNotOptimize(pinocchio::nonLinearEffects(pin, *d, s.q, s.v).data());
      benchmark::ClobberMemory();
    });
    add_benchmark("pin/g", [&pin, S, d = data()](int k) {
      benchmark::DoNotOptimize(pinocchio::computeGeneralizedGravity(pin, *d, (*S)[k].q).data());
      benchmark::ClobberMemory();
    });
    add_benchmark("pin/M", [&pin, S, d = data()](int k) {
      benchmark::DoNotOptimize(pinocchio::crba(pin, *d, (*S)[k].q).data());
      benchmark::ClobberMemory();
    });
    add_benchmark("pin/FD", [&pin, S, d = data()](int k) {
      const PinState& s = (*S)[k];
      benchmark::DoNotOptimize(pinocchio::aba(pin, *d, s.q, s.v, s.tau).data());
      benchmark::ClobberMemory();
    });
    add_benchmark("pin/dID", [&pin, S, d = data()](int k) {
      const PinState& s = (*S)[k];
      pinocchio::computeRNEADerivatives(pin, *d, s.q, s.v, s.a);
      benchmark::DoNotOptimize(d->dtau_dq.data());
      benchmark::ClobberMemory();
    });
    add_benchmark("pin/dFD", [&pin, S, d = data()](int k) {
      const PinState& s = (*S)[k];
      pinocchio::computeABADerivatives(pin, *d, s.q, s.v, s.tau);
      benchmark::DoNotOptimize(d->ddq_dq.data());
      benchmark::ClobberMemory();
    });
  }

 private:
  PinState convert(const State& s) const {
    const VectorX d = drift(m_, s.v);
    VectorX tau = VectorX::Zero(m_.nv);
    tau.tail(m_.num_joints()) = s.tau;
    return {to_pin_q(m_, map_, s.q, pin_.nq), to_pin_v(map_, s.v), to_pin_v(map_, s.a - d), to_pin_v(map_, -d),
            to_pin_v(map_, tau)};
  }

  const rbdc::Model& m_;
  pinocchio::Model pin_;
  IndexMap map_;
};

}  // namespace

std::unique_ptr<Side> pinocchio_side(const rbdc::Model& m, const std::string& urdf) {
  return std::make_unique<PinocchioSide>(m, urdf);
}

}  // namespace peer
