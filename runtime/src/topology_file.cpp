// Topology files (yaml-cpp): numbering overlay and standalone "arrays with parameters" form.
#include "rbdc/topology_file.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <map>

#include "text_checks.hpp"

namespace rbdc {
namespace {

class YamlReader {
 public:
  explicit YamlReader(std::string path) : path_(std::move(path)) {}

  [[noreturn]] void fail(const YAML::Node& at, const std::string& problem) const {
    const YAML::Mark mark = at.Mark();
    const std::string line = mark.line >= 0 ? std::to_string(mark.line + 1) + ":" : std::string();
    throw ModelError(path_ + ":" + line + " " + problem);
  }

  YAML::Node load() const {
    try {
      const YAML::Node root = YAML::LoadFile(path_);
      if (!root.IsMap()) throw ModelError(path_ + ": expected a YAML mapping at the top level");
      return root;
    } catch (const YAML::BadFile&) {
      throw ModelError(path_ + ": cannot open file");
    } catch (const YAML::ParserException& e) {
      throw ModelError(path_ + ":" + std::to_string(e.mark.line + 1) + ": malformed YAML: " + e.msg);
    }
  }

  YAML::Node required(const YAML::Node& map, const std::string& key) const {
    // operator[] on a scalar or a list throws (found by fuzz_topology)
    if (!map.IsMap()) fail(map, "expected a mapping with key '" + key + "'");
    const YAML::Node n = map[key];
    if (!n) fail(map, "missing key '" + key + "'");
    return n;
  }

  template <class T>
  T scalar(const YAML::Node& n, const std::string& what) const {
    if (!n.IsScalar()) fail(n, what + ": expected a single value");
    try {
      return n.as<T>();
    } catch (const YAML::Exception&) {
      fail(n, what + ": cannot read '" + n.Scalar() + "'");
    }
  }

  double number(const YAML::Node& n, const std::string& what) const {
    const double x = scalar<double>(n, what);
    if (!std::isfinite(x)) fail(n, what + " is NaN or Inf");
    return x;
  }

  Vector3 vector3(const YAML::Node& n, const std::string& what) const {
    if (!n.IsSequence() || n.size() != 3) fail(n, what + ": expected a list of 3 numbers");
    return {number(n[0], what), number(n[1], what), number(n[2], what)};
  }

  Matrix3 matrix3(const YAML::Node& n, const std::string& what) const {
    if (!n.IsSequence() || n.size() != 3) fail(n, what + ": expected 3 rows of 3 numbers");
    Matrix3 m;
    for (int r = 0; r < 3; ++r) m.row(r) = vector3(n[static_cast<size_t>(r)], what).transpose();
    return m;
  }

  std::vector<int> ints(const YAML::Node& n, const std::string& what) const {
    if (!n.IsSequence()) fail(n, what + ": expected a list of integers");
    std::vector<int> v;
    for (const YAML::Node& x : n) v.push_back(scalar<int>(x, what));
    return v;
  }

  std::vector<std::string> strings(const YAML::Node& n, const std::string& what) const {
    if (!n.IsSequence()) fail(n, what + ": expected a list of names");
    std::vector<std::string> v;
    for (const YAML::Node& x : n) v.push_back(name(x, what));
    return v;
  }

  /// A name, refused here (this file and line) when it is not plain text (text_checks.hpp): the model
  /// builder would refuse it too, but naming the robot's other file (found by fuzz_topology).
  std::string name(const YAML::Node& n, const std::string& what) const {
    std::string s = scalar<std::string>(n, what);
    if (!is_plain_text(s)) fail(n, what + " '" + escaped(s) + "' is not plain text (UTF-8 without control characters)");
    return s;
  }

