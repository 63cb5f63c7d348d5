// joint_sincos (rbdc_gen/support.hpp): the vectorised polynomials for double and float against the
// long double libm (glibc's sinl/cosl, far more accurate than a double ulp) over the range robots
// use, at the hard points (next to multiples of π/2), at edge values, and the fallbacks: within
// kFoldedAngle an absolute bound (sincos_folded), beyond it one ulp (sincos_reduced) and libm.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "rbdc_gen/support.hpp"

namespace {

constexpr int kBlock = 12;  // as many angles as the Mini Cheetah has joints

/// |value − reference| in units of the last place of the reference rounded to T.
template <class T>
double ulp_error(T value, long double reference) {
  const T rounded = static_cast<T>(reference);
  T ulp = std::nextafter(std::fabs(rounded), std::numeric_limits<T>::infinity()) - std::fabs(rounded);
  if (rounded == T(0)) ulp = std::numeric_limits<T>::denorm_min();
  return static_cast<double>(std::fabs(static_cast<long double>(value) - reference) / ulp);
}

/// The largest errors of one set of angles: absolute within kFoldedAngle, in ulp beyond it.
struct MaxError {
  double sin = 0, cos = 0;                // ulp, |x| > kFoldedAngle (every angle for float)
  double folded_sin = 0, folded_cos = 0;  // absolute, |x| <= kFoldedAngle (double only)
};

/// Within sincos_folded's range its absolute error: 3.2e-16 over 16 million angles, 3.5e-16 in its
/// comments and docs/performance.md.
constexpr double kFoldedAbsoluteError = 3.5e-16;

/// Largest sin and cos errors of joint_sincos<T> over `angles`, evaluated kBlock at a time.
template <class T>
MaxError max_error(const std::vector<T>& angles) {
  MaxError worst;
  for (size_t first = 0; first + kBlock <= angles.size(); first += kBlock) {
    T block[kBlock];
    for (int i = 0; i < kBlock; ++i) block[i] = angles[first + i];
    const auto trig = rbdc_gen::joint_sincos(block);
    for (int i = 0; i < kBlock; ++i) {
      const long double x = block[i];
      if (sizeof(T) == sizeof(double) && std::fabs(block[i]) <= rbdc_gen::simd::kFoldedAngle) {
        worst.folded_sin = std::max(worst.folded_sin, static_cast<double>(std::fabs(trig.sin[i] - std::sin(x))));
        worst.folded_cos = std::max(worst.folded_cos, static_cast<double>(std::fabs(trig.cos[i] - std::cos(x))));
      } else {
        worst.sin = std::max(worst.sin, ulp_error(trig.sin[i], std::sin(x)));
        worst.cos = std::max(worst.cos, ulp_error(trig.cos[i], std::cos(x)));
      }
    }
  }
  return worst;
}

/// Every error of `e` within its bound.
void expect_within_bounds(const MaxError& e, const char* where) {
  EXPECT_LE(e.sin, 1.0) << where;
  EXPECT_LE(e.cos, 1.0) << where;
  EXPECT_LE(e.folded_sin, kFoldedAbsoluteError) << where;
  EXPECT_LE(e.folded_cos, kFoldedAbsoluteError) << where;
}

std::vector<double> uniform_angles(double limit, int count, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(-limit, limit);
  std::vector<double> angles(static_cast<size_t>(count));
  for (double& x : angles) x = uniform(rng);
  return angles;
}

/// The doubles nearest to k·π/2 and their two neighbours on each side, k = 0 … kmax: there the
/// reduced argument is tiny and every bit of the three-part π/2 counts (and, for k = 1 … 3, the
/// folded one ends its range or sits next to ±π).
std::vector<double> near_multiples_of_half_pi(long kmax) {
  const long double half_pi = 1.570796326794896619231321691639751442L;
  std::vector<double> angles;
  for (long k = 0; k <= kmax; ++k) {
    const double centre = static_cast<double>(static_cast<long double>(k) * half_pi);
    double below = centre, above = centre;
    angles.push_back(centre);
    angles.push_back(-centre);
    for (int step = 0; step < 2; ++step) {
      below = std::nextafter(below, -1e300);
      above = std::nextafter(above, 1e300);
      angles.push_back(below);
      angles.push_back(above);
    }
  }
  while (angles.size() % kBlock != 0) angles.push_back(0.5);
  return angles;
}

#if defined(RBDC_HAS_VECTOR_SINCOS)
TEST(JointSincos, DoubleWithinItsBoundsOverTheRobotRange) {
  for (double limit : {1.0, rbdc_gen::simd::kFoldedAngle, 10.0, 1e3, rbdc_gen::simd::kMaxAngle}) {
    const MaxError e = max_error(uniform_angles(limit, 120000, 7));
    expect_within_bounds(e, std::to_string(limit).c_str());
  }
}

TEST(JointSincos, DoubleFoldedSineWithinThreeUlpAndExactWhereTiny) {
  // sin keeps a relative bound over the folded range, next to 0 and ±π too (π's low part as the
  // tail); cos has only the absolute one, as it crosses zero at ±π/2 inside the range.
  std::vector<double> angles = uniform_angles(rbdc_gen::simd::kFoldedAngle, 120000, 17);
  const std::vector<double> hard = near_multiples_of_half_pi(2);
  angles.insert(angles.end(), hard.begin(), hard.end());
  double worst = 0;
  for (size_t first = 0; first + kBlock <= angles.size(); first += kBlock) {
    double block[kBlock];
    for (int i = 0; i < kBlock; ++i) block[i] = angles[first + i];
    const auto trig = rbdc_gen::joint_sincos(block);
    for (int i = 0; i < kBlock; ++i) worst = std::max(worst, ulp_error(trig.sin[i], std::sin(static_cast<long double>(block[i]))));
  }
  EXPECT_LE(worst, 3.0);
  double tiny[kBlock] = {1e-300, -1e-300, 1e-20, -1e-20, std::numeric_limits<double>::denorm_min()};
  const auto trig = rbdc_gen::joint_sincos(tiny);
  for (int i = 0; i < kBlock; ++i) {
    EXPECT_EQ(trig.sin[i], tiny[i]);
    EXPECT_EQ(trig.cos[i], 1.0);
  }
}

TEST(JointSincos, DoubleWithinItsBoundsNextToMultiplesOfHalfPi) {
  const long kmax = static_cast<long>(rbdc_gen::simd::kMaxAngle / 1.5707963267948966);
  expect_within_bounds(max_error(near_multiples_of_half_pi(kmax)), "k·π/2");
}

TEST(JointSincos, DoubleEdgeValues) {
  const double tiny = std::numeric_limits<double>::denorm_min();
  const double max_angle = rbdc_gen::simd::kMaxAngle;
  const double folded = rbdc_gen::simd::kFoldedAngle;
  const double quarter_pi = 0.78539816339744831;
  std::vector<double> edges = {0.0, -0.0, tiny, -tiny, 1e-300, -1e-300, 1e-8, -1e-8,
                               quarter_pi, -quarter_pi, std::nextafter(quarter_pi, 1.0),
                               std::nextafter(quarter_pi, 0.0), max_angle, -max_angle,
                               folded, -folded, std::nextafter(folded, 9.0), std::nextafter(-folded, -9.0)};
  while (edges.size() % kBlock != 0) edges.push_back(2.0);
  expect_within_bounds(max_error(edges), "edges");
  double zeros[kBlock] = {};
  const auto at_zero = rbdc_gen::joint_sincos(zeros);
  for (int i = 0; i < kBlock; ++i) {
    EXPECT_EQ(at_zero.sin[i], 0.0);
    EXPECT_EQ(at_zero.cos[i], 1.0);
  }
}

TEST(JointSincos, OutOfRangeAndNonFiniteAnglesTakeLibmAndLeaveTheirNeighboursAlone) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  double mixed[kBlock] = {0.3, 2e5, -3e9, 1e300, inf, -inf, nan, 7.0, -7.0, 0.0, 1e6, -1.5};
  double tame[kBlock] = {0.3, 0.1, 0.1, 0.1, 0.1, 0.1, 0.1, 7.0, -7.0, 0.0, 0.1, -1.5};
  const auto trig = rbdc_gen::joint_sincos(mixed);
  const auto reference = rbdc_gen::joint_sincos(tame);
  for (int i = 0; i < kBlock; ++i) {
    const double x = mixed[i];
    if (std::isnan(x) || std::isinf(x)) {
      EXPECT_TRUE(std::isnan(trig.sin[i]) && std::isnan(trig.cos[i])) << x;
    } else if (std::fabs(x) > rbdc_gen::simd::kMaxAngle) {
      EXPECT_EQ(trig.sin[i], std::sin(x)) << x;
      EXPECT_EQ(trig.cos[i], std::cos(x)) << x;
    } else {  // the same bits as in a block without outliers
      EXPECT_EQ(trig.sin[i], reference.sin[i]) << x;
      EXPECT_EQ(trig.cos[i], reference.cos[i]) << x;
    }
  }
}

