// URDF → Model through urdfdom: fixed joints merged into their parent (inertia lumped), numbering by
// depth-first traversal in document order unless a topology file fixes it. Rules: docs/model.md.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "rbdc/model_builder.hpp"
#include "rbdc/topology_file.hpp"

namespace rbdc {

/// What a URDF <mimic> joint becomes (docs/model.md, "Mimic joints").
enum class MimicMode {
  Couple,       ///< q_follower = multiplier · q_leader + offset: a Coupling, no coordinate of its own
  Lock,         ///< a fixed joint at q = offset
  Independent,  ///< an ordinary joint; the <mimic> tag is ignored
};

struct UrdfOptions {
  bool floating_base = true;   ///< false: the root link is welded to the world (joint 0 Fixed)
  std::string root_link;       ///< empty: the URDF root (see docs/model.md for other choices)
  std::vector<FootSpec> feet;  ///< empty: from the topology file, else one per leaf body
  Vector3 gravity{0, 0, -9.81};
  MimicMode mimic = MimicMode::Couple;
  /// Joints turned into fixed joints at the given position (rad or m), then merged.
  std::map<std::string, double> locked_joints;
  std::string topology_file;  ///< optional overlay fixing numbering and feet
};

/// Loads and validates a URDF. Throws ModelError naming the file, the element and the problem;
/// `warnings` gets every repair and every ignored fault as "<file>:<line>: <element>: <problem>"
/// (also those found before a refusal).
Model load_urdf(const std::string& path, const UrdfOptions& opts = {},
                std::vector<std::string>* warnings = nullptr);

}  // namespace rbdc
