// Names and parts of the derivative quantities (derivative_quantities.hpp).
#include "derivative_quantities.hpp"

namespace rbdc_bench::derivatives {

const char* quantity_name(Quantity quantity) {
  switch (quantity) {
    case Quantity::inverse_dynamics: return "inverse_dynamics_derivatives";
    case Quantity::forward_dynamics: return "forward_dynamics_derivatives";
    case Quantity::bias: return "bias_derivatives";
    case Quantity::gravity: return "gravity_derivatives";
    case Quantity::feet_velocity: return "feet_velocity_derivatives";
    case Quantity::feet_force_term: return "feet_force_term_derivatives";
  }
  return "";
}

std::vector<Part> parts(Quantity quantity, int nv, int n_joints, int n_feet) {
  const char* output = "";
  switch (quantity) {
    case Quantity::inverse_dynamics: output = "dtau"; break;
    case Quantity::forward_dynamics: output = "da"; break;
    case Quantity::bias: output = "dbias"; break;
    case Quantity::gravity: output = "dg"; break;
    case Quantity::feet_velocity: output = "dpdot"; break;
    case Quantity::feet_force_term: output = "dtau_e"; break;
  }
  const int rows = quantity == Quantity::feet_velocity ? 3 * n_feet : nv;
  const char* input_names[kInputs] = {"v", "a", "tau", "f"};
  const int input_sizes[kInputs] = {nv, nv, n_joints, 3 * n_feet};
  std::vector<Part> result = {{std::string(output) + "_dq", 0, rows * nv}};
  for (int input = 0; input < kInputs; ++input) {
    if (!differentiates(quantity, input)) continue;
    const int begin = result.back().end;
    result.push_back({std::string(output) + "_d" + input_names[input], begin, begin + rows * input_sizes[input]});
  }
  return result;
}

}  // namespace rbdc_bench::derivatives