/// sin and cos of each angle by one polynomial directly, four lanes at a time.
template <void (*Four)(const rbdc_gen::simd::Vector<double, 4>&, rbdc_gen::simd::Vector<double, 4>&,
                       rbdc_gen::simd::Vector<double, 4>&)>
rbdc_gen::JointTrig<double, kBlock> by_polynomial(const double (&angles)[kBlock]) {
  rbdc_gen::JointTrig<double, kBlock> trig;
  for (int first = 0; first < kBlock; first += 4) {
    rbdc_gen::simd::Vector<double, 4> x, s, c;
    for (int k = 0; k < 4; ++k) x[k] = angles[first + k];
    Four(x, s, c);
    for (int k = 0; k < 4; ++k) trig.sin[first + k] = s[k], trig.cos[first + k] = c[k];
  }
  return trig;
}

TEST(JointSincos, OneCallTakesOnePolynomialForAllItsAngles) {
  // Within kFoldedAngle all fold; one angle beyond it sends them all through sincos_reduced, in the
  // time the old code took (a lane-by-lane choice ran both polynomials).
  double tame[kBlock] = {0.3, -1.2, 2.9, -3.1, 4.7, -4.7, 1.6, -1.6, 0.0, 3.2, -2.2, 1e-3};
  const auto folded = rbdc_gen::joint_sincos(tame);
  const auto expected_folded = by_polynomial<rbdc_gen::simd::sincos_folded<4>>(tame);
  double wide[kBlock];
  for (int i = 0; i < kBlock; ++i) wide[i] = tame[i];
  wide[4] = 4.75;
  const auto reduced = rbdc_gen::joint_sincos(wide);
  const auto expected_reduced = by_polynomial<rbdc_gen::simd::sincos_reduced<4>>(wide);
  for (int i = 0; i < kBlock; ++i) {
    EXPECT_EQ(folded.sin[i], expected_folded.sin[i]) << tame[i];
    EXPECT_EQ(folded.cos[i], expected_folded.cos[i]) << tame[i];
    EXPECT_EQ(reduced.sin[i], expected_reduced.sin[i]) << wide[i];
    EXPECT_EQ(reduced.cos[i], expected_reduced.cos[i]) << wide[i];
  }
}

