// The error study's reference (derivative_cases.hpp): the generated derivative code instantiated on
// __float128 (libquadmath; g++ or clang on x86-64). Not timed.
#pragma once

#include "derivative_generated.hpp"
#include "rbdc_gen/support.hpp"

#if !defined(RBDC_HAS_FLOAT128)
#error "the derivative reference needs __float128 and libquadmath (GCC or clang on x86-64)"
#endif

namespace rbdc_bench::derivatives {

template <class Api>
bool register_reference() {
  return register_error_variant(Api::name, "reference", evaluate_generated<Api, rbdc_gen::float128>);
}

}  // namespace rbdc_bench::derivatives
