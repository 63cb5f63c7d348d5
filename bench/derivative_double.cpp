// The generated derivative code in double (derivative_cases.hpp).
#include "derivative_generated.hpp"

namespace rbdc_bench::derivatives {

void add_generated_double(const LoadedRobot& loaded) { add_generated<double>(loaded, "generated_double"); }

}  // namespace rbdc_bench::derivatives
