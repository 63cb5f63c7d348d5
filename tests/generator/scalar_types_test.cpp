// The generated Mini Cheetah code instantiated with float, long double and __float128 (through the
// Eigen surface) agrees with double to the precision of the narrower type. The constants are
// written as double literals, so the wide types compute the same function as double, more exactly.
// The lane functions (scene limb_lanes, the legs in SIMD lanes) agree with their scalar namesakes
// (scenes full and derivatives) in every scalar type, and mass_matrix_lower writes M's lower
// triangle alone. The looped solve's kernels (rbdc_gen/solve.hpp) run in vector runs of 8 doubles
// and 16 floats and one column at a time for the other types: contact_dynamics_derivatives (48
// columns) agrees across them.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "mini_cheetah/contact/contact_dynamics_derivatives.hpp"
#include "mini_cheetah/derivatives/inverse_dynamics_derivatives.hpp"
#include "mini_cheetah/full.hpp"
#include "mini_cheetah/limb_lanes.hpp"

namespace {

namespace mc = rbdc_gen::mini_cheetah::full;
namespace lanes = rbdc_gen::mini_cheetah::limb_lanes;
namespace mc_derivatives = rbdc_gen::mini_cheetah::derivatives;
using LongMatrix = Eigen::Matrix<long double, Eigen::Dynamic, Eigen::Dynamic>;

struct State {
  mc::ConfigVector<double> q;
  mc::TangentVector<double> v, a;
  mc::JointVector<double> tau;
  mc::FeetMatrix<double> f;
};

State random_state(unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  State s;
  for (int k = 0; k < mc::nq; ++k) s.q[k] = u(rng);
  s.q.segment<4>(3).normalize();
  for (int k = 0; k < mc::nv; ++k) s.v[k] = 2 * u(rng), s.a[k] = 5 * u(rng);
  for (int k = 0; k < mc::n_joints; ++k) s.tau[k] = 10 * u(rng);
  for (int k = 0; k < 3 * mc::n_feet; ++k) s.f.data()[k] = 50 * u(rng);
  return s;
}

/// Every output of the functions under test, in one long-double matrix per function.
struct Outputs {
  LongMatrix M, tau, a, J, Lambda;
};

template <class T>
Outputs evaluate(const State& s) {
  const mc::ConfigVector<T> q = s.q.cast<T>();
  const mc::TangentVector<T> v = s.v.cast<T>(), acc = s.a.cast<T>();
  const mc::JointVector<T> tau = s.tau.cast<T>();
  const mc::FeetMatrix<T> f = s.f.cast<T>();
  mc::MassMatrix<T> M;
  mc::TangentVector<T> id, fd;
  mc::FeetJacobian<T> J;
  mc::OscInertia<T> Lambda;
  mc::OscJacobianT<T> JbarT;
  mc::Wrench<T> b;
  mc::mass_matrix(q, M);
  mc::inverse_dynamics(q, v, acc, id);
  mc::forward_dynamics(q, v, tau, f, fd);
  mc::feet_jacobian(q, J);
  mc::osc_closed_chain(q, v, T(50), Lambda, JbarT, b);
  return {M.template cast<long double>(), id.template cast<long double>(), fd.template cast<long double>(),
          J.template cast<long double>(), Lambda.template cast<long double>()};
}

/// Largest entry difference relative to the largest entry of the reference.
long double relative_difference(const LongMatrix& x, const LongMatrix& reference) {
  return (x - reference).cwiseAbs().maxCoeff() / reference.cwiseAbs().maxCoeff();
}

template <class T>
void expect_agreement(long double tolerance, unsigned seed) {
  const State s = random_state(seed);
  const Outputs wide = evaluate<double>(s), narrow = evaluate<T>(s);
  EXPECT_LT(relative_difference(narrow.M, wide.M), tolerance);
  EXPECT_LT(relative_difference(narrow.tau, wide.tau), tolerance);
  EXPECT_LT(relative_difference(narrow.a, wide.a), tolerance);
  EXPECT_LT(relative_difference(narrow.J, wide.J), tolerance);
  EXPECT_LT(relative_difference(narrow.Lambda, wide.Lambda), tolerance);
}

TEST(GeneratedScalarTypes, FloatAgreesWithDoubleToFloatPrecision) {
  for (unsigned seed = 0; seed < 10; ++seed) expect_agreement<float>(1e-4L, seed);
}

TEST(GeneratedScalarTypes, LongDoubleAgreesWithDouble) {
  for (unsigned seed = 0; seed < 10; ++seed) expect_agreement<long double>(1e-12L, seed);
}

#if defined(RBDC_HAS_FLOAT128)
TEST(GeneratedScalarTypes, Float128AgreesWithDouble) {
  for (unsigned seed = 0; seed < 10; ++seed) expect_agreement<rbdc_gen::float128>(1e-12L, seed);
}

// Quad is really computed wider than double: it matches long double far below double round-off.
TEST(GeneratedScalarTypes, Float128AgreesWithLongDoubleBeyondDoublePrecision) {
  for (unsigned seed = 0; seed < 10; ++seed) {
    const State s = random_state(seed);
    const Outputs quad = evaluate<rbdc_gen::float128>(s), extended = evaluate<long double>(s);
    EXPECT_LT(relative_difference(extended.M, quad.M), 1e-16L);
    EXPECT_LT(relative_difference(extended.a, quad.a), 1e-15L);
    EXPECT_LT(relative_difference(extended.Lambda, quad.Lambda), 1e-15L);
  }
}
#endif

/// contact_dynamics_derivatives' six outputs in T (raw-pointer overload), one after the other.
template <class T>
LongMatrix contact_derivatives(const State& s) {
  const int nv = mc::nv, nj = mc::n_joints, m = 3 * 4;  // four feet in contact
  std::vector<T> q(s.q.data(), s.q.data() + mc::nq), v(s.v.data(), s.v.data() + nv);
  std::vector<T> tau(s.tau.data(), s.tau.data() + nj);
  const int sizes[6] = {nv * nv, nv * nv, nv * nj, m * nv, m * nv, m * nj};
  std::vector<T> out[6];
  for (int k = 0; k < 6; ++k) out[k].resize(sizes[k]);
  rbdc_gen::mini_cheetah::contact::contact_dynamics_derivatives(
      q.data(), v.data(), tau.data(), out[0].data(), out[1].data(), out[2].data(), out[3].data(),
      out[4].data(), out[5].data());
  LongMatrix all(sizes[0] + sizes[1] + sizes[2] + sizes[3] + sizes[4] + sizes[5], 1);
  int row = 0;
  for (const auto& block : out)
    for (const T x : block) all(row++, 0) = static_cast<long double>(x);
  return all;
}

TEST(GeneratedScalarTypes, LoopedSolveAgreesAcrossScalarTypes) {
  for (unsigned seed = 0; seed < 3; ++seed) {
    const State s = random_state(seed);
    const LongMatrix wide = contact_derivatives<double>(s);
    EXPECT_LT(relative_difference(contact_derivatives<float>(s), wide), 1e-3L);
    EXPECT_LT(relative_difference(contact_derivatives<long double>(s), wide), 1e-10L);
  }
}

/// The lane functions against their scalar namesakes, both in T.
template <class T>
void expect_lanes_equal(long double tolerance, unsigned seed) {
  const State s = random_state(seed);
  const mc::ConfigVector<T> q = s.q.cast<T>();
  const mc::TangentVector<T> v = s.v.cast<T>(), acc = s.a.cast<T>();
  const mc::JointVector<T> tau = s.tau.cast<T>();
  const mc::FeetMatrix<T> f = s.f.cast<T>();
  mc::TangentVector<T> scalar, lane;
  mc::forward_dynamics(q, v, tau, f, scalar);
  lanes::forward_dynamics_lanes(q, v, tau, f, lane);
  EXPECT_LT(relative_difference(lane.template cast<long double>(), scalar.template cast<long double>()), tolerance);
  mc::inverse_dynamics(q, v, acc, scalar);
  lanes::inverse_dynamics_lanes(q, v, acc, lane);
  EXPECT_LT(relative_difference(lane.template cast<long double>(), scalar.template cast<long double>()), tolerance);
  mc::bias(q, v, scalar);
  lanes::bias_lanes(q, v, lane);
  EXPECT_LT(relative_difference(lane.template cast<long double>(), scalar.template cast<long double>()), tolerance);
  mc::MassMatrix<T> M, M_lanes;
  mc::mass_matrix(q, M);
  lanes::mass_matrix_lanes(q, M_lanes);
  EXPECT_LT(relative_difference(M_lanes.template cast<long double>(), M.template cast<long double>()), tolerance);
  // M's lower triangle alone, scalar and in lanes: the triangle equals M's, the entries above stay
  mc::MassMatrix<T> lower = mc::MassMatrix<T>::Zero(), lower_lanes = mc::MassMatrix<T>::Zero();
  lanes::mass_matrix_lower(q, lower);
  lanes::mass_matrix_lower_lanes(q, lower_lanes);
  const mc::MassMatrix<T> M_lower = M.template triangularView<Eigen::Lower>();
  EXPECT_LT(relative_difference(lower.template cast<long double>(), M_lower.template cast<long double>()), tolerance);
  EXPECT_LT(relative_difference(lower_lanes.template cast<long double>(), M_lower.template cast<long double>()), tolerance);
  mc::OscInertia<T> Lambda, Lambda_lanes;
  mc::OscJacobianT<T> JbarT, JbarT_lanes;
  mc::Wrench<T> b, b_lanes;
  mc::osc_open_chain(q, v, f, Lambda, JbarT, b);
  lanes::osc_open_chain_lanes(q, v, f, Lambda_lanes, JbarT_lanes, b_lanes);
  EXPECT_LT(relative_difference(Lambda_lanes.template cast<long double>(), Lambda.template cast<long double>()), tolerance);
  EXPECT_LT(relative_difference(JbarT_lanes.template cast<long double>(), JbarT.template cast<long double>()), tolerance);
  EXPECT_LT(relative_difference(b_lanes.template cast<long double>(), b.template cast<long double>()), tolerance);
  mc::MassMatrix<T> dq, dv, dq_lanes, dv_lanes;
  mc_derivatives::inverse_dynamics_derivatives(q, v, acc, dq, dv);
  lanes::inverse_dynamics_derivatives_lanes(q, v, acc, dq_lanes, dv_lanes);
  EXPECT_LT(relative_difference(dq_lanes.template cast<long double>(), dq.template cast<long double>()), tolerance);
  EXPECT_LT(relative_difference(dv_lanes.template cast<long double>(), dv.template cast<long double>()), tolerance);
}

TEST(GeneratedScalarTypes, LaneFunctionsEqualScalarOnes) {
  for (unsigned seed = 0; seed < 3; ++seed) {
    expect_lanes_equal<double>(1e-13L, seed);
    expect_lanes_equal<float>(1e-4L, seed);
    expect_lanes_equal<long double>(1e-16L, seed);
#if defined(RBDC_HAS_FLOAT128)
    expect_lanes_equal<rbdc_gen::float128>(1e-16L, seed);
#endif
  }
}

}  // namespace
