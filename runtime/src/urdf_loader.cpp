// URDF → ModelSpec → build_model. The XML graph (document order, tree checks) comes from
// read_urdf_outline; numbers, joint types and mimic tags come from urdfdom.
#include "rbdc/urdf_loader.hpp"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

#include "text_checks.hpp"
#include "urdf_outline.hpp"

namespace rbdc {
namespace {

/// Placement of a child frame in a parent frame: x_parent = R x_child + p.
struct Pose {
  Matrix3 R = Matrix3::Identity();
  Vector3 p = Vector3::Zero();
  Pose operator*(const Pose& b) const { return {R * b.R, R * b.p + p}; }
};

Pose to_pose(const urdf::Pose& u) {
  const urdf::Rotation& q = u.rotation;
  return {Eigen::Quaterniond(q.w, q.x, q.y, q.z).toRotationMatrix(),
          Vector3(u.position.x, u.position.y, u.position.z)};
}

/// urdfdom reports problems through console_bridge: collect them instead of printing.
class UrdfdomLog : public console_bridge::OutputHandler {
 public:
  UrdfdomLog() { console_bridge::useOutputHandler(this); }
  ~UrdfdomLog() override { console_bridge::restorePreviousOutputHandler(); }
  UrdfdomLog(const UrdfdomLog&) = delete;
  UrdfdomLog& operator=(const UrdfdomLog&) = delete;
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_ERROR) errors.push_back(text);
    if (level == console_bridge::CONSOLE_BRIDGE_LOG_WARN) warnings.push_back(text);
  }
  std::vector<std::string> errors, warnings;
};

std::string read_text(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    throw ModelError(path + ": cannot open file (missing or not a regular file)");
  }
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in) throw ModelError(path + ": cannot read file");
  const std::string s = text.str();
  if (s.find_first_not_of(" \t\r\n") == std::string::npos) throw ModelError(path + ": file is empty");
  return s;
}

// urdfdom reads the text without visuals, collisions and materials (read_urdf_outline), so what it
// still calls an error concerns the dynamics; its warnings are passed on.
urdf::ModelInterfaceSharedPtr parse_with_urdfdom(const std::string& path, const std::string& text,
                                                 std::vector<std::string>* warnings) {
  UrdfdomLog log;
  urdf::ModelInterfaceSharedPtr model;
  try {
    model = urdf::parseURDF(text);
  } catch (const std::exception& e) {
    log.errors.push_back(e.what());
  }
  // urdfdom logs some errors (e.g. an unparsable mass) and still returns a model: refuse those too.
  if (model == nullptr || !log.errors.empty()) {
    std::string why;
    for (const std::string& e : log.errors) why += (why.empty() ? "" : "; ") + e;
    throw ModelError(path + ": urdfdom refused the file: " + (why.empty() ? "no reason given" : why));
  }
  if (warnings != nullptr) {
    for (const std::string& w : log.warnings) warnings->push_back(path + ": urdfdom: " + w);
  }
  return model;
}

/// A body under construction: the links merged into it and their mass properties in body axes.
struct BodyDraft {
  std::vector<std::string> links;  ///< links[0] names the body
  std::vector<Body> parts;
  int parent = -1;
  JointSpec joint;  ///< joint from `parent` (unused for the root)
};

/// Lumps rigid parts expressed in one frame: mass sum, mass-weighted COM, and the parallel-axis
/// theorem for each part's inertia about the common COM. A massless part's rotational inertia is a
/// pure rotational inertia, the same about every point: it is summed as it is, also when the whole
/// body is massless (then the COM is the body origin).
Body lump(const std::string& name, const std::vector<Body>& parts) {
  Body b;
  b.name = name;
  Vector3 first_moment = Vector3::Zero();
  for (const Body& p : parts) {
    b.mass += p.mass;
    first_moment += p.mass * p.com;
  }
  if (b.mass > 0) b.com = first_moment / b.mass;
  for (const Body& p : parts) {
    const Vector3 d = p.com - b.com;
    b.inertia_com += p.inertia_com + p.mass * (d.squaredNorm() * Matrix3::Identity() - d * d.transpose());
  }
  return b;
}

