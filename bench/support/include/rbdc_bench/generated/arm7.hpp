// Adapter for generated/arm7/full (target rbdc_gen_arm7_full): fixed base, no operational space.
#pragma once

#include "arm7/full.hpp"
#include "rbdc_bench/generated_api.hpp"

namespace rbdc_bench {
struct GeneratedArm7 {
  RBDC_BENCH_GENERATED_CORE(rbdc_gen::arm7::full, "arm7")
  static constexpr bool has_osc = false;
};
}  // namespace rbdc_bench
