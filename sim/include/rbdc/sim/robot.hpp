// Loading the simulated robot: the Mini Cheetah URDF with its four feet.
#pragma once

#include <string>

#include "rbdc/model.hpp"

namespace rbdc::sim {

/// robots/mini_cheetah.urdf of this source tree (compiled in).
std::string default_urdf();

/// Loads a floating-base URDF with the topology file next to it (<name>.topology.yaml) if any;
/// throws rbdc::ModelError naming the file when it cannot.
Model load_robot(const std::string& urdf_path);

}  // namespace rbdc::sim
