// Compliant foot-ground contact of paper 000 Section 5: sphere-plane detection (Eq. 31), contact
// frame (Eqs. 32-33), Hertz normal force with a smoothstep damping ramp (Eqs. 34-36) and smooth
// stick-slip Coulomb friction (Eq. 38).
#pragma once

#include <vector>

#include "rbdc/data.hpp"
#include "rbdc/spatial.hpp"

namespace rbdc::sim {

/// Eq. 38 as printed: μ(v) applied to each tangential axis of the contact frame (default, the
/// paper's model; the friction may reach √2 μ f_n on a diagonal slip), or isotropic: μ(|v_t|) along
/// −v_t/|v_t|, bounded by μ f_n (an elliptic cone, closer to MuJoCo's).
enum class FrictionModel { PerAxis, Isotropic };
/// How the friction's stiff slope near v = 0 is stepped: explicitly (rings when dt exceeds about
/// 2 m_foot v_s / (1.5 μ_s f_n)) or linearly implicitly with the contact-space inverse inertia
/// (contact_solver.hpp), stable at Table I's v_s and dt.
enum class FrictionUpdate { Explicit, Implicit };

/// Paper 000 Table I, in the units we decided for it (docs/simulator.md): the Hertz law takes the
/// penetration in `length_unit` metres, so K = 1e4 means 1e4 N/mm^2.2 and a standing Mini Cheetah
/// sinks about 0.06 mm per foot. With length_unit = 1 (plain SI) it would sink about 6 cm.
struct ContactParameters {
  double stiffness = 1.0e4;        ///< K, N / length_unit^e (Eq. 34)
  double exponent = 2.2;           ///< e (Eq. 34)
  double length_unit = 1e-3;       ///< m; unit of δ inside the Hertz law
  double damping = 10.0;           ///< c_max, N/(m/s) (Eq. 35)
  double ramp_distance = 0.1e-3;   ///< w, m: damping ramps 0 → c_max over δ ∈ [−w, 0]
  double mu_static = 2.0;          ///< μ_s
  double v_static = 0.1e-3;        ///< v_s, m/s: |μ| reaches μ_s here
  double mu_dynamic = 2.0;         ///< μ_d
  double v_dynamic = 0.2e-3;       ///< v_d, m/s: |μ| is μ_d from here on
  double foot_radius = 0.02;       ///< r, m: sphere centred at the foot point (Eq. 31)
  FrictionModel friction = FrictionModel::PerAxis;
  FrictionUpdate friction_update = FrictionUpdate::Implicit;
  /// Force at the contact point C_k = p_f − r ẑ_C with its moment, friction from v_Ck (Eqs. 32-33,
  /// 38); false: force at the sphere centre (the foot point) and its velocity, so feet cannot roll.
  bool at_contact_point = true;
};

/// A plane through `point` with unit normal `normal` (world frame). Its contact frame {C}
/// (Eq. 33, R_C^W) has z along the normal and x, y spanning the plane.
class GroundPlane {
 public:
  GroundPlane() : GroundPlane(Vector3::Zero(), Vector3::UnitZ()) {}
  GroundPlane(const Vector3& point, const Vector3& normal);
  /// A plane through the origin tilted by `angle` (rad) about the world x axis.
  static GroundPlane tilted_about_x(double angle);

  const Vector3& point() const { return point_; }
  Vector3 normal() const { return W_R_C_.col(2); }
  const Matrix3& W_R_C() const { return W_R_C_; }  ///< contact-frame axes in world coordinates

 private:
  Vector3 point_;
  Matrix3 W_R_C_;
};

struct FootContact {
  bool active = false;        ///< δ ≤ 0 and a positive normal force
  double penetration = 0;     ///< δ = d_c (Eq. 31), m; negative inside the ground
  Vector3 force_C = Vector3::Zero();  ///< (f_x, f_y, f_n) in the contact frame
  Vector3 force_W = Vector3::Zero();  ///< the same force in world coordinates, applied at the foot
};

/// The world forces of `contacts` as the columns of `f` (3 × n_feet), what a controller measures.
void world_forces(const std::vector<FootContact>& contacts, Matrix3X& f);

/// Effective friction coefficient μ(v) of Eq. 38 for a slip speed v ≥ 0 (also valid for v < 0, odd):
/// smoothstep from −μ_s to μ_s over v ∈ [−v_s, v_s], then from μ_s to μ_d over |v| ∈ [v_s, v_d].
double friction_coefficient(const ContactParameters& p, double slip_speed);

/// Contact force on a foot sphere centred at p_W whose contact point moves with velocity v_W
/// (world frame; with p.at_contact_point the caller passes v_Ck, else the centre's velocity).
/// Friction follows p.friction with the explicit law f_t = −μ(v) f_n.
FootContact foot_contact(const ContactParameters& p, const GroundPlane& ground, const Vector3& p_W,
                         const Vector3& v_W);

/// Friction of one tangential axis stepped implicitly: the f solving f = −μ(u) f_n with
/// u = u_free + compliance · f, where u_free is the slip velocity the step would reach without this
/// friction and compliance = dt (J M⁻¹ Jᵀ)_ii > 0. The root lies between 0 and u_free. Newton's
/// iteration starts from the slip of the force `guess` (e.g. the previous sweep's) when that lies
/// inside.
double implicit_friction(const ContactParameters& p, double u_free, double compliance, double f_normal,
                         double guess = 0);

}  // namespace rbdc::sim
