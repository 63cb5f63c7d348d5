// The Mini Cheetah standing on its four feet with the generated rigid-contact functions
// (generated/mini_cheetah/contact/, scene scenes/contact.yaml):
//  1. contact_dynamics at a standing equilibrium: a = 0 and the contact forces carry the weight;
//  2. its linearisation for a contact MPC, ẋ = A δx + B δτ with x = (δq, v), from
//     contact_dynamics_derivatives, checked against central differences of contact_dynamics on the
//     manifold (q ⊕ δ, rbdc::integrate);
//  3. impulse_dynamics of a touchdown at 0.5 m/s: the feet stop (e = 0) or bounce back (e = 0.5).
// Exit code 1 if a check fails.   stand_mini_cheetah [--help]
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "mini_cheetah/contact.hpp"
#include "rbdc/rbdc.hpp"
#include "rbdc/urdf_loader.hpp"

namespace {

namespace gen = rbdc_gen::mini_cheetah::contact;
constexpr int nv = gen::nv, nu = gen::n_joints, nc3 = 3 * gen::n_feet;
using Config = gen::ConfigVector<double>;
using Tangent = gen::TangentVector<double>;
using Torques = gen::JointVector<double>;
using Forces = Eigen::Matrix<double, nc3, 1>;

int failures = 0;

void check(const std::string& what, double error, double tolerance) {
  const bool ok = error <= tolerance;
  failures += !ok;
  std::cout << (ok ? "  ok    " : "  FAIL  ") << what << ": " << error << " (tolerance " << tolerance << ")\n";
}

/// The standing pose of docs/runtime.md (p = (0, 0, 0.3), legs at (0, −0.8, 1.6)) and the joint
/// torques that hold it with the feet in contact: with a = 0 the KKT rows read g = Sᵀτ + Jᵀλ; the
/// least-norm λ carrying the trunk rows, then τ = g_joints − (Jᵀλ)_joints.
void standing(const rbdc::Model& model, Config& q, Torques& tau) {
  q.setZero();
  q[2] = 0.3;
  q[3] = 1;
  for (int j = 0; j < nu; ++j) q[7 + j] = (j % 3 == 1) ? -0.8 : (j % 3 == 2 ? 1.6 : 0.0);
  rbdc::Data data(model);
  const rbdc::VectorX g = rbdc::gravity_terms(model, data, q);
  const rbdc::MatrixX Jt = rbdc::feet_jacobian(model, data, q).transpose();
  const rbdc::VectorX lambda = Jt.topRows<6>().completeOrthogonalDecomposition().solve(g.head<6>());
  tau = g.tail<nu>() - (Jt * lambda).tail<nu>();
}

Eigen::Matrix<double, nv + nc3, 1> contact_outputs(const Config& q, const Tangent& v, const Torques& tau) {
  Tangent a;
  Forces lambda;
  gen::contact_dynamics(q, v, tau, a, lambda);
  return (Eigen::Matrix<double, nv + nc3, 1>() << a, lambda).finished();
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1) {
    std::cout << "usage: stand_mini_cheetah\nThe Mini Cheetah on four feet with the generated contact "
                 "dynamics, its linearisation and a touchdown; exit 1 if a check fails.\n";
    return std::string(argv[1]) == "--help" ? 0 : 2;
  }
  std::vector<std::string> warnings;  // the MIT thigh inertia breaks the triangle inequality
  const rbdc::Model model = rbdc::load_urdf(RBDC_SOURCE_DIR "/robots/mini_cheetah.urdf", {}, &warnings);
  Config q;
  Torques tau;
  standing(model, q, tau);
  const Tangent v = Tangent::Zero();

  std::cout << "1. standing equilibrium (contact_dynamics)\n";
  Tangent a;
  Forces lambda;
  gen::contact_dynamics(q, v, tau, a, lambda);
  rbdc::Data data(model);
  const double weight = rbdc::mass_matrix(model, data, q)(3, 3) * model.gravity.norm();  // M[3][3] = total mass
  double vertical = 0;
  for (int k = 0; k < gen::n_feet; ++k) vertical += lambda[3 * k + 2];
  check("|a| at the equilibrium", a.cwiseAbs().maxCoeff(), 1e-9);
  check("Σ λ_z − m g [N]", std::abs(vertical - weight), 1e-9 * weight);