class UrdfTranslator {
 public:
  UrdfTranslator(std::string path, const UrdfOutline& outline, const urdf::ModelInterface& urdf,
                 const UrdfOptions& opts, std::vector<std::string>* warnings)
      : path_(std::move(path)), outline_(outline), urdf_(urdf), opts_(opts), warnings_(warnings) {
    for (const UrdfJointEdge& j : outline_.joints) {
      child_joints_[j.parent].push_back(&j);
      parent_joint_[j.child] = &j;
    }
  }

  ModelSpec translate() {
    check_names();
    for (const auto& [name, value] : opts_.locked_joints) {
      if (urdf_.getJoint(name) == nullptr) {
        throw ModelError(path_ + ": locked joint '" + name + "' does not exist");
      }
    }
    if (opts_.mimic == MimicMode::Couple) resolve_mimics();
    drafts_.emplace_back();  // body 0, the root
    visit(choose_root(), 0, Pose{});
    if (!link_errors_.empty()) {
      std::string all;
      for (const std::string& e : link_errors_) all += (all.empty() ? "" : "\n") + e;
      throw ModelError(all);  // one line per bad link
    }
    return assemble();
  }

 private:
  [[noreturn]] void fail(const UrdfJointEdge* j, const std::string& problem) const {
    const std::string line = j == nullptr ? std::string() : std::to_string(j->line) + ":";
    throw ModelError(path_ + ":" + line + " " + problem);
  }

  void warn(const UrdfJointEdge* j, const std::string& problem) const {
    if (warnings_ != nullptr) warnings_->push_back(path_ + ":" + std::to_string(j->line) + ": " + problem);
  }

  /// "<file>:<line>: link '<name>'", the prefix of a link's warnings and refusals.
  std::string link_where(const std::string& link) const {
    return path_ + ":" + std::to_string(outline_.link_lines.at(link)) + ": link '" + link + "'";
  }

  // The outline (tinyxml) and urdfdom must agree on every name before their readings are matched:
  // a name that is not plain text (text_checks.hpp) may be read differently (found by fuzz_urdf).
  void check_names() const {
    for (const UrdfJointEdge& j : outline_.joints) {
      if (!is_plain_text(j.name)) fail(&j, "joint name '" + escaped(j.name) + "' is not plain text (UTF-8 without control characters)");
      if (urdf_.getJoint(j.name) == nullptr) fail(&j, "joint '" + j.name + "' was not read by urdfdom");
    }
    for (const auto& [link, line] : outline_.link_lines) {
      const std::string where = path_ + ":" + std::to_string(line) + ": link name '" + escaped(link) + "'";
      if (!is_plain_text(link)) throw ModelError(where + " is not plain text (UTF-8 without control characters)");
      if (urdf_.getLink(link) == nullptr) throw ModelError(where + " was not read by urdfdom");
    }
  }

  // Each mimic joint's final leader and coefficients, following chains of mimics
  // (q_c = m_c (m_b q_a + o_b) + o_c). Missing, unmovable or circular leaders are refused.
  void resolve_mimics() {
    for (const UrdfJointEdge& edge : outline_.joints) {
      const urdf::JointConstSharedPtr j = urdf_.getJoint(edge.name);
      if (j->mimic == nullptr) continue;
      Mimic rule{j->mimic->joint_name, j->mimic->multiplier, j->mimic->offset};
      std::vector<std::string> chain{j->name};
      for (;;) {
        const urdf::JointConstSharedPtr leader = urdf_.getJoint(rule.leader);
        const std::string label = "joint '" + j->name + "' mimics joint '" + rule.leader + "'";
        if (leader == nullptr) fail(&edge, label + ", which does not exist");
        if (std::find(chain.begin(), chain.end(), rule.leader) != chain.end()) {
          std::string cycle;
          for (const std::string& name : chain) cycle += "'" + name + "' → ";
          fail(&edge, "joint '" + j->name + "': its mimic joints form a cycle (" + cycle + "'" + rule.leader +
                          "')");
        }
        if (leader->type != urdf::Joint::REVOLUTE && leader->type != urdf::Joint::CONTINUOUS &&
            leader->type != urdf::Joint::PRISMATIC) {
          fail(&edge, label + ", which cannot move (only revolute, continuous and prismatic joints lead)");
        }
        if (leader->mimic == nullptr) break;
        chain.push_back(rule.leader);
        rule = {leader->mimic->joint_name, rule.multiplier * leader->mimic->multiplier,
                rule.multiplier * leader->mimic->offset + rule.offset};
      }
      mimics_[j->name] = rule;
    }
  }

