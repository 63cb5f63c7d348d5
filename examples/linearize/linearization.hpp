// Linearisation of the Mini Cheetah's forward dynamics on the configuration manifold, from the
// generated derivatives (generated/mini_cheetah/derivatives/, scene scenes/derivatives.yaml).
// State x = (δq, v) ∈ R^(2 nv) with q = q̄ ⊕ δq (rbdc::integrate, docs/conventions.md "Derivatives
// on the manifold"), input u = τ (the 12 joint torques); the foot forces f are held at the operating
// point. Continuous time: ẋ = F(x, u) ≈ A δx + B δu. Discrete time, semi-implicit Euler with step dt:
// v⁺ = v + dt·a(q, v, τ, f), q⁺ = q ⊕ dt·v⁺, x⁺ ≈ A_d δx + B_d δu.
#pragma once

#include <Eigen/Core>

#include "mini_cheetah/derivatives.hpp"
#include "rbdc/model.hpp"

namespace linearize {

namespace gen = rbdc_gen::mini_cheetah::derivatives;
constexpr int nv = gen::nv;
constexpr int nq = gen::nq;
constexpr int nu = gen::n_joints;
constexpr int nx = 2 * nv;

using Config = gen::ConfigVector<double>;
using Tangent = gen::TangentVector<double>;
using Torques = gen::JointVector<double>;
using Forces = gen::FeetMatrix<double>;
using StateMatrix = Eigen::Matrix<double, nx, nx>;
using InputMatrix = Eigen::Matrix<double, nx, nu>;
using State = Eigen::Matrix<double, nx, 1>;

/// Where the dynamics are linearised.
struct OperatingPoint {
  Config q;
  Tangent v;
  Torques tau;
  Forces f;  ///< world foot forces, one column per foot
};

struct Linearization {
  StateMatrix A;
  InputMatrix B;
};

/// The standing state of docs/runtime.md (rbdc-info's pose: p = (0, 0, 0.3), identity orientation,
/// legs at (0, −0.8, 1.6)) at rest, made an equilibrium: the foot forces are the minimum-norm ones
/// that carry the trunk rows of g (J_trunkᵀ f = g_trunk) and τ holds the joints (τ = g_j − (Jᵀf)_j),
/// so a = 0. Uses the runtime (rbdc::gravity_terms, rbdc::feet_jacobian) on `model`.
OperatingPoint standing_equilibrium(const rbdc::Model& model);

/// A = [0 1; ∂a/∂q ∂a/∂v], B = [0; ∂a/∂τ] from the generated forward_dynamics_derivatives. The
/// kinematic block is exactly [0 1] because the operating point is at rest (v = 0).
Linearization continuous(const OperatingPoint& op);

/// A_d = [1 + dt²∂a/∂q  dt(1 + dt∂a/∂v); dt∂a/∂q  1 + dt∂a/∂v], B_d = [dt²∂a/∂τ; dt∂a/∂τ]: the
/// derivatives of the semi-implicit Euler step at an equilibrium (a = 0, so v⁺ = 0 and the step
/// q ⊕ dt·v⁺ composes with q̄ ⊕ δq to first order as q̄ ⊕ (δq + dt·v⁺)).
Linearization discrete(const Linearization& continuous_time, double dt);

/// ẋ = F(x, u) in the chart x = (δq, v) about op.q: δq̇ from the exact chart kinematics (joints
/// and position: q̇ = v mapped through the chart; orientation: the inverse right Jacobian of SO(3)),
/// v̇ = generated forward_dynamics at q̄ ⊕ δq.
State continuous_dynamics(const rbdc::Model& model, const OperatingPoint& op, const State& x,
                          const Torques& tau);

/// x⁺ of one semi-implicit Euler step of the generated forward dynamics, in the chart about op.q.
State discrete_step(const rbdc::Model& model, const OperatingPoint& op, const State& x,
                    const Torques& tau, double dt);

/// Central differences (step h) of `dynamics(x, u)` at (0, op.tau): the A and B it implies.
template <class Dynamics>
Linearization finite_differences(const OperatingPoint& op, const Dynamics& dynamics, double h) {
  Linearization fd;
  for (int k = 0; k < nx; ++k) {
    const State step = h * State::Unit(k);
    fd.A.col(k) = (dynamics(step, op.tau) - dynamics(-step, op.tau)) / (2 * h);
  }
  for (int k = 0; k < nu; ++k) {
    const Torques step = h * Torques::Unit(k);
    fd.B.col(k) = (dynamics(State::Zero(), op.tau + step) - dynamics(State::Zero(), op.tau - step)) / (2 * h);
  }
  return fd;
}

}  // namespace linearize
