// Checking actuators (armature, geared rotors) and deriving their spatial constants; docs/model.md,
// "Actuators".
#include <Eigen/Eigenvalues>
#include <cmath>

#include "rbdc/mass_matrix_rank.hpp"
#include "rbdc/model_builder.hpp"

namespace rbdc {
namespace {

constexpr double kOrthonormalTol = 1e-9;
constexpr double kAxisNormMin = 1e-9;
// A rotor inertia may deviate from axial symmetry (or the triangle inequality) by this times its trace.
constexpr double kRotorTol = 1e-9;

int joint_index(const Model& m, const ActuatorSpec& a) {
  for (int i = 1; i < m.nb; ++i) {
    if (m.joints[static_cast<size_t>(i)].name == a.joint) return i;
  }
  throw ModelError(a.where + ": actuator of joint '" + a.joint + "': no such moving joint");
}

// Rotor checks: the inertia is a real one (symmetric, PSD, triangle inequality) and symmetric about
// the spin axis, I = J a aᵀ + J_t (1 - a aᵀ); otherwise it would change with the rotor angle, which
// the model does not track.
Rotor check_rotor(const Joint& j, const ActuatorSpec& a, const std::string& label) {
  const auto refuse = [&](const std::string& problem) { throw ModelError(label + ": " + problem); };
  if (!std::isfinite(a.gear_ratio) || a.gear_ratio <= 0) refuse("gear ratio must be finite and > 0");
  Body as_body;
  as_body.mass = a.rotor_mass;
  as_body.inertia_com = a.rotor_inertia;
  const Body b = repair_mass_properties(as_body, label + ": rotor", nullptr);
  Rotor r;
  r.gear_ratio = a.gear_ratio;
  r.mass = b.mass;
  r.inertia = b.inertia_com;
  r.rotation = a.rotor_rotation.value_or(j.rotation);
  r.translation = a.rotor_translation.value_or(j.translation);
  r.axis = a.rotor_axis.value_or(j.axis);
  if (!r.rotation.allFinite() || !r.translation.allFinite() || !r.axis.allFinite()) {
    refuse("rotor placement or axis has NaN or Inf");
  }
  const Matrix3& E = r.rotation;
  if ((E.transpose() * E - Matrix3::Identity()).norm() > kOrthonormalTol || E.determinant() < 0) {
    refuse("rotor rotation is not a proper orthonormal matrix");
  }
  if (r.axis.norm() < kAxisNormMin) refuse("rotor axis is zero");
  r.axis.normalize();
  const Matrix3& I = r.inertia;
  const double tol = kRotorTol * I.trace() + kInertiaRepairFloor;
  const Vector3 m = Eigen::SelfAdjointEigenSolver<Matrix3>(I, Eigen::EigenvaluesOnly).eigenvalues();
  if (m(0) + m(1) < m(2) - tol) refuse("rotor inertia breaks the triangle inequality (not physical)");
  const Matrix3 aa = r.axis * r.axis.transpose();
  const double J = r.axis.dot(I * r.axis);
  const double Jt = 0.5 * (I.trace() - J);
  if ((I - (J * aa + Jt * (Matrix3::Identity() - aa))).cwiseAbs().maxCoeff() > tol) {
    refuse("rotor inertia is not symmetric about the spin axis (it would change with the rotor angle)");
  }
  return r;
}

// X_rotor, rotor_inertia, rotor_subspace of the rotors (nb entries each).
void add_rotor_constants(Model& m) {
  const size_t nb = static_cast<size_t>(m.nb);
  m.X_rotor.assign(nb, Matrix6::Identity());
  m.rotor_inertia.assign(nb, Matrix6::Zero());
  m.rotor_subspace.assign(nb, Vector6::Zero());
  for (size_t i = 1; i < nb; ++i) {
    const Rotor& r = m.joints[i].rotor;
    if (r.gear_ratio == 0) continue;
    m.X_rotor[i] = motion_transform(r.rotation, r.translation);
    m.rotor_inertia[i] = spatial_inertia(r.mass, Vector3::Zero(), r.inertia);
    m.rotor_subspace[i].head<3>() = r.gear_ratio * r.axis;
  }
}

}  // namespace

void add_actuators(Model& m, const std::vector<ActuatorSpec>& actuators) {
  for (const ActuatorSpec& a : actuators) {
    const int i = joint_index(m, a);
    Joint& j = m.joints[static_cast<size_t>(i)];
    const std::string label = a.where + ": actuator of joint '" + a.joint + "'";
    if (a.armature) {
      if (!std::isfinite(*a.armature) || *a.armature < 0) {
        throw ModelError(label + ": armature must be finite and ≥ 0");
      }
      if (j.armature != 0) throw ModelError(label + ": armature given twice");
      j.armature = *a.armature;
      m.has_armature = true;
    }
    if (a.has_rotor) {
      if (j.rotor.gear_ratio != 0) throw ModelError(label + ": rotor given twice");
      j.rotor = check_rotor(j, a, label);
      m.has_rotors = true;
    }
  }
  // the armature may have regularised M (docs/model.md, "Singular mass matrix")
  if (m.has_rotors) add_rotor_constants(m);
  m.singular_mass_matrix = mass_matrix_singularity(m);
}

}  // namespace rbdc
