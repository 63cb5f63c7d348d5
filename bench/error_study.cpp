// rbdc-error-study: run time against error, the data behind bench/report's error table and plot.
// For every benchmark robot with generated code, every quantity and every variant (generated double
// and float, the runtime, and for the closed chain the runtime's exact closed form and the generated
// recursion at ground masses from 1e-4 to 1e8 × the total mass, paper 001 Fig. 7) it prints, as JSON,
// the max and median relative error over random states against the generated code in __float128
// (closed chain: the exact constrained closed form in long double, closed_chain_reference), and names
// the benchmark case ("quantity/implementation") that times the variant.
// Usage: rbdc-error-study [--states N]   (default 1000)
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "error_rows.hpp"
#include "rbdc/jacobian.hpp"
#include "rbdc_bench/accuracy.hpp"
#include "robot_states.hpp"
#include "rbdc_bench/generated_robots.hpp"

namespace rbdc_bench {
namespace {

// One variant: how to evaluate it, and which benchmark case times it.
struct Variant {
  std::string name, bench_quantity, implementation;
  double ground_mass;  ///< 0 when not a closed-chain variant
  std::function<std::vector<Quad>(const State&)> evaluate;
};

template <class Api>
void study(const LoadedRobot& loaded, int n_states, bool& first_row) {
  const rbdc::Model& model = loaded.model;
  rbdc::Data data(model);
  const double m_total = total_mass(model);
  const double m_min = smallest_body_mass(model);
  const double double_ground_mass = m_min / std::sqrt(std::numeric_limits<double>::epsilon());
  const double float_ground_mass = m_min / std::sqrt(double(std::numeric_limits<float>::epsilon()));
  // The states of the study are drawn apart from the benchmarks' (another seed).
  std::vector<State> states = random_states(model, n_states, /*seed=*/777);

  std::vector<Quantity> quantities = {Quantity::feet_jacobian, Quantity::quadratic_velocity_terms,
                                      Quantity::gravity_terms, Quantity::inverse_dynamics,
                                      Quantity::mass_matrix, Quantity::forward_dynamics};
  if constexpr (Api::has_osc) {
    quantities.push_back(Quantity::osc_open_chain);
    quantities.push_back(Quantity::osc_closed_chain);
  }
  for (Quantity quantity : quantities) {
    const std::string name = quantity_name(quantity);
    const std::string bench_quantity =
        quantity == Quantity::feet_jacobian ? "feet_positions_jacobian" : name;
    const bool closed = quantity == Quantity::osc_closed_chain;
    std::vector<Variant> variants = {
        {"generated_double", bench_quantity, "generated_double", closed ? double_ground_mass : 0,
         [&](const State& s) { return generated_output<Api, double>(quantity, s, double_ground_mass); }},
        {"generated_float", bench_quantity, "generated_float", closed ? float_ground_mass : 0,
         [&](const State& s) { return generated_output<Api, float>(quantity, s, float_ground_mass); }},
        {"runtime", bench_quantity, "runtime", closed ? double_ground_mass : 0,
         [&](const State& s) { return runtime_output(model, data, quantity, s, double_ground_mass); }},
    };
    if (closed) {
      variants.push_back({"runtime_closed_form", "osc_closed_form", "runtime", 0,
                          [&](const State& s) { return runtime_output(model, data, quantity, s, 0); }});
      for (int decade = -4; decade <= 8; ++decade) {
        const double mass = m_total * std::pow(10.0, decade);
        variants.push_back({"generated_double_ground_1e" + std::to_string(decade), bench_quantity,
                            "generated_double", mass, [&, mass](const State& s) {
                              return generated_output<Api, double>(quantity, s, mass);
                            }});
      }
    }
    const std::vector<Part> parts = output_parts(quantity, Api::nv, Api::n_joints, Api::n_feet);
    // errors[variant][part] over the states
    std::vector<std::vector<std::vector<double>>> errors(
        variants.size(), std::vector<std::vector<double>>(parts.size()));
    for (State s : states) {
      if (closed) s.v = feet_at_rest(rbdc::feet_jacobian(model, data, s.q), s.v);
      const std::vector<Quad> reference = closed ? closed_chain_reference<Api>(s)
                                                 : generated_output<Api, Quad>(quantity, s, 0);
      for (size_t i = 0; i < variants.size(); ++i) {
        const std::vector<Quad> value = variants[i].evaluate(s);
        for (size_t p = 0; p < parts.size(); ++p)
          errors[i][p].push_back(relative_error(value, reference, parts[p]));
      }
    }
    for (size_t i = 0; i < variants.size(); ++i) {
      for (size_t p = 0; p < parts.size(); ++p) {
        const double mass = variants[i].ground_mass > 0 ? variants[i].ground_mass : NAN;
        print_row({loaded.robot.name, name, parts[p].name, variants[i].name,
                   variants[i].bench_quantity + "/" + variants[i].implementation, mass, mass / m_total,
                   statistics(errors[i][p])},
                  first_row);
      }
    }
    std::fprintf(stderr, "rbdc-error-study: %s %s done\n", loaded.robot.name.c_str(), name.c_str());
  }
}

}  // namespace
}  // namespace rbdc_bench

int main(int argc, char** argv) {
  using namespace rbdc_bench;
  const int n_states = states_argument(argc, argv);
  bool first_row = true;
  print_study_start(n_states, "generated code in __float128; closed chain: exact closed form in long double");
  for_each_generated_robot([&](auto tag) {
    using Api = typename decltype(tag)::type;
    for_each_loaded_robot("error study", [&](const LoadedRobot& r) {
      study<Api>(r, n_states, first_row);
    }, Api::name);
  });
  print_study_end();
  return 0;
}
