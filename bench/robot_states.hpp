// What every implementation's provider starts from: each benchmark robot loaded (or skipped with a
// message when its file does not load) with its pre-generated states and ground mass.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "rbdc_bench/random_states.hpp"
#include "rbdc_bench/robots.hpp"

namespace rbdc_bench {

struct LoadedRobot {
  BenchRobot robot;
  rbdc::Model model;
  std::vector<State> states;  ///< kStateCount states, the same for every implementation
  double ground_mass;         ///< paper 001 Eq. 58 with double's ε: m_min / √ε
};

/// Calls `use` for every benchmark robot that loads; prints why a robot is skipped otherwise.
void for_each_loaded_robot(const std::string& implementation,
                           const std::function<void(const LoadedRobot&)>& use);

}  // namespace rbdc_bench
