#include "rbdc/control/drive_train.hpp"

#include <filesystem>
#include <stdexcept>

#include "rbdc/sim/robot.hpp"
#include "rbdc/urdf_loader.hpp"

namespace rbdc::control {

Model load_trot_robot(const std::string& urdf, ActuatorMode mode) {
  if (mode == ActuatorMode::None) return sim::load_robot(urdf);
  const std::filesystem::path path = urdf.empty() ? sim::default_urdf() : urdf;
  const std::filesystem::path overlay = path.parent_path() / (path.stem().string() + "_rotors.topology.yaml");
  if (!std::filesystem::exists(overlay)) {
    throw std::invalid_argument("--rotors: no rotor overlay " + overlay.string() + " next to " + path.string() +
                                " (docs/model.md, \"Actuators\")");
  }
  UrdfOptions options;
  options.floating_base = true;
  options.topology_file = overlay.string();
  return with_actuator_mode(load_urdf(path.string(), options), mode);
}

}  // namespace rbdc::control
