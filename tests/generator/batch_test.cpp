// rbdc_gen/batch.hpp: every Mini Cheetah function instantiated with Scalar = Batch<double> and
// Batch<float> (one register of the target: 8 and 16 lanes with AVX-512, 2 and 4 with SSE2 alone)
// gives, lane by lane, what the scalar function gives for that lane's state, to round-off;
// pack_states/unpack_states are inverse; Pack arithmetic and sin/cos per lane.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "mini_cheetah/full.hpp"
#include "rbdc_gen/batch.hpp"

namespace {

namespace mc = rbdc_gen::mini_cheetah::full;

/// W random states of the Mini Cheetah, stored one after another per input (AoS).
template <class T>
struct States {
  int lanes;
  std::vector<T> q, v, a, tau, f;
  T ground_mass;

  States(int lanes_, unsigned seed) : lanes(lanes_) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    auto fill = [&](std::vector<T>& x, int size, double scale) {
      x.resize(static_cast<size_t>(size * lanes));
      for (T& value : x) value = static_cast<T>(scale * uniform(rng));
    };
    fill(q, mc::nq, 1.5);
    fill(v, mc::nv, 2.0);
    fill(a, mc::nv, 5.0);
    fill(tau, mc::n_joints, 10.0);
    fill(f, 3 * mc::n_feet, 40.0);
    for (int k = 0; k < lanes; ++k) {  // unit quaternion
      T* quaternion = &q[static_cast<size_t>(k * mc::nq + 3)];
      const T norm = std::sqrt(quaternion[0] * quaternion[0] + quaternion[1] * quaternion[1] +
                               quaternion[2] * quaternion[2] + quaternion[3] * quaternion[3]);
      for (int i = 0; i < 4; ++i) quaternion[i] /= norm;
    }
    ground_mass = T(50);
  }
};

template <class T, int W>
std::vector<rbdc_gen::Pack<T, W>> packed(const std::vector<T>& states, int size) {
  std::vector<rbdc_gen::Pack<T, W>> packs(static_cast<size_t>(size));
  rbdc_gen::pack_states(states.data(), size, size, packs.data());
  return packs;
}

/// Runs `call(inputs…, outputs…)` once on packs and once per lane on scalars, compares each output
/// entry: |batch − scalar| <= tolerance · max(1, largest |scalar| of that output).
template <class T, int W, class Call>
void expect_batch_equals_scalar(const char* name, const States<T>& s, const std::vector<int>& out_sizes,
                                Call call, double tolerance) {
  using P = rbdc_gen::Pack<T, W>;
  const auto q = packed<T, W>(s.q, mc::nq), v = packed<T, W>(s.v, mc::nv), a = packed<T, W>(s.a, mc::nv);
  const auto tau = packed<T, W>(s.tau, mc::n_joints), f = packed<T, W>(s.f, 3 * mc::n_feet);
  const P ground(s.ground_mass);
  std::vector<std::vector<P>> batch_out;
  for (int size : out_sizes) batch_out.emplace_back(static_cast<size_t>(size), P(T(-7)));
  call(q.data(), v.data(), a.data(), tau.data(), f.data(), &ground, batch_out);

  for (int k = 0; k < W; ++k) {
    std::vector<std::vector<T>> out;
    for (int size : out_sizes) out.emplace_back(static_cast<size_t>(size), T(-7));
    call(&s.q[static_cast<size_t>(k * mc::nq)], &s.v[static_cast<size_t>(k * mc::nv)],
         &s.a[static_cast<size_t>(k * mc::nv)], &s.tau[static_cast<size_t>(k * mc::n_joints)],
         &s.f[static_cast<size_t>(k * 3 * mc::n_feet)], &s.ground_mass, out);
    for (size_t o = 0; o < out.size(); ++o) {
      double scale = 1.0;
      for (T x : out[o]) scale = std::max(scale, static_cast<double>(std::fabs(x)));
      for (size_t i = 0; i < out[o].size(); ++i) {
        ASSERT_NEAR(batch_out[o][i][k], out[o][i], tolerance * scale)
            << name << " output " << o << " entry " << i << " lane " << k;
      }
    }
  }
}

