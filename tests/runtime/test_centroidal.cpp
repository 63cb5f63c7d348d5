// Centre of mass, centroidal momentum and M⁻¹ (rbdc/centroidal.hpp, rbdc/crba.hpp) against
// independent routes: the CoM and the momentum summed body by body from homogeneous transforms,
// finite differences of the CoM and of A_G v along the motion at a = 0, and M · M⁻¹ = 1. On the test
// robots and on the same robots with a geared rotor on every joint.
#include <gtest/gtest.h>

#include "rbdc/centroidal.hpp"
#include "rbdc/crba.hpp"
#include "rbdc/kinematics.hpp"
#include "rotor_robots.hpp"

namespace rbdc {
namespace {

std::vector<Model> robots() {
  std::vector<Model> all = test::all_robots();
  for (const Model& m : test::rotor_robots()) all.push_back(m);
  return all;
}

/// X_W^i from the homogeneous transforms of the test (not the runtime's recursion).
Matrix6 world_to_body(const test::Pose& pose) { return motion_transform(pose.linear().transpose(), pose.translation()); }

/// h_G = Σ X*_i^G I_i v_i over the bodies and the rotors (v_rot = X_rot v_λ + S_rot q̇), with
/// X*_i^G = [1 -c̃; 0 1] (X_W^i)ᵀ; v_i from the runtime's kinematics (Eq. 13).
Vector6 momentum_body_by_body(const Model& model, Data& data, const VectorX& q, const VectorX& v,
                              const Vector3& com) {
  kinematics(model, data, q, v);
  const std::vector<test::Pose> pose = test::body_poses(model, q);
  const Matrix6 to_com = force_transform(Matrix3::Identity(), com);
  Vector6 h = Vector6::Zero();
  for (int i = 0; i < model.nb; ++i) {
    const size_t ui = static_cast<size_t>(i);
    h += to_com * world_to_body(pose[ui]).transpose() * model.inertia[ui] * data.v[ui];
    if (i > 0 && model.has_rotors) {
      const size_t carrier = static_cast<size_t>(model.parent[ui]);
      const Vector6 v_rot = model.X_rotor[ui] * data.v[carrier] +
                            model.rotor_subspace[ui] * v[model.joints[ui].v_index];
      h += to_com * world_to_body(pose[carrier]).transpose() * model.X_rotor[ui].transpose() *
           model.rotor_inertia[ui] * v_rot;
    }
  }
  return h;
}

Vector3 com_body_by_body(const Model& model, const VectorX& q) {
  const std::vector<test::Pose> pose = test::body_poses(model, q);
  double mass = 0;
  Vector3 sum = Vector3::Zero();
  for (int i = 0; i < model.nb; ++i) {
    const size_t ui = static_cast<size_t>(i);
    mass += model.bodies[ui].mass;
    sum += model.bodies[ui].mass * (pose[ui] * model.bodies[ui].com);
    const Rotor& rotor = model.joints[ui].rotor;
    if (i > 0 && rotor.gear_ratio > 0) {
      mass += rotor.mass;
      sum += rotor.mass * (pose[static_cast<size_t>(model.parent[ui])] * rotor.translation);
    }
  }
  return sum / mass;
}

class Centroidal : public ::testing::TestWithParam<int> {
 protected:
  Model model = robots()[static_cast<size_t>(GetParam())];
  Data data{model};
  test::RandomState random{23u + static_cast<unsigned>(GetParam())};
};

TEST_P(Centroidal, CenterOfMassAndMomentumMatchTheSumsOverBodies) {
  for (int trial = 0; trial < 10; ++trial) {
    const VectorX q = random.configuration(model);
    const VectorX v = random.vector(model.nv, 2.0);
    const Vector3 com = center_of_mass(model, data, q, v);
    const Vector3 com_velocity = data.com_velocity;
    EXPECT_LE((com - com_body_by_body(model, q)).norm(), 1e-13);
    const Matrix6X A_G = centroidal_momentum_matrix(model, data, q);
    EXPECT_LE((data.com - com).norm(), 1e-13);  // A_G's own CoM, from I_c0
    const Vector6 h = momentum_body_by_body(model, data, q, v, com);
    EXPECT_LE((A_G * v - h).norm(), 1e-12 * (1 + h.norm()));
    // linear momentum = m ċ, and J_c v = ċ
    const Matrix3X J_c = center_of_mass_jacobian(model, data, q);
    EXPECT_LE((J_c * v - com_velocity).norm(), 1e-12 * (1 + com_velocity.norm()));
    EXPECT_LE((h.tail<3>() / data.Ic[0](5, 5) - com_velocity).norm(), 1e-12 * (1 + com_velocity.norm()));
  }
}

TEST_P(Centroidal, CenterOfMassJacobianMatchesFiniteDifferences) {
  const double h = 1e-6;
  const VectorX q = random.configuration(model);
  const Matrix3X J_c = center_of_mass_jacobian(model, data, q);
  const VectorX zero = VectorX::Zero(model.nv);
  for (int c = 0; c < model.nv; ++c) {
    const VectorX step = h * VectorX::Unit(model.nv, c);
    const Vector3 plus = center_of_mass(model, data, test::integrate(model, q, step), zero);
    const Vector3 minus = center_of_mass(model, data, test::integrate(model, q, -step), zero);
    EXPECT_LE((J_c.col(c) - (plus - minus) / (2 * h)).norm(), 1e-8) << "column " << c;
  }
}

TEST_P(Centroidal, BiasIsTheDerivativeOfTheMomentumAtZeroAcceleration) {
  const double h = 1e-6;
  for (int trial = 0; trial < 10; ++trial) {
    const VectorX q = random.configuration(model);
    const VectorX v = random.vector(model.nv, 2.0);
    const Vector6 bias = centroidal_bias(model, data, q, v);
    // d/dt (A_G v) along a constant twist = Ȧ_G v + A_G a, a the twist's classical acceleration
    VectorX a_twist = VectorX::Zero(model.nv);
    if (model.floating_base) a_twist.segment<3>(3) = v.head<3>().cross(v.segment<3>(3));
    const Vector6 A_a = centroidal_momentum_matrix(model, data, q) * a_twist;
    const Vector6 plus = centroidal_momentum_matrix(model, data, test::integrate(model, q, h * v)) * v;
    const Vector6 minus = centroidal_momentum_matrix(model, data, test::integrate(model, q, -h * v)) * v;
    const Vector6 fd = (plus - minus) / (2 * h) - A_a;
    EXPECT_LE((bias - fd).norm(), 1e-7 * (1 + fd.norm()));
  }
}

TEST_P(Centroidal, MassMatrixTimesItsInverseIsTheIdentity) {
  for (int trial = 0; trial < 10; ++trial) {
    const VectorX q = random.configuration(model);
    const MatrixX M_inverse = mass_matrix_inverse(model, data, q);
    const MatrixX M = mass_matrix(model, data, q);
    EXPECT_LE((M * M_inverse - MatrixX::Identity(model.nv, model.nv)).norm(), 1e-9);
    EXPECT_LE((M_inverse - M_inverse.transpose()).norm(), 1e-9 * M_inverse.norm());
  }
}

INSTANTIATE_TEST_SUITE_P(Robots, Centroidal, ::testing::Range(0, 8));

}  // namespace
}  // namespace rbdc
