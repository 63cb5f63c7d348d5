// Issue 21's generated functions (frames, centroidal quantities, M⁻¹, rigid-contact and impulse
// dynamics and the contact derivatives; Mini Cheetah scenes whole_body_quadruped and contact) in
// double against the same code in __float128, the reference of the accuracy target: over 200 random
// states, the median relative error of every output (largest entry difference over the largest
// reference entry) is at most 1e-13. The medians and maxima are printed, so a run is also the
// measurement (docs/generated_api.md quotes it).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include "mini_cheetah/contact.hpp"
#include "mini_cheetah/whole_body_quadruped.hpp"

namespace {

namespace wb = rbdc_gen::mini_cheetah::whole_body_quadruped;
namespace contact = rbdc_gen::mini_cheetah::contact;
using rbdc_gen::float128;

constexpr int kStates = 200;

/// A state as double, the wide type computing the same function (double inputs) more exactly.
struct State {
  double q[wb::nq], v[wb::nv], tau[wb::n_joints];
};

State random_state(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  State s;
  for (double& x : s.q) x = u(rng);
  double norm = 0;
  for (int k = 3; k < 7; ++k) norm += s.q[k] * s.q[k];
  for (int k = 3; k < 7; ++k) s.q[k] /= std::sqrt(norm);
  for (double& x : s.v) x = 2 * u(rng);
  for (double& x : s.tau) x = 10 * u(rng);
  return s;
}

/// One generated function: its name, output names and sizes, and a call in scalar type T writing
/// each output to the arrays given.
template <class T>
using Call = std::function<void(const T* q, const T* v, const T* tau, std::vector<T*>& out)>;

struct Function {
  std::string name;
  std::vector<std::pair<std::string, int>> outputs;
  Call<double> in_double;
  Call<float128> in_float128;
};

/// A Function from one generic call, instantiated for both types.
template <class Generic>
Function make(std::string name, std::vector<std::pair<std::string, int>> outputs, Generic call) {
  return {std::move(name), std::move(outputs), call, call};
}

std::vector<Function> functions() {
  return {
      make("frame_placements", {{"R", 45}, {"p", 15}},
           [](auto q, auto, auto, auto& o) { wb::frame_placements(q, o[0], o[1]); }),
      make("frame_velocities", {{"v_local", 30}, {"v_world", 30}},
           [](auto q, auto v, auto, auto& o) { wb::frame_velocities(q, v, o[0], o[1]); }),
      make("frame_jacobians", {{"J_local", 540}, {"J_world", 540}},
           [](auto q, auto, auto, auto& o) { wb::frame_jacobians(q, o[0], o[1]); }),
      make("frame_bias_accelerations", {{"spatial", 30}, {"classical", 30}},
           [](auto q, auto v, auto, auto& o) { wb::frame_bias_accelerations(q, v, o[0], o[1]); }),
      make("feet_bias_accelerations", {{"Jdot_v", 12}},
           [](auto q, auto v, auto, auto& o) { wb::feet_bias_accelerations(q, v, o[0]); }),
      make("center_of_mass", {{"com", 3}, {"com_velocity", 3}},
           [](auto q, auto v, auto, auto& o) { wb::center_of_mass(q, v, o[0], o[1]); }),
      make("center_of_mass_jacobian", {{"J_c", 54}},
           [](auto q, auto, auto, auto& o) { wb::center_of_mass_jacobian(q, o[0]); }),
      make("centroidal_momentum_matrix", {{"A_G", 108}},
           [](auto q, auto, auto, auto& o) { wb::centroidal_momentum_matrix(q, o[0]); }),
      make("centroidal_bias", {{"Adot_v", 6}}, [](auto q, auto v, auto, auto& o) { wb::centroidal_bias(q, v, o[0]); }),
      make("mass_matrix_inverse", {{"M_inv", 324}},
           [](auto q, auto, auto, auto& o) { wb::mass_matrix_inverse(q, o[0]); }),
      make("contact_dynamics", {{"a", 18}, {"lambda", 12}},
           [](auto q, auto v, auto tau, auto& o) { contact::contact_dynamics(q, v, tau, o[0], o[1]); }),
      make("impulse_dynamics", {{"v_plus", 18}, {"impulse", 12}}, [](auto q, auto v, auto, auto& o) {
        const std::remove_pointer_t<std::remove_reference_t<decltype(o[0])>> restitution(0.5);
        contact::impulse_dynamics(q, v, &restitution, o[0], o[1]);
      }),
      make("contact_dynamics_derivatives",
           {{"da_dq", 324}, {"da_dv", 324}, {"da_dtau", 216}, {"dlambda_dq", 216}, {"dlambda_dv", 216},
            {"dlambda_dtau", 144}},
           [](auto q, auto v, auto tau, auto& o) {
             contact::contact_dynamics_derivatives(q, v, tau, o[0], o[1], o[2], o[3], o[4], o[5]);
           }),
  };
}

template <class T>
std::vector<std::vector<T>> evaluate(const Function& f, const State& s) {
  T q[wb::nq], v[wb::nv], tau[wb::n_joints];
  std::copy(s.q, s.q + wb::nq, q);
  std::copy(s.v, s.v + wb::nv, v);
  std::copy(s.tau, s.tau + wb::n_joints, tau);
  std::vector<std::vector<T>> out;
  std::vector<T*> pointers;
  for (const auto& output : f.outputs) out.emplace_back(output.second, T(0));
  for (auto& o : out) pointers.push_back(o.data());
  if constexpr (std::is_same_v<T, double>) f.in_double(q, v, tau, pointers);
  else f.in_float128(q, v, tau, pointers);
  return out;
}

TEST(WholeBodyPrecision, MedianErrorAgainstFloat128AtMost1e13) {
  std::mt19937 rng(21);
  std::vector<State> states;
  for (int k = 0; k < kStates; ++k) states.push_back(random_state(rng));
  std::printf("%-30s %-14s %12s %12s\n", "function", "output", "median", "max");
  for (const Function& f : functions()) {
    std::vector<std::vector<double>> errors(f.outputs.size());
    for (const State& s : states) {
      const auto narrow = evaluate<double>(f, s);
      const auto wide = evaluate<float128>(f, s);
      for (size_t o = 0; o < f.outputs.size(); ++o) {
        float128 difference = 0, scale = 0;
        for (size_t k = 0; k < wide[o].size(); ++k) {
          const float128 d = narrow[o][k] - wide[o][k];
          difference = std::max(difference, d < 0 ? -d : d);
          scale = std::max(scale, wide[o][k] < 0 ? -wide[o][k] : wide[o][k]);
        }
        ASSERT_GT(static_cast<double>(scale), 0.0) << f.name << " " << f.outputs[o].first << " is all zero";
        errors[o].push_back(static_cast<double>(difference / scale));
      }
    }
    for (size_t o = 0; o < f.outputs.size(); ++o) {
      std::vector<double>& e = errors[o];
      std::sort(e.begin(), e.end());
      const double median = e[e.size() / 2];
      std::printf("%-30s %-14s %12.3g %12.3g\n", f.name.c_str(), f.outputs[o].first.c_str(), median, e.back());
      EXPECT_LE(median, 1e-13) << f.name << " " << f.outputs[o].first;
    }
  }
}

}  // namespace
