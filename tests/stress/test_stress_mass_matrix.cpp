// M stays symmetric positive definite: on random and singular configurations (every joint at 0) of
// every benchmark robot, and with link mass ratios from 1e-6 to 1e6 (every odd-numbered body's mass
// and inertia scaled). A failure names the robot, the ratio and the smallest eigenvalue.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cstdio>
#include <string>

#include "rbdc/crba.hpp"
#include "rbdc_bench/random_states.hpp"
#include "stress_support.hpp"

namespace rbdc_stress {
namespace {

// Scales body i's mass and rotational inertia by `ratio` for odd i (and rebuilds its spatial inertia
// as the model builder does), so neighbouring links differ in mass by about `ratio`.
rbdc::Model with_mass_ratio(rbdc::Model model, double ratio) {
  for (int i = 1; i < model.nb; i += 2) {
    rbdc::Body& body = model.bodies[static_cast<size_t>(i)];
    body.mass *= ratio;
    body.inertia_com *= ratio;
    model.inertia[static_cast<size_t>(i)] = rbdc::spatial_inertia(body.mass, body.com, body.inertia_com);
  }
  return model;
}

struct Spectrum {
  double smallest = 1e300, largest = 0;
  bool cholesky_ok = true;
  double asymmetry = 0;
};

Spectrum check_states(const rbdc::Model& model, bool singular) {
  rbdc::Data data(model);
  Spectrum spectrum;
  auto states = rbdc_bench::random_states(model, state_count(200) / 10 + 10, 17);
  for (auto& s : states) {
    if (singular) s.q.tail(model.num_joints()).setZero();
    const rbdc::MatrixX& M = rbdc::mass_matrix(model, data, s.q);
    spectrum.asymmetry = std::max(spectrum.asymmetry, (M - M.transpose()).cwiseAbs().maxCoeff() /
                                                          M.cwiseAbs().maxCoeff());
    spectrum.cholesky_ok &= Eigen::LLT<rbdc::MatrixX>(M).info() == Eigen::Success;
    const Eigen::SelfAdjointEigenSolver<rbdc::MatrixX> eigen(M, Eigen::EigenvaluesOnly);
    spectrum.smallest = std::min(spectrum.smallest, eigen.eigenvalues().minCoeff());
    spectrum.largest = std::max(spectrum.largest, eigen.eigenvalues().maxCoeff());
  }
  return spectrum;
}

void expect_positive_definite(const std::string& label, const Spectrum& s) {
  std::printf("%-40s eigenvalues in [%.3g, %.3g], condition %.3g\n", label.c_str(), s.smallest,
              s.largest, s.largest / s.smallest);
  EXPECT_TRUE(s.cholesky_ok) << label << ": Cholesky of M failed";
  EXPECT_GT(s.smallest, 0.0) << label << ": M is not positive definite";
  EXPECT_EQ(s.asymmetry, 0.0) << label << ": M is not symmetric";
}

class StressMassMatrix : public ::testing::TestWithParam<const char*> {};

TEST_P(StressMassMatrix, PositiveDefiniteOnRandomAndSingularConfigurations) {
  const rbdc::Model model = load_robot(GetParam());
  expect_positive_definite(std::string(GetParam()) + " random", check_states(model, false));
  expect_positive_definite(std::string(GetParam()) + " singular", check_states(model, true));
}

TEST_P(StressMassMatrix, PositiveDefiniteForLinkMassRatiosFrom1e_6To1e6) {
  const rbdc::Model model = load_robot(GetParam());
  for (int exponent = -6; exponent <= 6; exponent += 2) {
    const double ratio = std::pow(10.0, exponent);
    expect_positive_definite(std::string(GetParam()) + " mass ratio 1e" + std::to_string(exponent),
                             check_states(with_mass_ratio(model, ratio), false));
  }
}

INSTANTIATE_TEST_SUITE_P(BenchRobots, StressMassMatrix,
                         ::testing::Values("mini_cheetah", "arm7", "humanoid32"));

}  // namespace
}  // namespace rbdc_stress
