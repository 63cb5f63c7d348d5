// Central finite differences for the derivative tests: on the manifold of q (q ⊕ δ by
// rbdc::integrate) and in plain coordinates, and the relative error they are compared with.
#pragma once

#include <algorithm>
#include <functional>

#include "rbdc/manifold.hpp"

namespace rbdc::test {

constexpr double kStep = 1e-5;         // central differences: O(h²) truncation, O(ε/h) round-off
constexpr double kFdTolerance = 1e-6;  // relative to max(1, largest entry)

using Function = std::function<VectorX(const VectorX&)>;

/// Central differences of f along the manifold tangent of q: column k = (f(q ⊕ h e_k) − f(q ⊕ −h e_k)) / 2h.
inline MatrixX manifold_differences(const Model& model, const VectorX& q, const Function& f) {
  MatrixX out(f(q).size(), model.nv);
  VectorX q_plus(model.nq), q_minus(model.nq);
  for (Eigen::Index k = 0; k < model.nv; ++k) {
    const VectorX step = kStep * VectorX::Unit(model.nv, k);
    rbdc::integrate(model, q, step, q_plus);
    rbdc::integrate(model, q, -step, q_minus);
    out.col(k) = (f(q_plus) - f(q_minus)) / (2 * kStep);
  }
  return out;
}

/// Central differences of f in plain coordinates of x.
inline MatrixX plain_differences(const VectorX& x, const Function& f) {
  MatrixX out(f(x).size(), x.size());
  for (Eigen::Index k = 0; k < x.size(); ++k) {
    const VectorX step = kStep * VectorX::Unit(x.size(), k);
    out.col(k) = (f(x + step) - f(x - step)) / (2 * kStep);
  }
  return out;
}

inline double relative_error(const MatrixX& actual, const MatrixX& expected) {
  return (actual - expected).cwiseAbs().maxCoeff() / std::max(1.0, expected.cwiseAbs().maxCoeff());
}

}  // namespace rbdc::test
