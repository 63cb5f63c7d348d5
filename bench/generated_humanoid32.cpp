// Generated humanoid32 code (rbdc_gen_humanoid32_full) in double and float.
#include "generated_cases.hpp"
#include "rbdc_bench/generated/humanoid32.hpp"

namespace rbdc_bench {
namespace {
const bool registered = register_provider(provide_generated<GeneratedHumanoid32>);
}  // namespace
}  // namespace rbdc_bench
