// Centre of mass and centroidal momentum: Orin, Goswami & Lee 2013 (Eqs. 25-26) on paper 000's
// kinematics (Eqs. 13-18, B3), CRBA (Alg. 5) and quadratic-velocity pass (Alg. 2).
#include "rbdc/centroidal.hpp"

#include "argument_checks.hpp"
#include "rbdc/bias_terms.hpp"
#include "rbdc/crba.hpp"
#include "rbdc/kinematics.hpp"
#include "tree_helpers.hpp"

namespace rbdc {

using detail::origin_of;
using detail::rotation_of;

namespace {

/// The point masses of the tree: body i's (at its COM) and each rotor's (at its origin, carried by
/// λ(j)), as (mass, carrier body, point in carrier coordinates).
struct PointMass {
  double mass;
  size_t body;
  Vector3 point;
};

template <class Visit>
void for_each_point_mass(const Model& model, Visit&& visit) {
  for (int i = 0; i < model.nb; ++i) {
    const size_t ui = static_cast<size_t>(i);
    visit(PointMass{model.bodies[ui].mass, ui, model.bodies[ui].com});
    const Rotor& rotor = model.joints[ui].rotor;
    if (i > 0 && rotor.gear_ratio > 0) {
      visit(PointMass{rotor.mass, static_cast<size_t>(model.parent[ui]), rotor.translation});
    }
  }
}

/// X*_i^G = [1 -c̃; 0 1] (X_W^i)ᵀ: a wrench at body i's origin in its coordinates → at the CoM c,
/// world axes (Eqs. 7-8).
Matrix6 wrench_to_com(const Data& data, size_t i) {
  return force_transform(Matrix3::Identity(), data.com) * data.X_world[i].transpose();
}

/// c from the root's composite inertia I_c0 = [.. m c̃_0; .. m 1] (body-0 coordinates), moved to the
/// world; after mass_matrix.
Vector3 com_from_composite_inertia(const Data& data) {
  const Matrix6& I = data.Ic[0];
  const double m = I(5, 5);
  const Matrix3 mc = I.topRightCorner<3, 3>();
  const Vector3 c0(mc(2, 1) / m, mc(0, 2) / m, mc(1, 0) / m);
  return origin_of(data.X_world[0]) + rotation_of(data.X_world[0]).transpose() * c0;
}

}  // namespace

const Vector3& center_of_mass(const Model& model, Data& data, const VectorRef& q, const VectorRef& v) {
  detail::check_qv("center_of_mass", model, data, q, v);
  kinematics(model, data, q, v);
  world_transforms(model, data, q);
  double mass = 0;
  data.com.setZero();
  data.com_velocity.setZero();
  // c ← Σ m_k p_k / m, ċ ← Σ m_k R^W (v_O + ω × r_k) / m over the point masses k on bodies i
  for_each_point_mass(model, [&](const PointMass& p) {
    const Matrix3 world_R_body = rotation_of(data.X_world[p.body]).transpose();
    const Vector6& v_i = data.v[p.body];
    mass += p.mass;
    data.com += p.mass * (origin_of(data.X_world[p.body]) + world_R_body * p.point);
    data.com_velocity += p.mass * (world_R_body * (v_i.tail<3>() + v_i.head<3>().cross(p.point)));
  });
  data.com /= mass;
  data.com_velocity /= mass;
  return data.com;
}

const Matrix3X& center_of_mass_jacobian(const Model& model, Data& data, const VectorRef& q) {
  detail::check_q("center_of_mass_jacobian", model, data, q);
  world_transforms(model, data, q);
  double mass = 0;
  data.com_jacobian.setZero();
  // J_c ← Σ m_k R_i^W [-r̃_k 1] J_i / m                      (Eq. B3 at the point r_k)
  for_each_point_mass(model, [&](const PointMass& p) {
    if (p.mass == 0) return;
    detail::body_jacobian(model, data, static_cast<int>(p.body), data.J_foot);
    const Matrix3 world_R_body = rotation_of(data.X_world[p.body]).transpose();
    mass += p.mass;
    data.J_foot_at_point.noalias() = motion_transform(Matrix3::Identity(), p.point) * data.J_foot;
    data.com_jacobian.noalias() += p.mass * world_R_body * data.J_foot_at_point.bottomRows<3>();
  });
  data.com_jacobian /= mass;
  return data.com_jacobian;
}

const Matrix6X& centroidal_momentum_matrix(const Model& model, Data& data, const VectorRef& q) {
  detail::check_q("centroidal_momentum_matrix", model, data, q);
  mass_matrix(model, data, q);  // composite inertias I_ci (Eq. 26)
  world_transforms(model, data, q);
  data.com = com_from_composite_inertia(data);
  //   floating base: A_G[:, 0:6] ← X*_0^G I_c0
  if (model.floating_base) data.A_G.leftCols<6>().noalias() = wrench_to_com(data, 0) * data.Ic[0];
  for (int j = 1; j < model.nb; ++j) {
    const size_t uj = static_cast<size_t>(j);
    const int col = model.joints[uj].v_index;
    //   A_G[:, j] ← X*_j^G I_cj S_j                         (Orin et al. 2013, Eq. 25)
    Vector6 F = data.Ic[uj] * model.motion_subspace[uj];
    data.A_G.col(col).noalias() = wrench_to_com(data, uj) * F;
    //   rotor j spins at gr q̇_j on λ(j): A_G[:, j] += X*_λ(j)^G X_rotᵀ I_rot S_rot
    if (model.has_rotors) {
      F = model.X_rotor[uj].transpose() * (model.rotor_inertia[uj] * model.rotor_subspace[uj]);
      data.A_G.col(col).noalias() += wrench_to_com(data, static_cast<size_t>(model.parent[uj])) * F;
    }
  }
  return data.A_G;
}

const Vector6& centroidal_bias(const Model& model, Data& data, const VectorRef& q, const VectorRef& v) {
  detail::check_qv("centroidal_bias", model, data, q, v);
  center_of_mass(model, data, q, v);
  //   f_0 ← Σ_i X*_i^0 f_i with f_i at a = 0               (Alg. 2's inward pass)
  quadratic_velocity_terms(model, data, q, v);
  //   Ȧ_G v ← X*_0^G f_0                                   (Orin et al. 2013, Eq. 26)
  data.centroidal_bias.noalias() = wrench_to_com(data, 0) * data.f_body[0];
  return data.centroidal_bias;
}

}  // namespace rbdc
