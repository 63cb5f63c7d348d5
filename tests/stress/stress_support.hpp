// Shared by the stress tests: how many random states to use, and a loop over the generated robots
// that are built (each with its adapter from rbdc_bench/generated/).
#pragma once

#include <cstdlib>
#include <string>

#include "rbdc_bench/robots.hpp"
#if defined(RBDC_HAVE_GEN_MINI_CHEETAH)
#include "rbdc_bench/generated/mini_cheetah.hpp"
#endif
#if defined(RBDC_HAVE_GEN_ARM7)
#include "rbdc_bench/generated/arm7.hpp"
#endif
#if defined(RBDC_HAVE_GEN_HUMANOID32)
#include "rbdc_bench/generated/humanoid32.hpp"
#endif

namespace rbdc_stress {

/// RBDC_STRESS_STATES when set (the full run uses 100000), else the reduced CI count.
inline int state_count(int ci_count) {
  const char* text = std::getenv("RBDC_STRESS_STATES");
  return text ? std::atoi(text) : ci_count;
}

inline rbdc::Model load_robot(const std::string& name) {
  return rbdc_bench::load_bench_robot(rbdc_bench::bench_robot(RBDC_SOURCE_DIR, name));
}

template <class T>
struct Tag {
  using type = T;
};

/// Calls use(Tag<Api>{}) for every generated robot adapter that is built.
template <class Use>
void for_each_generated_robot(Use&& use) {
#if defined(RBDC_HAVE_GEN_MINI_CHEETAH)
  use(Tag<rbdc_bench::GeneratedMiniCheetah>{});
#endif
#if defined(RBDC_HAVE_GEN_ARM7)
  use(Tag<rbdc_bench::GeneratedArm7>{});
#endif
#if defined(RBDC_HAVE_GEN_HUMANOID32)
  use(Tag<rbdc_bench::GeneratedHumanoid32>{});
#endif
  (void)use;
}

}  // namespace rbdc_stress