/// Every function of the full scene, through one generic call shape.
template <class T, int W>
void check_every_function(double tolerance) {
  const States<T> s(W, 5);
  const int nv = mc::nv, nf = 3 * mc::n_feet;
  auto check = [&](const char* name, std::vector<int> sizes, auto call) {
    expect_batch_equals_scalar<T, W>(name, s, sizes, call, tolerance);
  };
  check("feet_positions", {nf}, [](auto q, auto, auto, auto, auto, auto, auto& out) {
    mc::feet_positions(q, out[0].data());
  });
  check("feet_velocities", {nf}, [](auto q, auto v, auto, auto, auto, auto, auto& out) {
    mc::feet_velocities(q, v, out[0].data());
  });
  check("feet_jacobian", {nf * nv}, [](auto q, auto, auto, auto, auto, auto, auto& out) {
    mc::feet_jacobian(q, out[0].data());
  });
  check("quadratic_velocity_terms", {nv}, [](auto q, auto v, auto, auto, auto, auto, auto& out) {
    mc::quadratic_velocity_terms(q, v, out[0].data());
  });
  check("gravity_terms", {nv}, [](auto q, auto, auto, auto, auto, auto, auto& out) {
    mc::gravity_terms(q, out[0].data());
  });
  check("feet_force_terms", {nv}, [](auto q, auto, auto, auto, auto f, auto, auto& out) {
    mc::feet_force_terms(q, f, out[0].data());
  });
  check("inverse_dynamics", {nv}, [](auto q, auto v, auto a, auto, auto, auto, auto& out) {
    mc::inverse_dynamics(q, v, a, out[0].data());
  });
  check("mass_matrix", {nv * nv}, [](auto q, auto, auto, auto, auto, auto, auto& out) {
    mc::mass_matrix(q, out[0].data());
  });
  check("forward_dynamics", {nv}, [](auto q, auto v, auto, auto tau, auto f, auto, auto& out) {
    mc::forward_dynamics(q, v, tau, f, out[0].data());
  });
  check("osc_open_chain", {36, 6 * mc::n_joints, 6}, [](auto q, auto v, auto, auto, auto f, auto, auto& out) {
    mc::osc_open_chain(q, v, f, out[0].data(), out[1].data(), out[2].data());
  });
  check("osc_closed_chain", {36, 6 * mc::n_joints, 6}, [](auto q, auto v, auto, auto, auto, auto m, auto& out) {
    mc::osc_closed_chain(q, v, m, out[0].data(), out[1].data(), out[2].data());
  });
}

TEST(Batch, EveryFunctionInDoubleEqualsOneScalarCallPerLane) {
  check_every_function<double, rbdc_gen::Batch<double>::lanes>(1e-12);
}

TEST(Batch, EveryFunctionInFloatEqualsOneScalarCallPerLane) {
  check_every_function<float, rbdc_gen::Batch<float>::lanes>(1e-4);
}

TEST(Batch, IsOneRegisterOfTheTarget) {
#if defined(__AVX512F__)
  constexpr int bytes = 64;
#elif defined(__AVX__)
  constexpr int bytes = 32;
#else
  constexpr int bytes = 16;
#endif
  EXPECT_EQ(rbdc_gen::Batch<double>::lanes, bytes / 8);
  EXPECT_EQ(rbdc_gen::Batch<float>::lanes, bytes / 4);
  EXPECT_EQ(sizeof(rbdc_gen::Batch<double>), static_cast<size_t>(bytes));
}

TEST(Batch, PackAndUnpackAreInverse) {
  constexpr int W = 8, size = 5, stride = 7;  // stride > size: gaps between states stay untouched
  std::vector<double> states(W * stride);
  for (size_t i = 0; i < states.size(); ++i) states[i] = 0.5 * static_cast<double>(i);
  rbdc_gen::Pack<double, W> packs[size];
  rbdc_gen::pack_states(states.data(), stride, size, packs);
  EXPECT_EQ(packs[2][3], states[3 * stride + 2]);
  std::vector<double> back(W * stride, -1.0);
  rbdc_gen::unpack_states(packs, size, back.data(), stride);
  for (int k = 0; k < W; ++k) {
    for (int i = 0; i < stride; ++i) {
      EXPECT_EQ(back[static_cast<size_t>(k * stride + i)], i < size ? states[static_cast<size_t>(k * stride + i)] : -1.0);
    }
  }
}

