// The generated derivative code in float (derivative_cases.hpp).
#include "derivative_generated.hpp"

namespace rbdc_bench::derivatives {

void add_generated_float(const LoadedRobot& loaded) { add_generated<float>(loaded, "generated_float"); }

}  // namespace rbdc_bench::derivatives
