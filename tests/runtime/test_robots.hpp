// Test robots and random states shared by the runtime algorithm tests (all_robots() order):
//  0 mini_cheetah(): the product's robots/mini_cheetah.urdf through the URDF loader;
//  1 arm7(): a fixed-base 7-DoF arm with oblique and negative axes and rotated joint origins;
//  2 branched(): a floating-base tree built from PRED/SUCC arrays with oblique axes, rotated
//    origins, rotated inertial frames, a prismatic joint and three feet;
//  3 branched_urdf(): tests/data/branched_robot.urdf, the same ingredients plus fixed joints that
//    the loader merges (inertia lumping), and a foot on a merged link.
// quadruped() builds a Mini-Cheetah-like model from arrays (paper 000 Eq. 1) without the loader.
#pragma once

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "rbdc/model_builder.hpp"
#include "rbdc/urdf_loader.hpp"

namespace rbdc::test {

inline Matrix3 rpy(double r, double p, double y) {  // URDF rpy → rotation (child axes in parent)
  return (Eigen::AngleAxisd(y, Vector3::UnitZ()) * Eigen::AngleAxisd(p, Vector3::UnitY()) *
          Eigen::AngleAxisd(r, Vector3::UnitX()))
      .toRotationMatrix();
}

inline Body body(const std::string& name, double mass, const Vector3& com, const Matrix3& inertia) {
  Body b;
  b.name = name;
  b.mass = mass;
  b.com = com;
  b.inertia_com = inertia;
  return b;
}

inline JointSpec joint(const std::string& name, JointType type, const Vector3& axis,
                       const Vector3& origin, const Matrix3& origin_rotation = Matrix3::Identity()) {
  JointSpec j;
  j.name = name;
  j.type = type;
  j.axis = axis.normalized();
  j.translation = origin;
  j.rotation = origin_rotation.transpose();  // E_T = Rᵀ of the URDF rpy
  return j;
}

/// Rotational inertia with products of inertia: R diag(d) Rᵀ.
inline Matrix3 rotated_inertia(const Vector3& principal, const Matrix3& R) {
  return R * principal.asDiagonal() * R.transpose();
}

inline Model quadruped() {
  ModelSpec s;
  s.name = "quadruped";
  s.floating_base = true;
  s.bodies.push_back(body("trunk", 3.3, Vector3::Zero(),
                          Vector3(0.011253, 0.036203, 0.042673).asDiagonal()));
  const char* legs[] = {"LF", "RF", "LH", "RH"};
  const double x_sign[] = {1, 1, -1, -1};
  const double y_sign[] = {1, -1, 1, -1};
  Matrix3 abad_inertia, hip_inertia;
  abad_inertia << 381, 58, 0.45, 58, 560, 0.95, 0.45, 0.95, 444;
  hip_inertia << 1983, 245, 13, 245, 2103, 1.5, 13, 1.5, 408;
  for (int leg = 0; leg < 4; ++leg) {
    const double sy = y_sign[leg];
    const Matrix3 mirror = Vector3(1, sy, 1).asDiagonal();  // flips y for right legs
    const int first = 3 * leg + 1;
    const std::string p = legs[leg];
    s.pred.insert(s.pred.end(), {0, first, first + 1});
    s.succ.insert(s.succ.end(), {first, first + 1, first + 2});
    s.joints.push_back(joint(p + "_abad", JointType::Revolute, Vector3::UnitX(),
                             Vector3(0.19 * x_sign[leg], 0.049 * sy, 0)));
    s.joints.push_back(joint(p + "_hip", JointType::Revolute, -Vector3::UnitY(),
                             Vector3(0, 0.062 * sy, 0), rpy(0, 0, M_PI)));
    s.joints.push_back(joint(p + "_knee", JointType::Revolute, -Vector3::UnitY(),
                             Vector3(0, 0, -0.209)));
    s.bodies.push_back(body(p + "_abad_link", 0.54, Vector3(0, 0.036 * sy, 0),
                            mirror * abad_inertia * 1e-6 * mirror));
    s.bodies.push_back(body(p + "_thigh", 0.634, Vector3(0, 0.016 * sy, -0.02),
                            mirror * hip_inertia * 1e-6 * mirror));
    s.bodies.push_back(body(p + "_shank", 0.064, Vector3(0, 0, -0.061),
                            Vector3(245e-6, 248e-6, 6e-6).asDiagonal()));
    s.feet.push_back(Foot{p + "_foot", first + 2, Vector3(0, 0.004 * sy, -0.195)});
  }
  return build_model(s);
}

inline Model arm7() {
  ModelSpec s;
  s.name = "arm7";
  s.floating_base = false;
  s.bodies.push_back(body("base", 4.0, Vector3(0, 0, 0.05), Vector3(0.02, 0.02, 0.015).asDiagonal()));
  const Vector3 axes[] = {Vector3(0, 0, 1), Vector3(0, 1, 0.2), Vector3(0.1, -0.3, 1),
                          Vector3(0, -1, 0), Vector3(1, 1, 1), Vector3(0, 1, 0),
                          Vector3(-0.2, 0.1, -1)};
  for (int i = 1; i <= 7; ++i) {
    s.pred.push_back(i - 1);
    s.succ.push_back(i);
    s.joints.push_back(joint("j" + std::to_string(i), JointType::Revolute, axes[i - 1],
                             Vector3(0.01 * i, -0.02, 0.15 + 0.01 * i),
                             rpy(0.1 * i, -0.05 * i, 0.2 * (i % 3))));
    s.bodies.push_back(body("link" + std::to_string(i), 3.0 - 0.3 * i,
                            Vector3(0.01, 0.02 * (i % 2), 0.07),
                            rotated_inertia(Vector3(0.02, 0.018, 0.008) / i, rpy(0.3 * i, 0.2, -0.1 * i))));
  }
  s.feet.push_back(Foot{"tool", 7, Vector3(0.02, 0.01, 0.1)});
  return build_model(s);
}

inline Model branched() {
  ModelSpec s;
  s.name = "branched";
  s.floating_base = true;
  s.bodies.push_back(body("base", 2.0, Vector3(0.02, -0.01, 0.03),
                          rotated_inertia(Vector3(0.02, 0.03, 0.025), rpy(0.2, 0.4, -0.3))));
  // branch A: 1 → 2 → 3 (prismatic) ; branch B: 4 → 5 ; branch C on body 1: 6
  s.pred = {0, 1, 2, 0, 4, 1};
  s.succ = {1, 2, 3, 4, 5, 6};
  s.joints.push_back(joint("a1", JointType::Revolute, Vector3(0.3, -0.5, 0.8), Vector3(0.2, 0.1, 0),
                           rpy(0.3, -0.2, 0.5)));
  s.joints.push_back(joint("a2", JointType::Revolute, Vector3(-1, 0.2, 0.1), Vector3(0, 0.05, -0.2),
                           rpy(-0.4, 0.1, 0.2)));
  s.joints.push_back(joint("a3", JointType::Prismatic, Vector3(0.1, 0.2, -1), Vector3(0.02, 0, -0.15),
                           rpy(0, 0.3, 0)));
  s.joints.push_back(joint("b1", JointType::Revolute, Vector3(0, 0, -1), Vector3(-0.2, -0.1, 0.05),
                           rpy(0.1, 0.2, 0.3)));
  s.joints.push_back(joint("b2", JointType::Revolute, Vector3(0.5, 0.5, 0.1), Vector3(0.01, -0.03, -0.18)));
  s.joints.push_back(joint("c1", JointType::Revolute, Vector3(0, 1, 0), Vector3(0.05, 0.08, 0.02),
                           rpy(1.0, 0, -0.7)));
  const double masses[] = {0.7, 0.5, 0.2, 0.9, 0.3, 0.4};
  for (int i = 1; i <= 6; ++i) {
    s.bodies.push_back(body("link" + std::to_string(i), masses[i - 1],
                            Vector3(0.01 * i, -0.02, -0.05 + 0.01 * i),
                            rotated_inertia(Vector3(3e-3, 2e-3, 1e-3) * masses[i - 1],
                                            rpy(0.5 * i, -0.3 * i, 0.2))));
  }
  s.feet.push_back(Foot{"footA", 3, Vector3(0.01, 0.02, -0.1)});
  s.feet.push_back(Foot{"footB", 5, Vector3(0, -0.01, -0.12)});
  s.feet.push_back(Foot{"footC", 6, Vector3(0.03, 0.05, 0.0)});
  return build_model(s);
}

inline Model mini_cheetah() {
  std::vector<std::string> warnings;  // the MIT thigh inertia breaks the triangle inequality
  return load_urdf(RBDC_SOURCE_DIR "/robots/mini_cheetah.urdf", UrdfOptions{}, &warnings);
}

inline Model branched_urdf() {
  UrdfOptions options;
  options.feet = {{"footA", "a_foot", Vector3(0.01, 0, -0.02)},
                  {"footB", "b_foot", Vector3(0.02, -0.01, -0.05)},
                  {"footC", "c_arm", Vector3(0.1, 0.02, 0)}};
  return load_urdf(RBDC_SOURCE_DIR "/tests/data/branched_robot.urdf", options);
}

/// Robots that every identity test runs on (see the list at the top).
inline std::vector<Model> all_robots() { return {mini_cheetah(), arm7(), branched(), branched_urdf()}; }

using Pose = Eigen::Isometry3d;

/// World pose of every body by the product of homogeneous transforms (child frame → world).
inline std::vector<Pose> body_poses(const Model& model, const VectorX& q) {
  std::vector<Pose> pose(static_cast<size_t>(model.nb), Pose::Identity());
  if (model.floating_base) {
    pose[0].translation() = q.head<3>();
    pose[0].linear() = Eigen::Quaterniond(q[3], q[4], q[5], q[6]).normalized().toRotationMatrix();
  }
  for (int i = 1; i < model.nb; ++i) {
    const Joint& j = model.joints[static_cast<size_t>(i)];
    Pose placement = Pose::Identity();  // joint frame in the parent frame
    placement.linear() = j.rotation.transpose();
    placement.translation() = j.translation;
    Pose motion = Pose::Identity();
    if (j.type == JointType::Prismatic) {
      motion.translation() = q[j.q_index] * j.axis;
    } else {
      motion.linear() = Eigen::AngleAxisd(q[j.q_index], j.axis).toRotationMatrix();
    }
    pose[static_cast<size_t>(i)] = pose[static_cast<size_t>(model.parent[static_cast<size_t>(i)])] * placement * motion;
  }
  return pose;
}

struct RandomState {
  explicit RandomState(unsigned seed) : rng(seed) {}
  std::mt19937 rng;
  std::uniform_real_distribution<double> unit{-1.0, 1.0};

