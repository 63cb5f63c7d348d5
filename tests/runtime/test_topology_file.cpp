// Topology files: the Mini Cheetah overlay and standalone forms give the URDF's model; bad files are
// refused with messages naming the file and the problem.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "model_test_support.hpp"
#include "rbdc/ir_json.hpp"
#include "rbdc/topology_file.hpp"
#include "rbdc/urdf_loader.hpp"

namespace rbdc {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using test::data_path;
using test::model_error;
using test::source_path;

const std::string kMiniCheetah = source_path("robots/mini_cheetah.urdf");

Model mini_cheetah_with_overlay(const std::string& topology) {
  UrdfOptions opts;
  opts.topology_file = topology;
  return load_urdf(kMiniCheetah, opts);
}

void expect_same_model(const Model& a, const Model& b) {
  ASSERT_EQ(a.nb, b.nb);
  EXPECT_EQ(a.pred, b.pred);
  EXPECT_EQ(a.succ, b.succ);
  EXPECT_EQ(a.parent, b.parent);
  EXPECT_EQ(a.support, b.support);
  EXPECT_EQ(a.children, b.children);
  EXPECT_EQ(a.subtree, b.subtree);
  for (size_t i = 0; i < static_cast<size_t>(a.nb); ++i) {
    EXPECT_EQ(a.bodies[i].name, b.bodies[i].name);
    EXPECT_EQ(a.joints[i].name, b.joints[i].name);
    EXPECT_LT((a.inertia[i] - b.inertia[i]).cwiseAbs().maxCoeff(), 1e-15) << "body " << i;
    EXPECT_LT((a.X_tree[i] - b.X_tree[i]).cwiseAbs().maxCoeff(), 1e-15) << "joint " << i;
    EXPECT_EQ(a.motion_subspace[i], b.motion_subspace[i]);
  }
  ASSERT_EQ(a.feet.size(), b.feet.size());
  for (size_t k = 0; k < a.feet.size(); ++k) {
    EXPECT_EQ(a.feet[k].name, b.feet[k].name);
    EXPECT_EQ(a.feet[k].body, b.feet[k].body);
    EXPECT_EQ(a.feet[k].offset, b.feet[k].offset);
  }
  ASSERT_EQ(a.frames.size(), b.frames.size());
  for (size_t k = 0; k < a.frames.size(); ++k) {
    EXPECT_EQ(a.frames[k].name, b.frames[k].name);
    EXPECT_EQ(a.frames[k].body, b.frames[k].body);
    EXPECT_LT((a.frames[k].rotation - b.frames[k].rotation).cwiseAbs().maxCoeff(), 1e-15) << a.frames[k].name;
    EXPECT_LT((a.frames[k].translation - b.frames[k].translation).cwiseAbs().maxCoeff(), 1e-15) << a.frames[k].name;
  }
}

TEST(TopologyFile, MiniCheetahOverlayReadsEquation1AndTheFeet) {
  const Topology t = read_topology(source_path("robots/mini_cheetah.topology.yaml"));
  EXPECT_EQ(t.pred, (std::vector<int>{0, 1, 2, 0, 4, 5, 0, 7, 8, 0, 10, 11}));
  EXPECT_EQ(t.succ, (std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}));
  ASSERT_EQ(t.feet.size(), 4u);
  EXPECT_EQ(t.feet[1].link, "RF_knee");
  EXPECT_EQ(t.feet[1].offset, Vector3(0, 0.004, -0.195));
}

TEST(TopologyFile, UrdfWithOverlayEqualsUrdfAloneAndStandalone) {
  const Model urdf_only = load_urdf(kMiniCheetah);
  const Model overlay = mini_cheetah_with_overlay(source_path("robots/mini_cheetah.topology.yaml"));
  const Model standalone = load_topology(data_path("mini_cheetah_standalone.yaml"));
  expect_same_model(urdf_only, overlay);
  expect_same_model(overlay, standalone);
  EXPECT_EQ(to_ir_json(overlay), to_ir_json(standalone));
}

TEST(TopologyFile, OverlayRenumbersBodiesAndPlacesFeetOnMergedLinks) {
  const Model m = mini_cheetah_with_overlay(data_path("topology_reordered.yaml"));
  EXPECT_EQ(m.bodies[1].name, "LH_abad");
  EXPECT_EQ(m.bodies[12].name, "RF_knee");
  EXPECT_EQ(m.joints[1].translation, Vector3(-0.19, 0.049, 0));
  ASSERT_EQ(m.feet.size(), 1u);
  EXPECT_EQ(m.feet[0].body, 3);  // LH_foot is merged into LH_knee, body 3 in this numbering
  EXPECT_EQ(m.feet[0].offset, Vector3(0, -0.004, -0.195));
}

