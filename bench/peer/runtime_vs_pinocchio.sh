#!/usr/bin/env bash
# shellcheck source-path=SCRIPTDIR disable=SC2034  # pin, out, opt are read by pinocchio_setup.sh
# Builds bench/peer/runtime_vs_pinocchio.cpp against a Pinocchio 3 source snapshot kept outside the
# repository (pinocchio_setup.sh) and the runtime of an rbdc build, then runs it on the given URDFs.
# Usage: bench/peer/runtime_vs_pinocchio.sh PINOCCHIO_SRC OUT URDF...
#   PINOCCHIO_SRC  a checkout or `git archive` of github.com/stack-of-tasks/pinocchio (v3.7.0 used)
#   OUT            scratch directory for the objects and the program
#   RBDC_BUILD_DIR the rbdc build holding librbdc_runtime (default build/; built there if missing)
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
pin="$1" out="$2"; shift 2
opt=(-std=c++17 -O2 -DNDEBUG)
# shellcheck source=pinocchio_setup.sh
source "$root/bench/peer/pinocchio_setup.sh"

program="$root/bench/peer/runtime_vs_pinocchio.cpp"
compile "$out/runtime_vs_pinocchio.o" "$program" "$root/bench/peer/pinocchio_conventions.hpp" \
  "$root"/runtime/include/rbdc/*.hpp -- "${pin_flags[@]}" -I"$root/runtime/include"
"$cxx" "$out/runtime_vs_pinocchio.o" "${pin_objects[@]}" "$rbdc_runtime" \
  -lurdfdom_model -lyaml-cpp -lconsole_bridge -ltinyxml -Wl,-rpath,"$(dirname "$rbdc_runtime")" -o "$out/runtime_vs_pinocchio"
"$out/runtime_vs_pinocchio" "$@"
