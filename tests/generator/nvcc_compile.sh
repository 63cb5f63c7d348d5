#!/usr/bin/env bash
# Compiles CUDA kernels that call generated functions (RBDC_HOST_DEVICE) for the device: the Mini
# Cheetah's, the arm's looped forward-dynamics derivatives, and every loop form no bundled robot's
# scene takes, on chains generated with the form forced. Exit 77 (CTest: skipped) when nvcc is not
# installed.
# Usage: nvcc_compile.sh GENERATED EIGEN_INCLUDE RBDC MAKE_CHAIN SCENES
set -euo pipefail
generated="$1" eigen="$2" rbdc="$3" make_chain="$4" scenes="$5"
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
# A host-only call in device code is only a warning to nvcc (20011-20015): made errors, so that it fails here.
nvcc_flags=(-std=c++17 --expt-relaxed-constexpr -Wno-deprecated-gpu-targets -diag-suppress 20012 -diag-error 20011,20013,20014,20015 -isystem "$eigen")
"$nvcc" "${nvcc_flags[@]}" -I "$generated" -c "$work/kernel.cu" -o "$work/kernel.o"
echo "nvcc compiled generated mass_matrix, forward_dynamics and a looped forward_dynamics_derivatives for the device"

# The loops over the bodies (rbdc_gen/crba.hpp, rnea_derivatives.hpp, osc.hpp, the feet's loop in
# solve.hpp), the low-rank product (InverseTimesVectors, articulated_inverse) and the chain's RNEA and
# forward dynamics as one loop (chain_inverse_dynamics, articulated_forward_dynamics), each function called with null pointers: the call
# instantiates it for the device, which is all this checks.
python3 "$make_chain" 8 "$work/chain8.urdf" > /dev/null
python3 "$make_chain" 32 "$work/chain32.urdf" > /dev/null
for scene in osc_looped mass_matrix_looped_crba; do
  "$rbdc" generate "$work/chain8.urdf" --floating-base --scene "$scenes/$scene.yaml" -o "$work/gen" > /dev/null
done
for scene in forward_dynamics_derivatives_low_rank chain_loop; do
  "$rbdc" generate "$work/chain32.urdf" --fixed-base --scene "$scenes/$scene.yaml" -o "$work/gen" > /dev/null
done
headers=("$work"/gen/chain8/common/*.hpp "$work"/gen/chain32/common/forward_dynamics_derivatives_*.hpp
         "$(grep -l articulated_forward_dynamics "$work"/gen/chain32/common/forward_dynamics_[0-9a-f]*.hpp)"
         "$(grep -l chain_inverse_dynamics "$work"/gen/chain32/common/inverse_dynamics_*.hpp)")
{
  for header in "${headers[@]}"; do echo "#include \"${header#"$work"/gen/}\""; done
  echo 'template <class... Args>'
  echo '__device__ void call_with_nulls(void (*function)(Args...)) { function(static_cast<Args>(nullptr)...); }'
  echo '__global__ void looped_forms() {'
  for header in "${headers[@]}"; do
    robot="$(basename "$(dirname "$(dirname "$header")")")" stem="$(basename "$header" .hpp)"
    echo "  call_with_nulls(&rbdc_gen::$robot::common::$stem::${stem%_*}<double>);"
  done
  echo '}'
} > "$work/looped.cu"
for loop in crba_loop rnea_derivatives_loop osc_columns_loop InverseTimesVectors articulated_inverse \
            articulated_forward_dynamics chain_inverse_dynamics; do
  grep -q "$loop" "$work/looped.cu" "${headers[@]}" || { echo "no generated header calls $loop"; exit 1; }
done
"$nvcc" "${nvcc_flags[@]}" -I "$work/gen" -c "$work/looped.cu" -o "$work/looped.o"
echo "nvcc compiled ${#headers[@]} looped functions for the device: the CRBA, RNEA-derivative, feet and OSC loops, the low-rank product and its M⁻¹, the chain's RNEA and forward dynamics ($("$nvcc" --version | tail -n 1))"
