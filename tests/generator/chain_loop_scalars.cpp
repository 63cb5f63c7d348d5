// The chain's loops (rbdc_gen/articulated_inverse.hpp: chain_inverse_dynamics,
// articulated_forward_dynamics, articulated_inverse) instantiated for every scalar the generated API
// promises: float, long double, __float128 and SIMD packs of states (rbdc_gen::Batch). Compiled
// (-fsyntax-only, the project's compiler with GNU extensions, as scalar_types_test.cpp) by generator_verify_chain_low_rank
// against the 34-link chain's kept headers, whose double instantiation that test verifies against the
// runtime.
#include "chain34/chain_loop.hpp"
#include "chain34/forward_dynamics_derivatives_low_rank.hpp"
#include "rbdc_gen/batch.hpp"

namespace loop = rbdc_gen::chain34::chain_loop;
namespace low_rank = rbdc_gen::chain34::forward_dynamics_derivatives_low_rank;

template <class S>
void every_loop(S* q, S* v, S* a, S* f, S* out, S* da_dq, S* da_dv, S* da_dtau, S* da_df) {
  loop::inverse_dynamics(q, v, a, out);
  loop::bias(q, v, out);
  loop::quadratic_velocity_terms(q, v, out);
  loop::forward_dynamics(q, v, a, f, out);
  low_rank::forward_dynamics_derivatives(q, v, a, f, da_dq, da_dv, da_dtau, da_df);
}

template void every_loop<float>(float*, float*, float*, float*, float*, float*, float*, float*, float*);
template void every_loop<long double>(long double*, long double*, long double*, long double*, long double*,
                                      long double*, long double*, long double*, long double*);
#if defined(RBDC_HAS_FLOAT128)  // rbdc_gen/support.hpp: where quadmath gives __float128 its sin and cos
using Quad = rbdc_gen::float128;
template void every_loop<Quad>(Quad*, Quad*, Quad*, Quad*, Quad*, Quad*, Quad*, Quad*, Quad*);
#endif
using Pack = rbdc_gen::Batch<double>;
template void every_loop<Pack>(Pack*, Pack*, Pack*, Pack*, Pack*, Pack*, Pack*, Pack*, Pack*);
