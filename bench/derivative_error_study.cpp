// rbdc-derivative-error-study: the derivative quantities' error against the generated derivative code
// in __float128, for every variant registered (derivative_errors.hpp: generated double and float, the
// runtime, dual numbers on the generated primal, central differences) and every robot whose
// reference is linked in. Prints JSON rows like rbdc-error-study's: per quantity and part (dtau_dq,
// da_df, …) the median and max of ‖x − x_ref‖₂ / ‖x_ref‖₂ over random states, and the benchmark case
// that times the variant (rbdc-bench-derivatives times inverse_dynamics_derivatives and
// forward_dynamics_derivatives). bench/report merges the rows into the run-time-against-error study.
// Usage: rbdc-derivative-error-study [--states N]   (default 1000)
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "derivative_errors.hpp"
#include "error_rows.hpp"
#include "robot_states.hpp"

namespace rbdc_bench::derivatives {
namespace {

/// ‖x − ref‖₂ / ‖ref‖₂ over [part.begin, part.end); NaN if not finite.
double relative_error(const std::vector<long double>& x, const std::vector<long double>& ref, const Part& part) {
  long double difference = 0, norm = 0;
  for (int i = part.begin; i < part.end; ++i) {
    const long double d = x[static_cast<size_t>(i)] - ref[static_cast<size_t>(i)];
    difference += d * d;
    norm += ref[static_cast<size_t>(i)] * ref[static_cast<size_t>(i)];
  }
  const double error = static_cast<double>(std::sqrt(difference / norm));
  return std::isfinite(error) ? error : std::nan("");
}

void study(const LoadedRobot& loaded, int n_states, bool& first_row) {
  const rbdc::Model& model = loaded.model;
  Evaluate reference;
  std::vector<const ErrorVariant*> variants;
  std::vector<Evaluate> evaluate;
  for (const ErrorVariant& v : error_variants()) {
    if (v.robot != loaded.robot.name) continue;
    if (v.name == "reference") {
      reference = v.make(model);
    } else {
      variants.push_back(&v);
      evaluate.push_back(v.make(model));
    }
  }
  if (!reference) return;
  const std::vector<State> states = random_states(model, n_states, /*seed=*/777);
  for (Quantity quantity : kQuantities) {
    const std::vector<Part> all = parts(quantity, model.nv, static_cast<int>(states[0].tau.size()),
                                        static_cast<int>(model.feet.size()));
    // errors[variant][part] over the states
    std::vector<std::vector<std::vector<double>>> errors(variants.size(), std::vector<std::vector<double>>(all.size()));
    std::vector<long double> expected, value;
    for (const State& s : states) {
      reference(quantity, s, expected);
      for (size_t i = 0; i < variants.size(); ++i) {
        evaluate[i](quantity, s, value);
        for (size_t p = 0; p < all.size(); ++p) errors[i][p].push_back(relative_error(value, expected, all[p]));
      }
    }
    for (size_t i = 0; i < variants.size(); ++i) {
      for (size_t p = 0; p < all.size(); ++p) {
        const std::string quantity_text = quantity_name(quantity);
        print_row({loaded.robot.name, quantity_text, all[p].name, variants[i]->name,
                   quantity_text + "/" + variants[i]->name, NAN, NAN, statistics(errors[i][p])},
                  first_row);
      }
    }
    std::fprintf(stderr, "rbdc-derivative-error-study: %s %s done\n", loaded.robot.name.c_str(),
                 quantity_name(quantity));
  }
}

}  // namespace
}  // namespace rbdc_bench::derivatives

int main(int argc, char** argv) {
  using namespace rbdc_bench;
  const int n_states = states_argument(argc, argv);
  bool first_row = true;
  print_study_start(n_states, "generated derivative code in __float128");
  for_each_loaded_robot("derivative error study", [&](const LoadedRobot& robot) {
    derivatives::study(robot, n_states, first_row);
  });
  print_study_end();
  return 0;
}
