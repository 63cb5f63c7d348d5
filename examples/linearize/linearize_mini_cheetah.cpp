// Linearises the Mini Cheetah's forward dynamics at the standing equilibrium, continuous and
// discrete time, checks both against central differences of the (continuous, resp. discrete)
// dynamics and prints a short report; exit code 1 if a check fails. Derivatives: the generated
// code (generated/mini_cheetah/derivatives/), cross-checked against the runtime's.
//   linearize_mini_cheetah [--dt SECONDS] [--csv DIR]
#include <Eigen/Eigenvalues>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include "linearization.hpp"
#include "rbdc/rbdc.hpp"
#include "rbdc/urdf_loader.hpp"

namespace {

using namespace linearize;

constexpr double kFdStep = 1e-6;
// Central differences with step h carry ~ε|x|/h round-off and O(h²) truncation: ~1e-9 here.
constexpr double kTolerance = 1e-6;

/// max |X − Y| over the rows [row, row + rows), relative to the largest entry of X − reference
/// there (so the dt-scaled blocks of A_d are judged on their own scale, not against the identity).
template <class M>
double block_error(const M& X, const M& Y, const M& reference, int row, int rows) {
  const auto d = (X - Y).middleRows(row, rows);
  const double scale = (X - reference).middleRows(row, rows).cwiseAbs().maxCoeff();
  return d.cwiseAbs().maxCoeff() / std::max(scale, 1e-300);
}

struct Check {
  std::string what;
  double error;
};

std::vector<Check> compare(const std::string& name, const Linearization& analytic,
                           const Linearization& fd, const StateMatrix& A_reference) {
  const InputMatrix B_reference = InputMatrix::Zero();
  return {{name + " A, δq rows", block_error(analytic.A, fd.A, A_reference, 0, nv)},
          {name + " A, v rows ", block_error(analytic.A, fd.A, A_reference, nv, nv)},
          {name + " B, δq rows", block_error(analytic.B, fd.B, B_reference, 0, nv)},
          {name + " B, v rows ", block_error(analytic.B, fd.B, B_reference, nv, nv)}};
}

template <class M>
void write_csv(const std::string& path, const M& m) {
  std::ofstream out(path);
  out << std::setprecision(17);
  for (int r = 0; r < m.rows(); ++r) {
    for (int c = 0; c < m.cols(); ++c) out << (c ? "," : "") << m(r, c);
    out << "\n";
  }
  if (!out) throw std::runtime_error("cannot write " + path);
}

/// Mean wall time of `call` in microseconds over `repetitions` calls.
template <class Call>
double microseconds_per_call(int repetitions, const Call& call) {
  const auto start = std::chrono::steady_clock::now();
  for (int k = 0; k < repetitions; ++k) call();
  const std::chrono::duration<double, std::micro> elapsed = std::chrono::steady_clock::now() - start;
  return elapsed.count() / repetitions;
}

}  // namespace

