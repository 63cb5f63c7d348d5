#include "rbdc/sim/contact.hpp"

#include <cmath>
#include <stdexcept>

#include "rbdc/sim/smoothstep.hpp"

namespace rbdc::sim {

GroundPlane::GroundPlane(const Vector3& point, const Vector3& normal) : point_(point) {
  if (!(normal.norm() > 0)) throw std::invalid_argument("GroundPlane: the normal must be non-zero");
  const Vector3 z = normal.normalized();
  // x: the world x axis projected onto the plane (world y when the normal is along x).
  const Vector3 seed = std::abs(z.x()) < 0.9 ? Vector3::UnitX() : Vector3::UnitY();
  const Vector3 x = (seed - seed.dot(z) * z).normalized();
  W_R_C_.col(0) = x;
  W_R_C_.col(1) = z.cross(x);
  W_R_C_.col(2) = z;
}

GroundPlane GroundPlane::tilted_about_x(double angle) {
  return GroundPlane(Vector3::Zero(), Vector3(0, -std::sin(angle), std::cos(angle)));
}

double friction_coefficient(const ContactParameters& p, double v) {
  const double speed = std::abs(v);
  double mu;
  if (speed <= p.v_static)  // −μ_s → μ_s through v = 0
    mu = p.mu_static * (2 * smoothstep(-p.v_static, p.v_static, speed) - 1);
  else  // static → sliding
    mu = p.mu_static + (p.mu_dynamic - p.mu_static) * smoothstep(p.v_static, p.v_dynamic, speed);
  return v < 0 ? -mu : mu;
}

FootContact foot_contact(const ContactParameters& p, const GroundPlane& ground, const Vector3& p_W,
                         const Vector3& v_W) {
  FootContact c;
  const Vector3 n = ground.normal();
  // Eq. 31: d_f = ẑ_Cᵀ r_{P,f}, δ = d_c = d_f − r.
  c.penetration = n.dot(p_W - ground.point()) - p.foot_radius;
  if (c.penetration > 0) return c;
  // Eq. 36: δ̇ = ẑ_Cᵀ v_f (= ẑ_Cᵀ v_C: the rolling term ω × (−r ẑ_C) has no normal part).
  const double penetration_rate = n.dot(v_W);
  // Eq. 34: Hertz spring, pushing out of the ground: f_s = K |δ|^e (δ in `length_unit`).
  const double f_spring = p.stiffness * std::pow(-c.penetration / p.length_unit, p.exponent);
  // Eq. 35: f_d = −c δ̇ with c ramping 0 → c_max over δ ∈ [−w, 0].
  const double c_eff = p.damping * smoothstep(0, p.ramp_distance, -c.penetration);
  const double f_normal = f_spring - c_eff * penetration_rate;
  if (f_normal <= 0) return c;  // the ground pushes, never pulls
  // Eq. 38 on the slip velocity v_C (contact-frame x, y).
  const Vector3 v_C = ground.W_R_C().transpose() * v_W;
  Vector3 force_C(0, 0, f_normal);
  if (p.friction == FrictionModel::PerAxis) {
    force_C.x() = -friction_coefficient(p, v_C.x()) * f_normal;
    force_C.y() = -friction_coefficient(p, v_C.y()) * f_normal;
  } else if (const double slip = std::hypot(v_C.x(), v_C.y()); slip > 0) {
    const double scale = -friction_coefficient(p, slip) * f_normal / slip;
    force_C.x() = scale * v_C.x();
    force_C.y() = scale * v_C.y();
  }
  c.active = true;
  c.force_C = force_C;
  c.force_W = ground.W_R_C() * force_C;
  return c;
}

namespace {

// dμ/dv of friction_coefficient (even in v): the smoothstep's slope 6 s (1 − s) on each piece.
double friction_slope(const ContactParameters& p, double v) {
  const double speed = std::abs(v);
  if (speed <= p.v_static) {
    const double s = (speed + p.v_static) / (2 * p.v_static);
    return 6 * p.mu_static * s * (1 - s) / p.v_static;
  }
  if (speed >= p.v_dynamic) return 0;
  const double s = (speed - p.v_static) / (p.v_dynamic - p.v_static);
  return 6 * (p.mu_dynamic - p.mu_static) * s * (1 - s) / (p.v_dynamic - p.v_static);
}

}  // namespace

double implicit_friction(const ContactParameters& p, double u_free, double compliance, double f_normal,
                         double guess) {
  if (u_free == 0 || f_normal <= 0) return 0;
  // g(u) = u − u_free + k μ(u), k = compliance f_n: g(0) = −u_free and g(u_free) has the sign of
  // u_free, so [0, u_free] brackets a root (μ need not be monotone when μ_d < μ_s). Newton's steps,
  // bisecting whenever one leaves the bracket.
  const double k = compliance * f_normal;
  const double sign = u_free > 0 ? 1 : -1;
  double lo = 0, hi = std::abs(u_free);  // in |u|: g(lo) < 0 < g(hi)
  // Start from the slip the guessed force gives, if it is inside the bracket.
  double u = u_free + compliance * guess;
  if (!(sign * u > lo && sign * u < hi)) u = 0;
  for (int i = 0; i < 100; ++i) {
    const double mu = friction_coefficient(p, u);
    const double g = sign * (u - u_free + k * mu);  // increasing through the root
    if (g < 0) lo = sign * u; else hi = sign * u;
    if (std::abs(g) < 1e-9 * p.v_static || hi - lo < 1e-12 * p.v_static) return -mu * f_normal;
    const double slope = 1 + k * friction_slope(p, u);
    double next = sign * (u - sign * g / slope);
    if (!(slope > 0) || next <= lo || next >= hi) next = 0.5 * (lo + hi);
    u = sign * next;
  }
  return -friction_coefficient(p, u) * f_normal;
}

void world_forces(const std::vector<FootContact>& contacts, Matrix3X& f) {
  f.resize(3, static_cast<Eigen::Index>(contacts.size()));
  for (std::size_t k = 0; k < contacts.size(); ++k) f.col(static_cast<Eigen::Index>(k)) = contacts[k].force_W;
}

}  // namespace rbdc::sim
