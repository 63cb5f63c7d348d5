// Topology files (YAML): PRED/SUCC arrays over a list of body names (paper 000 Eq. 1) plus feet and
// frames, either
// as an overlay that fixes the numbering and feet of a URDF, or standalone with per-joint parameters
// and per-body inertias. Format: docs/model.md.
#pragma once

#include <string>
#include <vector>

#include "rbdc/model_builder.hpp"

namespace rbdc {

/// A foot named by link: `offset` is in the frame of `link` (which may be merged into a body).
struct FootSpec {
  std::string name;
  std::string link;
  Vector3 offset = Vector3::Zero();
};

/// An operational frame named by link: its pose (`rotation`: frame axes in link coordinates, as a
/// URDF rpy gives them; `translation`: its origin) is in the frame of `link`, which may be merged
/// into a body (docs/model.md, "Frames").
struct FrameSpec {
  std::string name;
  std::string link;
  Matrix3 rotation = Matrix3::Identity();
  Vector3 translation = Vector3::Zero();
};

/// The numbering part of a topology file (both forms).
struct Topology {
  std::string source;               ///< file name, for messages
  std::vector<std::string> bodies;  ///< body (link) names in final numbering, body 0 = root
  std::vector<int> pred, succ;      ///< joints 1 … nb-1, Eq. 1
  std::vector<FootSpec> feet;
  std::vector<FrameSpec> frames;        ///< the `frames:` section, added to the links' frames
  std::vector<ActuatorSpec> actuators;  ///< the `actuators:` section (docs/model.md, "Actuators")
};

/// Reads the numbering and feet of a topology file (either form). Throws ModelError.
Topology read_topology(const std::string& path);

/// Loads a standalone topology file (arrays plus joint and body parameters) into a Model.
/// Throws ModelError; non-fatal findings go to `warnings` when given.
Model load_topology(const std::string& path, std::vector<std::string>* warnings = nullptr);

/// True when `path` names a topology YAML file (by extension .yaml / .yml).
bool is_topology_path(const std::string& path);

}  // namespace rbdc
