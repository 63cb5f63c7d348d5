#!/usr/bin/env bash
# Compiles a CUDA kernel that calls generated Mini Cheetah functions (RBDC_HOST_DEVICE), for the
# device. Exit 77 (CTest: skipped) when nvcc is not installed.
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
#include "mini_cheetah/full.hpp"
namespace mc = rbdc_gen::mini_cheetah::full;
__global__ void dynamics(const double* q, const double* v, const double* tau, const double* f,
                         double* M, double* a, float* Mf) {
  mc::mass_matrix(q, M);
  mc::forward_dynamics(q, v, tau, f, a);
  float qf[mc::nq];
  for (int k = 0; k < mc::nq; ++k) qf[k] = static_cast<float>(q[k]);
  mc::mass_matrix(qf, Mf);
}
CU
"$nvcc" -std=c++17 --expt-relaxed-constexpr -Wno-deprecated-gpu-targets -diag-suppress 20012 \
  -I "$generated" -isystem "$eigen" -c "$work/kernel.cu" -o "$work/kernel.o"
echo "nvcc compiled generated mass_matrix and forward_dynamics for the device ($("$nvcc" --version | tail -n 1))"
