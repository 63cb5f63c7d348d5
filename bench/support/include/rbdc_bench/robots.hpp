// The robots the benchmarks and stress tests run on, loaded from the project's own robots/ folder
// exactly as the generator loads them (default URDF options: one foot per leaf body), so runtime,
// generated code and MuJoCo see the same model: the robots of robots/bundled.json.
#pragma once

#include <string>
#include <vector>

#include "rbdc/model.hpp"

namespace rbdc_bench {

struct BenchRobot {
  std::string name;        ///< also the generated namespace rbdc_gen::<name>
  std::string urdf;        ///< absolute path
  std::string topology;    ///< absolute path of the topology overlay (rotors, numbering), or empty
  bool floating_base;
  bool independent_mimic;  ///< mimic joints loaded as ordinary joints (a big robot's, bench/big_robots.json)
};

/// The bundled robots (robots/bundled.json), with paths below `source_dir` (the project root).
std::vector<BenchRobot> bench_robots(const std::string& source_dir);

/// The named robot of bench_robots(); throws std::invalid_argument for an unknown name.
BenchRobot bench_robot(const std::string& source_dir, const std::string& name);

/// Loads the robot's URDF with its base type and topology overlay, as tools/regenerate does. Throws
/// rbdc::ModelError.
rbdc::Model load_bench_robot(const BenchRobot& robot);

/// Σ body masses, and the smallest positive body mass (m_min of paper 001 Eq. 58, as the runtime's
/// rbdc::default_ground_mass takes it).
double total_mass(const rbdc::Model& model);
double smallest_body_mass(const rbdc::Model& model);

}  // namespace rbdc_bench
