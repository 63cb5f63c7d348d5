// Internal: the link/joint graph of a URDF read straight from the XML (tinyxml, as urdfdom uses), in
// document order. urdfdom keeps joints in a name-sorted map and lets a second parent overwrite the
// first, so numbering and the tree checks are done here.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace rbdc {

struct UrdfJointEdge {
  std::string name, type, parent, child;
  int line = 0;
};

struct UrdfOutline {
  std::vector<std::string> links;     ///< document order
  std::map<std::string, int> link_lines;  ///< line of each <link>
  std::vector<UrdfJointEdge> joints;  ///< document order
  std::string root;                   ///< the one link without a parent
  /// Revolute/prismatic joints written without <limit> (the URDF spec requires one; Drake-made files
  /// omit it). They are loaded as unlimited.
  std::vector<std::string> joints_without_limits;
  /// The text to give urdfdom: the input without what the dynamics never read (<visual>,
  /// <collision>, <material>), so that a fault there cannot stop the load, and with a placeholder
  /// <limit> in the joints above.
  std::string urdfdom_text;
  /// Faults found in the dropped elements ("<path>:<line>: …"), reported as warnings.
  std::vector<std::string> warnings;

  int joint_line(const std::string& joint) const;  ///< 0 when unknown
};

/// Parses `text` (the contents of `path`) and checks it is one tree: well-formed XML, a <robot> with
/// links, joints naming existing links, one parent per link, one root, no cycles. Throws ModelError.
UrdfOutline read_urdf_outline(const std::string& path, const std::string& text);

}  // namespace rbdc