TEST(JointSincos, FloatWithinOneUlp) {
  const std::vector<double> wide = uniform_angles(1e3, 60000, 11);
  const std::vector<float> angles(wide.begin(), wide.end());
  const MaxError e = max_error(angles);
  EXPECT_LE(e.sin, 1.0);
  EXPECT_LE(e.cos, 1.0);
}

TEST(JointSincos, EveryBlockSizeMatchesTheBlockOfTwelve) {
  // Zero-padded tails: sizes 1 … 12 give the same values as the full block.
  double block[kBlock];
  for (int i = 0; i < kBlock; ++i) block[i] = 0.7 * i - 3.1;
  const auto full = rbdc_gen::joint_sincos(block);
  double one[1] = {block[0]};
  double five[5] = {block[0], block[1], block[2], block[3], block[4]};
  const auto trig_one = rbdc_gen::joint_sincos(one);
  const auto trig_five = rbdc_gen::joint_sincos(five);
  EXPECT_EQ(trig_one.sin[0], full.sin[0]);
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(trig_five.sin[i], full.sin[i]);
    EXPECT_EQ(trig_five.cos[i], full.cos[i]);
  }
}

/// Each lane of sincos<8> (AVX-512's width, kAngleLanes) against sincos<4> on its half: lane for
/// lane the same operations, so the same bits.
template <void (*Eight)(const rbdc_gen::simd::Vector<double, 8>&, rbdc_gen::simd::Vector<double, 8>&,
                        rbdc_gen::simd::Vector<double, 8>&),
          void (*Four)(const rbdc_gen::simd::Vector<double, 4>&, rbdc_gen::simd::Vector<double, 4>&,
                       rbdc_gen::simd::Vector<double, 4>&)>
void expect_eight_lanes_as_four(const std::vector<double>& angles) {
  using rbdc_gen::simd::Vector;
  for (size_t first = 0; first + 8 <= angles.size(); first += 8) {
    Vector<double, 8> x8, s8, c8;
    Vector<double, 4> low, high, s_low, c_low, s_high, c_high;
    for (int k = 0; k < 8; ++k) x8[k] = angles[first + k];
    for (int k = 0; k < 4; ++k) low[k] = x8[k], high[k] = x8[k + 4];
    Eight(x8, s8, c8);
    Four(low, s_low, c_low);
    Four(high, s_high, c_high);
    for (int k = 0; k < 4; ++k) {
      EXPECT_EQ(s8[k], s_low[k]) << x8[k];
      EXPECT_EQ(c8[k], c_low[k]) << x8[k];
      EXPECT_EQ(s8[k + 4], s_high[k]) << x8[k + 4];
      EXPECT_EQ(c8[k + 4], c_high[k]) << x8[k + 4];
    }
  }
}

TEST(JointSincos, EightLanesGiveTheBitsOfFour) {
  // This build may lack AVX-512, so the eight-lane polynomials are compared here directly.
  using namespace rbdc_gen::simd;
  std::vector<double> angles = uniform_angles(1e3, 4000, 13);
  std::vector<double> hard = near_multiples_of_half_pi(200);
  angles.insert(angles.end(), hard.begin(), hard.end());
  expect_eight_lanes_as_four<sincos_reduced<8>, sincos_reduced<4>>(angles);
  angles = uniform_angles(kFoldedAngle, 4000, 19);
  hard = near_multiples_of_half_pi(2);
  angles.insert(angles.end(), hard.begin(), hard.end());
  expect_eight_lanes_as_four<sincos_folded<8>, sincos_folded<4>>(angles);
}
#endif

TEST(JointSincos, LongDoubleTakesLibm) {
  long double block[3] = {0.5L, -2.0L, 123.25L};
  const auto trig = rbdc_gen::joint_sincos(block);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(trig.sin[i], std::sin(block[i]));
    EXPECT_EQ(trig.cos[i], std::cos(block[i]));
  }
}

}  // namespace
