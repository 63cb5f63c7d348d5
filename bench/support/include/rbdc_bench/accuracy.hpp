// Accuracy against a high-precision reference: every quantity evaluated by the generated code in any
// scalar (float, double, and __float128 as the reference) or by the runtime, returned as one flat
// column-major vector in __float128 with named parts (Λ, J̄ᵀ, b for the operational-space
// quantities), and the relative error ‖x − x_ref‖₂ / ‖x_ref‖₂ of each part.
#pragma once

#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include "rbdc/data.hpp"
#include "rbdc_bench/random_states.hpp"
#include "rbdc_gen/support.hpp"

#if !defined(RBDC_HAS_FLOAT128)
#error "the accuracy reference needs __float128 and libquadmath (GCC or clang on x86-64)"
#endif

namespace rbdc_bench {

using Quad = rbdc_gen::float128;

enum class Quantity {
  feet_jacobian,
  quadratic_velocity_terms,
  gravity_terms,
  inverse_dynamics,
  mass_matrix,
  forward_dynamics,
  osc_open_chain,
  osc_closed_chain,
};

const char* quantity_name(Quantity quantity);

/// A part of a flat output: [begin, end) and its name ("" for single-part quantities).
struct Part {
  std::string name;
  int begin, end;
};

/// The parts of `quantity` for a robot with these dimensions.
std::vector<Part> output_parts(Quantity quantity, int nv, int n_joints, int n_feet);

/// ‖x − ref‖₂ / ‖ref‖₂ over [part.begin, part.end), in quad precision; NaN if either is not finite.
double relative_error(const std::vector<Quad>& x, const std::vector<Quad>& ref, const Part& part);

/// Velocities with every foot at rest: v minus its least-squares component J⁺ J v (J: 3·n_feet × nv,
/// the feet Jacobian at the state's q), so J v = 0 as the closed-chain quantities assume (Eq. 16).
rbdc::VectorX feet_at_rest(const rbdc::MatrixX& J, const rbdc::VectorX& v);

/// The runtime's value of `quantity` (osc_closed_chain: all feet in contact at `ground_mass`;
/// ground_mass ≤ 0 selects the exact constrained closed form, osc_closed_form_constrained).
std::vector<Quad> runtime_output(const rbdc::Model& model, rbdc::Data& data, Quantity quantity,
                                 const State& s, double ground_mass);

/// The generated code's value of `quantity` in scalar T (Api: rbdc_bench/generated/<robot>.hpp).
template <class Api, class T>
std::vector<Quad> generated_output(Quantity quantity, const State& s, double ground_mass) {
  auto convert = [](const auto& x) {
    std::vector<T> out(static_cast<size_t>(x.size()));
    for (Eigen::Index i = 0; i < x.size(); ++i) out[static_cast<size_t>(i)] = static_cast<T>(x.data()[i]);
    return out;
  };
  const std::vector<T> q = convert(s.q), v = convert(s.v), a = convert(s.a), tau = convert(s.tau),
                       f = convert(s.f);
  const int nv = Api::nv, nj = Api::n_joints, nf = Api::n_feet;
  std::vector<T> out;
  switch (quantity) {
    case Quantity::feet_jacobian:
      out.resize(static_cast<size_t>(3 * nf * nv));
      Api::feet_jacobian(q.data(), out.data());
      break;
    case Quantity::quadratic_velocity_terms:
      out.resize(static_cast<size_t>(nv));
      Api::quadratic_velocity_terms(q.data(), v.data(), out.data());
      break;
    case Quantity::gravity_terms:
      out.resize(static_cast<size_t>(nv));
      Api::gravity_terms(q.data(), out.data());
      break;
    case Quantity::inverse_dynamics:
      out.resize(static_cast<size_t>(nv));
      Api::inverse_dynamics(q.data(), v.data(), a.data(), out.data());
      break;
    case Quantity::mass_matrix:
      out.resize(static_cast<size_t>(nv * nv));
      Api::mass_matrix(q.data(), out.data());
      break;
    case Quantity::forward_dynamics:
      out.resize(static_cast<size_t>(nv));
      Api::forward_dynamics(q.data(), v.data(), tau.data(), f.data(), out.data());
      break;
    case Quantity::osc_open_chain:
    case Quantity::osc_closed_chain:
      if constexpr (Api::has_osc) {
        out.resize(static_cast<size_t>(36 + 6 * nj + 6));
        T* Lambda = out.data();
        T* JbarT = Lambda + 36;
        T* b = JbarT + 6 * nj;
        if (quantity == Quantity::osc_open_chain) {
          Api::osc_open_chain(q.data(), v.data(), f.data(), Lambda, JbarT, b);
        } else {
          const T mass = static_cast<T>(ground_mass);
          Api::osc_closed_chain(q.data(), v.data(), &mass, Lambda, JbarT, b);
        }
      }
      break;
  }
  return std::vector<Quad>(out.begin(), out.end());
}

/// The exact contact-constrained operational-space quantities (paper 001 Eqs. 16-26, all feet in
/// contact, feet at rest) in long double, as the reference for osc_closed_chain. They are built from
/// the generated M, c + g, feet Jacobian (long double) and J̇_c v, the feet's classical acceleration
/// at a = 0, by a complex step along the motion (exact to rounding, no step-size error):
///   J̇_c v = Im(ṗ_feet(q + i·h·q̇, v + i·h·v̇)) / h,  q̇ = (R v_B, ½ Q ⊗ (0, ω_B), q̇_joints),
///   v̇ = (0, −ω_B × v_B, 0) (zero classical trunk acceleration, docs/conventions.md).
/// The generated closed-chain recursion cannot be its own reference: its constants are folded in
/// double, and the ground mass multiplies their rounding (see docs/benchmarks.md).
template <class Api>
std::vector<Quad> closed_chain_reference(const State& s) {
  using Real = long double;
  using Complex = std::complex<Real>;
  using MatrixR = Eigen::Matrix<Real, Eigen::Dynamic, Eigen::Dynamic>;
  using VectorR = Eigen::Matrix<Real, Eigen::Dynamic, 1>;
  const int nv = Api::nv, nq = Api::nq, nc = 3 * Api::n_feet;
  const VectorR q = s.q.cast<Real>(), v = s.v.cast<Real>();
  MatrixR H(nv, nv), J(nc, nv);
  VectorR bias(nv), zero = VectorR::Zero(nv);
  Api::mass_matrix(q.data(), H.data());
  Api::feet_jacobian(q.data(), J.data());
  Api::inverse_dynamics(q.data(), v.data(), zero.data(), bias.data());  // C + G

  // Complex step for J̇_c v.
  const Real h = 1e-40L;
  const Eigen::Quaternion<Real> Q(q[3], q[4], q[5], q[6]);
  const Eigen::Matrix<Real, 3, 1> w = v.template head<3>(), v_B = v.template segment<3>(3);
  const Eigen::Matrix<Real, 3, 1> p_dot = Q.toRotationMatrix() * v_B;
  const Eigen::Quaternion<Real> Q_dot = Q * Eigen::Quaternion<Real>(0, w.x(), w.y(), w.z());
  const Eigen::Matrix<Real, 3, 1> v_B_dot = -w.cross(v_B);
  std::vector<Complex> q_c(static_cast<size_t>(nq)), v_c(static_cast<size_t>(nv)), p_c(static_cast<size_t>(nc));
  for (int i = 0; i < nq; ++i) q_c[static_cast<size_t>(i)] = Complex(q[i], 0);
  for (int i = 0; i < nv; ++i) v_c[static_cast<size_t>(i)] = Complex(v[i], 0);
  const Real q_dot_quaternion[4] = {Real(0.5) * Q_dot.w(), Real(0.5) * Q_dot.x(), Real(0.5) * Q_dot.y(),
                                    Real(0.5) * Q_dot.z()};
  for (int k = 0; k < 3; ++k) {
    q_c[static_cast<size_t>(k)] += Complex(0, h * p_dot[k]);
    v_c[static_cast<size_t>(3 + k)] += Complex(0, h * v_B_dot[k]);
  }
  for (int k = 0; k < 4; ++k) q_c[static_cast<size_t>(3 + k)] += Complex(0, h * q_dot_quaternion[k]);
  for (int i = 7; i < nq; ++i) q_c[static_cast<size_t>(i)] += Complex(0, h * v[i - 1]);
  Api::feet_velocities(q_c.data(), v_c.data(), p_c.data());
  VectorR feet_bias(nc);
  for (int i = 0; i < nc; ++i) feet_bias[i] = p_c[static_cast<size_t>(i)].imag() / h;

  // Eqs. 16-26 with J_t = [1 0] (J̇_t = 0 in our coordinates).
  const MatrixR H_inv = H.llt().solve(MatrixR::Identity(nv, nv));
  const MatrixR Lambda_c = (J * H_inv * J.transpose()).llt().solve(MatrixR::Identity(nc, nc));
  const MatrixR N_cT = MatrixR::Identity(nv, nv) - J.transpose() * Lambda_c * J * H_inv;
  const MatrixR H_inv_N_cT = H_inv * N_cT;
  const MatrixR Lambda = H_inv_N_cT.topLeftCorner(6, 6).llt().solve(MatrixR::Identity(6, 6));
  const MatrixR JbarT = Lambda * H_inv_N_cT.topRows(6);
  const VectorR b = JbarT * bias + Lambda * (H_inv * J.transpose() * Lambda_c * feet_bias).head(6);

  std::vector<Quad> out(Lambda.data(), Lambda.data() + 36);
  const MatrixR JbarT_joints = JbarT.rightCols(nv - 6);
  out.insert(out.end(), JbarT_joints.data(), JbarT_joints.data() + JbarT_joints.size());
  out.insert(out.end(), b.data(), b.data() + 6);
  return out;
}

}  // namespace rbdc_bench