  bool unlimited(const std::string& joint) const {
    const std::vector<std::string>& v = outline_.joints_without_limits;
    return std::find(v.begin(), v.end(), joint) != v.end();
  }

  bool massless(const std::string& link) const {
    const urdf::LinkConstSharedPtr l = urdf_.getLink(link);
    return l->inertial == nullptr || l->inertial->mass == 0;
  }

  // The URDF root unless opts.root_link names another link. Links above the chosen root are
  // dropped, so they must be massless with one child and joined by fixed (or floating) joints. A
  // massless URDF root whose only joint is floating (a "world" link) is dropped the same way.
  std::string choose_root() const {
    std::string root = opts_.root_link;
    if (root.empty()) {
      root = outline_.root;
      const auto kids = child_joints_.find(root);
      if (kids != child_joints_.end() && kids->second.size() == 1 &&
          kids->second[0]->type == "floating" && massless(root)) {
        root = kids->second[0]->child;
      }
    }
    if (urdf_.getLink(root) == nullptr) {
      throw ModelError(path_ + ": root link '" + root + "' does not exist");
    }
    for (std::string at = root; at != outline_.root;) {
      const UrdfJointEdge* j = parent_joint_.at(at);
      const bool only_child = child_joints_.at(j->parent).size() == 1;
      if ((j->type != "fixed" && j->type != "floating") || !massless(j->parent) || !only_child) {
        fail(j, "cannot use link '" + root + "' as the root: link '" + j->parent +
                    "' above it would have to be dropped, but it has mass, other children or a "
                    "moving joint ('" + j->name + "')");
      }
      if (j->type == "floating" && !opts_.floating_base) {
        warn(j, "floating joint '" + j->name + "' from link '" + j->parent + "' is dropped: the fixed "
                "base welds link '" + root + "' to the world");
      }
      at = j->parent;
    }
    return root;
  }

  // Whether fixed joints merge `link` with other links into one body (it was merged into `body`, or a
  // fixed child will be merged into it): its inertia is then only a part of the body's.
  bool merged_with_others(const std::string& link, int body) const {
    if (drafts_[static_cast<size_t>(body)].links.size() > 1) return true;
    const auto kids = child_joints_.find(link);
    if (kids == child_joints_.end()) return false;
    return std::any_of(kids->second.begin(), kids->second.end(),
                       [](const UrdfJointEdge* j) { return j->type == "fixed"; });
  }

  void add_mass_properties(const std::string& link, int body, const Pose& pose) {
    const urdf::InertialSharedPtr& in = urdf_.getLink(link)->inertial;
    if (in == nullptr) return;
    Body part;
    part.mass = in->mass;
    const Pose inertial = to_pose(in->origin);
    Matrix3 I;
    I << in->ixx, in->ixy, in->ixz, in->ixy, in->iyy, in->iyz, in->ixz, in->iyz, in->izz;
    part.com = inertial.p;
    part.inertia_com = inertial.R * I * inertial.R.transpose();  // inertial frame → link frame
    // A massless link with inertia that cannot move changes nothing: drop its inertia.
    if (part.mass == 0 && body == 0 && !opts_.floating_base && I.cwiseAbs().maxCoeff() > 0 &&
        I.allFinite()) {
      part.inertia_com.setZero();
      if (warnings_ != nullptr) {
        warnings_->push_back(link_where(link) + ": zero mass but non-zero rotational inertia; welded to "
                             "the world (it cannot move), so the inertia is ignored");
      }
    }
    part = repair_mass_properties(part, link_where(link), warnings_,
                                  merged_with_others(link, body) ? Indefinite::Defer : Indefinite::Refuse);
    part.com = pose.R * part.com + pose.p;  // link frame → body frame
    part.inertia_com = pose.R * part.inertia_com * pose.R.transpose();
    drafts_[static_cast<size_t>(body)].parts.push_back(part);
  }

  // Motion of a locked 1-DoF joint at position q, as a pose of the child in the joint frame.
  static Pose joint_motion(const urdf::Joint& j, const Vector3& axis, double q) {
    if (j.type == urdf::Joint::PRISMATIC) return {Matrix3::Identity(), q * axis};
    return {Eigen::AngleAxisd(q, axis).toRotationMatrix(), Vector3::Zero()};
  }