  VectorX configuration(const Model& model) {
    VectorX q(model.nq);
    for (Eigen::Index k = 0; k < q.size(); ++k) q[k] = 1.5 * unit(rng);
    if (model.floating_base) {
      q.head<3>() *= 0.5;
      q.segment<4>(3).normalize();
    }
    return q;
  }
  VectorX vector(Eigen::Index n, double scale = 1.0) {
    VectorX x(n);
    for (Eigen::Index k = 0; k < n; ++k) x[k] = scale * unit(rng);
    return x;
  }
  Matrix3X forces(const Model& model, double scale = 20.0) {
    Matrix3X f(3, static_cast<Eigen::Index>(model.feet.size()));
    for (Eigen::Index k = 0; k < f.size(); ++k) f.data()[k] = scale * unit(rng);
    return f;
  }
};

/// Configuration reached by moving along the tangent direction dv (nv) for unit time, to first
/// order exactly: joints add, a floating base moves by the body twist dv[0:6]
/// (R ← R exp(ω̃), p ← p + R v). Used for finite differences.
inline VectorX integrate(const Model& model, const VectorX& q, const VectorX& dv) {
  VectorX out = q;
  const int offset_q = model.floating_base ? 7 : 0;
  const int offset_v = model.root_dofs();
  out.tail(model.nq - offset_q) += dv.tail(model.nv - offset_v);
  if (model.floating_base) {
    const Eigen::Quaterniond quat(q[3], q[4], q[5], q[6]);
    const Vector3 w = dv.head<3>();
    const Eigen::Quaterniond step(Eigen::AngleAxisd(w.norm(), w.norm() > 0 ? Vector3(w.normalized()) : Vector3::UnitX()));
    const Eigen::Quaterniond next = (quat * step).normalized();
    out.head<3>() = q.head<3>() + quat.toRotationMatrix() * dv.segment<3>(3);
    out.segment<4>(3) << next.w(), next.x(), next.y(), next.z();
  }
  return out;
}

}  // namespace rbdc::test