  std::cout << "2. linearisation for MPC (contact_dynamics_derivatives vs central differences)\n";
  gen::MassMatrix<double> da_dq, da_dv;
  Eigen::Matrix<double, nv, nu> da_dtau;
  Eigen::Matrix<double, nc3, nv> dl_dq, dl_dv;
  Eigen::Matrix<double, nc3, nu> dl_dtau;
  // A perturbed state, so that every term (velocity products too) is exercised.
  Tangent v1;
  for (int k = 0; k < nv; ++k) v1[k] = 0.1 * std::sin(1.0 + k);
  Torques tau1 = tau;
  tau1[1] += 0.5;
  gen::contact_dynamics_derivatives(q, v1, tau1, da_dq, da_dv, da_dtau, dl_dq, dl_dv, dl_dtau);
  const double h = 1e-5;  // O(h²) truncation against O(ε/h) round-off
  Eigen::Matrix<double, nv + nc3, nv> fd_q, fd_v;
  Eigen::Matrix<double, nv + nc3, nu> fd_tau;
  for (int k = 0; k < nv; ++k) {
    rbdc::VectorX plus(gen::nq), minus(gen::nq);
    rbdc::integrate(model, q, h * rbdc::VectorX::Unit(nv, k), plus);
    rbdc::integrate(model, q, -h * rbdc::VectorX::Unit(nv, k), minus);
    fd_q.col(k) = (contact_outputs(plus, v1, tau1) - contact_outputs(minus, v1, tau1)) / (2 * h);
    const Tangent dv = h * Tangent::Unit(k);
    fd_v.col(k) = (contact_outputs(q, v1 + dv, tau1) - contact_outputs(q, v1 - dv, tau1)) / (2 * h);
  }
  for (int k = 0; k < nu; ++k) {
    const Torques dt = h * Torques::Unit(k);
    fd_tau.col(k) = (contact_outputs(q, v1, tau1 + dt) - contact_outputs(q, v1, tau1 - dt)) / (2 * h);
  }
  const auto rel = [](const auto& x, const auto& y) {
    return (x - y).cwiseAbs().maxCoeff() / std::max(1.0, y.cwiseAbs().maxCoeff());
  };
  check("∂a/∂q", rel(da_dq, fd_q.topRows<nv>()), 1e-6);
  check("∂a/∂v", rel(da_dv, fd_v.topRows<nv>()), 1e-6);
  check("∂a/∂τ", rel(da_dtau, fd_tau.topRows<nv>()), 1e-6);
  check("∂λ/∂q", rel(dl_dq, fd_q.bottomRows<nc3>()), 1e-6);
  check("∂λ/∂v", rel(dl_dv, fd_v.bottomRows<nc3>()), 1e-6);
  check("∂λ/∂τ", rel(dl_dtau, fd_tau.bottomRows<nc3>()), 1e-6);
  // The continuous-time model an MPC uses: ẋ = A δx + B δτ, x = (δq, v).
  Eigen::Matrix<double, 2 * nv, 2 * nv> A = Eigen::Matrix<double, 2 * nv, 2 * nv>::Zero();
  A.topRightCorner<nv, nv>().setIdentity();
  A.bottomLeftCorner<nv, nv>() = da_dq;
  A.bottomRightCorner<nv, nv>() = da_dv;
  Eigen::Matrix<double, 2 * nv, nu> B = Eigen::Matrix<double, 2 * nv, nu>::Zero();
  B.bottomRows<nv>() = da_dtau;
  std::cout << "  A (" << A.rows() << " × " << A.cols() << "), B (" << B.rows() << " × " << B.cols()
            << "), ‖B‖_max = " << B.cwiseAbs().maxCoeff() << "\n";

  std::cout << "3. touchdown at 0.5 m/s (impulse_dynamics)\n";
  Tangent falling = Tangent::Zero();
  falling[5] = -0.5;  // trunk linear velocity, trunk coordinates (upright: world z)
  const rbdc::MatrixX J = rbdc::feet_jacobian(model, data, q);
  for (double e : {0.0, 0.5}) {
    Tangent v_plus;
    Forces impulse;
    gen::impulse_dynamics(q, falling, e, v_plus, impulse);
    check("J v⁺ + e J v⁻, e = " + std::to_string(e).substr(0, 3), (J * v_plus + e * J * falling).cwiseAbs().maxCoeff(), 1e-12);
  }
  std::cout << (failures ? "FAILED\n" : "all checks passed\n");
  return failures ? 1 : 0;
}
