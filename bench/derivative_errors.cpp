// The registry of error-study variants (derivative_errors.hpp).
#include "derivative_errors.hpp"

namespace rbdc_bench::derivatives {

std::vector<ErrorVariant>& error_variants() {
  static std::vector<ErrorVariant> variants;
  return variants;
}

bool register_error_variant(const std::string& robot, const std::string& name, MakeEvaluate make) {
  error_variants().push_back({robot, name, make});
  return true;
}

}  // namespace rbdc_bench::derivatives
