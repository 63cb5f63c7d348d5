#include "robot_states.hpp"

#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>

#include "registry.hpp"

namespace rbdc_bench {

void for_each_loaded_robot(const std::string& implementation,
                           const std::function<void(const LoadedRobot&)>& use,
                           const std::string& only) {
  for (const BenchRobot& robot : bench_robots(RBDC_SOURCE_DIR)) {
    if (!only.empty() && robot.name != only) continue;
    LoadedRobot loaded{robot, {}, {}, 0.0};
    try {
      loaded.model = load_bench_robot(robot);
      loaded.states = random_states(loaded.model, kStateCount, /*seed=*/20240601);
      loaded.ground_mass = smallest_body_mass(loaded.model) /
                           std::sqrt(std::numeric_limits<double>::epsilon());
      use(loaded);
    } catch (const std::exception& error) {
      std::fprintf(stderr, "rbdc-bench: %s: skipping %s: %s\n", implementation.c_str(),
                   robot.name.c_str(), error.what());
    }
  }
}

}  // namespace rbdc_bench
