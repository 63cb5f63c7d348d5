// Mimic couplings (rbdc/coupling.hpp): a two-finger gripper against a hand calculation, and a coupled
// model against the independent one with the constraint q_f = m q_l + o applied by hand.
#include <gtest/gtest.h>

#include "model_test_support.hpp"
#include "rbdc/bias_terms.hpp"
#include "rbdc/coupling.hpp"
#include "rbdc/crba.hpp"
#include "rbdc/inverse_dynamics.hpp"
#include "rbdc/kinematics.hpp"
#include "rbdc/osc.hpp"
#include "rbdc/urdf_loader.hpp"

namespace rbdc {
namespace {

using test::data_path;

Model load(const std::string& file, bool floating_base, MimicMode mimic,
           const Vector3& gravity = Vector3(0, 0, -9.81)) {
  UrdfOptions opts;
  opts.floating_base = floating_base;
  opts.mimic = mimic;
  opts.gravity = gravity;
  return load_urdf(data_path(file), opts);
}

// tests/data/two_finger_gripper.urdf, fixed palm, gravity along -y: y_left = 0.05 + q (0.1 kg),
// y_right = -(0.05 + 2 q + 0.01) (0.2 kg). So G = (1, 2)ᵀ, M' = m_l + 4 m_r = 0.9 kg,
// V = 9.81 (m_l y_left + m_r y_right) gives g' = dV/dq = 9.81 (m_l - 2 m_r) = -2.943 N, c' = 0.
TEST(Coupling, TwoFingerGripperMatchesTheHandCalculation) {
  const Model m = load("two_finger_gripper.urdf", false, MimicMode::Couple, Vector3(0, -9.81, 0));
  Data data(m);
  const CoupledCoordinates c = coupled_coordinates(m);
  ASSERT_EQ(c.nq, 1);
  ASSERT_EQ(c.nv, 1);
  EXPECT_EQ(c.num_joints(), 1);
  const MatrixX G = coupling_matrix(m);
  EXPECT_EQ(G, (MatrixX(2, 1) << 1, 2).finished());
  const VectorX q = VectorX::Constant(1, 0.02), v = VectorX::Constant(1, 0.3);
  const VectorX q_tree = expand_configuration(m, q);
  EXPECT_TRUE(q_tree.isApprox((VectorX(2) << 0.02, 0.05).finished(), 1e-15));
  EXPECT_EQ(independent_configuration(m, q_tree), q);
  const Matrix3X& p = feet_positions(m, data, q_tree);
  EXPECT_TRUE(p.col(0).isApprox(Vector3(0, 0.07, 0), 1e-15));
  EXPECT_TRUE(p.col(1).isApprox(Vector3(0, -0.10, 0), 1e-15));
  const MatrixX M = G.transpose() * mass_matrix(m, data, q_tree) * G;
  EXPECT_NEAR(M(0, 0), 0.9, 1e-15);
  EXPECT_NEAR((G.transpose() * gravity_terms(m, data, q_tree))(0), -2.943, 1e-13);
  EXPECT_NEAR((G.transpose() * quadratic_velocity_terms(m, data, q_tree, G * v))(0), 0.0, 1e-15);
  const VectorX a = coupled_forward_dynamics(m, data, q, v, VectorX::Constant(1, 1.0), Matrix3X::Zero(3, 2));
  EXPECT_NEAR(a(0), (1 + 2.943) / 0.9, 1e-12);
}

// tests/data/mimic_chain.urdf: jb = -ja + 0.25, jc = -3 ja + 1.25 (jc mimics jb), three axes.
MatrixX hand_G(bool floating_base) {
  const int root = floating_base ? 6 : 0;
  MatrixX G = MatrixX::Zero(root + 3, root + 1);
  G.topLeftCorner(root, root).setIdentity();
  G.bottomRightCorner(3, 1) << 1, -1, -3;
  return G;
}

VectorX hand_q_tree(const VectorX& q, bool floating_base) {
  const int root = floating_base ? 7 : 0;
  VectorX q_tree(root + 3);
  q_tree.head(root) = q.head(root);
  const double qa = q[root];
  q_tree.tail(3) << qa, -qa + 0.25, -3 * qa + 1.25;
  return q_tree;
}

TEST(Coupling, CoupledModelIsTheIndependentOneWithTheConstraintAppliedByHand) {
  const Model coupled = load("mimic_chain.urdf", true, MimicMode::Couple);
  const Model independent = load("mimic_chain.urdf", true, MimicMode::Independent);
  ASSERT_TRUE(independent.couplings.empty());
  Data coupled_data(coupled), data(independent);
  const MatrixX G = hand_G(true);
  EXPECT_EQ(coupling_matrix(coupled), G);
  VectorX q(8);
  q << 0.1, -0.2, 0.3, 0.5, 0.5, -0.5, 0.5, 0.7;  // unit quaternion
  const VectorX v = (VectorX(7) << 0.3, -0.1, 0.2, 0.5, -0.4, 0.1, 1.3).finished();
  const VectorX tau = VectorX::Constant(1, 2.5);
  const VectorX q_tree = hand_q_tree(q, true);
  EXPECT_TRUE(expand_configuration(coupled, q).isApprox(q_tree, 1e-15));
  // The coupled forward dynamics satisfies the independent model's RNEA projected on the
  // constraint: Gᵀ ID(q_tree, G v, G a) = (0, τ) — the constraint forces do no work along G.
  const VectorX a = coupled_forward_dynamics(coupled, coupled_data, q, v, tau, Matrix3X::Zero(3, 1));
  const VectorX projected = G.transpose() * inverse_dynamics(independent, data, q_tree, G * v, G * a);
  EXPECT_TRUE(projected.head(6).isZero(1e-11)) << projected.transpose();
  EXPECT_NEAR(projected(6), 2.5, 1e-11);
}

// With G constant the projected bias has no extra velocity-product term: for one coordinate,
// Lagrange gives c' = ½ (dM'/dq) v². Checked against a central difference of M' = Gᵀ M G.
TEST(Coupling, ProjectedBiasNeedsNoExtraTermWhenGIsConstant) {
  const Model m = load("mimic_chain.urdf", false, MimicMode::Couple, Vector3::Zero());
  Data data(m);
  const MatrixX G = hand_G(false);
  const auto coupled_M = [&](double qa) {
    return (G.transpose() * mass_matrix(m, data, expand_configuration(m, VectorX::Constant(1, qa))) * G)(0, 0);
  };
  const double qa = 0.4, v = 1.7, h = 1e-6;
  const double dM = (coupled_M(qa + h) - coupled_M(qa - h)) / (2 * h);
  const VectorX q_tree = expand_configuration(m, VectorX::Constant(1, qa));
  const double c = (G.transpose() * quadratic_velocity_terms(m, data, q_tree, G * VectorX::Constant(1, v)))(0);
  EXPECT_GT(std::abs(dM), 1e-3);  // the check has something to see
  EXPECT_NEAR(c, 0.5 * dM * v * v, 1e-8);
}

TEST(Coupling, TheOscRecursionRefusesCoupledModels) {
  const Model m = load("mimic_chain.urdf", true, MimicMode::Couple);
  Data data(m);
  VectorX q = VectorX::Zero(m.nq);
  q[3] = 1;
  try {
    osc_open_chain(m, data, q, VectorX::Zero(m.nv), Matrix3X::Zero(3, 1));
    ADD_FAILURE() << "no error";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("has mimic couplings"), std::string::npos) << e.what();
  }
}

TEST(Coupling, ModelsWithoutCouplingsHaveTheIdentity) {
  const Model m = load("mimic_chain.urdf", false, MimicMode::Independent);
  EXPECT_EQ(coupling_matrix(m), MatrixX::Identity(3, 3));
  const VectorX q = (VectorX(3) << 0.1, 0.2, 0.3).finished();
  EXPECT_EQ(expand_configuration(m, q), q);
  EXPECT_THROW(expand_configuration(m, VectorX::Zero(2)), std::invalid_argument);
}

}  // namespace
}  // namespace rbdc
