// The public URDFs in ${RBDC_SHARED_DIR}/robots load with the right DoF and total mass, or are refused
// with a clear message. The expected mass is summed from the file's <mass value="…"> texts, a route
// independent of urdfdom and of the fixed-joint lumping.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "model_test_support.hpp"
#include "rbdc/urdf_loader.hpp"

namespace rbdc {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using test::model_error;
using test::shared_robot_path;

double mass_in_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  const std::string s = text.str();
  const std::string tag = "<mass value=\"";  // the form all the shared files use
  double sum = 0;
  for (size_t at = s.find(tag); at != std::string::npos; at = s.find(tag, at + 1)) {
    sum += std::stod(s.substr(at + tag.size()));
  }
  return sum;
}

double total_mass(const Model& m) {
  double sum = 0;
  for (const Body& b : m.bodies) sum += b.mass;
  return sum;
}

struct SharedRobot {
  const char* file;
  bool floating_base;
  bool lock_mimic;
  int dofs;  ///< 1-DoF joints after merging fixed and locked joints
};

void PrintTo(const SharedRobot& r, std::ostream* os) { *os << r.file; }

class SharedRobotFile : public ::testing::TestWithParam<SharedRobot> {};

TEST_P(SharedRobotFile, LoadsWithItsDofsAndMass) {
  const SharedRobot& r = GetParam();
  const std::string path = shared_robot_path(r.file);
  UrdfOptions opts;
  opts.floating_base = r.floating_base;
  opts.lock_mimic = r.lock_mimic;
  const Model m = load_urdf(path, opts);
  EXPECT_EQ(m.num_joints(), r.dofs);
  EXPECT_EQ(m.nv, r.dofs + (r.floating_base ? 6 : 0));
  const double expected = mass_in_file(path);
  EXPECT_GT(expected, 0);
  EXPECT_NEAR(total_mass(m), expected, 1e-9 * expected);
}

INSTANTIATE_TEST_SUITE_P(
    Robots, SharedRobotFile,
    ::testing::Values(SharedRobot{"anymal_b.urdf", true, false, 12}, SharedRobot{"solo12.urdf", true, false, 12},
                      SharedRobot{"mini_cheetah_pybullet.urdf", true, false, 12},
                      SharedRobot{"iiwa14.urdf", false, false, 7},
                      // Panda: 7 arm joints + finger 1; finger 2 mimics finger 1 and is locked.
                      SharedRobot{"panda.urdf", false, true, 8},
                      // Talos: 44 revolute joints, 12 of them mimic gripper joints.
                      SharedRobot{"talos.urdf", true, true, 32}),
    [](const ::testing::TestParamInfo<SharedRobot>& info) {
      std::string name = info.param.file;
      return name.substr(0, name.find('.'));
    });

TEST(SharedRobots, MimicJointsAreRefusedByDefault) {
  EXPECT_THAT(model_error([] { load_urdf(shared_robot_path("panda.urdf")); }),
              AllOf(HasSubstr("panda.urdf"), HasSubstr("joint 'panda_finger_joint2' mimics joint 'panda_finger_joint1'"),
                    HasSubstr("lock_mimic")));
  EXPECT_THAT(model_error([] { load_urdf(shared_robot_path("talos.urdf")); }),
              AllOf(HasSubstr("talos.urdf"), HasSubstr("mimics joint 'gripper_left_joint'")));
}

TEST(SharedRobots, RevoluteJointsWithoutLimitsLoadUnlimitedWithAWarning) {
  std::vector<std::string> warnings;
  UrdfOptions opts;
  opts.floating_base = false;
  const Model m = load_urdf(shared_robot_path("iiwa14.urdf"), opts, &warnings);
  EXPECT_TRUE(std::isinf(m.joints[1].upper));
  ASSERT_FALSE(warnings.empty());
  EXPECT_THAT(warnings[0], HasSubstr("joint 'iiwa_joint_1' has no <limit>"));
}

}  // namespace
}  // namespace rbdc
