// The big-ground-inertia approximation (paper 001 Table 2) across ground masses, against the exact
// constrained closed form in long double (rbdc_bench::closed_chain_reference), all four Mini Cheetah
// feet in contact and at rest:
//  - Eq. 59: for 500 random configurations within the joint ranges of a trot, the ground masses of
//    minimum Λ̃ and b̃ error lie within a decade of the heuristic m_min / √ε (Eq. 58). Paper 001 found
//    this for all 500 of its configurations; ours (random joint rates, feet at rest) put 499 / 500 Λ̃
//    minima and 482 / 500 b̃ minima there, the rest at up to 50× the heuristic, so the test asserts
//    ≥ 99 % and ≥ 95 %, prints the counts, and bounds what a user of Eq. 58 pays: the error AT the
//    heuristic is at most 100× the configuration's minimum error (measured: 29×);
//  - across 12 decades of ground mass (1e-4 … 1e8 × total mass) the outputs stay finite, and the
//    median error at the heuristic beats the median at both ends of the range.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

#include "rbdc/jacobian.hpp"
#include "rbdc_bench/accuracy.hpp"
#include "rbdc_bench/generated/mini_cheetah.hpp"
#include "stress_support.hpp"

namespace rbdc_stress {
namespace {

using Api = rbdc_bench::generated::mini_cheetah;
using rbdc_bench::Quantity;

// Joint ranges of a trot (MIT sign convention: abad, hip, knee per leg; standing at (0, -0.8, 1.6)).
rbdc_bench::StateRanges trot_ranges() {
  rbdc_bench::StateRanges ranges;
  for (int leg = 0; leg < 4; ++leg) {
    ranges.joint_ranges.push_back({-0.3, 0.3});
    ranges.joint_ranges.push_back({-1.3, -0.3});
    ranges.joint_ranges.push_back({0.8, 2.4});
  }
  return ranges;
}

std::vector<rbdc_bench::State> stance_states(const rbdc::Model& model, int count) {
  rbdc::Data data(model);
  std::vector<rbdc_bench::State> states = rbdc_bench::random_states(model, count, 59, trot_ranges());
  for (auto& s : states) s.v = rbdc_bench::feet_at_rest(rbdc::feet_jacobian(model, data, s.q), s.v);
  return states;
}

TEST(StressGroundMass, HeuristicWithinADecadeOfTheErrorMinimum) {
  const rbdc::Model model = load_robot("mini_cheetah");
  const double m_total = rbdc_bench::total_mass(model);
  const double heuristic = rbdc_bench::smallest_body_mass(model) /
                           std::sqrt(std::numeric_limits<double>::epsilon());
  const auto parts = rbdc_bench::output_parts(Quantity::osc_closed_chain, Api::nv, Api::n_joints,
                                              Api::n_feet);
  const auto& Lambda = parts[0];
  const auto& b = parts[2];
  int in_range_Lambda = 0, in_range_b = 0;
  double lowest = 1e300, highest = 0;  // argmin / heuristic over all configurations
  double worst_penalty = 0;            // max over configurations of error(heuristic) / min error
  const std::vector<rbdc_bench::State> states = stance_states(model, 500);
  for (const auto& s : states) {
    const auto reference = rbdc_bench::closed_chain_reference<Api>(s);
    auto errors_at = [&](double mass) {
      const auto x = rbdc_bench::generated_output<Api, double>(Quantity::osc_closed_chain, s, mass);
      return std::make_pair(rbdc_bench::relative_error(x, reference, Lambda),
                            rbdc_bench::relative_error(x, reference, b));
    };
    double best_Lambda = 1e300, best_b = 1e300, argmin_Lambda = 0, argmin_b = 0;
    for (double decades = -4; decades <= 8.001; decades += 0.125) {
      const double mass = m_total * std::pow(10.0, decades);
      const auto [e_Lambda, e_b] = errors_at(mass);
      if (e_Lambda < best_Lambda) best_Lambda = e_Lambda, argmin_Lambda = mass;
      if (e_b < best_b) best_b = e_b, argmin_b = mass;
    }
    auto within_a_decade = [&](double mass) {
      return mass >= heuristic / 10 && mass <= heuristic * 10;
    };
    in_range_Lambda += within_a_decade(argmin_Lambda);
    in_range_b += within_a_decade(argmin_b);
    for (double m : {argmin_Lambda, argmin_b}) {
      lowest = std::min(lowest, m / heuristic);
      highest = std::max(highest, m / heuristic);
    }
    const auto [at_Lambda, at_b] = errors_at(heuristic);
    worst_penalty = std::max({worst_penalty, at_Lambda / best_Lambda, at_b / best_b});
  }
  const int n = static_cast<int>(states.size());
  std::printf("heuristic ground mass %.3g kg (%.3g x total mass); minima within a decade: "
              "Lambda %d / %d, b %d / %d; argmin / heuristic in [%.3g, %.3g]; error at the heuristic "
              "at most %.3g x the minimum\n",
              heuristic, heuristic / m_total, in_range_Lambda, n, in_range_b, n, lowest, highest,
              worst_penalty);
  EXPECT_GE(in_range_Lambda, n * 99 / 100);
  EXPECT_GE(in_range_b, n * 95 / 100);
  EXPECT_LE(worst_penalty, 100.0);
}

TEST(StressGroundMass, TwelveDecadesStayFiniteAndTheHeuristicBeatsTheEnds) {
  const rbdc::Model model = load_robot("mini_cheetah");
  const double m_total = rbdc_bench::total_mass(model);
  const double heuristic = rbdc_bench::smallest_body_mass(model) /
                           std::sqrt(std::numeric_limits<double>::epsilon());
  const auto parts = rbdc_bench::output_parts(Quantity::osc_closed_chain, Api::nv, Api::n_joints,
                                              Api::n_feet);
  std::vector<double> at_low_end, at_heuristic, at_high_end;
  for (const auto& s : stance_states(model, 50)) {
    const auto reference = rbdc_bench::closed_chain_reference<Api>(s);
    auto worst_error = [&](double mass) {
      const auto x = rbdc_bench::generated_output<Api, double>(Quantity::osc_closed_chain, s, mass);
      double worst = 0;
      for (const auto& part : parts) worst = std::max(worst, rbdc_bench::relative_error(x, reference, part));
      return worst;
    };
    for (int decade = -4; decade <= 8; ++decade)
      EXPECT_TRUE(std::isfinite(worst_error(m_total * std::pow(10.0, decade))))
          << "ground mass 1e" << decade << " x total mass";
    at_low_end.push_back(worst_error(m_total * 1e-4));
    at_heuristic.push_back(worst_error(heuristic));
    at_high_end.push_back(worst_error(m_total * 1e8));
  }
  auto median = [](std::vector<double> x) {
    std::sort(x.begin(), x.end());
    return x[x.size() / 2];
  };
  std::printf("median worst-part error: 1e-4 x total %.3g, heuristic %.3g, 1e8 x total %.3g\n",
              median(at_low_end), median(at_heuristic), median(at_high_end));
  EXPECT_LT(median(at_heuristic), median(at_low_end));
  EXPECT_LT(median(at_heuristic), median(at_high_end));
}

}  // namespace
}  // namespace rbdc_stress