  // Depth-first over links, children in document order: a moving joint opens a new body, a fixed
  // (or locked) joint merges the child link into the current body at its composed placement.
  void visit(const std::string& link, int body, const Pose& pose) {
    drafts_[static_cast<size_t>(body)].links.push_back(link);
    placement_[link] = {body, pose};
    try {  // a link's mass properties concern it alone: report every bad link, not just the first
      add_mass_properties(link, body, pose);
    } catch (const ModelError& e) {
      link_errors_.push_back(e.what());
    }
    const auto kids = child_joints_.find(link);
    if (kids == child_joints_.end()) return;
    for (const UrdfJointEdge* edge : kids->second) {
      const urdf::Joint& j = *urdf_.getJoint(edge->name);
      const Pose origin = pose * to_pose(j.parent_to_joint_origin_transform);
      if (!origin.R.allFinite() || !origin.p.allFinite()) fail(edge, "joint '" + j.name + "': origin has NaN or Inf");
      if (j.type == urdf::Joint::FIXED) {
        visit(j.child_link_name, body, origin);
        continue;
      }
      if (j.type != urdf::Joint::REVOLUTE && j.type != urdf::Joint::CONTINUOUS &&
          j.type != urdf::Joint::PRISMATIC) {
        fail(edge, "joint '" + j.name + "' has unsupported type '" + edge->type +
                       "' (supported: revolute, continuous, prismatic, fixed; floating only above "
                       "the root link)");
      }
      const Vector3 axis(j.axis.x, j.axis.y, j.axis.z);
      if (!axis.allFinite()) fail(edge, "joint '" + j.name + "': axis has NaN or Inf");
      if (axis.norm() < 1e-9) fail(edge, "joint '" + j.name + "': axis is zero");
      const auto locked = opts_.locked_joints.find(j.name);
      if (locked != opts_.locked_joints.end()) {
        visit(j.child_link_name, body, origin * joint_motion(j, axis.normalized(), locked->second));
        continue;
      }
      if (j.mimic != nullptr && opts_.mimic == MimicMode::Lock) {
        visit(j.child_link_name, body, origin * joint_motion(j, axis.normalized(), j.mimic->offset));
        continue;
      }
      if (j.mimic != nullptr && opts_.mimic == MimicMode::Couple) {
        const Mimic& rule = mimics_.at(j.name);
        const auto leader_lock = opts_.locked_joints.find(rule.leader);
        if (leader_lock != opts_.locked_joints.end()) {  // a locked leader locks its followers
          const double q = rule.multiplier * leader_lock->second + rule.offset;
          visit(j.child_link_name, body, origin * joint_motion(j, axis.normalized(), q));
          continue;
        }
        couplings_.push_back({j.name, rule});
      }
      BodyDraft draft;
      draft.parent = body;
      draft.joint.name = j.name;
      draft.joint.type = j.type == urdf::Joint::PRISMATIC ? JointType::Prismatic : JointType::Revolute;
      draft.joint.axis = axis;
      draft.joint.rotation = origin.R.transpose();  // E_T: parent → joint coordinates
      draft.joint.translation = origin.p;
      if (j.type != urdf::Joint::CONTINUOUS && j.limits != nullptr && !unlimited(j.name)) {
        draft.joint.lower = j.limits->lower;
        draft.joint.upper = j.limits->upper;
      }
      drafts_.push_back(draft);
      visit(j.child_link_name, static_cast<int>(drafts_.size()) - 1, Pose{});
    }
  }

  Foot resolve_foot(const FootSpec& f, const std::string& source) const {
    const auto it = placement_.find(f.link);
    if (it == placement_.end()) {
      throw ModelError(source + ": foot '" + f.name + "': link '" + f.link +
                       "' is not a link of the model");
    }
    const Pose& pose = it->second.pose;
    return {f.name, it->second.body, pose.R * f.offset + pose.p};
  }

  // A declared frame: its pose in its link's frame, composed with the link's placement in its body.
  Frame resolve_frame(const FrameSpec& f, const std::string& source, const std::vector<int>& number_of) const {
    const auto it = placement_.find(f.link);
    if (it == placement_.end()) {
      throw ModelError(source + ": frame '" + f.name + "': link '" + f.link + "' is not a link of the model");
    }
    const Pose& link = it->second.pose;
    return {f.name, number_of[static_cast<size_t>(it->second.body)], (link.R * f.rotation).transpose(),
            link.R * f.translation + link.p};
  }

