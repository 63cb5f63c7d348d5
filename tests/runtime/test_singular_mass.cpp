// Massless bodies and the singular-mass-matrix rule (docs/model.md, "Singular mass matrix"): a
// massless base keeps its pure rotational inertia through fixed-joint merging, a singular M loads
// with a warning, kinematics and inverse dynamics keep working, and the functions that need M⁻¹
// refuse it; an inertia indefinite in a merged link is checked on the merged body.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "model_test_support.hpp"
#include "rbdc/crba.hpp"
#include "rbdc/derivatives.hpp"
#include "rbdc/forward_dynamics.hpp"
#include "rbdc/inverse_dynamics.hpp"
#include "rbdc/model_builder.hpp"
#include "rbdc/osc.hpp"
#include "rbdc/urdf_loader.hpp"
#include "test_robots.hpp"

namespace rbdc {
namespace {

using ::testing::AllOf;
using ::testing::Contains;
using ::testing::HasSubstr;
using test::argument_error;
using test::data_path;
using test::RandomState;

TEST(SingularMass, MasslessBaseKeepsItsRotationalInertiaThroughMerging) {
  std::vector<std::string> warnings;
  const Model m = load_urdf(data_path("massless_inertial_base.urdf"), {}, &warnings);
  EXPECT_EQ(m.bodies[0].mass, 0);
  EXPECT_EQ(m.bodies[0].inertia_com, Vector3(0.05, 0.06, 0.03).asDiagonal().toDenseMatrix());
  EXPECT_EQ(m.singular_mass_matrix, "");
  RandomState rs(5);
  Data d(m);
  for (int trial = 0; trial < 5; ++trial) {
    const VectorX q = rs.configuration(m), v = rs.vector(m.nv), tau = rs.vector(m.num_joints());
    const VectorX a = forward_dynamics(m, d, q, v, tau, Matrix3X::Zero(3, static_cast<Eigen::Index>(m.feet.size())));
    ASSERT_TRUE(a.allFinite());
    VectorX generalised = VectorX::Zero(m.nv);
    generalised.tail(m.num_joints()) = tau;
    EXPECT_LT((inverse_dynamics(m, d, q, v, a) - generalised).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<MatrixX>(mass_matrix(m, d, q)).eigenvalues().minCoeff(), 1e-6);
  }
}

TEST(SingularMass, MasslessLeafLoadsWithAWarningAndMInverseFunctionsRefuse) {
  std::vector<std::string> warnings;
  const Model m = load_urdf(data_path("massless_leaf.urdf"), {}, &warnings);
  EXPECT_THAT(warnings, Contains(AllOf(HasSubstr("massless_leaf.urdf: the mass matrix is singular: joint 'ja'"),
                                       HasSubstr("body 'ghost' is a moving leaf with zero mass"))));
  EXPECT_THAT(m.singular_mass_matrix, HasSubstr("joint 'ja' (dof 6)"));
  Data d(m);
  RandomState rs(7);
  const VectorX q = rs.configuration(m), v = rs.vector(m.nv), a = rs.vector(m.nv);
  EXPECT_TRUE(inverse_dynamics(m, d, q, v, a).allFinite());  // kinematics and ID work
  EXPECT_TRUE(mass_matrix(m, d, q).allFinite());
  const Matrix3X no_feet = Matrix3X::Zero(3, static_cast<Eigen::Index>(m.feet.size()));
  EXPECT_THAT(argument_error([&] { forward_dynamics(m, d, q, v, VectorX::Zero(1), no_feet); }),
              AllOf(HasSubstr("rbdc::forward_dynamics: model 'massless_leaf': the mass matrix is singular"),
                    HasSubstr("needs M⁻¹")));
  EXPECT_THAT(argument_error([&] { osc_open_chain(m, d, q, v, no_feet); }), HasSubstr("rbdc::osc_open_chain"));
  EXPECT_THAT(argument_error([&] { osc_closed_chain(m, d, q, v, std::vector<int>{}); }), HasSubstr("rbdc::osc_closed_chain"));
  DerivativeData dd(m);
  EXPECT_THAT(argument_error([&] { forward_dynamics_derivatives(m, d, dd, q, v, VectorX::Zero(1), no_feet); }),
              HasSubstr("rbdc::forward_dynamics_derivatives"));
}

TEST(SingularMass, AnArmatureRegularisesAMasslessLeaf) {
  Model m = load_urdf(data_path("massless_leaf.urdf"));
  ActuatorSpec armature;
  armature.joint = "ja";
  armature.where = "test";
  armature.armature = 1e-3;
  add_actuators(m, {armature});
  EXPECT_EQ(m.singular_mass_matrix, "");
  Data d(m);
  RandomState rs(9);
  const VectorX q = rs.configuration(m), v = rs.vector(m.nv);
  EXPECT_TRUE(forward_dynamics(m, d, q, v, VectorX::Ones(1), Matrix3X::Zero(3, static_cast<Eigen::Index>(m.feet.size()))).allFinite());
}

TEST(SingularMass, MasslessBaseWithoutInertiaIsSingular) {
  const Model m = load_urdf(data_path("massless_base_singular.urdf"));
  EXPECT_THAT(m.singular_mass_matrix, HasSubstr("floating-base dof 2 has pivot"));
  UrdfOptions fixed;
  fixed.floating_base = false;  // welded, the same arm is regular
  EXPECT_EQ(load_urdf(data_path("massless_base_singular.urdf"), fixed).singular_mass_matrix, "");
}

TEST(SingularMass, IndefiniteInertiaOfAMergedLinkIsCheckedOnTheMergedBody) {
  std::vector<std::string> warnings;
  const Model m = load_urdf(data_path("merged_indefinite_antenna.urdf"), {}, &warnings);
  EXPECT_THAT(warnings, Contains(AllOf(HasSubstr("merged_indefinite_antenna.urdf:7: link 'antenna'"),
                                       HasSubstr("not positive semi-definite"),
                                       HasSubstr("merged inertia is checked instead"))));
  EXPECT_NEAR(m.bodies[0].mass, 40 + 1e-6, 1e-12);
  EXPECT_GT(Eigen::SelfAdjointEigenSolver<Matrix3>(m.bodies[0].inertia_com).eigenvalues().minCoeff(), 1.0);
}

}  // namespace
}  // namespace rbdc
