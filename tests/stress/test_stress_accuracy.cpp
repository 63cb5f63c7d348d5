// Relative error of every quantity against the generated code in __float128, for the generated code
// in double and float and for the runtime, over random states, fast states (joint rates up to
// 100 rad/s) and singular configurations (every joint at 0: straight knees, aligned axes). The
// bounds below are the documented accuracy (docs/benchmarks.md); the printed table is the float
// code's error per quantity.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <vector>

#include "rbdc_bench/accuracy.hpp"
#include "stress_support.hpp"

namespace rbdc_stress {
namespace {

using rbdc_bench::Quantity;
using rbdc_bench::State;

/// Max relative error allowed per quantity: {double (generated and runtime), float}.
struct Bound {
  double double_precision, single_precision;
};

Bound bound_for(Quantity quantity) {
  switch (quantity) {
    case Quantity::forward_dynamics: return {1e-10, 1e-3};  // through M⁻¹: cond(M) up to ~1e6
    case Quantity::osc_open_chain: return {1e-10, 1e-3};
    default: return {1e-12, 1e-4};
  }
}

struct Family {
  const char* name;
  rbdc_bench::StateRanges ranges;
  bool singular;  ///< every joint angle set to 0
  int divisor;    ///< this family uses state_count / divisor states
};

std::vector<Family> families() {
  rbdc_bench::StateRanges fast;
  fast.joint_velocity = 100.0;
  fast.trunk_velocity = 10.0;
  return {{"random", {}, false, 1}, {"fast", fast, false, 10}, {"singular", {}, true, 10}};
}

struct Errors {
  std::vector<double> values;
  void add(double e) { values.push_back(e); }
  double max() const {
    double m = 0;
    for (double e : values) m = std::isnan(e) ? e : std::max(m, e);
    return m;
  }
  double median() {
    std::sort(values.begin(), values.end());
    return values.empty() ? 0 : values[values.size() / 2];
  }
};

template <class Api>
void check_robot() {
  const rbdc::Model model = load_robot(Api::name);
  rbdc::Data data(model);
  std::vector<Quantity> quantities = {Quantity::feet_jacobian, Quantity::quadratic_velocity_terms,
                                      Quantity::gravity_terms, Quantity::inverse_dynamics,
                                      Quantity::mass_matrix, Quantity::forward_dynamics};
  if constexpr (Api::has_osc) quantities.push_back(Quantity::osc_open_chain);
  for (const Family& family : families()) {
    std::vector<State> states = rbdc_bench::random_states(
        model, std::max(1, state_count(300) / family.divisor), /*seed=*/4242, family.ranges);
    if (family.singular)
      for (State& s : states) s.q.tail(model.num_joints()).setZero();
    for (Quantity quantity : quantities) {
      const auto parts = rbdc_bench::output_parts(quantity, Api::nv, Api::n_joints, Api::n_feet);
      const Bound bound = bound_for(quantity);
      for (const auto& part : parts) {
        Errors generated_double, generated_float, runtime;
        for (const State& s : states) {
          const auto reference = rbdc_bench::generated_output<Api, rbdc_bench::Quad>(quantity, s, 0);
          auto error = [&](const std::vector<rbdc_bench::Quad>& x) {
            return rbdc_bench::relative_error(x, reference, part);
          };
          generated_double.add(error(rbdc_bench::generated_output<Api, double>(quantity, s, 0)));
          generated_float.add(error(rbdc_bench::generated_output<Api, float>(quantity, s, 0)));
          runtime.add(error(rbdc_bench::runtime_output(model, data, quantity, s, 0)));
        }
        const std::string label = std::string(Api::name) + " " + family.name + " " +
                                  rbdc_bench::quantity_name(quantity) +
                                  (part.name.empty() ? "" : "." + part.name);
        std::printf("%-58s double %.2e / %.2e  float %.2e / %.2e  runtime %.2e / %.2e (max / median)\n",
                    label.c_str(), generated_double.max(), generated_double.median(),
                    generated_float.max(), generated_float.median(), runtime.max(), runtime.median());
        EXPECT_LE(generated_double.max(), bound.double_precision) << label << " (generated double)";
        EXPECT_LE(runtime.max(), bound.double_precision) << label << " (runtime)";
        EXPECT_LE(generated_float.max(), bound.single_precision) << label << " (generated float)";
      }
    }
  }
}

TEST(StressAccuracy, RelativeErrorAgainstQuadPrecisionWithinBounds) {
  int robots = 0;
  for_each_generated_robot([&](auto tag) {
    check_robot<typename decltype(tag)::type>();
    ++robots;
  });
  EXPECT_GT(robots, 0) << "no generated robot was built";
}

}  // namespace
}  // namespace rbdc_stress
