#!/usr/bin/env bash
# Compiles CUDA kernels that call generated Mini Cheetah functions and the arm's looped
# forward-dynamics derivatives (RBDC_HOST_DEVICE), for the device. Exit 77 (CTest: skipped) when
# nvcc is not installed.
set -euo pipefail
generated="$1"
eigen="$2"
nvcc="$(command -v nvcc || true)"
if [ -z "$nvcc" ] && [ -x /usr/local/cuda/bin/nvcc ]; then
  nvcc=/usr/local/cuda/bin/nvcc
fi
if [ -z "$nvcc" ]; then
  echo "skipped: nvcc not found"
  exit 77
fi
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cat > "$work/kernel.cu" <<'CU'
#include "arm7/derivatives.hpp"
#include "mini_cheetah/full.hpp"
namespace mc = rbdc_gen::mini_cheetah::full;
namespace arm = rbdc_gen::arm7::derivatives;
__global__ void dynamics(const double* q, const double* v, const double* tau, const double* f,
                         double* M, double* a, float* Mf) {
  mc::mass_matrix(q, M);
  mc::forward_dynamics(q, v, tau, f, a);
  float qf[mc::nq];
  for (int k = 0; k < mc::nq; ++k) qf[k] = static_cast<float>(q[k]);
  mc::mass_matrix(qf, Mf);
}
// The arm's forward-dynamics derivatives are a looped solve (rbdc_gen/solve.hpp).
__global__ void arm_derivatives(const double* q, const double* v, const double* tau, const double* f,
                                double* da_dq, double* da_dv, double* da_dtau, double* da_df) {
  arm::forward_dynamics_derivatives(q, v, tau, f, da_dq, da_dv, da_dtau, da_df);
}
CU
"$nvcc" -std=c++17 --expt-relaxed-constexpr -Wno-deprecated-gpu-targets -diag-suppress 20012 \
  -I "$generated" -isystem "$eigen" -c "$work/kernel.cu" -o "$work/kernel.o"
echo "nvcc compiled generated mass_matrix, forward_dynamics and a looped forward_dynamics_derivatives for the device ($("$nvcc" --version | tail -n 1))"
