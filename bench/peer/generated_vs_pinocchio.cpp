// rbdc's generated code against Pinocchio 3, one binary per robot (issue 20; results/bench/
// peer_pinocchio.md): ID, c + g, g, M, FD and the derivatives of ID and FD, timed by Google Benchmark
// as pairs `pin/<quantity>` and `rbdc/<quantity>` on the same 64 random states. Not part of the
// build: bench/peer/generated_vs_pinocchio.sh generates the code, compiles and runs it.
//
// Before timing, the two sides are compared on every state (in rbdc's coordinates, Pinocchio's mapped
// by pinocchio_conventions.hpp): max over the states of max|rbdc − pin| / max(1, max|pin|). ∂/∂v is
// compared on the joint columns only: the base columns differ by the documented ω × v term
// (docs/conventions.md, "Pinocchio's convention"). Exit 1, untimed, if any is above 1e-8.
//
// Usage: generated_vs_pinocchio URDF --floating-base|--fixed-base [--independent-mimic] [benchmark flags]
// (the URDF and options the code was generated from: the runtime's model gives the joint names).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <iostream>
#include <random>
#include <string>

#include "generated_vs_pinocchio.hpp"
#include "rbdc/urdf_loader.hpp"

namespace {

using peer::State;

std::vector<State> random_states(const rbdc::Model& m) {
  std::mt19937_64 rng(20);
  std::uniform_real_distribution<double> uniform(-1, 1);
  std::normal_distribution<double> normal;
  auto random = [&](int n) { return Eigen::VectorXd::NullaryExpr(n, [&] { return uniform(rng); }).eval(); };
  std::vector<State> states;
  for (int k = 0; k < peer::kStates; ++k) {
    State s{random(m.nq), random(m.nv), random(m.nv), random(m.num_joints())};
    // uniform on S³; rbdc's order w, x, y, z
    if (m.floating_base) s.q.segment<4>(3) = Eigen::Vector4d(normal(rng), normal(rng), normal(rng), normal(rng)).normalized();
    states.push_back(s);
  }
  return states;
}

/// Prints the agreement of the two sides on `states`; returns the worst figure.
double agreement(const rbdc::Model& m, const peer::Side& gen, const peer::Side& pin, const std::vector<State>& states) {
  using peer::Outputs;
  const int nj = m.num_joints();
  const std::vector<std::pair<const char*, std::function<Eigen::MatrixXd(const Outputs&)>>> quantities = {
      {"ID", [](const Outputs& o) { return o.tau; }},
      {"c+g", [](const Outputs& o) { return o.cg; }},
      {"g", [](const Outputs& o) { return o.g; }},
      {"M", [](const Outputs& o) { return o.M; }},
      {"FD", [](const Outputs& o) { return o.a; }},
      {"dID/dq", [](const Outputs& o) { return o.dtau_dq; }},
      {"dID/dv[joint cols]", [nj](const Outputs& o) { return o.dtau_dv.rightCols(nj); }},
      {"dFD/dq", [](const Outputs& o) { return o.da_dq; }},
      {"dFD/dv[joint cols]", [nj](const Outputs& o) { return o.da_dv.rightCols(nj); }},
      {"dFD/dtau", [](const Outputs& o) { return o.da_dtau; }},
  };
  std::vector<double> worst(quantities.size(), 0.0);
  for (const State& s : states) {
    const Outputs r = gen.outputs(s), p = pin.outputs(s);
    for (std::size_t k = 0; k < quantities.size(); ++k) {
      const Eigen::MatrixXd x = quantities[k].second(r), reference = quantities[k].second(p);
      if (x.rows() != reference.rows() || x.cols() != reference.cols()) throw std::runtime_error("sizes differ");
      // = pinocchio_conventions.hpp's difference (not included here: this TU stays free of Pinocchio)
      const double d = (x - reference).cwiseAbs().maxCoeff() / std::max(1.0, reference.cwiseAbs().maxCoeff());
      worst[k] = std::max(worst[k], std::isnan(d) ? INFINITY : d);
    }
  }
  std::printf("agreement %s, max over %zu states of max|rbdc - pin| / max(1, max|pin|), rbdc's coordinates:\n",
              peer::generated_robot(), states.size());
  for (std::size_t k = 0; k < quantities.size(); ++k) std::printf("  %s %.1e", quantities[k].first, worst[k]);
  std::printf("\n");
  std::fflush(stdout);
  return *std::max_element(worst.begin(), worst.end());
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);  // takes its --benchmark_* flags out of argv
  const char* urdf = nullptr;
  int base = -1;  // 1 floating, 0 fixed
  rbdc::UrdfOptions options;
  for (int k = 1; k < argc; ++k) {
    if (!std::strcmp(argv[k], "--floating-base")) base = 1;
    else if (!std::strcmp(argv[k], "--fixed-base")) base = 0;
    else if (!std::strcmp(argv[k], "--independent-mimic")) options.mimic = rbdc::MimicMode::Independent;
    else if (!urdf && argv[k][0] != '-') urdf = argv[k];
    else base = -2;
  }
  if (!urdf || base < 0) {
    std::cerr << "usage: " << argv[0]
              << " URDF --floating-base|--fixed-base [--independent-mimic] [--benchmark_... flags]\n";
    return 2;
  }
  options.floating_base = base == 1;
  try {
    const rbdc::Model m = rbdc::load_urdf(urdf, options);
    const std::unique_ptr<peer::Side> gen = peer::generated_side(m), pin = peer::pinocchio_side(m, urdf);
    const std::vector<State> states = random_states(m);
    const double worst = agreement(m, *gen, *pin, states);
    if (!(worst <= 1e-8)) {
      std::fprintf(stderr, "agreement %.1e is worse than 1e-8: not timed\n", worst);
      return 1;
    }
    benchmark::AddCustomContext("robot", peer::generated_robot());
    benchmark::AddCustomContext("urdf", urdf);
    pin->register_benchmarks(states);
    gen->register_benchmarks(states);
    benchmark::RunSpecifiedBenchmarks();
    benchmark::Shutdown();
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
