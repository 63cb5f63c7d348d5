#include "rbdc_bench/accuracy.hpp"

#include <Eigen/Dense>

#include "rbdc/bias_terms.hpp"
#include "rbdc/crba.hpp"
#include "rbdc/forward_dynamics.hpp"
#include "rbdc/inverse_dynamics.hpp"
#include "rbdc/jacobian.hpp"
#include "rbdc/osc.hpp"

namespace rbdc_bench {

const char* quantity_name(Quantity quantity) {
  switch (quantity) {
    case Quantity::feet_jacobian: return "feet_jacobian";
    case Quantity::quadratic_velocity_terms: return "quadratic_velocity_terms";
    case Quantity::gravity_terms: return "gravity_terms";
    case Quantity::inverse_dynamics: return "inverse_dynamics";
    case Quantity::mass_matrix: return "mass_matrix";
    case Quantity::forward_dynamics: return "forward_dynamics";
    case Quantity::osc_open_chain: return "osc_open_chain";
    case Quantity::osc_closed_chain: return "osc_closed_chain";
  }
  return "?";
}

std::vector<Part> output_parts(Quantity quantity, int nv, int n_joints, int n_feet) {
  switch (quantity) {
    case Quantity::feet_jacobian: return {{"", 0, 3 * n_feet * nv}};
    case Quantity::mass_matrix: return {{"", 0, nv * nv}};
    case Quantity::osc_open_chain:
    case Quantity::osc_closed_chain:
      return {{"Lambda", 0, 36}, {"JbarT", 36, 36 + 6 * n_joints},
              {"b", 36 + 6 * n_joints, 42 + 6 * n_joints}};
    default: return {{"", 0, nv}};
  }
}

double relative_error(const std::vector<Quad>& x, const std::vector<Quad>& ref, const Part& part) {
  Quad difference = 0, norm = 0;
  for (int i = part.begin; i < part.end; ++i) {
    const Quad d = x[static_cast<size_t>(i)] - ref[static_cast<size_t>(i)];
    difference += d * d;
    norm += ref[static_cast<size_t>(i)] * ref[static_cast<size_t>(i)];
  }
  const double error = static_cast<double>(rbdc_gen::sqrt(difference) / rbdc_gen::sqrt(norm));
  return std::isfinite(error) ? error : std::nan("");
}

rbdc::VectorX feet_at_rest(const rbdc::MatrixX& J, const rbdc::VectorX& v) {
  return v - J.completeOrthogonalDecomposition().solve(J * v);
}

std::vector<Quad> runtime_output(const rbdc::Model& model, rbdc::Data& data, Quantity quantity,
                                 const State& s, double ground_mass) {
  auto flat = [](const auto& x) {
    return std::vector<Quad>(x.data(), x.data() + x.size());
  };
  auto osc_flat = [](const rbdc::OscQuantities& o) {
    std::vector<Quad> out(o.Lambda.data(), o.Lambda.data() + 36);
    out.insert(out.end(), o.JbarT.data(), o.JbarT.data() + o.JbarT.size());
    out.insert(out.end(), o.b.data(), o.b.data() + 6);
    return out;
  };
  std::vector<int> all_feet;
  for (int k = 0; k < static_cast<int>(model.feet.size()); ++k) all_feet.push_back(k);
  switch (quantity) {
    case Quantity::feet_jacobian: return flat(rbdc::feet_jacobian(model, data, s.q));
    case Quantity::quadratic_velocity_terms:
      return flat(rbdc::quadratic_velocity_terms(model, data, s.q, s.v));
    case Quantity::gravity_terms: return flat(rbdc::gravity_terms(model, data, s.q));
    case Quantity::inverse_dynamics: return flat(rbdc::inverse_dynamics(model, data, s.q, s.v, s.a));
    case Quantity::mass_matrix: return flat(rbdc::mass_matrix(model, data, s.q));
    case Quantity::forward_dynamics:
      return flat(rbdc::forward_dynamics(model, data, s.q, s.v, s.tau, s.f));
    case Quantity::osc_open_chain: return osc_flat(rbdc::osc_open_chain(model, data, s.q, s.v, s.f));
    case Quantity::osc_closed_chain:
      if (ground_mass <= 0) {
        rbdc::OscReferenceData closed_form(model);  // not timed: sized per call
        return osc_flat(rbdc::osc_closed_form_constrained(model, data, closed_form, s.q, s.v, all_feet));
      }
      return osc_flat(rbdc::osc_closed_chain(model, data, s.q, s.v, all_feet, ground_mass));
  }
  return {};
}

}  // namespace rbdc_bench
