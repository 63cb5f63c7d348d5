// The truncated, weighted least-squares solve of paper 001 Eq. 55: x = A† y where the
// Moore-Penrose pseudo-inverse drops every singular value σ_i < σ_max / 100 ("for numerical
// stability", Section 5.1). Fixed-size Eigen matrices, so no heap is touched.
#pragma once

#include <Eigen/SVD>

namespace rbdc::control {

/// Singular values below this fraction of the largest are treated as zero (paper 001 Sec. 5.1).
inline constexpr double kSingularValueCutoff = 1.0 / 100.0;

/// x = A† y with singular values σ_i < cutoff · σ_max discarded; returns the rank kept through
/// `rank` when it is not null. A zero matrix gives x = 0 and rank 0.
template <int Rows, int Cols>
Eigen::Matrix<double, Cols, 1> truncated_pseudo_inverse_solve(
    const Eigen::Matrix<double, Rows, Cols>& A, const Eigen::Matrix<double, Rows, 1>& y,
    double cutoff = kSingularValueCutoff, int* rank = nullptr) {
  const Eigen::JacobiSVD<Eigen::Matrix<double, Rows, Cols>> svd(A, Eigen::ComputeFullU |
                                                                       Eigen::ComputeFullV);
  const auto& sigma = svd.singularValues();  // sorted, largest first
  // A† y = Σ_i v_i (u_iᵀ y) / σ_i over the kept singular values.
  Eigen::Matrix<double, Cols, 1> x = Eigen::Matrix<double, Cols, 1>::Zero();
  int kept = 0;
  for (int i = 0; i < sigma.size(); ++i) {
    if (!(sigma[i] > 0) || sigma[i] < cutoff * sigma[0]) break;
    x += svd.matrixV().col(i) * (svd.matrixU().col(i).dot(y) / sigma[i]);
    ++kept;
  }
  if (rank) *rank = kept;
  return x;
}

}  // namespace rbdc::control