  /// A mapping key as text: YAML also allows a list or a mapping as a key (found by fuzz_topology:
  /// YAML::TypedBadConversion escaped).
  std::string key(const YAML::Node& k, const std::string& what) const {
    if (!k.IsScalar()) fail(k, what + ": expected a name as the key");
    return k.Scalar();
  }

  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// URDF convention: R = Rz(yaw) Ry(pitch) Rx(roll) places the child frame in the parent.
Matrix3 rotation_from_rpy(const Vector3& rpy) {
  return (Eigen::AngleAxisd(rpy.z(), Vector3::UnitZ()) * Eigen::AngleAxisd(rpy.y(), Vector3::UnitY()) *
          Eigen::AngleAxisd(rpy.x(), Vector3::UnitX()))
      .toRotationMatrix();
}

// One entry of `actuators:`; a rotor is present when gear_ratio is given. The values are checked
// by add_actuators (model_builder.hpp), which names this file and line.
ActuatorSpec read_actuator(const YamlReader& yaml, const YAML::Node& n) {
  if (!n.IsMap()) yaml.fail(n, "actuators: expected a mapping per joint");
  ActuatorSpec a;
  a.joint = yaml.name(yaml.required(n, "joint"), "actuator joint");
  a.where = yaml.path() + ":" + std::to_string(n.Mark().line + 1);
  const std::string what = "actuator of joint '" + a.joint + "'";
  static const char* const kKeys[] = {"joint", "armature", "gear_ratio", "rotor_mass",
                                      "rotor_inertia", "xyz", "rpy", "axis"};
  for (const auto& kv : n) {
    const std::string key = yaml.key(kv.first, what);
    if (std::find(std::begin(kKeys), std::end(kKeys), key) == std::end(kKeys)) {
      yaml.fail(kv.first, what + ": unknown key '" + key + "'");
    }
  }
  if (n["armature"]) a.armature = yaml.number(n["armature"], what + " armature");
  a.has_rotor = static_cast<bool>(n["gear_ratio"]);
  if (!a.has_rotor) {
    if (n["rotor_mass"] || n["rotor_inertia"] || n["xyz"] || n["rpy"] || n["axis"]) {
      yaml.fail(n, what + ": rotor values without gear_ratio");
    }
    return a;
  }
  a.gear_ratio = yaml.number(n["gear_ratio"], what + " gear_ratio");
  a.rotor_mass = yaml.number(yaml.required(n, "rotor_mass"), what + " rotor_mass");
  a.rotor_inertia = yaml.matrix3(yaml.required(n, "rotor_inertia"), what + " rotor_inertia");
  if (n["xyz"]) a.rotor_translation = yaml.vector3(n["xyz"], what + " xyz");
  if (n["rpy"]) a.rotor_rotation = rotation_from_rpy(yaml.vector3(n["rpy"], what + " rpy")).transpose();
  if (n["axis"]) a.rotor_axis = yaml.vector3(n["axis"], what + " axis");
  return a;
}

// A `frames:` entry: {name, body: LINK, xyz, rpy} (xyz and rpy default to zero).
FrameSpec read_frame(const YamlReader& yaml, const YAML::Node& n) {
  FrameSpec f;
  f.name = yaml.name(yaml.required(n, "name"), "frame name");
  const std::string what = "frame '" + f.name + "'";
  for (const auto& kv : n) {
    const std::string key = yaml.key(kv.first, what);
    if (key != "name" && key != "body" && key != "xyz" && key != "rpy") {
      yaml.fail(kv.first, what + ": unknown key '" + key + "' (name, body, xyz, rpy)");
    }
  }
  f.link = yaml.name(yaml.required(n, "body"), what + " body");
  if (n["xyz"]) f.translation = yaml.vector3(n["xyz"], what + " xyz");
  if (n["rpy"]) f.rotation = rotation_from_rpy(yaml.vector3(n["rpy"], what + " rpy"));
  return f;
}

Topology read_arrays(const YamlReader& yaml, const YAML::Node& root) {
  Topology t;
  t.source = yaml.path();
  t.bodies = yaml.strings(yaml.required(root, "bodies"), "bodies");
  t.pred = yaml.ints(yaml.required(root, "PRED"), "PRED");
  t.succ = yaml.ints(yaml.required(root, "SUCC"), "SUCC");
  if (t.bodies.empty()) yaml.fail(root["bodies"], "bodies: the list is empty");
  if (t.pred.size() + 1 != t.bodies.size() || t.succ.size() + 1 != t.bodies.size()) {
    yaml.fail(root["PRED"], "PRED and SUCC need one entry per joint (" +
                                std::to_string(t.bodies.size() - 1) + " for " +
                                std::to_string(t.bodies.size()) + " bodies)");
  }
  if (const YAML::Node feet = root["feet"]) {
    if (!feet.IsSequence()) yaml.fail(feet, "feet: expected a list");
    for (const YAML::Node& f : feet) {
      const std::string name = yaml.name(yaml.required(f, "name"), "foot name");
      t.feet.push_back({name, yaml.name(yaml.required(f, "body"), "foot '" + name + "' body"),
                        yaml.vector3(yaml.required(f, "offset"), "foot '" + name + "' offset")});
    }
  }
  if (const YAML::Node frames = root["frames"]) {
    if (!frames.IsSequence()) yaml.fail(frames, "frames: expected a list");
    for (const YAML::Node& f : frames) t.frames.push_back(read_frame(yaml, f));
  }
  if (const YAML::Node actuators = root["actuators"]) {
    if (!actuators.IsSequence()) yaml.fail(actuators, "actuators: expected a list");
    for (const YAML::Node& a : actuators) t.actuators.push_back(read_actuator(yaml, a));
  }
  return t;
}

JointSpec read_joint(const YamlReader& yaml, const YAML::Node& n, int i) {
  JointSpec j;
  j.name = yaml.name(yaml.required(n, "name"), "joint " + std::to_string(i) + " name");
  const std::string what = "joint '" + j.name + "'";
  const std::string type = yaml.scalar<std::string>(yaml.required(n, "type"), what + " type");
  if (type == "revolute") {
    j.type = JointType::Revolute;
  } else if (type == "prismatic") {
    j.type = JointType::Prismatic;
  } else {
    yaml.fail(n["type"], what + ": unsupported type '" + type + "' (revolute or prismatic)");
  }
  j.axis = yaml.vector3(yaml.required(n, "axis"), what + " axis");
  if (n["rpy"]) j.rotation = rotation_from_rpy(yaml.vector3(n["rpy"], what + " rpy")).transpose();
  if (n["xyz"]) j.translation = yaml.vector3(n["xyz"], what + " xyz");
  if (n["lower"]) j.lower = yaml.number(n["lower"], what + " lower");
  if (n["upper"]) j.upper = yaml.number(n["upper"], what + " upper");
  return j;
}

Body read_body(const YamlReader& yaml, const YAML::Node& inertias, const std::string& name) {
  const YAML::Node n = inertias[name];
  if (!n) yaml.fail(inertias, "inertias: no entry for body '" + name + "'");
  const std::string what = "body '" + name + "'";
  Body b;
  b.name = name;
  b.mass = yaml.number(yaml.required(n, "mass"), what + " mass");
  if (n["com"]) b.com = yaml.vector3(n["com"], what + " com");
  if (n["inertia"]) b.inertia_com = yaml.matrix3(n["inertia"], what + " inertia");
  return b;
}

}  // namespace

bool is_topology_path(const std::string& path) {
  const auto ends_with = [&](const std::string& ext) {
    return path.size() >= ext.size() && path.compare(path.size() - ext.size(), ext.size(), ext) == 0;
  };
  return ends_with(".yaml") || ends_with(".yml");
}

Topology read_topology(const std::string& path) {
  const YamlReader yaml(path);
  return read_arrays(yaml, yaml.load());
}

Model load_topology(const std::string& path, std::vector<std::string>* warnings) {
  const YamlReader yaml(path);
  const YAML::Node root = yaml.load();
  const Topology t = read_arrays(yaml, root);
  ModelSpec spec;
  spec.source = path;
  spec.name = yaml.name(yaml.required(root, "name"), "name");
  if (root["floating_base"]) spec.floating_base = yaml.scalar<bool>(root["floating_base"], "floating_base");
  if (root["gravity"]) spec.gravity = yaml.vector3(root["gravity"], "gravity");
  spec.pred = t.pred;
  spec.succ = t.succ;
  spec.actuators = t.actuators;

  const YAML::Node joints = yaml.required(root, "joints");
  if (!joints.IsSequence() || joints.size() + 1 != t.bodies.size()) {
    yaml.fail(joints, "joints: expected a list with one entry per joint (" +
                          std::to_string(t.bodies.size() - 1) + ")");
  }
  for (size_t k = 0; k < joints.size(); ++k) {
    spec.joints.push_back(read_joint(yaml, joints[k], static_cast<int>(k) + 1));
  }
  const YAML::Node inertias = yaml.required(root, "inertias");
  if (!inertias.IsMap()) yaml.fail(inertias, "inertias: expected a mapping from body name to mass properties");
  std::map<std::string, int> number_of;
  for (const std::string& name : t.bodies) {
    number_of.emplace(name, static_cast<int>(spec.bodies.size()));
    spec.bodies.push_back(read_body(yaml, inertias, name));
  }
  for (const FootSpec& f : t.feet) {
    const auto it = number_of.find(f.link);
    if (it == number_of.end()) {
      throw ModelError(path + ": foot '" + f.name + "': body '" + f.link + "' is not in the body list");
    }
    spec.feet.push_back({f.name, it->second, f.offset});
  }
  // Frames: one per body at its origin, then the file's own (docs/model.md, "Frames").
  for (size_t b = 0; b < t.bodies.size(); ++b) spec.frames.push_back({t.bodies[b], static_cast<int>(b)});
  for (const FrameSpec& f : t.frames) {
    const auto it = number_of.find(f.link);
    if (it == number_of.end()) {
      throw ModelError(path + ": frame '" + f.name + "': body '" + f.link + "' is not in the body list");
    }
    spec.frames.push_back({f.name, it->second, f.rotation.transpose(), f.translation});
  }
  return build_model(spec, warnings);
}

}  // namespace rbdc
