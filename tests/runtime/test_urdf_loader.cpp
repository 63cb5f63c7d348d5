// URDF loading: the bundled Mini Cheetah (paper 000 Eqs. 1-3), fixed-joint lumping, rotated inertial
// frames, feet, locking, mimic policy, every repair with its warning and every refusal of bad input.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>

#include "model_test_support.hpp"
#include "rbdc/urdf_loader.hpp"

namespace rbdc {
namespace {

using ::testing::AllOf;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using test::data_path;
using test::model_error;
using test::source_path;

const std::string kMiniCheetah = source_path("robots/mini_cheetah.urdf");
const double kHalfPi = 1.5707963267948966;

double total_mass(const Model& m) {
  double sum = 0;
  for (const Body& b : m.bodies) sum += b.mass;
  return sum;
}

Matrix3 rotation_z(double angle) { return Eigen::AngleAxisd(angle, Vector3::UnitZ()).toRotationMatrix(); }

TEST(MiniCheetahUrdf, TopologyArraysFollowEquations1To3) {
  const Model m = load_urdf(kMiniCheetah);
  EXPECT_EQ(m.name, "mini_cheetah");
  EXPECT_EQ(m.nb, 13);
  EXPECT_EQ(m.nq, 19);
  EXPECT_EQ(m.nv, 18);
  const std::vector<int> pred = {-1, 0, 1, 2, 0, 4, 5, 0, 7, 8, 0, 10, 11};   // Eq. 1
  const std::vector<int> succ = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};   // Eq. 1
  const std::vector<int> lambda = {-1, 0, 1, 2, 0, 4, 5, 0, 7, 8, 0, 10, 11};  // Eqs. 2-3
  EXPECT_EQ(m.pred, pred);
  EXPECT_EQ(m.succ, succ);
  EXPECT_EQ(m.parent, lambda);
  const char* names[] = {"trunk",   "LF_abad", "LF_hip", "LF_knee", "RF_abad", "RF_hip", "RF_knee",
                         "LH_abad", "LH_hip",  "LH_knee", "RH_abad", "RH_hip", "RH_knee"};
  for (int i = 0; i < 13; ++i) EXPECT_EQ(m.bodies[static_cast<size_t>(i)].name, names[i]);
}

TEST(MiniCheetahUrdf, MassFramesAndFeetFollowTheParameterSheet) {
  std::vector<std::string> warnings;
  const Model m = load_urdf(kMiniCheetah, {}, &warnings);
  EXPECT_NEAR(total_mass(m), 8.252, 1e-12);
  // Hip joint: frame turned Rz(π), so E_T = Rz(π)ᵀ; right legs mirrored (sheet section 2).
  EXPECT_TRUE(m.joints[2].rotation.isApprox(rotation_z(M_PI).transpose(), 1e-15));
  EXPECT_EQ(m.joints[5].translation, Vector3(0, -0.062, 0));
  EXPECT_EQ(m.joints[10].translation, Vector3(-0.19, -0.049, 0));
  EXPECT_EQ(m.bodies[5].com, Vector3(0, -0.016, -0.02));
  EXPECT_EQ(m.bodies[5].inertia_com(0, 1), -0.000245);
  ASSERT_EQ(m.feet.size(), 4u);  // default rule: the massless foot links on the knees
  EXPECT_EQ(m.feet[0].name, "LF_foot");
  EXPECT_EQ(m.feet[0].body, 3);
  EXPECT_EQ(m.feet[0].offset, Vector3(0, -0.004, -0.195));
  EXPECT_EQ(m.feet[3].body, 12);
  EXPECT_EQ(m.feet[3].offset, Vector3(0, 0.004, -0.195));
  // The published thigh inertia breaks the triangle inequality: one warning per hip, no refusal.
  ASSERT_EQ(warnings.size(), 4u);
  EXPECT_THAT(warnings[0], AllOf(HasSubstr("mini_cheetah.urdf"), HasSubstr("'LF_hip'"),
                                 HasSubstr("triangle inequality")));
  EXPECT_THAT(warnings[3], HasSubstr("'RH_hip'"));
}

TEST(UrdfLoader, FixedJointSplitBodyEqualsTheSingleLinkBody) {
  const Model split = load_urdf(data_path("split_body.urdf"));
  const Model single = load_urdf(data_path("single_body.urdf"));
  ASSERT_EQ(split.nb, 3);
  ASSERT_EQ(single.nb, 3);
  for (int i = 0; i < 3; ++i) {
    const size_t u = static_cast<size_t>(i);
    EXPECT_LT((split.inertia[u] - single.inertia[u]).cwiseAbs().maxCoeff(), 1e-12) << "body " << i;
    EXPECT_LT((split.X_tree[u] - single.X_tree[u]).cwiseAbs().maxCoeff(), 1e-12) << "joint " << i;
  }
  // The merged link's moving child is re-attached at the composed placement.
  EXPECT_TRUE(split.joints[2].translation.isApprox(Vector3(0, 0.1, -0.2), 1e-15));
  EXPECT_EQ(split.joints[2].axis, Vector3(1, 0, 0));
}

TEST(UrdfLoader, RotatedInertialFrameIsTurnedIntoTheLinkFrame) {
  // tip: inertial origin (0.1, 0, 0) rotated Rz(90°), inertia diag(1, 2, 3)e-3 about the COM, so
  // diag(2, 1, 3)e-3 in link axes: I = [I_c + m c̃ c̃ᵀ, m c̃; m c̃ᵀ, m 1] by hand.
  const Model m = load_urdf(data_path("split_body.urdf"));
  Matrix6 expected = Matrix6::Zero();
  const double mass = 0.5, cx = 0.1;
  expected.topLeftCorner<3, 3>() = Vector3(0.002, 0.001 + mass * cx * cx, 0.003 + mass * cx * cx).asDiagonal();
  expected(1, 5) = -mass * cx;  // m c̃ with c = (cx, 0, 0)
  expected(2, 4) = mass * cx;
  expected(5, 1) = -mass * cx;
  expected(4, 2) = mass * cx;
  expected.bottomRightCorner<3, 3>() = mass * Matrix3::Identity();
  EXPECT_LT((m.inertia[2] - expected).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(UrdfLoader, DefaultFootIsTheMasslessTipLinkElseTheLeafOrigin) {
  const Model split = load_urdf(data_path("split_body.urdf"));
  ASSERT_EQ(split.feet.size(), 1u);
  EXPECT_EQ(split.feet[0].name, "tool");
  EXPECT_EQ(split.feet[0].body, 2);
  EXPECT_EQ(split.feet[0].offset, Vector3(0, 0, -0.3));
  const Model single = load_urdf(data_path("single_body.urdf"));
  ASSERT_EQ(single.feet.size(), 1u);
  EXPECT_EQ(single.feet[0].name, "tip");
  EXPECT_EQ(single.feet[0].offset, Vector3::Zero());
}

TEST(UrdfLoader, ExplicitFeetOnAMergedLinkKeepTheirPlace) {
  UrdfOptions opts;
  opts.feet = {{"knee_point", "lower", Vector3(0.05, 0, 0)}};
  const Model m = load_urdf(data_path("split_body.urdf"), opts);
  ASSERT_EQ(m.feet.size(), 1u);
  EXPECT_EQ(m.feet[0].body, 1);
  EXPECT_TRUE(m.feet[0].offset.isApprox(Vector3(0, 0.05, -0.2), 1e-15));  // Rz(90°)·(0.05,0,0) + (0,0,-0.2)
  opts.feet = {{"nowhere", "no_such_link", Vector3::Zero()}};
  EXPECT_THAT(model_error([&] { load_urdf(data_path("split_body.urdf"), opts); }),
              HasSubstr("foot 'nowhere': link 'no_such_link' is not a link of the model"));
}

TEST(UrdfLoader, FixedBaseWeldsTheRoot) {
  UrdfOptions opts;
  opts.floating_base = false;
  const Model m = load_urdf(kMiniCheetah, opts);
  EXPECT_EQ(m.joints[0].type, JointType::Fixed);
  EXPECT_EQ(m.nq, 12);
  EXPECT_EQ(m.nv, 12);
}

TEST(UrdfLoader, LockedJointIsMergedAtItsPosition) {
  UrdfOptions opts;
  opts.locked_joints = {{"elbow", kHalfPi}};
  const Model m = load_urdf(data_path("split_body.urdf"), opts);
  ASSERT_EQ(m.nb, 2);
  EXPECT_NEAR(m.bodies[1].mass, 2.5, 1e-15);
  // tip COM (0.1, 0, 0) stays on the elbow's x axis: body-frame (0, 0.2, -0.2), merged COM (0, 0.04, -0.2).
  EXPECT_TRUE(m.bodies[1].com.isApprox(Vector3(0, 0.04, -0.2), 1e-14));
  opts.locked_joints = {{"no_such_joint", 0}};
  EXPECT_THAT(model_error([&] { load_urdf(data_path("split_body.urdf"), opts); }),
              HasSubstr("locked joint 'no_such_joint' does not exist"));
}

TEST(UrdfLoader, MimicJointIsCoupledByDefaultLockedOrIndependentOnRequest) {
  const std::string path = data_path("mimic.urdf");
  const Model coupled = load_urdf(path);
  EXPECT_EQ(coupled.nb, 3);
  ASSERT_EQ(coupled.couplings.size(), 1u);
  EXPECT_EQ(coupled.joints[static_cast<size_t>(coupled.couplings[0].follower)].name, "jb");
  EXPECT_EQ(coupled.joints[static_cast<size_t>(coupled.couplings[0].leader)].name, "ja");
  EXPECT_EQ(coupled.couplings[0].multiplier, -1);
  EXPECT_EQ(coupled.couplings[0].offset, 0.25);
  UrdfOptions opts;
  opts.mimic = MimicMode::Independent;
  const Model independent = load_urdf(path, opts);
  EXPECT_EQ(independent.nb, 3);
  EXPECT_TRUE(independent.couplings.empty());
  opts.mimic = MimicMode::Lock;
  const Model m = load_urdf(path, opts);
  EXPECT_EQ(m.nb, 2);  // jb locked at its offset 0.25 about y: b's COM (0,0,-0.1) swings to x < 0
  const Vector3 b_com = Vector3(0, 0, -0.2) + Eigen::AngleAxisd(0.25, Vector3::UnitY()) * Vector3(0, 0, -0.1);
  EXPECT_TRUE(m.bodies[0].com.isApprox((Vector3(0, 0, -0.1) + b_com) / 2, 1e-14));
}

TEST(UrdfLoader, ChainsOfMimicJointsCoupleToTheFirstLeader) {
  const Model m = load_urdf(data_path("mimic_chain.urdf"));
  ASSERT_EQ(m.couplings.size(), 2u);  // jb = -ja + 0.25, jc = 3 jb + 0.5 = -3 ja + 1.25
  EXPECT_EQ(m.joints[static_cast<size_t>(m.couplings[1].follower)].name, "jc");
  EXPECT_EQ(m.joints[static_cast<size_t>(m.couplings[1].leader)].name, "ja");
  EXPECT_DOUBLE_EQ(m.couplings[1].multiplier, -3);
  EXPECT_DOUBLE_EQ(m.couplings[1].offset, 1.25);
}

TEST(UrdfLoader, ALockedLeaderLocksItsFollowers) {
  UrdfOptions opts;
  opts.locked_joints = {{"ja", 0.5}};
  const Model m = load_urdf(data_path("mimic.urdf"), opts);
  EXPECT_EQ(m.nb, 1);  // jb locked at -0.5 + 0.25
  const Vector3 b_com = Vector3(0, 0, -0.2) + Eigen::AngleAxisd(-0.25, Vector3::UnitY()) * Vector3(0, 0, -0.1);
  const Vector3 a_com = Vector3(0, 0, -0.2) + Eigen::AngleAxisd(0.5, Vector3::UnitY()) * Vector3(0, 0, -0.1);
  EXPECT_TRUE(m.bodies[0].com.isApprox((Vector3(0, 0, -0.1) + a_com + b_com) / 3, 1e-14));
}

// Warnings name the file and line; the robot loads with the repair applied.
std::vector<std::string> warnings_of(const std::string& file, const UrdfOptions& opts = {}) {
  std::vector<std::string> warnings;
  load_urdf(data_path(file), opts, &warnings);
  return warnings;
}

TEST(UrdfLoaderRepairs, RoundOffIndefiniteInertiaIsClippedWithAWarning) {
  std::vector<std::string> warnings;
  const Model m = load_urdf(data_path("round_off_inertia.urdf"), {}, &warnings);
  ASSERT_FALSE(warnings.empty());
  EXPECT_THAT(warnings[0], AllOf(HasSubstr("round_off_inertia.urdf:6: link 'arm'"),
                                 HasSubstr("negative by 1.4e-20"), HasSubstr("clipped")));
  const Eigen::SelfAdjointEigenSolver<Matrix3> eigen(m.bodies[1].inertia_com);
  EXPECT_GE(eigen.eigenvalues().minCoeff(), 0.0);
  EXPECT_NEAR(eigen.eigenvalues().maxCoeff(), 1.4e-20, 1e-30);
}

TEST(UrdfLoaderRepairs, IndefiniteInertiaBeyondRoundOffIsRefused) {
  EXPECT_THAT(model_error([] { load_urdf(data_path("slightly_indefinite.urdf")); }),
              AllOf(HasSubstr("slightly_indefinite.urdf:5: link 'arm'"), HasSubstr("not positive semi-definite")));
}

TEST(UrdfLoaderRepairs, VisualCollisionAndMaterialFaultsAreWarnings) {
  EXPECT_THAT(warnings_of("appearance_faults.urdf"),
              ElementsAre(HasSubstr("appearance_faults.urdf:8: link 'base': <visual> without <geometry>"),
                          HasSubstr("appearance_faults.urdf:12: link 'arm': <collision> without <geometry>"),
                          HasSubstr("appearance_faults.urdf:5: <material> without a name")));
}

TEST(UrdfLoaderRepairs, MasslessLinksWithInertiaAreDroppedWhereWeldedElseKept) {
  UrdfOptions opts;
  opts.floating_base = false;
  std::vector<std::string> warnings;
  const Model m = load_urdf(data_path("massless_inertia.urdf"), opts, &warnings);
  EXPECT_THAT(warnings, ElementsAre(HasSubstr(":6: link 'world': zero mass but non-zero rotational inertia; welded"),
                                    HasSubstr(":7: link 'mount': zero mass but non-zero rotational inertia; welded"),
                                    HasSubstr(":10: link 'sensor': zero mass but non-zero rotational inertia; kept")));
  EXPECT_EQ(m.bodies[0].inertia_com, Matrix3::Identity() * 0.01);  // base only
  EXPECT_TRUE(m.bodies[1].inertia_com.isApprox(Matrix3::Identity() * 0.012, 1e-14));  // arm + sensor
}

TEST(UrdfLoaderRepairs, JointWithoutLimitLoadsUnlimitedWithAWarning) {
  std::vector<std::string> warnings;
  const Model m = load_urdf(data_path("unlimited.urdf"), {}, &warnings);
  EXPECT_TRUE(std::isinf(m.joints[1].upper));
  EXPECT_THAT(warnings, ElementsAre(HasSubstr("unlimited.urdf:6: joint 'hinge' has no <limit>")));
}

TEST(UrdfLoaderRepairs, FixedBaseWarnsWhenItDropsTheFilesFloatingJoint) {
  EXPECT_TRUE(warnings_of("world_floating.urdf").empty());
  UrdfOptions opts;
  opts.floating_base = false;
  EXPECT_THAT(warnings_of("world_floating.urdf", opts),
              ElementsAre(HasSubstr("world_floating.urdf:5: floating joint 'free' from link 'world' is dropped")));
}

TEST(UrdfLoaderRepairs, EveryBadLinkIsRefusedInOneMessage) {
  EXPECT_THAT(model_error([] { load_urdf(data_path("two_bad_links.urdf")); }),
              AllOf(HasSubstr("two_bad_links.urdf:5: link 'light': mass is negative\n"),
                    HasSubstr("two_bad_links.urdf:6: link 'wobbly': rotational inertia is not positive")));
}

TEST(UrdfLoader, MasslessWorldRootIsDroppedOrMerged) {
  const Model floating = load_urdf(data_path("world_floating.urdf"));  // world -floating-> base
  EXPECT_EQ(floating.bodies[0].name, "base");
  EXPECT_EQ(floating.joints[1].axis, Vector3(0, 0, -1));
  UrdfOptions opts;
  opts.floating_base = false;
  const Model welded = load_urdf(data_path("world_fixed.urdf"), opts);  // world -fixed-> base, merged
  EXPECT_EQ(welded.bodies[0].name, "world");
  EXPECT_EQ(welded.bodies[0].com, Vector3(0, 0, 0.5));
  EXPECT_EQ(welded.nv, 1);
  opts.root_link = "base";  // drops the massless world above it
  const Model rerooted = load_urdf(data_path("world_fixed.urdf"), opts);
  EXPECT_EQ(rerooted.bodies[0].name, "base");
  EXPECT_EQ(rerooted.bodies[0].com, Vector3::Zero());
}

TEST(UrdfLoader, RootLinkBelowAMovingJointIsRefused) {
  UrdfOptions opts;
  opts.root_link = "upper";
  EXPECT_THAT(model_error([&] { load_urdf(data_path("split_body.urdf"), opts); }),
              AllOf(HasSubstr("split_body.urdf:"), HasSubstr("cannot use link 'upper' as the root"),
                    HasSubstr("'hinge'")));
  opts.root_link = "missing";
  EXPECT_THAT(model_error([&] { load_urdf(data_path("split_body.urdf"), opts); }),
              HasSubstr("root link 'missing' does not exist"));
}

struct BadUrdf {
  const char* file;
  const char* message;
};

void PrintTo(const BadUrdf& b, std::ostream* os) { *os << b.file; }

class BadUrdfFile : public ::testing::TestWithParam<BadUrdf> {};

TEST_P(BadUrdfFile, IsRefusedWithAClearMessage) {
  const std::string path = data_path(GetParam().file);
  const std::string e = model_error([&] { load_urdf(path); });
  EXPECT_THAT(e, HasSubstr(GetParam().file));
  EXPECT_THAT(e, HasSubstr(GetParam().message));
}

INSTANTIATE_TEST_SUITE_P(
    Fixtures, BadUrdfFile,
    ::testing::Values(
        BadUrdf{"does_not_exist.urdf", "cannot open file"}, BadUrdf{"empty.urdf", "file is empty"},
        BadUrdf{"malformed.urdf", ":5: malformed XML"}, BadUrdf{"no_links.urdf", "no links"},
        BadUrdf{"missing_link.urdf", "joint 'elbow' names link 'forearm', which does not exist"},
        BadUrdf{"two_parents.urdf", "link 'b' has two parents: joint 'jb' (line 6) and joint 'jab'"},
        BadUrdf{"cycle.urdf", "cycle"}, BadUrdf{"detached_cycle.urdf", "cycle through link 'b'"},
        BadUrdf{"several_roots.urdf", "several root links (links without a parent joint): 'base' and 'other'"},
        BadUrdf{"planar.urdf", "joint 'slide' has unsupported type 'planar'"},
        BadUrdf{"floating_mid.urdf", "joint 'float' has unsupported type 'floating'"},
        BadUrdf{"zero_axis.urdf", "joint 'bad_axis': axis is zero"},
        BadUrdf{"nan_origin.urdf", "Malformed parent origin element for joint [nan_joint]"},
        BadUrdf{"inf_mass.urdf", "Could not parse inertial element for Link [heavy]"},
        BadUrdf{"negative_mass.urdf", "link 'light': mass is negative"},
        BadUrdf{"non_psd.urdf", "link 'wobbly': rotational inertia is not positive semi-definite"},
        BadUrdf{"slightly_indefinite.urdf", "link 'arm': rotational inertia is not positive semi-definite"},
        BadUrdf{"mimic_missing_leader.urdf", ":6: joint 'jb' mimics joint 'nowhere', which does not exist"},
        BadUrdf{"mimic_cycle.urdf", ":7: joint 'ja': its mimic joints form a cycle ('ja' → 'jb' → 'ja')"},
        BadUrdf{"mimic_fixed_leader.urdf", ":8: joint 'jb' mimics joint 'ja', which cannot move"}),
    [](const ::testing::TestParamInfo<BadUrdf>& info) {
      std::string name = info.param.file;
      return name.substr(0, name.find('.'));
    });

// Found by tests/fuzz (fuzz_ir_json, fuzz_urdf): names reach the IR and generated C++; the loader
// refuses them before urdfdom and rbdc's own reading could disagree, with the file and line.
TEST(UrdfLoader, NamesMustBePlainText) {
  EXPECT_THAT(model_error([] { load_urdf(data_path("control_char_name.urdf")); }),
              HasSubstr("control_char_name.urdf:6: link name 'arm\\x0ax' is not plain text"));
}

// urdfdom formats its error about an unreadable number with the number's text as the format string:
// "1%s%s" as a mass crashed the process. The outline refuses a '%' in any attribute urdfdom reads as
// numbers (tests/data/percent_in_number.urdf, also a fuzz_urdf seed), before urdfdom sees it.
TEST(UrdfLoader, PercentInANumberIsRefusedBeforeUrdfdom) {
  EXPECT_THAT(model_error([] { load_urdf(data_path("percent_in_number.urdf")); }),
              HasSubstr("percent_in_number.urdf:7: link 'arm': <mass> attribute 'value' holds a '%', "
                        "which no number has"));
}

}  // namespace
}  // namespace rbdc
