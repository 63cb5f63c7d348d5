// Forward-mode dual numbers with N tangent directions: the independent "third opinion" on rbdc's
// derivatives (issue 12). The generated primal functions are templates on their scalar, call
// sin, cos and sqrt unqualified and build constants as Scalar(double), so instantiating them on
// Dual<N> differentiates them exactly (to round-off) along N directions in one call.
#pragma once

#include <array>
#include <cmath>

namespace rbdc_test {

template <int N>
struct Dual {
  double value = 0.0;
  std::array<double, N> d{};  ///< ∂value/∂(direction k)

  Dual() = default;
  Dual(double x) : value(x) {}  // NOLINT: implicit, constants in generated code are Scalar(c)

  /// A variable with value x and unit tangent along direction k.
  static Dual variable(double x, int k) {
    Dual r(x);
    r.d[k] = 1.0;
    return r;
  }

  Dual& operator+=(const Dual& b) { return *this = *this + b; }
  Dual& operator-=(const Dual& b) { return *this = *this - b; }
  Dual& operator*=(const Dual& b) { return *this = *this * b; }
  Dual& operator/=(const Dual& b) { return *this = *this / b; }

  friend Dual operator+(const Dual& a, const Dual& b) {
    Dual r(a.value + b.value);
    for (int k = 0; k < N; ++k) r.d[k] = a.d[k] + b.d[k];
    return r;
  }
  friend Dual operator-(const Dual& a, const Dual& b) {
    Dual r(a.value - b.value);
    for (int k = 0; k < N; ++k) r.d[k] = a.d[k] - b.d[k];
    return r;
  }
  friend Dual operator-(const Dual& a) {
    Dual r(-a.value);
    for (int k = 0; k < N; ++k) r.d[k] = -a.d[k];
    return r;
  }
  friend Dual operator*(const Dual& a, const Dual& b) {
    Dual r(a.value * b.value);
    for (int k = 0; k < N; ++k) r.d[k] = a.d[k] * b.value + a.value * b.d[k];
    return r;
  }
  friend Dual operator/(const Dual& a, const Dual& b) {
    const double inverse = 1.0 / b.value;
    Dual r(a.value * inverse);
    for (int k = 0; k < N; ++k) r.d[k] = (a.d[k] - r.value * b.d[k]) * inverse;
    return r;
  }
  // Found by argument-dependent lookup from the generated code's unqualified calls.
  friend Dual sin(const Dual& a) { return chain(a, std::sin(a.value), std::cos(a.value)); }
  friend Dual cos(const Dual& a) { return chain(a, std::cos(a.value), -std::sin(a.value)); }
  friend Dual sqrt(const Dual& a) {
    const double root = std::sqrt(a.value);
    return chain(a, root, 0.5 / root);
  }

 private:
  static Dual chain(const Dual& a, double value, double slope) {
    Dual r(value);
    for (int k = 0; k < N; ++k) r.d[k] = slope * a.d[k];
    return r;
  }
};

/// Seeds a floating-base configuration q (nq = nv + 1) as duals along the manifold tangents
/// δ = (δθ, δp, joints) of docs/conventions.md, directions first..first+nv-1: the position moves by
/// R e_k, the quaternion by ½ q ⊗ (0, e_k), joint j by 1. Fixed base (nq == nv): unit tangents.
template <int N>
void seed_configuration(const double* q, int nq, int nv, int first, Dual<N>* out) {
  for (int i = 0; i < nq; ++i) out[i] = Dual<N>(q[i]);
  if (nq == nv) {
    for (int k = 0; k < nv; ++k) out[k].d[first + k] = 1.0;
    return;
  }
  const double w = q[3], x = q[4], y = q[5], z = q[6];
  const double R[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
                          {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
                          {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}};
  for (int k = 0; k < 3; ++k) {
    for (int r = 0; r < 3; ++r) out[r].d[first + 3 + k] = R[r][k];  // δp_k
  }
  // ½ q ⊗ (0, e_k) for k = x, y, z: (−x, w, z, −y)/2, (−y, −z, w, x)/2, (−z, y, −x, w)/2.
  const double tangent[3][4] = {{-x, w, z, -y}, {-y, -z, w, x}, {-z, y, -x, w}};
  for (int k = 0; k < 3; ++k) {
    for (int c = 0; c < 4; ++c) out[3 + c].d[first + k] = 0.5 * tangent[k][c];
  }
  for (int k = 6; k < nv; ++k) out[k + 1].d[first + k] = 1.0;
}

}  // namespace rbdc_test
