// rbdc's runtime against Pinocchio 3 on URDF files (issue 23: every robot Pinocchio loads is accepted and
// its M, c, g, τ agree to 1e-12). Not part of the build: it needs a Pinocchio source snapshot kept outside
// the repository; bench/peer/runtime_vs_pinocchio.sh compiles and runs it (results/bench/peer_runtime.md).
//
// Each file is loaded by both, floating and fixed base, mimic joints independent (Pinocchio's default).
// Random states are mapped to Pinocchio's conventions (pinocchio_conventions.hpp, docs/conventions.md): q = (p, xyzw, joints) from
// (p, wxyz, joints); v-indexed rows and columns permuted (its free flyer is (v, ω), its joints matched
// by name, a continuous joint as (cos, sin)); its spatial base acceleration a_P = a − (0, ω × v).
// Printed per quantity: max over the states of max|rbdc − pin| / max(1, max|pin|).
#include <pinocchio/algorithm/aba.hpp>
#include <pinocchio/algorithm/crba.hpp>
#include <pinocchio/algorithm/joint-configuration.hpp>
#include <pinocchio/algorithm/rnea.hpp>
#include <pinocchio/multibody/data.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "pinocchio_conventions.hpp"

#include "rbdc/bias_terms.hpp"
#include "rbdc/crba.hpp"
#include "rbdc/forward_dynamics.hpp"
#include "rbdc/inverse_dynamics.hpp"
#include "rbdc/urdf_loader.hpp"

namespace {

using namespace peer;  // the coordinate mapping (pinocchio_conventions.hpp)

constexpr int kStates = 1000;

struct Worst {
  double M = 0, c = 0, g = 0, tau = 0, a = 0;
  std::string pinocchio_input = "the file";
};

Worst compare(const std::string& path, bool floating) {
  rbdc::UrdfOptions options;
  options.floating_base = floating;
  options.mimic = rbdc::MimicMode::Independent;
  std::vector<std::string> warnings;
  const rbdc::Model m = rbdc::load_urdf(path, options, &warnings);
  std::string note;
  const pinocchio::Model pin = pinocchio_model(path, floating, &note);
  if (pin.nv != m.nv) throw std::runtime_error("nv differs: Pinocchio " + std::to_string(pin.nv));
  std::printf("%s, %s base: nv %d, %zu rbdc warnings%s%s\n", path.c_str(), floating ? "floating" : "fixed", m.nv,
              warnings.size(), note.empty() ? "" : "; ", note.c_str());
  const IndexMap map = map_indices(m, pin);
  rbdc::Data data(m);
  pinocchio::Data pd(pin);
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> uniform(-1, 1);
  std::normal_distribution<double> normal;
  const rbdc::Matrix3X no_forces = rbdc::Matrix3X::Zero(3, static_cast<Eigen::Index>(m.feet.size()));
  Worst worst;
  if (!note.empty()) worst.pinocchio_input = "limits added";
  for (int s = 0; s < kStates; ++s) {
    VectorX q = VectorX::NullaryExpr(m.nq, [&] { return uniform(rng); });
    if (floating) q.segment<4>(3) = Eigen::Vector4d(normal(rng), normal(rng), normal(rng), normal(rng)).normalized();
    const VectorX v = VectorX::NullaryExpr(m.nv, [&] { return uniform(rng); });
    const VectorX a = VectorX::NullaryExpr(m.nv, [&] { return uniform(rng); });
    const VectorX tau = VectorX::NullaryExpr(m.num_joints(), [&] { return uniform(rng); });
    const VectorX d = drift(m, v);  // a_P = a − d
    const VectorX qp = to_pin_q(m, map, q, pin.nq), vp = to_pin_v(map, v);

    MatrixX Mp = pinocchio::crba(pin, pd, qp);
    Mp.triangularView<Eigen::StrictlyLower>() = Mp.transpose();
    worst.M = std::max(worst.M, difference(rbdc::mass_matrix(m, data, q), from_pin_m(map, Mp)));
    const VectorX gp = from_pin_v(map, pinocchio::computeGeneralizedGravity(pin, pd, qp));
    worst.g = std::max(worst.g, difference(rbdc::gravity_terms(m, data, q), gp));
    const VectorX cgp = from_pin_v(map, pinocchio::rnea(pin, pd, qp, vp, to_pin_v(map, -d)));
    worst.c = std::max(worst.c, difference(rbdc::quadratic_velocity_terms(m, data, q, v), cgp - gp));
    const VectorX taup = from_pin_v(map, pinocchio::rnea(pin, pd, qp, vp, to_pin_v(map, a - d)));
    worst.tau = std::max(worst.tau, difference(rbdc::inverse_dynamics(m, data, q, v, a), taup));
    VectorX applied = VectorX::Zero(m.nv);
    applied.tail(m.num_joints()) = tau;
    const VectorX ap = from_pin_v(map, pinocchio::aba(pin, pd, qp, vp, to_pin_v(map, applied))) + d;
    worst.a = std::max(worst.a, difference(rbdc::forward_dynamics(m, data, q, v, tau, no_forces), ap));
  }
  return worst;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::cerr << "usage: runtime_vs_pinocchio FILE.urdf...\n";
    return 2;
  }
  std::vector<std::string> rows;
  double overall = 0;
  for (int k = 1; k < argc; ++k) {
    for (const bool floating : {true, false}) {
      const Worst w = compare(argv[k], floating);
      char row[512];
      std::snprintf(row, sizeof row, "| %s | %s | %s | %.1e | %.1e | %.1e | %.1e | %.1e |", argv[k],
                    floating ? "floating" : "fixed", w.pinocchio_input.c_str(), w.M, w.c, w.g, w.tau, w.a);
      rows.emplace_back(row);
      overall = std::max({overall, w.M, w.c, w.g, w.tau, w.a});
    }
  }
  std::printf("\n%d random states per row; max|rbdc − pin| / max(1, max|pin|)\n\n", kStates);
  std::printf("| robot | base | Pinocchio reads | M | c | g | τ = ID | a = FD |\n|---|---|---|---|---|---|---|---|\n");
  for (const std::string& row : rows) std::printf("%s\n", row.c_str());
  std::printf("\nworst %.1e\n", overall);
  return overall <= 1e-12 ? 0 : 1;
}
