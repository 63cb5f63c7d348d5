// Generated mini_cheetah code (rbdc_gen_mini_cheetah_full) in double and float.
#include "generated_cases.hpp"
#include "rbdc_bench/generated/mini_cheetah.hpp"

namespace rbdc_bench {
namespace {
const bool registered = register_provider(provide_generated<GeneratedMiniCheetah>);
}  // namespace
}  // namespace rbdc_bench
