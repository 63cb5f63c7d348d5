// Validation and derivation of the Model from topology arrays (paper 000 Section 2.2, Eqs. 1-2).
#include "rbdc/model_builder.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

#include "text_checks.hpp"

namespace rbdc {
namespace {

// Tolerances, relative to the size of the quantity checked.
constexpr double kAxisNormMin = 1e-9;
constexpr double kOrthonormalTol = 1e-9;
constexpr double kTriangleTol = 1e-9;
// Relative size of a defect that is plain floating-point round-off (repaired silently).
constexpr double kRoundOff = 1e-14;
// A body lighter than this is almost certainly a placeholder (e.g. a 1e-6 kg dummy link); it is kept
// but reported because it makes M badly conditioned.
constexpr double kTinyMass = 1e-4;

template <class Derived>
bool all_finite(const Eigen::MatrixBase<Derived>& m) {
  return m.allFinite();
}

std::string body_label(const ModelSpec& spec, int i) {
  std::ostringstream s;
  const std::string& n = spec.bodies[static_cast<size_t>(i)].name;
  if (n.empty()) {
    s << "body " << i;
  } else {
    s << "body '" << n << "' (" << i << ")";
  }
  return s.str();
}

std::string joint_label(const ModelSpec& spec, int i) {
  std::ostringstream s;
  const std::string& n = spec.joints[static_cast<size_t>(i - 1)].name;
  if (n.empty()) {
    s << "joint " << i;
  } else {
    s << "joint '" << n << "' (" << i << ")";
  }
  return s.str();
}

[[noreturn]] void fail(const ModelSpec& spec, const std::string& what) {
  throw ModelError(spec.source + ": " + what);
}

void check_sizes(const ModelSpec& spec) {
  if (spec.bodies.empty()) fail(spec, "the model has no bodies");
  const size_t n = spec.bodies.size() - 1;
  if (spec.pred.size() != n || spec.succ.size() != n || spec.joints.size() != n) {
    std::ostringstream s;
    s << "array sizes disagree: " << spec.bodies.size() << " bodies need " << n
      << " joints, but PRED has " << spec.pred.size() << ", SUCC has " << spec.succ.size()
      << " and the joint list has " << spec.joints.size() << " entries";
    fail(spec, s.str());
  }
  if (!all_finite(spec.gravity)) fail(spec, "gravity is not finite");
}

// Names must be plain text (text_checks.hpp) and bodies, joints unique.
void check_names(const ModelSpec& spec) {
  const auto check_text = [&](const std::string& what, const std::string& name) {
    if (!is_plain_text(name)) {
      fail(spec, what + " '" + escaped(name) + "' is not plain text (UTF-8 without control characters)");
    }
  };
  check_text("robot name", spec.name);
  std::set<std::string> bodies, joints;
  for (const Body& b : spec.bodies) {
    check_text("body name", b.name);
    if (!b.name.empty() && !bodies.insert(b.name).second) {
      fail(spec, "body name '" + b.name + "' is used twice");
    }
  }
  for (const JointSpec& j : spec.joints) {
    check_text("joint name", j.name);
    if (!j.name.empty() && !joints.insert(j.name).second) {
      fail(spec, "joint name '" + j.name + "' is used twice");
    }
  }
  for (const Foot& f : spec.feet) check_text("foot name", f.name);
}

// λ(i) = min(PRED(i), SUCC(i)) (Eq. 2); regular numbering requires the other endpoint to be i and
// λ(i) < i. With nb - 1 joints each ending at its own body this also rules out cycles, a body with two
// parents and bodies disconnected from the root.
std::vector<int> derive_parents(const ModelSpec& spec) {
  const int nb = static_cast<int>(spec.bodies.size());
  std::vector<int> parent(static_cast<size_t>(nb), -1);
  for (int i = 1; i < nb; ++i) {
    const int p = spec.pred[static_cast<size_t>(i - 1)];
    const int s = spec.succ[static_cast<size_t>(i - 1)];
    std::ostringstream where;
    where << joint_label(spec, i) << " with PRED = " << p << ", SUCC = " << s;
    if (p < 0 || p >= nb || s < 0 || s >= nb) {
      fail(spec, where.str() + ": body index out of range 0 … " + std::to_string(nb - 1));
    }
    if (p == s) fail(spec, where.str() + ": joins a body to itself (cycle)");
    if (std::max(p, s) != i) {
      fail(spec, where.str() + ": neither endpoint is body " + std::to_string(i) +
                     "; numbering must be regular (joint i ends at body i, λ(i) < i), so the "
                     "bodies form a cycle, a body has two parents, or the order is not a tree order");
    }
    parent[static_cast<size_t>(i)] = std::min(p, s);
  }
  return parent;
}

bool is_proper_rotation(const Matrix3& E) {
  return (E.transpose() * E - Matrix3::Identity()).norm() <= kOrthonormalTol && E.determinant() > 0;
}

void check_joint(const ModelSpec& spec, int i, JointSpec& j) {
  const std::string label = joint_label(spec, i);
  if (j.type != JointType::Revolute && j.type != JointType::Prismatic) {
    fail(spec, label + ": only revolute and prismatic joints may follow the root joint");
  }
  if (!all_finite(j.axis)) fail(spec, label + ": axis has NaN or Inf");
  if (!all_finite(j.rotation)) fail(spec, label + ": rotation has NaN or Inf");
  if (!all_finite(j.translation)) fail(spec, label + ": translation has NaN or Inf");
  if (std::isnan(j.lower) || std::isnan(j.upper)) fail(spec, label + ": limit is NaN");
  if (j.lower > j.upper) fail(spec, label + ": lower limit exceeds upper limit");
  const double norm = j.axis.norm();
  if (norm < kAxisNormMin) fail(spec, label + ": axis is zero");
  j.axis /= norm;
  const Matrix3& E = j.rotation;
  if (!is_proper_rotation(E)) {
    fail(spec, label + ": rotation is not a proper orthonormal matrix");
  }
}

// Frames (docs/model.md, "Frames"): an existing body, a finite pose with a proper rotation, and a
// name no other frame has (a bad name in a scene could not tell which one it meant).
void check_frames(const ModelSpec& spec) {
  std::set<std::string> names;
  const int nb = static_cast<int>(spec.bodies.size());
  for (const Frame& f : spec.frames) {
    const std::string label = "frame '" + f.name + "'";
    if (f.name.empty()) fail(spec, "a frame has no name");
    if (!names.insert(f.name).second) fail(spec, label + ": the name is used twice");
    if (f.body < 0 || f.body >= nb) fail(spec, label + ": body " + std::to_string(f.body) + " does not exist");
    if (!all_finite(f.rotation) || !all_finite(f.translation)) fail(spec, label + ": pose has NaN or Inf");
    const Matrix3& E = f.rotation;
    if (!is_proper_rotation(E)) {
      fail(spec, label + ": rotation is not a proper orthonormal matrix");
    }
  }
}

// Principal moments of a symmetric 3x3 inertia, ascending.
Vector3 principal_moments(const Matrix3& I) {
  return Eigen::SelfAdjointEigenSolver<Matrix3>(I, Eigen::EigenvaluesOnly).eigenvalues();
}

// "<source>[:<line>]: body '<name>' (i)", the prefix of a body's messages.
std::string body_where(const ModelSpec& spec, int i) {
  const size_t ui = static_cast<size_t>(i);
  const bool line = ui < spec.body_lines.size() && spec.body_lines[ui] > 0;
  return spec.source + (line ? ":" + std::to_string(spec.body_lines[ui]) : "") + ": " + body_label(spec, i);
}

void check_body(ModelSpec& spec, int i, std::vector<std::string>* warnings) {
  Body& b = spec.bodies[static_cast<size_t>(i)];
  const std::string label = body_where(spec, i);
  b = repair_mass_properties(b, label, warnings);
  if (warnings == nullptr || b.mass == 0) return;
  const Vector3 moments = principal_moments(b.inertia_com);
  if (moments(0) + moments(1) < moments(2) * (1 - kTriangleTol)) {
    std::ostringstream s;
    s.precision(6);
    s << label << ": rotational inertia breaks the triangle inequality ("
      << moments(0) << " + " << moments(1) << " < " << moments(2)
      << "); kept as given, but no real mass distribution has it";
    warnings->push_back(s.str());
  }
  if (b.mass < kTinyMass) {
    std::ostringstream s;
    s << label << ": tiny mass " << b.mass
      << " kg (placeholder?); the mass matrix may be badly conditioned";
    warnings->push_back(s.str());
  }
}

Joint root_joint(bool floating_base) {
  Joint j;
  j.name = "root";
  j.type = floating_base ? JointType::Floating : JointType::Fixed;
  j.axis = Vector3::Zero();
  return j;
}

Vector6 motion_subspace_of(const Joint& j) {
  Vector6 S = Vector6::Zero();
  if (j.type == JointType::Revolute) S.head<3>() = j.axis;
  if (j.type == JointType::Prismatic) S.tail<3>() = j.axis;
  return S;
}

// κ, μ, ν from λ; bodies are visited in increasing order, so each set comes out ascending.
// ν(0) is every body (κ never holds joint 0).
void derive_sets(Model& m) {
  const size_t nb = static_cast<size_t>(m.nb);
  m.support.assign(nb, {});
  m.children.assign(nb, {});
  m.subtree.assign(nb, {});
  for (int i = 1; i < m.nb; ++i) {
    const int p = m.parent[static_cast<size_t>(i)];
    m.support[static_cast<size_t>(i)] = m.support[static_cast<size_t>(p)];
    m.support[static_cast<size_t>(i)].push_back(i);
    m.children[static_cast<size_t>(p)].push_back(i);
  }
  for (int i = 0; i < m.nb; ++i) {
    for (int k = i; k < m.nb; ++k) {
      const std::vector<int>& kappa = m.support[static_cast<size_t>(k)];
      if (i == 0 || k == i || std::binary_search(kappa.begin(), kappa.end(), i)) {
        m.subtree[static_cast<size_t>(i)].push_back(k);
      }
    }
  }
}

// q_follower = multiplier · q_leader + offset: both 1-DoF joints, each follower coupled once, leaders
// independent (the loader resolves chains of mimics), finite numbers.
void check_couplings(const ModelSpec& spec) {
  const int nb = static_cast<int>(spec.bodies.size());
  std::vector<bool> follows(static_cast<size_t>(nb), false);
  for (const Coupling& c : spec.couplings) {
    if (c.follower < 1 || c.follower >= nb || c.leader < 1 || c.leader >= nb) {
      fail(spec, "coupling of joint " + std::to_string(c.follower) + " to joint " +
                     std::to_string(c.leader) + ": joint index out of range 1 … " + std::to_string(nb - 1));
    }
    const std::string label = joint_label(spec, c.follower) + " coupled to " + joint_label(spec, c.leader);
    if (c.follower == c.leader) fail(spec, label + ": a joint cannot follow itself");
    if (!std::isfinite(c.multiplier) || !std::isfinite(c.offset)) {
      fail(spec, label + ": multiplier or offset is NaN or Inf");
    }
    if (follows[static_cast<size_t>(c.follower)]) fail(spec, label + ": the joint is coupled twice");
    follows[static_cast<size_t>(c.follower)] = true;
  }
  for (const Coupling& c : spec.couplings) {
    if (follows[static_cast<size_t>(c.leader)]) {
      fail(spec, joint_label(spec, c.follower) + " follows " + joint_label(spec, c.leader) +
                     ", which itself follows another joint; couple it to that joint directly");
    }
  }
}

}  // namespace

Body repair_mass_properties(const Body& body, const std::string& where,
                            std::vector<std::string>* warnings, Indefinite indefinite) {
  const auto refuse = [&](const std::string& problem) { throw ModelError(where + ": " + problem); };
  const auto warn = [&](const std::string& problem) {
    if (warnings != nullptr) warnings->push_back(where + ": " + problem);
  };
  if (!std::isfinite(body.mass)) refuse("mass is NaN or Inf");
  if (!all_finite(body.com)) refuse("COM has NaN or Inf");
  if (!all_finite(body.inertia_com)) refuse("inertia has NaN or Inf");
  if (body.mass < 0) refuse("mass is negative");
  Body b = body;
  Matrix3& I = b.inertia_com;
  const double trace = std::abs(I.trace());
  // Beyond `repairable` a defect is refused; up to `silent` it is plain floating-point round-off
  // (e.g. of lumping fixed links) and repaired without a word.
  const double repairable = kInertiaRepairTolerance * trace + kInertiaRepairFloor;
  const double silent = kRoundOff * trace;
  const double asymmetry = (I - I.transpose()).cwiseAbs().maxCoeff();
  if (asymmetry > repairable) {
    std::ostringstream s;
    s << "rotational inertia is not symmetric (largest |I - Iᵀ| entry " << asymmetry << ")";
    refuse(s.str());
  }
  if (asymmetry > 0) {
    I = 0.5 * (I + I.transpose()).eval();
    if (asymmetry > silent) {
      std::ostringstream s;
      s << "rotational inertia is not symmetric by " << asymmetry << " kg·m² (round-off); symmetrised";
      warn(s.str());
    }
  }
  const Eigen::SelfAdjointEigenSolver<Matrix3> eigen(I);
  const Vector3 moments = eigen.eigenvalues();
  if (moments(0) < -repairable) {
    std::ostringstream s;
    s << "rotational inertia is not positive semi-definite (principal moments " << moments.transpose()
      << ")";
    if (indefinite == Indefinite::Refuse) refuse(s.str());
    warn(s.str() + "; fixed joints merge the link with others, so their merged inertia is checked instead");
  } else if (moments(0) < 0) {
    I = eigen.eigenvectors() * moments.cwiseMax(0.0).asDiagonal() * eigen.eigenvectors().transpose();
    if (-moments(0) > silent) {
      std::ostringstream s;
      s << "rotational inertia has principal moments (" << moments.transpose()
        << "), negative by " << -moments(0) << " kg·m² (round-off); clipped to zero";
      warn(s.str());
    }
  }
  if (b.mass == 0 && I.cwiseAbs().maxCoeff() > 0) {
    warn("zero mass but non-zero rotational inertia; kept as a pure rotational inertia");
  }
  return b;
}

Model build_model(const ModelSpec& spec_in, std::vector<std::string>* warnings) {
  ModelSpec spec = spec_in;  // axes get normalized
  check_sizes(spec);
  check_names(spec);
  const std::vector<int> parent = derive_parents(spec);
  const int nb = static_cast<int>(spec.bodies.size());
  for (int i = 1; i < nb; ++i) check_joint(spec, i, spec.joints[static_cast<size_t>(i - 1)]);
  for (int i = 0; i < nb; ++i) check_body(spec, i, warnings);
  check_couplings(spec);
  for (const Foot& f : spec.feet) {
    const std::string label = "foot '" + f.name + "'";
    if (f.body < 0 || f.body >= nb) {
      fail(spec, label + ": body " + std::to_string(f.body) + " does not exist");
    }
    if (!all_finite(f.offset)) fail(spec, label + ": offset has NaN or Inf");
  }
  check_frames(spec);

  Model m;
  m.name = spec.name;
  m.floating_base = spec.floating_base;
  m.nb = nb;
  m.nq = (spec.floating_base ? 7 : 0) + nb - 1;
  m.nv = (spec.floating_base ? 6 : 0) + nb - 1;
  m.gravity = spec.gravity;
  m.pred.assign(1, -1);
  m.succ.assign(1, 0);
  m.pred.insert(m.pred.end(), spec.pred.begin(), spec.pred.end());
  m.succ.insert(m.succ.end(), spec.succ.begin(), spec.succ.end());
  m.parent = parent;
  m.bodies = spec.bodies;
  m.feet = spec.feet;
  m.frames = spec.frames;  // grouped by body, keeping the source's order within a body
  std::stable_sort(m.frames.begin(), m.frames.end(), [](const Frame& a, const Frame& b) { return a.body < b.body; });
  m.couplings = spec.couplings;
  std::sort(m.couplings.begin(), m.couplings.end(),
            [](const Coupling& a, const Coupling& b) { return a.follower < b.follower; });

  m.joints.push_back(root_joint(spec.floating_base));
  const int q0 = spec.floating_base ? 7 : 0;
  const int v0 = spec.floating_base ? 6 : 0;
  for (int i = 1; i < nb; ++i) {
    const JointSpec& js = spec.joints[static_cast<size_t>(i - 1)];
    Joint j;
    j.name = js.name;
    j.type = js.type;
    j.axis = js.axis;
    j.rotation = js.rotation;
    j.translation = js.translation;
    j.lower = js.lower;
    j.upper = js.upper;
    j.q_index = q0 + i - 1;
    j.v_index = v0 + i - 1;
    m.joints.push_back(j);
  }
  for (const Joint& j : m.joints) {
    m.X_tree.push_back(motion_transform(j.rotation, j.translation));
    m.motion_subspace.push_back(motion_subspace_of(j));
  }
  for (const Body& b : m.bodies) m.inertia.push_back(spatial_inertia(b.mass, b.com, b.inertia_com));
  derive_sets(m);
  add_actuators(m, spec.actuators);
  // A singular M (e.g. a massless moving leaf) loads: kinematics and inverse dynamics work; the
  // functions that need M⁻¹ refuse the model (docs/model.md, "Singular mass matrix").
  if (!m.singular_mass_matrix.empty() && warnings != nullptr) {
    warnings->push_back(spec.source + ": " + m.singular_mass_matrix + "; kinematics and inverse dynamics "
                        "work, forward dynamics and OSC refuse it (lock the joint, or give the body mass "
                        "or the joint armature)");
  }
  return m;
}

}  // namespace rbdc
