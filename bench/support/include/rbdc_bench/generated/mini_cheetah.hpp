// Adapter for generated/mini_cheetah/full (target rbdc_gen_mini_cheetah_full).
#pragma once

#include "mini_cheetah/full.hpp"
#include "rbdc_bench/generated_api.hpp"

namespace rbdc_bench {
struct GeneratedMiniCheetah {
  RBDC_BENCH_GENERATED_CORE(rbdc_gen::mini_cheetah::full, "mini_cheetah")
  RBDC_BENCH_GENERATED_OSC(rbdc_gen::mini_cheetah::full)
};
}  // namespace rbdc_bench
