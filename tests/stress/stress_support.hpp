// Shared by the stress tests: how many random states to use, and the loop over the generated robots
// that are built (rbdc_bench/generated_robots.hpp, from robots/bundled.json).
#pragma once

#include <cstdlib>
#include <string>

#include "rbdc_bench/generated_robots.hpp"
#include "rbdc_bench/robots.hpp"

namespace rbdc_stress {

/// RBDC_STRESS_STATES when set (the full run uses 100000), else the reduced CI count.
inline int state_count(int ci_count) {
  const char* text = std::getenv("RBDC_STRESS_STATES");
  return text ? std::atoi(text) : ci_count;
}

inline rbdc::Model load_robot(const std::string& name) {
  return rbdc_bench::load_bench_robot(rbdc_bench::bench_robot(RBDC_SOURCE_DIR, name));
}

using rbdc_bench::for_each_generated_robot;
using rbdc_bench::Tag;

}  // namespace rbdc_stress
