// The fixed robot that the topology overlays and body-wrench files of the fuzz targets refer to:
// a trunk with two two-joint legs (revolute, prismatic) ending in a merged massless foot, and a
// continuous arm; the seeds in corpus/topology and corpus/body_wrenches name its links.
#pragma once

#include <string>

namespace rbdc_fuzz {

/// Path of the robot's URDF, written once into the temporary folder (removed at exit).
const std::string& base_robot_urdf();

}  // namespace rbdc_fuzz
