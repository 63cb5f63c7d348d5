// rbdc-sim --rotors (control/drive_train.hpp): the trot robot with MIT's rotors as bodies, reduced to
// armature, or without them; the generated rotor dynamics against the runtime; a short PD trot on the
// rotor model.
#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <stdexcept>
#include <string>

#include "rbdc/control/drive_train.hpp"
#include "rbdc/control/pd_trot.hpp"
#include "rbdc/sim/robot.hpp"
#include "rbdc/sim/run.hpp"
#include "rbdc/sim/tree_ltdl.hpp"

using namespace rbdc;

namespace {

double link_mass(const Model& m) {
  double sum = 0;
  for (const Body& b : m.bodies) sum += b.mass;
  return sum;
}

TEST(DriveTrain, ModesLoadTheRotorsAsBodiesAsArmatureOrNot) {
  const Model none = control::load_trot_robot("", ActuatorMode::None);
  EXPECT_FALSE(none.has_rotors || none.has_armature);
  const Model full = control::load_trot_robot("", ActuatorMode::Full);
  ASSERT_TRUE(full.has_rotors);
  double rotors = 0;
  for (const Joint& j : full.joints) rotors += j.rotor.mass;
  EXPECT_NEAR(link_mass(full) + rotors, 8.912, 1e-12);
  const Model armature = control::load_trot_robot("", ActuatorMode::Armature);
  EXPECT_FALSE(armature.has_rotors);
  EXPECT_NEAR(link_mass(armature), 8.252, 1e-12);
  for (int i = 1; i < armature.nb; ++i) {
    const Joint& j = armature.joints[static_cast<size_t>(i)];
    EXPECT_NEAR(j.armature, j.name.find("knee") != std::string::npos ? 0.005484 : 0.002268, 1e-6) << j.name;
  }
  // The same numbering and feet as the robot without rotors: the controller and CSV see one robot.
  ASSERT_EQ(full.nb, none.nb);
  for (int i = 0; i < none.nb; ++i) EXPECT_EQ(full.bodies[static_cast<size_t>(i)].name, none.bodies[static_cast<size_t>(i)].name);
  EXPECT_EQ(full.feet.size(), none.feet.size());
}

TEST(DriveTrain, AUrdfWithoutRotorOverlayIsRefused) {
  try {
    control::load_trot_robot(std::string(RBDC_SOURCE_DIR) + "/robots/arm7.urdf", ActuatorMode::Full);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("arm7_rotors.topology.yaml"), std::string::npos) << e.what();
  }
}

// The simulator's generated rotor dynamics (generated/mini_cheetah_rotors) against the runtime on the
// same rotor model, at random states: forward dynamics, the step terms (a₀, the feet's rows, M's
// factor), M and the feet.
TEST(DriveTrain, GeneratedRotorDynamicsEqualTheRuntime) {
  const Model model = control::load_trot_robot("", ActuatorMode::Full);
  const std::unique_ptr<sim::DynamicsModel> generated = sim::make_generated_rotor_dynamics();
  const std::unique_ptr<sim::DynamicsModel> runtime = sim::make_runtime_dynamics(model);
  ASSERT_EQ(generated->nq(), model.nq);
  std::mt19937 rng(14);
  std::uniform_real_distribution<double> u(-1, 1);
  const auto random = [&](Eigen::Index n, double scale) {
    VectorX x(n);
    for (Eigen::Index k = 0; k < n; ++k) x[k] = scale * u(rng);
    return x;
  };
  const auto relative = [](const MatrixX& a, const MatrixX& b) { return (a - b).norm() / b.norm(); };
  for (int trial = 0; trial < 5; ++trial) {
    VectorX q = random(model.nq, 1.0);
    q.segment<4>(3).normalize();
    const VectorX v = random(model.nv, 3.0), tau = random(model.nv - 6, 5.0);
    const VectorX f = random(3 * static_cast<Eigen::Index>(model.feet.size()), 30.0);
    VectorX a_gen(model.nv), a_run(model.nv);
    generated->forward_dynamics(q.data(), v.data(), tau.data(), f.data(), a_gen.data());
    runtime->forward_dynamics(q.data(), v.data(), tau.data(), f.data(), a_run.data());
    EXPECT_LT(relative(a_gen, a_run), 1e-12);
    sim::StepTerms t_gen, t_run;
    sim::TreeLtdl factor_gen(sim::dof_parents(model)), factor_run(sim::dof_parents(model));
    generated->step_terms(q.data(), v.data(), tau.data(), t_gen, factor_gen);
    runtime->step_terms(q.data(), v.data(), tau.data(), t_run, factor_run);
    EXPECT_LT(relative(t_gen.a_free, t_run.a_free), 1e-12);
    EXPECT_LT(relative(t_gen.J, t_run.J), 1e-12);
    EXPECT_LT(relative(t_gen.Jw, t_run.Jw), 1e-12);
    EXPECT_LT(relative(factor_gen.inverse_pivots(), factor_run.inverse_pivots()), 1e-12);
    MatrixX M_gen, M_run;
    generated->mass_matrix(q.data(), M_gen);
    runtime->mass_matrix(q.data(), M_run);
    EXPECT_LT(relative(M_gen, M_run), 1e-12);
    const Eigen::Index n = 3 * static_cast<Eigen::Index>(model.feet.size());
    VectorX p_gen(n), p_run(n), pd_gen(n), pd_run(n);
    generated->feet_state(q.data(), v.data(), p_gen.data(), pd_gen.data());
    runtime->feet_state(q.data(), v.data(), p_run.data(), pd_run.data());
    EXPECT_LT(relative(p_gen, p_run), 1e-12);
    EXPECT_LT(relative(pd_gen, pd_run), 1e-12);
  }
}

TEST(DriveTrain, ShortTrotWithRotorsStaysUpright) {
  const Model model = control::load_trot_robot("", ActuatorMode::Full);
  const std::unique_ptr<sim::DynamicsModel> dynamics = sim::make_runtime_dynamics(model);
  sim::Simulator simulator(*dynamics, sim::SimOptions{});
  control::PdTrotController controller(model, control::GaitParameters{}, control::PdGains{},
                                       sim::SimOptions{}.contact.foot_radius);
  sim::RunOptions options;
  options.duration = 0.3;
  options.sample_interval = 0;
  options.progress = false;
  const sim::RunSummary summary = run(simulator, controller, options);
  EXPECT_TRUE(summary.finite);
  EXPECT_GT(summary.min_trunk_height, 0.2);
}

}  // namespace
