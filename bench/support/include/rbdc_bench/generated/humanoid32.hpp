// Adapter for generated/humanoid32/full (target rbdc_gen_humanoid32_full).
#pragma once

#include "humanoid32/full.hpp"
#include "rbdc_bench/generated_api.hpp"

namespace rbdc_bench {
struct GeneratedHumanoid32 {
  RBDC_BENCH_GENERATED_CORE(rbdc_gen::humanoid32::full, "humanoid32")
  RBDC_BENCH_GENERATED_OSC(rbdc_gen::humanoid32::full)
};
}  // namespace rbdc_bench
