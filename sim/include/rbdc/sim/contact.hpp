// Compliant foot-ground contact of paper 000 Section 5: sphere-plane detection (Eq. 31), contact
// frame (Eqs. 32-33), Hertz normal force with a smoothstep damping ramp (Eqs. 34-36) and smooth
// stick-slip Coulomb friction (Eq. 38).
#pragma once

#include <vector>

#include "rbdc/data.hpp"
#include "rbdc/spatial.hpp"

namespace rbdc::sim {

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

/// Contact force on a foot sphere centred at p_W moving with velocity v_W (world frame).
/// Friction is isotropic: it opposes the tangential slip velocity with magnitude μ(|v_t|) f_n, so
/// it never exceeds μ f_n (applying Eq. 38 per axis would allow √2 μ f_n).
FootContact foot_contact(const ContactParameters& p, const GroundPlane& ground, const Vector3& p_W,
                         const Vector3& v_W);

}  // namespace rbdc::sim
