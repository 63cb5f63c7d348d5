// Generated arm7 code (rbdc_gen_arm7_full) in double and float.
#include "generated_cases.hpp"
#include "rbdc_bench/generated/arm7.hpp"

namespace rbdc_bench {
namespace {
const bool registered = register_provider(provide_generated<GeneratedArm7>);
}  // namespace
}  // namespace rbdc_bench
