// The runtime's derivative functions as blocks (derivative_runtime.hpp).
#include "derivative_runtime.hpp"

#include <algorithm>
#include <initializer_list>

namespace rbdc_bench::derivatives {
namespace {

/// Copies the matrices one after the other (column-major, as the block's parts).
void copy(std::initializer_list<const rbdc::MatrixX*> matrices, double* block) {
  for (const rbdc::MatrixX* m : matrices) block = std::copy(m->data(), m->data() + m->size(), block);
}

}  // namespace

void runtime_columns(RuntimeWork& w, Quantity quantity, const State& s, double* block) {
  rbdc::DerivativeData& d = w.derivatives;
  switch (quantity) {
    case Quantity::inverse_dynamics:
      rbdc::inverse_dynamics_derivatives(w.model, w.data, d, s.q, s.v, s.a);
      copy({&d.dtau_dq, &d.dtau_dv}, block);
      break;
    case Quantity::forward_dynamics:
      rbdc::forward_dynamics_derivatives(w.model, w.data, d, s.q, s.v, s.tau, s.f);
      copy({&d.da_dq, &d.da_dv, &d.da_dtau, &d.da_df}, block);
      break;
    case Quantity::bias:
      rbdc::bias_derivatives(w.model, w.data, d, s.q, s.v);
      copy({&d.dbias_dq, &d.dbias_dv}, block);
      break;
    case Quantity::gravity:
      rbdc::gravity_derivatives(w.model, w.data, d, s.q);
      copy({&d.dg_dq}, block);
      break;
    case Quantity::feet_velocity:
      rbdc::feet_velocity_derivatives(w.model, w.data, d, s.q, s.v);
      copy({&d.dpdot_dq}, block);
      break;
    case Quantity::feet_force_term:
      rbdc::feet_force_term_derivatives(w.model, w.data, d, s.q, s.f);
      copy({&d.dtau_e_dq}, block);
      break;
  }
}

}  // namespace rbdc_bench::derivatives
