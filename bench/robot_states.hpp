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

/// Calls `use` for every benchmark robot (or only the one named `only`) that loads; a robot that
/// does not load, or that `use` refuses by throwing, is skipped with a message naming the reason.
void for_each_loaded_robot(const std::string& implementation,
                           const std::function<void(const LoadedRobot&)>& use,
                           const std::string& only = "");

}  // namespace rbdc_bench
