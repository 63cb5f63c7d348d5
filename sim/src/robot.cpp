#include "rbdc/sim/robot.hpp"

#include "rbdc/urdf_loader.hpp"

namespace rbdc::sim {

std::string default_urdf() { return RBDC_SOURCE_DIR "/robots/mini_cheetah.urdf"; }

Model load_robot(const std::string& urdf_path) {
  UrdfOptions options;
  options.floating_base = true;
  return load_urdf(urdf_path.empty() ? default_urdf() : urdf_path, options);
}

}  // namespace rbdc::sim