  // One frame per link (docs/model.md, "Frames"), merged links included, in body order and, within
  // a body, in the order the depth-first visit met them (the body's own link first).
  std::vector<Frame> link_frames(const std::vector<int>& order, const std::vector<int>& number_of) const {
    std::vector<Frame> frames;
    for (const int draft : order) {
      for (const std::string& link : drafts_[static_cast<size_t>(draft)].links) {
        const Pose& pose = placement_.at(link).pose;
        frames.push_back({link, number_of[static_cast<size_t>(draft)], pose.R.transpose(), pose.p});
      }
    }
    return frames;
  }

  // Default feet: one per leaf body, at its last merged massless tip link (toe/foot links) if any,
  // else at the body origin.
  std::vector<Foot> default_feet() const {
    std::vector<bool> has_children(drafts_.size(), false);
    for (const BodyDraft& d : drafts_) {
      if (d.parent >= 0) has_children[static_cast<size_t>(d.parent)] = true;
    }
    std::vector<Foot> feet;
    for (size_t b = 0; b < drafts_.size(); ++b) {
      if (has_children[b]) continue;
      const std::vector<std::string>& links = drafts_[b].links;
      Foot foot{links[0], static_cast<int>(b), Vector3::Zero()};
      for (size_t k = 1; k < links.size(); ++k) {
        if (child_joints_.count(links[k]) == 0 && massless(links[k])) {
          foot = {links[k], static_cast<int>(b), placement_.at(links[k]).pose.p};
        }
      }
      feet.push_back(foot);
    }
    return feet;
  }

  // Body order: depth-first (identity), or as the topology file lists the bodies, after checking
  // that its PRED/SUCC agree with the URDF's parent relations.
  std::vector<int> numbering(const Topology* topo) const {
    const int nb = static_cast<int>(drafts_.size());
    std::vector<int> order(static_cast<size_t>(nb));
    for (int i = 0; i < nb; ++i) order[static_cast<size_t>(i)] = i;
    if (topo == nullptr) return order;
    const std::string& src = topo->source;
    if (static_cast<int>(topo->bodies.size()) != nb) {
      throw ModelError(src + ": lists " + std::to_string(topo->bodies.size()) + " bodies, but " +
                       path_ + " has " + std::to_string(nb) + " after merging fixed joints");
    }
    std::map<std::string, int> draft_of;
    for (int i = 0; i < nb; ++i) draft_of[drafts_[static_cast<size_t>(i)].links[0]] = i;
    std::vector<bool> used(static_cast<size_t>(nb), false);
    for (int k = 0; k < nb; ++k) {
      const std::string& name = topo->bodies[static_cast<size_t>(k)];
      const auto it = draft_of.find(name);
      if (it == draft_of.end()) {
        const auto merged = placement_.find(name);
        throw ModelError(src + ": body '" + name + "' " +
                         (merged == placement_.end()
                              ? "is not a link of " + path_
                              : "is merged by a fixed joint into body '" +
                                    drafts_[static_cast<size_t>(merged->second.body)].links[0] + "'"));
      }
      if (used[static_cast<size_t>(it->second)]) throw ModelError(src + ": body '" + name + "' is listed twice");
      used[static_cast<size_t>(it->second)] = true;
      order[static_cast<size_t>(k)] = it->second;
    }
    if (order[0] != 0) {
      throw ModelError(src + ": body 0 is '" + topo->bodies[0] + "', but the root link is '" +
                       drafts_[0].links[0] + "'");
    }
    for (int i = 1; i < nb; ++i) {
      const int p = topo->pred[static_cast<size_t>(i - 1)], s = topo->succ[static_cast<size_t>(i - 1)];
      const std::string joint = "joint " + std::to_string(i) + " (PRED " + std::to_string(p) +
                                ", SUCC " + std::to_string(s) + ")";
      if (std::max(p, s) != i || std::min(p, s) < 0) {
        throw ModelError(src + ": " + joint + ": must join body " + std::to_string(i) +
                         " to a body with a smaller number (regular numbering, λ(i) < i)");
      }
      const int urdf_parent = drafts_[static_cast<size_t>(order[static_cast<size_t>(i)])].parent;
      if (order[static_cast<size_t>(std::min(p, s))] != urdf_parent) {
        throw ModelError(src + ": " + joint + " hangs body '" + topo->bodies[static_cast<size_t>(i)] +
                         "' from '" + topo->bodies[static_cast<size_t>(std::min(p, s))] +
                         "', but in " + path_ + " its parent is '" +
                         drafts_[static_cast<size_t>(urdf_parent)].links[0] + "'");
      }
    }
    return order;
  }

