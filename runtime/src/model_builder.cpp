// Validation and derivation of the Model from topology arrays (paper 000 Section 2.2, Eqs. 1-2).
#include "rbdc/model_builder.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace rbdc {
namespace {

// Tolerances, relative to the size of the quantity checked.
constexpr double kAxisNormMin = 1e-9;
constexpr double kOrthonormalTol = 1e-9;
constexpr double kSymmetryTol = 1e-9;
constexpr double kEigenTol = 1e-12;
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

void check_unique_names(const ModelSpec& spec) {
  std::set<std::string> bodies, joints;
  for (const Body& b : spec.bodies) {
    if (!b.name.empty() && !bodies.insert(b.name).second) {
      fail(spec, "body name '" + b.name + "' is used twice");
    }
  }
  for (const JointSpec& j : spec.joints) {
    if (!j.name.empty() && !joints.insert(j.name).second) {
      fail(spec, "joint name '" + j.name + "' is used twice");
    }
  }
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
  if ((E.transpose() * E - Matrix3::Identity()).norm() > kOrthonormalTol || E.determinant() < 0) {
    fail(spec, label + ": rotation is not a proper orthonormal matrix");
  }
}

// Principal moments of a symmetric 3x3 inertia, ascending.
Vector3 principal_moments(const Matrix3& I) {
  return Eigen::SelfAdjointEigenSolver<Matrix3>(I, Eigen::EigenvaluesOnly).eigenvalues();
}

void check_body(const ModelSpec& spec, int i, std::vector<std::string>* warnings) {
  const Body& b = spec.bodies[static_cast<size_t>(i)];
  const std::string label = body_label(spec, i);
  check_mass_properties(b, spec.source + ": " + label);
  if (warnings == nullptr || b.mass == 0) return;
  const Vector3 moments = principal_moments(b.inertia_com);
  if (moments(0) + moments(1) < moments(2) * (1 - kSymmetryTol)) {
    std::ostringstream s;
    s.precision(6);
    s << spec.source << ": " << label << ": rotational inertia breaks the triangle inequality ("
      << moments(0) << " + " << moments(1) << " < " << moments(2)
      << "); kept as given, but no real mass distribution has it";
    warnings->push_back(s.str());
  }
  if (b.mass < kTinyMass) {
    std::ostringstream s;
    s << spec.source << ": " << label << ": tiny mass " << b.mass
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

// A joint whose subtree carries no inertia about its axis gives M a zero diagonal entry
// (d_i = S_iᵀ I^c_i S_i = 0), e.g. a massless leaf: refuse it.
void check_moving_inertia(const ModelSpec& spec, const Model& m) {
  std::vector<Matrix6> composite = m.inertia;
  for (int i = m.nb - 1; i >= 1; --i) {
    const size_t ui = static_cast<size_t>(i);
    const Vector6& S = m.motion_subspace[ui];
    if (S.dot(composite[ui] * S) <= 1e-15) {
      std::string reason = m.bodies[ui].mass == 0 && m.children[ui].empty()
                               ? body_label(spec, i) + " is a moving leaf with zero mass"
                               : "the subtree of " + body_label(spec, i) +
                                     " has no inertia about the joint axis";
      fail(spec, joint_label(spec, i) + ": " + reason +
                     ", so the mass matrix would be singular");
    }
    const Matrix6& X = m.X_tree[ui];  // I^c_λ += X_Tᵀ I^c_i X_T (joint at q = 0)
    composite[static_cast<size_t>(m.parent[ui])] += X.transpose() * composite[ui] * X;
  }
}

}  // namespace

void check_mass_properties(const Body& b, const std::string& where) {
  const auto refuse = [&](const std::string& problem) { throw ModelError(where + ": " + problem); };
  if (!std::isfinite(b.mass)) refuse("mass is NaN or Inf");
  if (!all_finite(b.com)) refuse("COM has NaN or Inf");
  if (!all_finite(b.inertia_com)) refuse("inertia has NaN or Inf");
  if (b.mass < 0) refuse("mass is negative");
  const Matrix3& I = b.inertia_com;
  const double scale = std::max(I.norm(), 1e-300);
  if ((I - I.transpose()).norm() > kSymmetryTol * scale) refuse("rotational inertia is not symmetric");
  if (b.mass == 0) {
    if (I.norm() != 0) refuse("zero mass but non-zero rotational inertia");
    return;
  }
  const Vector3 moments = principal_moments(I);
  if (moments(0) < -kEigenTol * scale) {
    std::ostringstream s;
    s << "rotational inertia is not positive semi-definite (principal moments "
      << moments.transpose() << ")";
    refuse(s.str());
  }
}

Model build_model(const ModelSpec& spec_in, std::vector<std::string>* warnings) {
  ModelSpec spec = spec_in;  // axes get normalized
  check_sizes(spec);
  check_unique_names(spec);
  const std::vector<int> parent = derive_parents(spec);
  const int nb = static_cast<int>(spec.bodies.size());
  for (int i = 1; i < nb; ++i) check_joint(spec, i, spec.joints[static_cast<size_t>(i - 1)]);
  for (int i = 0; i < nb; ++i) check_body(spec, i, warnings);
  for (const Foot& f : spec.feet) {
    const std::string label = "foot '" + f.name + "'";
    if (f.body < 0 || f.body >= nb) {
      fail(spec, label + ": body " + std::to_string(f.body) + " does not exist");
    }
    if (!all_finite(f.offset)) fail(spec, label + ": offset has NaN or Inf");
  }

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
  check_moving_inertia(spec, m);
  return m;
}

}  // namespace rbdc
