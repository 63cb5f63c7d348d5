// Bad numbers in: a NaN or ±Inf in any input a quantity reads gives a non-finite result (NaN for a
// NaN in), never a crash or a hang (ctest's timeout), for the runtime and the generated code in double
// and float; rbdc::check_finite catches such inputs before the call.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "rbdc/check_finite.hpp"
#include "rbdc_bench/accuracy.hpp"
#include "stress_support.hpp"

namespace rbdc_stress {
namespace {

using rbdc_bench::Quad;
using rbdc_bench::Quantity;
using rbdc_bench::State;

enum class Slot { joint_angle, velocity, acceleration, torque, foot_force };

bool reads(Quantity quantity, Slot slot) {
  switch (slot) {
    case Slot::joint_angle: return true;
    case Slot::velocity:
      return quantity == Quantity::quadratic_velocity_terms || quantity == Quantity::inverse_dynamics ||
             quantity == Quantity::forward_dynamics || quantity == Quantity::osc_open_chain ||
             quantity == Quantity::osc_closed_chain;
    case Slot::acceleration: return quantity == Quantity::inverse_dynamics;
    case Slot::torque: return quantity == Quantity::forward_dynamics;
    case Slot::foot_force:
      return quantity == Quantity::forward_dynamics || quantity == Quantity::osc_open_chain;
  }
  return false;
}

// The state with `bad` in the slot: joint 2's angle (it moves every body after it; joint 1 of a
// fixed-base arm turns about the vertical, and no quantity may depend on its angle), the first
// velocity and acceleration, the first torque, the first foot's x force.
State poisoned(State s, const rbdc::Model& model, Slot slot, double bad) {
  switch (slot) {
    case Slot::joint_angle: s.q[model.joints[2].q_index] = bad; break;
    case Slot::velocity: s.v[0] = bad; break;
    case Slot::acceleration: s.a[0] = bad; break;
    case Slot::torque: s.tau[0] = bad; break;
    case Slot::foot_force: s.f(0, 0) = bad; break;
  }
  return s;
}

bool has_nan(const std::vector<Quad>& x) {
  for (const Quad& e : x)
    if (e != e) return true;
  return false;
}

bool all_finite(const std::vector<Quad>& x) {
  for (const Quad& e : x)
    if (!std::isfinite(static_cast<double>(e))) return false;
  return true;
}

template <class Api>
void check_robot() {
  const rbdc::Model model = load_robot(Api::name);
  rbdc::Data data(model);
  const State clean = rbdc_bench::random_states(model, 1, 99)[0];
  std::vector<Quantity> quantities = {Quantity::feet_jacobian, Quantity::quadratic_velocity_terms,
                                      Quantity::gravity_terms, Quantity::inverse_dynamics,
                                      Quantity::mass_matrix, Quantity::forward_dynamics};
  if constexpr (Api::has_osc) {
    quantities.push_back(Quantity::osc_open_chain);
    quantities.push_back(Quantity::osc_closed_chain);
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (Quantity quantity : quantities) {
    for (Slot slot : {Slot::joint_angle, Slot::velocity, Slot::acceleration, Slot::torque,
                      Slot::foot_force}) {
      if (!reads(quantity, slot)) continue;
      for (double bad : {nan, inf, -inf}) {
        const State s = poisoned(clean, model, slot, bad);
        const double ground_mass = 1e6;
        const std::string label = std::string(Api::name) + " " + rbdc_bench::quantity_name(quantity) +
                                  " slot " + std::to_string(static_cast<int>(slot)) + " value " +
                                  std::to_string(bad);
        const std::vector<std::vector<Quad>> outputs = {
            rbdc_bench::runtime_output(model, data, quantity, s, ground_mass),
            rbdc_bench::generated_output<Api, double>(quantity, s, ground_mass),
            rbdc_bench::generated_output<Api, float>(quantity, s, ground_mass)};
        const char* names[] = {"runtime", "generated double", "generated float"};
        for (size_t i = 0; i < outputs.size(); ++i) {
          EXPECT_FALSE(all_finite(outputs[i])) << label << ": " << names[i] << " hid the bad input";
          if (std::isnan(bad)) {
            EXPECT_TRUE(has_nan(outputs[i])) << label << ": " << names[i];
          }
        }
      }
    }
  }
}

TEST(StressBadNumbers, NonFiniteInputGivesNonFiniteOutput) {
  int robots = 0;
  for_each_generated_robot([&](auto tag) {
    check_robot<typename decltype(tag)::type>();
    ++robots;
  });
  EXPECT_GT(robots, 0);
}

TEST(StressBadNumbers, CheckFiniteFindsNanAndInfInAnyArgument) {
  const rbdc::Model model = load_robot("mini_cheetah");
  const State s = rbdc_bench::random_states(model, 1, 5)[0];
  EXPECT_TRUE(rbdc::check_finite(s.q, s.v, s.a, s.tau, s.f));
  for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                     -std::numeric_limits<double>::infinity()}) {
    State with_bad_v = s;
    with_bad_v.v[model.nv - 1] = bad;
    EXPECT_FALSE(rbdc::check_finite(with_bad_v.v));
    EXPECT_FALSE(rbdc::check_finite(s.q, with_bad_v.v, s.a));
    State with_bad_f = s;
    with_bad_f.f(2, 3) = bad;
    EXPECT_FALSE(rbdc::check_finite(s.q, s.v, with_bad_f.f));
  }
}

}  // namespace
}  // namespace rbdc_stress
