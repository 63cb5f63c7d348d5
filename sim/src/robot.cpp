#include "rbdc/sim/robot.hpp"

#include <filesystem>

#include "rbdc/urdf_loader.hpp"

namespace rbdc::sim {

std::string default_urdf() { return RBDC_SOURCE_DIR "/robots/mini_cheetah.urdf"; }

Model load_robot(const std::string& urdf_path) {
  const std::filesystem::path urdf = urdf_path.empty() ? default_urdf() : urdf_path;
  UrdfOptions options;
  options.floating_base = true;
  // robots/<name>.topology.yaml fixes the paper's numbering and the feet.
  std::filesystem::path topology = urdf;
  topology.replace_extension(".topology.yaml");
  if (std::filesystem::exists(topology)) options.topology_file = topology.string();
  return load_urdf(urdf.string(), options);
}

}  // namespace rbdc::sim
