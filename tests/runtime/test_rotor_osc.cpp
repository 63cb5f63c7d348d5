// Paper 001's operational-space recursions with geared rotors and armature (docs/runtime.md,
// "Rotors and armature"): against the closed forms, which take the rotors in through M, c and g, and
// against forward dynamics.
#include <gtest/gtest.h>


#include "rbdc/forward_dynamics.hpp"
#include "rbdc/jacobian.hpp"
#include "rbdc/osc.hpp"
#include "rotor_robots.hpp"
#include "test_robots.hpp"

namespace rbdc::test {
namespace {

double relative(const MatrixX& a, const MatrixX& b) { return (a - b).norm() / b.norm(); }

std::vector<Model> floating_rotor_robots() {
  std::vector<Model> robots;
  for (const Model& m : rotor_robots()) {
    if (m.floating_base) robots.push_back(m);
  }
  return robots;
}

TEST(RotorOsc, OpenChainRecursionEqualsClosedForm) {
  RandomState rs(31);
  for (const Model& m : floating_rotor_robots()) {
    Data data(m);
    OscReferenceData closed_form(m);
    for (int trial = 0; trial < 10; ++trial) {
      const VectorX q = rs.configuration(m), v = rs.vector(m.nv, 2.0);
      const Matrix3X f = rs.forces(m);
      const OscQuantities recursion = osc_open_chain(m, data, q, v, f);
      const OscQuantities reference = osc_closed_form(m, data, closed_form, q, v, f);
      EXPECT_LE(relative(recursion.Lambda, reference.Lambda), 1e-10) << m.name;
      EXPECT_LE(relative(recursion.JbarT, reference.JbarT), 1e-10) << m.name;
      EXPECT_LE(relative(recursion.b, reference.b), 1e-10) << m.name;
    }
  }
}

// Λ_t a[0:6] + b_t = J̄_tᵀ τ with a from forward dynamics (f_t = 0), and the rotors matter.
TEST(RotorOsc, TaskEquationHoldsForForwardDynamics) {
  RandomState rs(37);
  for (const Model& m : floating_rotor_robots()) {
    Data data(m);
    const VectorX q = rs.configuration(m), v = rs.vector(m.nv, 2.0);
    const VectorX tau = rs.vector(m.num_joints(), 5.0);
    const Matrix3X f = rs.forces(m);
    const VectorX a = forward_dynamics(m, data, q, v, tau, f);
    const OscQuantities osc = osc_open_chain(m, data, q, v, f);
    const Vector6 rhs = osc.JbarT * tau;
    EXPECT_LE((osc.Lambda * a.head<6>() + osc.b - rhs).norm(), 1e-10 * (1 + rhs.norm() + osc.b.norm())) << m.name;
    Model plain = m;
    plain.has_rotors = false;
    Data plain_data(plain);
    EXPECT_GT(relative(osc_open_chain(plain, plain_data, q, v, f).b, osc.b), 1e-4) << m.name;
  }
}

// The big-ground-inertia closed chain (Table 2) against the constrained closed form at stance states
// (feet velocities zero), on the Mini Cheetah with the test rotors, at the heuristic ground mass
// (Eq. 58). The rotors' reflected inertia raises the truncation error ~50x at a given ground mass
// (measured: Λ 3e-8 → 3e-6, b 2e-8 → 6e-7; the best ground mass moves up about a decade), so the
// bound is looser than test_osc.cpp's study without rotors.
TEST(RotorOsc, ClosedChainApproximatesConstrainedClosedForm) {
  RandomState rs(41);
  const Model m = with_rotors(mini_cheetah());
  Data data(m);
  OscReferenceData closed_form(m);
  const std::vector<int> contacts = {0, 1, 2, 3};
  for (int trial = 0; trial < 4; ++trial) {
    const VectorX q = rs.configuration(m);
    const MatrixX J = feet_jacobian(m, data, q);
    VectorX v = rs.vector(m.nv, 1.0);
    v -= J.transpose() * (J * J.transpose()).ldlt().solve(J * v);
    const OscQuantities reference = osc_closed_form_constrained(m, data, closed_form, q, v, contacts);
    const OscQuantities recursion = osc_closed_chain(m, data, q, v, contacts);
    EXPECT_LE(relative(recursion.Lambda, reference.Lambda), 2e-5) << "trial " << trial;
    EXPECT_LE(relative(recursion.b, reference.b), 2e-5) << "trial " << trial;
  }
}

}  // namespace
}  // namespace rbdc::test