// transposed_lanes<N, J>(p): lane k is p[k·N + J], by vector loads and shuffles for double and float,
// element by element for other types; N = 5 puts the four entries in four different vectors.
template <class T, int N, int J>
void expect_transposed() {
  T p[4 * N];
  for (int i = 0; i < 4 * N; ++i) p[i] = static_cast<T>(i);
  const auto lanes = rbdc_gen::transposed_lanes<N, J>(p);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(lanes[k], static_cast<T>(k * N + J)) << "N " << N << " J " << J;
}

TEST(Lanes, TransposedLanesTakeEntryJOfEachLimb) {
  expect_transposed<double, 3, 0>(), expect_transposed<double, 3, 2>(), expect_transposed<double, 5, 4>();
  expect_transposed<double, 1, 0>(), expect_transposed<float, 3, 1>(), expect_transposed<long double, 5, 3>();
}

/// store_transposed_lanes of K lane values (x_k's lane l = 100 k + l) into four separate segments
/// of a zeroed buffer: segment l holds lane l of x_0 … x_K−1, every other entry stays zero.
template <class T, int K>
void expect_stored_transposed() {
  T out[4 * 20] = {};
  T* const starts[4] = {out + 41, out, out + 62, out + 20};  // out of order, gaps between them
  rbdc_gen::Lanes<T> x[K];
  for (int k = 0; k < K; ++k)
    x[k] = rbdc_gen::make_lanes<T>(100 * k, 100 * k + 1, 100 * k + 2, 100 * k + 3);
  rbdc_gen::store_transposed_lanes<K>(starts, x);
  int written = 0;
  for (int l = 0; l < 4; ++l)
    for (int k = 0; k < K; ++k, ++written) EXPECT_EQ(starts[l][k], static_cast<T>(100 * k + l)) << "K " << K;
  int nonzero = 0;
  for (T value : out) nonzero += value != T(0);
  EXPECT_EQ(nonzero, written - 1) << "K " << K;  // x_0's lane 0 is the only zero written
}

TEST(Lanes, StoredTransposedPutsEachLimbsLanesTogether) {
  expect_stored_transposed<double, 3>(), expect_stored_transposed<double, 6>();
  expect_stored_transposed<double, 9>(), expect_stored_transposed<float, 5>();
  expect_stored_transposed<long double, 4>();
}

TEST(Batch, ArithmeticAndTrigonometryPerLane) {
  using P = rbdc_gen::Pack<double, 8>;
  P x, y;
  for (int k = 0; k < P::lanes; ++k) {
    x.v[k] = 0.75 * k - 2.0;
    y.v[k] = 1.0 + k;
  }
  const P r = (x * y - P(0.5)) / y + -x;
  const P s = sin(x), c = cos(x), root = sqrt(y);
  double angles[P::lanes];
  for (int k = 0; k < P::lanes; ++k) angles[k] = x[k];
  const auto trig = rbdc_gen::joint_sincos(angles);  // the scalar path: the same polynomial
  for (int k = 0; k < P::lanes; ++k) {
    EXPECT_DOUBLE_EQ(r[k], (x[k] * y[k] - 0.5) / y[k] + -x[k]);
    EXPECT_DOUBLE_EQ(s[k], trig.sin[k]);
    EXPECT_DOUBLE_EQ(c[k], trig.cos[k]);
    EXPECT_EQ(root[k], std::sqrt(y[k]));
  }
  x.v[3] = 3e6;  // out of the polynomials' range: libm for that lane only
  EXPECT_EQ(sin(x)[3], std::sin(3e6));
  EXPECT_NEAR(sin(x)[2], s[2], 4e-16);  // the pack's other lanes now by sincos_reduced
}

}  // namespace
