#include "urdf_outline.hpp"

#include <tinyxml.h>

#include <initializer_list>
#include <map>
#include <set>

#include "rbdc/model_builder.hpp"

namespace rbdc {
namespace {

std::string attribute(const TiXmlElement* e, const char* name) {
  const char* value = e->Attribute(name);
  return value == nullptr ? std::string() : std::string(value);
}

std::string child_link_attribute(const TiXmlElement* joint, const char* tag) {
  const TiXmlElement* e = joint->FirstChildElement(tag);
  return e == nullptr ? std::string() : attribute(e, "link");
}

// <visual> and <collision> without <geometry>, and a <material> (of the robot, or of a visual)
// neither named nor described, are faults outside the dynamics: warn, then drop every such element.
void strip_appearance(const std::string& path, TiXmlElement* robot, std::vector<std::string>& warnings) {
  const auto warn = [&](const TiXmlElement* e, const std::string& problem) {
    warnings.push_back(path + ":" + std::to_string(e->Row()) + ": " + problem +
                       "; ignored (not used for dynamics)");
  };
  std::vector<TiXmlElement*> dropped;
  for (TiXmlElement* link = robot->FirstChildElement("link"); link != nullptr;
       link = link->NextSiblingElement("link")) {
    for (const char* tag : {"visual", "collision"}) {
      for (TiXmlElement* e = link->FirstChildElement(tag); e != nullptr; e = e->NextSiblingElement(tag)) {
        if (e->FirstChildElement("geometry") == nullptr) {
          warn(e, "link '" + attribute(link, "name") + "': <" + tag + "> without <geometry>");
        }
        dropped.push_back(e);
      }
    }
  }
  for (TiXmlElement* e = robot->FirstChildElement("material"); e != nullptr;
       e = e->NextSiblingElement("material")) {
    if (attribute(e, "name").empty()) warn(e, "<material> without a name");
    dropped.push_back(e);
  }
  for (TiXmlElement* e : dropped) e->Parent()->RemoveChild(e);
}

// urdfdom reports a malformed number with the attribute's text inside the format string it hands to
// console_bridge, so a '%' there is read as a printf directive ("1%s%s" as a mass crashes the
// process). No number holds a '%': refuse one in the attributes urdfdom reads as numbers before it
// sees them. (Names are logged through a "%s" and are safe.)
void refuse_percent_in_numbers(const std::string& path, const TiXmlElement* robot) {
  const auto check = [&](const std::string& owner, const TiXmlElement* e) {
    for (const TiXmlAttribute* a = e->FirstAttribute(); a != nullptr; a = a->Next()) {
      if (std::string(a->Name()) == "joint") continue;  // <mimic joint="…">: a name
      if (std::string(a->Value()).find('%') != std::string::npos) {
        throw ModelError(path + ":" + std::to_string(e->Row()) + ": " + owner + ": <" + e->Value() +
                         "> attribute '" + a->Name() + "' holds a '%', which no number has");
      }
    }
  };
  const auto check_children = [&](const std::string& owner, const TiXmlElement* parent,
                                  std::initializer_list<const char*> tags) {
    for (const char* tag : tags) {
      for (const TiXmlElement* e = parent->FirstChildElement(tag); e != nullptr;
           e = e->NextSiblingElement(tag)) {
        check(owner, e);
      }
    }
  };
  for (const TiXmlElement* link = robot->FirstChildElement("link"); link != nullptr;
       link = link->NextSiblingElement("link")) {
    const std::string owner = "link '" + attribute(link, "name") + "'";
    for (const TiXmlElement* inertial = link->FirstChildElement("inertial"); inertial != nullptr;
         inertial = inertial->NextSiblingElement("inertial")) {
      check_children(owner, inertial, {"origin", "mass", "inertia"});
    }
  }
  for (const TiXmlElement* joint = robot->FirstChildElement("joint"); joint != nullptr;
       joint = joint->NextSiblingElement("joint")) {
    check_children("joint '" + attribute(joint, "name") + "'", joint,
                   {"origin", "axis", "limit", "dynamics", "safety_controller", "calibration", "mimic"});
  }
}

}  // namespace

int UrdfOutline::joint_line(const std::string& joint) const {
  for (const UrdfJointEdge& j : joints) {
    if (j.name == joint) return j.line;
  }
  return 0;
}

UrdfOutline read_urdf_outline(const std::string& path, const std::string& text) {
  const auto fail = [&](int line, const std::string& problem) {
    throw ModelError(path + ":" + (line > 0 ? std::to_string(line) + ":" : std::string()) + " " +
                     problem);
  };
  TiXmlDocument doc;
  doc.Parse(text.c_str());
  if (doc.Error()) {
    fail(doc.ErrorRow(), std::string("malformed XML: ") + doc.ErrorDesc() + " (column " +
                             std::to_string(doc.ErrorCol()) + ")");
  }
  TiXmlElement* robot = doc.RootElement();
  if (robot == nullptr || std::string(robot->Value()) != "robot") {
    fail(robot == nullptr ? 0 : robot->Row(), "the root element is not <robot>");
  }

  UrdfOutline outline;
  std::map<std::string, int>& link_line = outline.link_lines;
  for (const TiXmlElement* e = robot->FirstChildElement("link"); e != nullptr;
       e = e->NextSiblingElement("link")) {
    const std::string name = attribute(e, "name");
    if (name.empty()) fail(e->Row(), "<link> without a name");
    if (!link_line.emplace(name, e->Row()).second) {
      fail(e->Row(), "link '" + name + "' is defined twice (first on line " +
                         std::to_string(link_line[name]) + ")");
    }
    outline.links.push_back(name);
  }
  if (outline.links.empty()) fail(robot->Row(), "no links: <robot> has no <link> element");

  std::map<std::string, const UrdfJointEdge*> parent_joint;  // child link → its joint
  for (TiXmlElement* e = robot->FirstChildElement("joint"); e != nullptr;
       e = e->NextSiblingElement("joint")) {
    UrdfJointEdge j{attribute(e, "name"), attribute(e, "type"), child_link_attribute(e, "parent"),
                    child_link_attribute(e, "child"), e->Row()};
    const std::string label = "joint '" + j.name + "'";
    if (j.name.empty()) fail(j.line, "<joint> without a name");
    if (j.parent.empty() || j.child.empty()) fail(j.line, label + ": missing <parent> or <child> link");
    for (const std::string* link : {&j.parent, &j.child}) {
      if (link_line.count(*link) == 0) fail(j.line, label + " names link '" + *link + "', which does not exist");
    }
    if (j.parent == j.child) fail(j.line, label + ": joins link '" + j.child + "' to itself (cycle)");
    if ((j.type == "revolute" || j.type == "prismatic") && e->FirstChildElement("limit") == nullptr) {
      outline.joints_without_limits.push_back(j.name);
      TiXmlElement limit("limit");  // urdfdom refuses these joints without it; its values are unused
      limit.SetAttribute("effort", "0");
      limit.SetAttribute("velocity", "0");
      e->InsertEndChild(limit);
    }
    outline.joints.push_back(j);
  }
  refuse_percent_in_numbers(path, robot);
  strip_appearance(path, robot, outline.warnings);
  TiXmlPrinter printer;
  doc.Accept(&printer);
  outline.urdfdom_text = printer.CStr();
  for (const UrdfJointEdge& j : outline.joints) {
    const auto [it, fresh] = parent_joint.emplace(j.child, &j);
    if (!fresh) {
      fail(j.line, "link '" + j.child + "' has two parents: joint '" + it->second->name + "' (line " +
                       std::to_string(it->second->line) + ") and joint '" + j.name + "'");
    }
  }

  std::vector<std::string> roots;
  for (const std::string& link : outline.links) {
    if (parent_joint.count(link) == 0) roots.push_back(link);
  }
  if (roots.empty()) {
    fail(robot->Row(), "cycle: every link has a parent joint, so there is no root link");
  }
  if (roots.size() > 1) {
    fail(link_line[roots[1]], "several root links (links without a parent joint): '" + roots[0] +
                                  "' and '" + roots[1] + "'; a URDF must be one tree");
  }
  outline.root = roots[0];

  // With one parent per link and a single root, a link that cannot reach the root lies on a cycle.
  for (const std::string& link : outline.links) {
    std::set<std::string> seen;
    std::string at = link;
    while (at != outline.root) {
      if (!seen.insert(at).second) {
        const UrdfJointEdge* j = parent_joint.at(at);
        fail(j->line, "cycle through link '" + at + "' (joint '" + j->name + "')");
      }
      at = parent_joint.at(at)->parent;
    }
  }
  return outline;
}

}  // namespace rbdc