TEST(TopologyFile, OverlayDisagreeingWithTheUrdfIsRefused) {
  EXPECT_THAT(model_error([] { mini_cheetah_with_overlay(data_path("topology_wrong_parent.yaml")); }),
              AllOf(HasSubstr("topology_wrong_parent.yaml"), HasSubstr("joint 3 (PRED 0, SUCC 3)"),
                    HasSubstr("hangs body 'LF_knee' from 'trunk'"), HasSubstr("its parent is 'LF_hip'")));
  EXPECT_THAT(model_error([] { mini_cheetah_with_overlay(data_path("topology_merged_link.yaml")); }),
              HasSubstr("body 'LF_foot' is merged by a fixed joint into body 'LF_knee'"));
  EXPECT_THAT(model_error([] { mini_cheetah_with_overlay(data_path("topology_irregular.yaml")); }),
              HasSubstr("joint 3 (PRED 2, SUCC 4): must join body 3"));
}

TEST(TopologyFile, DeclaredFramesComposeWithTheirLinksPlacement) {
  const Model m = mini_cheetah_with_overlay(data_path("topology_frames.yaml"));
  const auto named = [&](const std::string& name) {
    for (const Frame& f : m.frames) if (f.name == name) return f;
    ADD_FAILURE() << "no frame " << name;
    return Frame{};
  };
  const Frame foot = named("LF_foot"), sensor = named("LF_toe_sensor");
  EXPECT_EQ(sensor.body, foot.body);  // LF_foot is merged into LF_knee
  // the declared pose (xyz in LF_foot, rpy 0 0.5 0) composed with LF_foot's placement in LF_knee
  const Matrix3 foot_R_sensor = Eigen::AngleAxisd(0.5, Vector3::UnitY()).toRotationMatrix();
  EXPECT_LT((sensor.translation - (foot.translation + foot.rotation.transpose() * Vector3(0.01, 0, 0))).norm(), 1e-15);
  EXPECT_LT((sensor.rotation - (foot.rotation.transpose() * foot_R_sensor).transpose()).norm(), 1e-15);
}

TEST(TopologyFile, BadFramesAreRefused) {
  EXPECT_THAT(model_error([] { mini_cheetah_with_overlay(data_path("topology_frame_unknown_link.yaml")); }),
              AllOf(HasSubstr("topology_frame_unknown_link.yaml"),
                    HasSubstr("frame 'shin_camera': link 'LF_shin' is not a link of the model")));
  EXPECT_THAT(model_error([] { mini_cheetah_with_overlay(data_path("topology_frame_duplicate.yaml")); }),
              HasSubstr("frame 'trunk': the name is used twice"));
}

TEST(TopologyFile, BadStandaloneFilesAreRefused) {
  EXPECT_THAT(model_error([] { load_topology(data_path("standalone_missing_inertia.yaml")); }),
              AllOf(HasSubstr("standalone_missing_inertia.yaml"), HasSubstr("no entry for body 'arm'")));
  EXPECT_THAT(model_error([] { load_topology(data_path("standalone_bad_type.yaml")); }),
              HasSubstr("joint 'shoulder': unsupported type 'planar'"));
  EXPECT_THAT(model_error([] { load_topology(data_path("malformed.yaml")); }),
              AllOf(HasSubstr("malformed.yaml:"), HasSubstr("malformed YAML")));
  EXPECT_THAT(model_error([] { load_topology(data_path("no_such_file.yaml")); }), HasSubstr("cannot open file"));
}

// YAML allows a list or a mapping as a key; found by fuzz_topology (the seeds of tests/fuzz/corpus).
TEST(TopologyFile, KeysThatAreNotNamesAreRefused) {
  const std::string frame = source_path("tests/fuzz/corpus/topology/frame_key_not_a_name.yaml");
  EXPECT_THAT(model_error([&] { load_topology(frame); }),
              HasSubstr("frame_key_not_a_name.yaml:14: frame 'tool': expected a name as the key"));
  const std::string actuator = source_path("tests/fuzz/corpus/topology/actuator_key_not_a_name.yaml");
  EXPECT_THAT(model_error([&] { load_topology(actuator); }),
              HasSubstr("actuator_key_not_a_name.yaml:13: actuator of joint 'shoulder': expected a name as the key"));
}

TEST(TopologyFile, DetectedByExtension) {
  EXPECT_TRUE(is_topology_path("robots/mini_cheetah.topology.yaml"));
  EXPECT_TRUE(is_topology_path("a.yml"));
  EXPECT_FALSE(is_topology_path("robots/mini_cheetah.urdf"));
}

}  // namespace
}  // namespace rbdc
