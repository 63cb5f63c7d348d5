#include "rbdc_bench/robots.hpp"

#include <algorithm>
#include <stdexcept>

#include "rbdc/urdf_loader.hpp"

namespace rbdc_bench {

std::vector<BenchRobot> bench_robots(const std::string& source_dir) {
  struct Entry {
    const char* name;
    const char* urdf;
    const char* topology;
    bool floating_base;
    bool independent_mimic;
  };
  static const Entry entries[] = {
#include "rbdc_bench/bundled_robots.inc"
  };
  std::vector<BenchRobot> robots;
  for (const Entry& e : entries) {
    const std::string topology = *e.topology ? source_dir + "/" + e.topology : "";
    robots.push_back({e.name, source_dir + "/" + e.urdf, topology, e.floating_base, e.independent_mimic});
  }
  return robots;
}

BenchRobot bench_robot(const std::string& source_dir, const std::string& name) {
  for (const BenchRobot& robot : bench_robots(source_dir))
    if (robot.name == name) return robot;
  throw std::invalid_argument("rbdc_bench: unknown benchmark robot '" + name + "'");
}

rbdc::Model load_bench_robot(const BenchRobot& robot) {
  rbdc::UrdfOptions options;
  options.floating_base = robot.floating_base;
  options.topology_file = robot.topology;
  if (robot.independent_mimic) options.mimic = rbdc::MimicMode::Independent;
  return rbdc::load_urdf(robot.urdf, options);
}

double total_mass(const rbdc::Model& model) {
  double sum = 0;
  for (const rbdc::Body& body : model.bodies) sum += body.mass;
  return sum;
}

double smallest_body_mass(const rbdc::Model& model) {
  double smallest = total_mass(model);
  for (const rbdc::Body& body : model.bodies)
    if (body.mass > 0) smallest = std::min(smallest, body.mass);
  return smallest;
}

}  // namespace rbdc_bench