  ModelSpec assemble() const {
    std::unique_ptr<Topology> topo;
    if (!opts_.topology_file.empty()) {
      topo = std::make_unique<Topology>(read_topology(opts_.topology_file));
    }
    const std::vector<int> order = numbering(topo.get());
    std::vector<int> number_of(order.size());
    for (size_t k = 0; k < order.size(); ++k) number_of[static_cast<size_t>(order[k])] = static_cast<int>(k);

    ModelSpec spec;
    spec.name = urdf_.getName();
    spec.source = path_;
    spec.floating_base = opts_.floating_base;
    spec.gravity = opts_.gravity;
    for (size_t k = 0; k < order.size(); ++k) {
      const BodyDraft& d = drafts_[static_cast<size_t>(order[k])];
      spec.bodies.push_back(lump(d.links[0], d.parts));
      spec.body_lines.push_back(outline_.link_lines.at(d.links[0]));
      if (k == 0) continue;
      spec.joints.push_back(d.joint);
      spec.pred.push_back(topo ? topo->pred[k - 1] : number_of[static_cast<size_t>(d.parent)]);
      spec.succ.push_back(topo ? topo->succ[k - 1] : static_cast<int>(k));
    }
    std::map<std::string, int> joint_number;
    for (size_t k = 0; k < spec.joints.size(); ++k) joint_number[spec.joints[k].name] = static_cast<int>(k) + 1;
    for (const auto& [follower, rule] : couplings_) {
      spec.couplings.push_back({joint_number.at(follower), joint_number.at(rule.leader), rule.multiplier, rule.offset});
    }
    std::vector<Foot> feet;
    if (!opts_.feet.empty()) {
      for (const FootSpec& f : opts_.feet) feet.push_back(resolve_foot(f, path_));
    } else if (topo && !topo->feet.empty()) {
      for (const FootSpec& f : topo->feet) feet.push_back(resolve_foot(f, topo->source));
    } else {
      feet = default_feet();
    }
    for (Foot& f : feet) f.body = number_of[static_cast<size_t>(f.body)];
    spec.feet = feet;
    spec.frames = link_frames(order, number_of);
    if (topo) {
      for (const FrameSpec& f : topo->frames) spec.frames.push_back(resolve_frame(f, topo->source, number_of));
    }
    if (topo) spec.actuators = topo->actuators;
    return spec;
  }

  struct LinkPlacement {
    int body = 0;
    Pose pose;  ///< link frame in body frame
  };

  /// q_follower = multiplier · q_leader + offset, the leader being a joint that mimics none.
  struct Mimic {
    std::string leader;
    double multiplier = 1, offset = 0;
  };

  std::string path_;
  const UrdfOutline& outline_;
  const urdf::ModelInterface& urdf_;
  const UrdfOptions& opts_;
  std::vector<std::string>* warnings_;
  std::map<std::string, std::vector<const UrdfJointEdge*>> child_joints_;
  std::map<std::string, Mimic> mimics_;
  std::vector<std::pair<std::string, Mimic>> couplings_;  ///< coupled followers, in visiting order
  std::vector<std::string> link_errors_;  ///< refusals of links' mass properties, in visiting order
  std::map<std::string, const UrdfJointEdge*> parent_joint_;
  std::vector<BodyDraft> drafts_;
  std::map<std::string, LinkPlacement> placement_;
};

}  // namespace

Model load_urdf(const std::string& path, const UrdfOptions& opts, std::vector<std::string>* warnings) {
  const std::string text = read_text(path);
  const UrdfOutline outline = read_urdf_outline(path, text);
  if (warnings != nullptr) {
    warnings->insert(warnings->end(), outline.warnings.begin(), outline.warnings.end());
    for (const std::string& j : outline.joints_without_limits) {
      warnings->push_back(path + ":" + std::to_string(outline.joint_line(j)) + ": joint '" + j +
                          "' has no <limit>; loaded without position limits");
    }
  }
  const urdf::ModelInterfaceSharedPtr urdf = parse_with_urdfdom(path, outline.urdfdom_text, warnings);
  return build_model(UrdfTranslator(path, outline, *urdf, opts, warnings).translate(), warnings);
}

}  // namespace rbdc
