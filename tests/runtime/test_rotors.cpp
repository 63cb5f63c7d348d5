// Geared rotors and armature (docs/model.md "Actuators", docs/runtime.md "Rotors and armature"):
// the identities of the dynamics with rotors, the reduction of a thin massless rotor to armature,
// a gyroscopic torque by hand, and the refusal of bad actuator input.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "model_test_support.hpp"
#include "rbdc/actuator_mode.hpp"
#include "rbdc/bias_terms.hpp"
#include "rbdc/crba.hpp"
#include "rbdc/forward_dynamics.hpp"
#include "rbdc/inverse_dynamics.hpp"
#include "rbdc/kinematics.hpp"
#include "rbdc/topology_file.hpp"
#include "rotor_robots.hpp"
#include "test_robots.hpp"

namespace rbdc::test {
namespace {

// ½ vᵀ M v computed body by body: links, rotors (v_rot = X_rot v_λ + S_rot q̇) and armature.
double kinetic_energy(const Model& m, Data& d, const VectorX& q, const VectorX& v) {
  kinematics(m, d, q, v);
  double T = 0;
  for (int i = 0; i < m.nb; ++i) {
    const size_t ui = static_cast<size_t>(i);
    T += 0.5 * d.v[ui].dot(m.inertia[ui] * d.v[ui]);
    if (i == 0) continue;
    const double qd = v[m.joints[ui].v_index];
    T += 0.5 * m.joints[ui].armature * qd * qd;
    if (!m.has_rotors) continue;
    const Vector6 vr = m.X_rotor[ui] * d.v[static_cast<size_t>(m.parent[ui])] + m.rotor_subspace[ui] * qd;
    T += 0.5 * vr.dot(m.rotor_inertia[ui] * vr);
  }
  return T;
}

TEST(Rotors, MassMatrixSymmetricPositiveDefinite) {
  RandomState rs(3);
  for (const Model& m : rotor_robots()) {
    ASSERT_TRUE(m.has_rotors);
    Data d(m), plain_data(m);
    const VectorX q = rs.configuration(m);
    const MatrixX M = mass_matrix(m, d, q);
    EXPECT_LT((M - M.transpose()).cwiseAbs().maxCoeff(), 1e-12) << m.name;
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<MatrixX>(M).eigenvalues().minCoeff(), 0) << m.name;
  }
}

TEST(Rotors, InverseDynamicsEqualsMassMatrixTimesAccelerationPlusBias) {
  RandomState rs(5);
  for (const Model& m : rotor_robots()) {
    Data d(m);
    const VectorX q = rs.configuration(m), v = rs.vector(m.nv), a = rs.vector(m.nv);
    const VectorX M_a = mass_matrix(m, d, q) * a;
    const VectorX c = quadratic_velocity_terms(m, d, q, v);
    const VectorX g = gravity_terms(m, d, q);
    const VectorX tau = inverse_dynamics(m, d, q, v, a);
    EXPECT_LT((tau - (M_a + c + g)).cwiseAbs().maxCoeff(), 1e-10) << m.name;
    // and the rotors do change every term (the test would pass vacuously otherwise)
    Data plain_data(m);
    Model plain = m;
    plain.has_rotors = false;
    EXPECT_GT((inverse_dynamics(plain, plain_data, q, v, a) - tau).norm(), 1e-4) << m.name;
  }
}

TEST(Rotors, MassMatrixColumnsAreInverseDynamicsOfUnitAccelerations) {
  RandomState rs(7);
  for (const Model& m : rotor_robots()) {
    Data d(m);
    const VectorX q = rs.configuration(m), zero = VectorX::Zero(m.nv);
    const MatrixX M = mass_matrix(m, d, q);
    const VectorX g = inverse_dynamics(m, d, q, zero, zero);
    for (Eigen::Index k = 0; k < m.nv; ++k) {
      const VectorX column = inverse_dynamics(m, d, q, zero, VectorX::Unit(m.nv, k)) - g;
      EXPECT_LT((column - M.col(k)).cwiseAbs().maxCoeff(), 1e-12) << m.name << " column " << k;
    }
  }
}

TEST(Rotors, ForwardDynamicsUndoesInverseDynamics) {
  RandomState rs(11);
  for (const Model& m : rotor_robots()) {
    Data d(m);
    const VectorX q = rs.configuration(m), v = rs.vector(m.nv);
    const VectorX tau = rs.vector(m.num_joints(), 5.0);
    const VectorX a = forward_dynamics(m, d, q, v, tau, Matrix3X::Zero(3, static_cast<Eigen::Index>(m.feet.size())));
    const VectorX back = inverse_dynamics(m, d, q, v, a);
    if (m.floating_base) {
      EXPECT_LT(back.head<6>().cwiseAbs().maxCoeff(), 1e-9) << m.name;
    }
    EXPECT_LT((back.tail(m.num_joints()) - tau).cwiseAbs().maxCoeff(), 1e-9) << m.name;
  }
}

TEST(Rotors, KineticEnergyBodyByBodyEqualsHalfVMv) {
  RandomState rs(13);
  for (const Model& m : rotor_robots()) {
    Data d(m);
    const VectorX q = rs.configuration(m), v = rs.vector(m.nv);
    const double from_M = 0.5 * v.dot(mass_matrix(m, d, q) * v);
    EXPECT_NEAR(kinetic_energy(m, d, q, v), from_M, 1e-12 * (1 + from_M)) << m.name;
  }
}

// A rotor of zero mass and zero transverse inertia (J about its axis only) differs from the armature
// gr² J in one thing: its spin inertia also turns with the carrier's angular velocity about the spin
// axis, ω_a = aᵀ ω_λ(rot) = w v. Its energy is ½ J (w v + gr q̇_i)², the armature's ½ J gr² q̇_i², so
//   M_full − M_armature = J (w + gr e_i)ᵀ(w + gr e_i) − J gr² e_iᵀ e_i   (summed over the rotors).
TEST(Rotors, ThinMasslessRotorIsArmaturePlusItsCarrierSpinCoupling) {
  RandomState rs(17);
  for (const Model& base : all_robots()) {
    std::vector<ActuatorSpec> full_specs, armature_specs;
    std::vector<Vector3> axes;
    for (int i = 1; i < base.nb; ++i) {
      ActuatorSpec a;
      a.joint = base.joints[static_cast<size_t>(i)].name;
      a.where = "test";
      a.has_rotor = true;
      a.gear_ratio = 6 + i;
      a.rotor_axis = Vector3(0.2, -0.4 * i, 1).normalized();
      axes.push_back(*a.rotor_axis);
      a.rotor_inertia = rotor_inertia(*a.rotor_axis, 5e-5 * i, 5e-5 * i);  // replaced below
      a.rotor_translation = Vector3(0.01, 0.02 * i, 0);
      a.rotor_rotation = rpy(0.1, 0.2 * i, -0.3).transpose();
      full_specs.push_back(a);
      ActuatorSpec arm;
      arm.joint = a.joint;
      arm.where = "test";
      arm.armature = a.gear_ratio * a.gear_ratio * 5e-5 * i;
      armature_specs.push_back(arm);
    }
    Model full = base, armature = base;
    add_actuators(full, full_specs);
    add_actuators(armature, armature_specs);
    // The limit J a aᵀ (no transverse inertia) breaks the triangle inequality, so add_actuators
    // refuses it as input; it is set here directly, as the mathematical limit the relation is about.
    for (int i = 1; i < base.nb; ++i) {
      const Vector3 a = full.joints[static_cast<size_t>(i)].rotor.axis;
      full.rotor_inertia[static_cast<size_t>(i)] =
          spatial_inertia(0, Vector3::Zero(), rotor_inertia(a, 5e-5 * i, 0));
    }
    Data df(full), da(armature);
    const VectorX q = rs.configuration(base);
    const MatrixX difference = mass_matrix(full, df, q) - mass_matrix(armature, da, q);
    MatrixX expected = MatrixX::Zero(base.nv, base.nv);
    for (int i = 1; i < base.nb; ++i) {
      const size_t ui = static_cast<size_t>(i);
      const Rotor& r = full.joints[ui].rotor;
      const double J = 5e-5 * i;
      // w: the carrier's angular velocity about the spin axis per unit v, one unit velocity at a time
      VectorX w(base.nv);
      for (Eigen::Index k = 0; k < base.nv; ++k) {
        kinematics(full, df, q, VectorX::Unit(base.nv, k));
        w[k] = r.axis.dot((full.X_rotor[ui] * df.v[static_cast<size_t>(base.parent[ui])]).head<3>());
      }
      VectorX u = w;
      u[base.joints[ui].v_index] += r.gear_ratio;
      expected += J * u * u.transpose();
      expected(base.joints[ui].v_index, base.joints[ui].v_index) -= J * r.gear_ratio * r.gear_ratio;
    }
    EXPECT_GT(expected.norm(), 1e-6) << base.name;  // the coupling is really there
    EXPECT_LT((difference - expected).cwiseAbs().maxCoeff(), 1e-12) << base.name;
  }
}

// A floating trunk turning at ω about z carries a rotor spinning at gr·q̇ about x (J along, Jt
// across, massless). Its angular momentum in trunk axes is h = (J gr q̇, 0, Jt ω), constant there,
// so the trunk must supply ḣ = ω × h = (0, J gr q̇ ω, 0): the gyroscopic torque, about y. The
// joint's own row gets nothing (the spin is steady).
TEST(Rotors, GyroscopicTorqueOnTheCarrierByHand) {
  ModelSpec s;
  s.name = "gyro";
  s.bodies = {body("trunk", 2.0, Vector3::Zero(), Vector3(0.1, 0.2, 0.3).asDiagonal()),
              body("link", 0.5, Vector3(0, 0, -0.1), Vector3(1e-3, 1e-3, 1e-3).asDiagonal())};
  s.pred = {0};
  s.succ = {1};
  s.joints = {joint("spin", JointType::Revolute, Vector3::UnitX(), Vector3(0.1, 0.05, 0))};
  const double gr = 9.33, J = 6.3e-5, Jt = 3.3e-5, omega = 2.0, qd = 5.0;
  ActuatorSpec a;
  a.joint = "spin";
  a.where = "test";
  a.has_rotor = true;
  a.gear_ratio = gr;
  a.rotor_inertia = Vector3(J, Jt, Jt).asDiagonal();
  a.rotor_translation = Vector3(-0.05, 0.02, 0.01);
  a.rotor_rotation = Matrix3::Identity();
  const Model plain = build_model(s);
  s.actuators = {a};
  const Model rotor = build_model(s);
  Data dp(plain), dr(rotor);
  VectorX q = VectorX::Zero(rotor.nq);
  q[3] = 1;  // identity quaternion (w first)
  VectorX v = VectorX::Zero(rotor.nv);
  v[2] = omega;
  v[6] = qd;
  VectorX expected = VectorX::Zero(rotor.nv);
  expected[1] = J * gr * qd * omega;
  const VectorX difference = quadratic_velocity_terms(rotor, dr, q, v) - quadratic_velocity_terms(plain, dp, q, v);
  EXPECT_LT((difference - expected).cwiseAbs().maxCoeff(), 1e-12) << difference.transpose();
}

std::string topology_error(const std::string& fixture) {
  return model_error([&] {
    UrdfOptions options;
    options.topology_file = data_path(fixture);
    std::vector<std::string> warnings;
    load_urdf(source_path("robots/mini_cheetah.urdf"), options, &warnings);
  });
}

TEST(Rotors, BadActuatorInputIsRefusedNamingFileAndJoint) {
  using ::testing::AllOf;
  using ::testing::HasSubstr;
  EXPECT_THAT(topology_error("actuator_negative_mass.yaml"),
              AllOf(HasSubstr("actuator_negative_mass.yaml:"), HasSubstr("'LF_hip_joint'"),
                    HasSubstr("mass is negative")));
  EXPECT_THAT(topology_error("actuator_negative_ratio.yaml"),
              AllOf(HasSubstr("'LF_knee_joint'"), HasSubstr("gear ratio must be finite and > 0")));
  EXPECT_THAT(topology_error("actuator_not_axisymmetric.yaml"),
              AllOf(HasSubstr("'LF_abad_joint'"), HasSubstr("not symmetric about the spin axis")));
  EXPECT_THAT(topology_error("actuator_unknown_joint.yaml"),
              AllOf(HasSubstr("'LF_elbow_joint'"), HasSubstr("no such moving joint")));
  EXPECT_THAT(topology_error("actuator_negative_armature.yaml"),
              AllOf(HasSubstr("'RF_hip_joint'"), HasSubstr("armature must be finite and ≥ 0")));
}

Model mini_cheetah_with_rotors() {
  UrdfOptions options;
  options.topology_file = source_path("robots/mini_cheetah_rotors.topology.yaml");
  std::vector<std::string> warnings;  // the MIT thigh inertia breaks the triangle inequality
  return load_urdf(source_path("robots/mini_cheetah.urdf"), options, &warnings);
}

// Cheetah-Software's model test (mini_cheetah_parameters.md, model notes): parent vector
// {0,0,0,0,0,0,5,6,7,5,9,10,5,12,13,5,15,16} in MIT's numbering (0-4 placeholders of the floating
// base, 5 the trunk, then FR, FL, HR, HL, abad → hip → knee), totalNonRotorMass() == 8.2520 and
// totalRotorMass() == 0.66. Our numbering (trunk 0; LF, RF, LH, RH) is mapped to MIT's by name.
TEST(Rotors, MiniCheetahReproducesCheetahSoftwareModelChecks) {
  const Model m = mini_cheetah_with_rotors();
  ASSERT_TRUE(m.has_rotors);
  const std::vector<std::string> mit_legs = {"RF", "LF", "RH", "LH"};  // MIT's FR, FL, HR, HL
  const std::vector<std::string> parts = {"abad", "hip", "knee"};
  const auto mit_id = [&](const std::string& name) {
    if (name == "trunk") return 5;
    for (size_t leg = 0; leg < 4; ++leg) {
      for (size_t p = 0; p < 3; ++p) {
        if (name == mit_legs[leg] + "_" + parts[p]) return static_cast<int>(6 + 3 * leg + p);
      }
    }
    ADD_FAILURE() << "no MIT id for body " << name;
    return -1;
  };
  std::vector<int> mit_parent(18, 0);
  for (int i = 1; i < m.nb; ++i) {
    mit_parent[static_cast<size_t>(mit_id(m.bodies[static_cast<size_t>(i)].name))] =
        mit_id(m.bodies[static_cast<size_t>(m.parent[static_cast<size_t>(i)])].name);
  }
  EXPECT_EQ(mit_parent, (std::vector<int>{0, 0, 0, 0, 0, 0, 5, 6, 7, 5, 9, 10, 5, 12, 13, 5, 15, 16}));
  double links = 0, rotors = 0;
  for (const Body& b : m.bodies) links += b.mass;
  for (const Joint& j : m.joints) rotors += j.rotor.mass;
  EXPECT_NEAR(links, 8.2520, 1e-12);
  EXPECT_NEAR(rotors, 0.66, 1e-12);
  EXPECT_NEAR(links + rotors, 8.912, 1e-12);
  // the reflected inertias gr²·J of the sheet (1.3): 0.002268 at abad and hip, 0.005484 at the knee
  for (const Joint& j : m.joints) {
    if (j.rotor.gear_ratio == 0) continue;
    EXPECT_NEAR(reflected_inertia(j.rotor), j.name.find("knee") != std::string::npos ? 0.005484 : 0.002268, 1e-6) << j.name;
  }
  // every identity holds on it too
  RandomState rs(23);
  Data d(m);
  const VectorX q = rs.configuration(m), v = rs.vector(m.nv), a = rs.vector(m.nv);
  const VectorX tau = inverse_dynamics(m, d, q, v, a);
  const VectorX expected = mass_matrix(m, d, q) * a + quadratic_velocity_terms(m, d, q, v) + gravity_terms(m, d, q);
  EXPECT_LT((tau - expected).cwiseAbs().maxCoeff(), 1e-10);
}

// Cheetah-Software's two Mini Cheetah ABA cases (common/test/test_mini_cheetah_model.cpp,
// simulatorDynamicsABANoExternalForceMiniCheetah and simulatorDynamicsWithExternalForceMiniCheetah):
// body orientation rBody = Cx(.123) Cz(.232) Cy(.111) with their coordinateRotation C (the transpose
// of the active rotation), passed as rotationMatrixToQuaternion(rBodyᵀ), so W_R_B = rBody; body
// velocity (1…6) (ω; v, body coordinates), position (6, 7, 8); in MIT's joint order (FR, FL, HR,
// HL; abad, hip, knee) q_k = k + 1, q̇_k = 2(k + 1), τ_k = −3(k + 1). The second case adds on
// every link (MIT body b = 5 trunk, 6 + 3·leg + part) the spatial force f_b,j = 0.3 (b + j + 1),
// (moment; force) in world coordinates about the world origin (runABA: pA[i] -= Xa[i]^{-T} f_i);
// read as body coordinates at the body origin instead, the second case fails.
// Their printed references: dBodyPosition, dBodyVelocity (the trunk's spatial acceleration) and q̈.
struct CheetahSoftwareCase {
  const char* name;
  bool external_forces;
  Vector3 pd;
  Vector6 vbd;
  std::vector<double> qdd;  // MIT's joint order
};

void PrintTo(const CheetahSoftwareCase& c, std::ostream* os) { *os << c.name; }

class CheetahSoftwareAba : public ::testing::TestWithParam<CheetahSoftwareCase> {};

TEST_P(CheetahSoftwareAba, RotorModelReproducesTheirPrintedDigits) {
  const CheetahSoftwareCase& c = GetParam();
  const Model m = mini_cheetah_with_rotors();
  const auto C = [](double angle, const Vector3& axis) {  // their coordinateRotation
    return Matrix3(Eigen::AngleAxisd(angle, axis).toRotationMatrix().transpose());
  };
  const Matrix3 W_R_B = C(.123, Vector3::UnitX()) * C(.232, Vector3::UnitZ()) * C(.111, Vector3::UnitY());
  const Eigen::Quaterniond orientation(W_R_B);
  const std::vector<std::string> mit_legs = {"RF", "LF", "RH", "LH"};  // MIT's FR, FL, HR, HL
  const std::vector<std::string> parts = {"abad", "hip", "knee"};
  const auto mit_index = [&](const std::string& name) {  // MIT's link number 0 … 11 of a body/joint
    for (int k = 0; k < 12; ++k) {
      if (name.rfind(mit_legs[static_cast<size_t>(k / 3)] + "_" + parts[static_cast<size_t>(k % 3)], 0) == 0) return k;
    }
    return -1;
  };
  VectorX q(m.nq), v(m.nv), tau(m.num_joints());
  q << 6, 7, 8, orientation.w(), orientation.x(), orientation.y(), orientation.z(), VectorX::Zero(12);
  v << 1, 2, 3, 4, 5, 6, VectorX::Zero(12);
  for (int i = 1; i < m.nb; ++i) {
    const Joint& joint = m.joints[static_cast<size_t>(i)];
    const int k = mit_index(joint.name);
    ASSERT_GE(k, 0) << joint.name;
    q(joint.q_index) = k + 1;
    v(joint.v_index) = 2 * (k + 1);
    tau(i - 1) = -3.0 * (k + 1);
  }
  Data d(m);
  VectorX qdd = forward_dynamics(m, d, q, v, tau, Matrix3X::Zero(3, static_cast<Eigen::Index>(m.feet.size())));
  if (c.external_forces) {
    const std::vector<Matrix6> X_world = world_transforms(m, d, q);  // X_W^i, world → body motion
    std::vector<Vector6> wrenches(static_cast<size_t>(m.nb));
    for (int i = 0; i < m.nb; ++i) {
      const int b = i == 0 ? 5 : 6 + mit_index(m.bodies[static_cast<size_t>(i)].name);
      Vector6 f_world;
      for (int j = 0; j < 6; ++j) f_world(j) = 0.3 * (b + j + 1);
      wrenches[static_cast<size_t>(i)] = X_world[static_cast<size_t>(i)].inverse().transpose() * f_world;
    }
    qdd += d.M_llt.solve(external_wrench_terms(m, d, q, wrenches));
  }
  const Vector3 pd = W_R_B * v.segment<3>(3);
  Vector6 spatial = qdd.head<6>();
  spatial.tail<3>() -= v.head<3>().cross(v.segment<3>(3));
  // their digits: 6 significant figures (4 decimals for dBodyPosition)
  const auto printed = [](double reference) { return 6e-6 * std::abs(reference) + 1e-12; };
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(pd(k), c.pd(k), 5e-5) << "dBodyPosition " << k;
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(spatial(k), c.vbd(k), printed(c.vbd(k))) << "dBodyVelocity " << k;
  for (int i = 1; i < m.nb; ++i) {
    const Joint& joint = m.joints[static_cast<size_t>(i)];
    const double reference = c.qdd[static_cast<size_t>(mit_index(joint.name))];
    EXPECT_NEAR(qdd(joint.v_index), reference, printed(reference)) << "qdd " << joint.name;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, CheetahSoftwareAba,
    ::testing::Values(
        CheetahSoftwareCase{"NoExternalForce", false, Vector3(4.3717, 4.8598, 5.8541),
                            (Vector6() << 1217.31, -182.793, -171.524, -4.09393, 33.6798, -59.975).finished(),
                            {-1946.36, -1056.62, -1470.57, -3133.03, -1263.89, -2626.9, -6637.38, -4071.88,
                             -4219.14, -7554.08, -3392.44, -5112.85}},
        CheetahSoftwareCase{"WithExternalForce", true, Vector3(4.3717, 4.8598, 5.8541),
                            (Vector6() << 3153.46, 42.6931, 264.584, -3.80573, -53.3519, 68.5713).finished(),
                            {-1211.85, -1167.39, -2024.94, 394.414, -297.854, -2292.29, -1765.92, -4040.78,
                             -4917.41, 149.368, -2508.2, -4969.02}}),
    [](const ::testing::TestParamInfo<CheetahSoftwareCase>& info) { return std::string(info.param.name); });

// The scene key `actuators` on the runtime side: `none` is the model without actuators, `armature`
// the model without rotors whose diagonal gains armature + gr² aᵀ I a, joint by joint.
TEST(Rotors, ActuatorModesReduceTheModel) {
  RandomState rs(29);
  for (const Model& plain : all_robots()) {
    const Model full = with_rotors(plain);
    const Model none = with_actuator_mode(full, ActuatorMode::None);
    const Model armature = with_actuator_mode(full, ActuatorMode::Armature);
    EXPECT_FALSE(none.has_rotors || none.has_armature || armature.has_rotors);
    EXPECT_TRUE(armature.has_armature);
    Data dp(plain), dn(none), da(armature);
    const VectorX q = rs.configuration(full), v = rs.vector(full.nv), acc = rs.vector(full.nv);
    const MatrixX M_plain = mass_matrix(plain, dp, q);
    EXPECT_EQ(mass_matrix(none, dn, q), M_plain) << full.name;
    EXPECT_EQ(inverse_dynamics(none, dn, q, v, acc), inverse_dynamics(plain, dp, q, v, acc)) << full.name;
    VectorX diagonal = VectorX::Zero(full.nv);
    for (int i = 1; i < full.nb; ++i) {
      const Joint& j = full.joints[static_cast<size_t>(i)];
      diagonal[j.v_index] = j.armature + reflected_inertia(j.rotor);
    }
    const MatrixX expected = M_plain + MatrixX(diagonal.asDiagonal());
    EXPECT_LT((mass_matrix(armature, da, q) - expected).cwiseAbs().maxCoeff(), 1e-15) << full.name;
    const VectorX tau = inverse_dynamics(armature, da, q, v, acc);
    EXPECT_LT((tau - (inverse_dynamics(plain, dp, q, v, acc) + diagonal.cwiseProduct(acc))).cwiseAbs().maxCoeff(),
              1e-12) << full.name;
  }
  EXPECT_EQ(parse_actuator_mode("armature"), ActuatorMode::Armature);
  EXPECT_THROW(parse_actuator_mode("rotors"), std::invalid_argument);
}

TEST(Rotors, ModelWithoutActuatorsIsUnchanged) {
  for (const Model& m : all_robots()) {
    EXPECT_FALSE(m.has_rotors);
    EXPECT_FALSE(m.has_armature);
    EXPECT_TRUE(m.X_rotor.empty());
  }
}

}  // namespace
}  // namespace rbdc::test