int main(int argc, char** argv) {
  double dt = 1e-3;
  std::string csv_dir;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--dt" && i + 1 < argc) {
      dt = std::atof(argv[++i]);
    } else if (arg == "--csv" && i + 1 < argc) {
      csv_dir = argv[++i];
    } else {
      std::cout << "usage: linearize_mini_cheetah [--dt SECONDS] [--csv DIR]\n"
                   "Linearises the Mini Cheetah's forward dynamics at the standing equilibrium\n"
                   "(continuous A, B and semi-implicit-Euler A_d, B_d for dt, default 0.001 s),\n"
                   "checks them against central differences; --csv writes A.csv, B.csv, A_d.csv, B_d.csv.\n";
      return arg == "--help" || arg == "-h" ? 0 : 2;
    }
  }
  if (!(dt > 0)) {
    std::cerr << "error: --dt must be a positive number of seconds\n";
    return 2;
  }
  std::vector<std::string> warnings;  // the MIT thigh inertia breaks the triangle inequality
  const rbdc::Model model = rbdc::load_urdf(RBDC_SOURCE_DIR "/robots/mini_cheetah.urdf", {}, &warnings);
  const OperatingPoint op = standing_equilibrium(model);
  Tangent a;
  gen::forward_dynamics(op.q, op.v, op.tau, op.f, a);

  const Linearization lin = continuous(op);
  const Linearization lin_d = discrete(lin, dt);
  const auto F = [&](const State& x, const Torques& u) { return continuous_dynamics(model, op, x, u); };
  const auto step = [&](const State& x, const Torques& u) { return discrete_step(model, op, x, u, dt); };
  std::vector<Check> checks = compare("continuous", lin, finite_differences(op, F, kFdStep),
                                      StateMatrix::Zero());
  for (const Check& c : compare("discrete  ", lin_d, finite_differences(op, step, kFdStep),
                                StateMatrix::Identity())) {
    checks.push_back(c);
  }

  // Third opinion: the runtime's analytic derivatives (rbdc/derivatives.hpp).
  rbdc::Data data(model);
  rbdc::DerivativeData derivatives(model);
  rbdc::forward_dynamics_derivatives(model, data, derivatives, op.q, op.v, op.tau, op.f);
  const double runtime_difference =
      std::max((lin.A.bottomRows<nv>() - (Eigen::Matrix<double, nv, nx>() << derivatives.da_dq, derivatives.da_dv).finished())
                       .cwiseAbs().maxCoeff() / derivatives.da_dq.cwiseAbs().maxCoeff(),
               (lin.B.bottomRows<nv>() - derivatives.da_dtau).cwiseAbs().maxCoeff() /
                   derivatives.da_dtau.cwiseAbs().maxCoeff());
  checks.push_back({"generated vs runtime ∂a/∂(q, v, τ)", runtime_difference});

  gen::MassMatrix<double> da_dq, da_dv;
  Eigen::Matrix<double, nv, nu> da_dtau;
  Eigen::Matrix<double, nv, 12> da_df;
  const double generated_us = microseconds_per_call(20000, [&] {
    gen::forward_dynamics_derivatives(op.q, op.v, op.tau, op.f, da_dq, da_dv, da_dtau, da_df);
  });
  const double runtime_us = microseconds_per_call(500, [&] {
    rbdc::forward_dynamics_derivatives(model, data, derivatives, op.q, op.v, op.tau, op.f);
  });

  std::cout << std::setprecision(3)
            << "Mini Cheetah forward dynamics linearised at the standing equilibrium\n"
            << "derivatives: generated (generated/mini_cheetah/derivatives, scene derivatives);"
               " runtime rbdc::forward_dynamics_derivatives as a cross-check\n"
            << "operating point: p = (0, 0, 0.3), identity orientation, legs (0, -0.8, 1.6), v = 0;"
               " |a| = " << a.cwiseAbs().maxCoeff() << " m/s² (equilibrium)\n"
            << "  foot forces (world, N, columns LF RF LH RH):\n" << op.f << "\n"
            << "  joint torques (N·m): " << op.tau.transpose() << "\n"
            << "continuous time: A " << nx << "×" << nx << ", B " << nx << "×" << nu
            << "  (state (δq, v) on the manifold, input τ)\n"
            << "discrete time (semi-implicit Euler, dt = " << dt << " s): A_d " << nx << "×" << nx
            << ", B_d " << nx << "×" << nu << "; spectral radius of A_d "
            << lin_d.A.eigenvalues().cwiseAbs().maxCoeff() << "\n"
            << "checks against central differences (step " << kFdStep << "), relative error per block"
               " (tolerance " << kTolerance << "):\n";
  bool ok = a.cwiseAbs().maxCoeff() < 1e-9;
  for (const Check& c : checks) {
    const bool pass = c.error < kTolerance;
    ok = ok && pass;
    std::cout << "  " << c.what << "  " << c.error << (pass ? "" : "  FAILED") << "\n";
  }
  std::cout << "time per forward_dynamics_derivatives call: generated " << generated_us
            << " µs, runtime " << runtime_us << " µs\n";
  if (!csv_dir.empty()) {
    write_csv(csv_dir + "/A.csv", lin.A);
    write_csv(csv_dir + "/B.csv", lin.B);
    write_csv(csv_dir + "/A_d.csv", lin_d.A);
    write_csv(csv_dir + "/B_d.csv", lin_d.B);
    std::cout << "wrote A.csv, B.csv, A_d.csv, B_d.csv to " << csv_dir << "\n";
  }
  std::cout << (ok ? "all checks passed\n" : "CHECK FAILED\n");
  return ok ? 0 : 1;
}
