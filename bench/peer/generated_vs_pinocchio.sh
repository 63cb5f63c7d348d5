#!/usr/bin/env bash
# shellcheck source-path=SCRIPTDIR disable=SC2034  # pin, out, opt are read by pinocchio_setup.sh
# rbdc's generated code against Pinocchio 3 for one robot (generated_vs_pinocchio.cpp): generates the
# robot's `full` and `derivatives` scenes, builds its benchmark binary (Pinocchio's TU is
# robot-independent and compiled once per OUT), runs it RUNS times (each run checks the agreement,
# then times) and prints peer_ratios.py's table.
# Usage: bench/peer/generated_vs_pinocchio.sh PINOCCHIO_SRC OUT ROBOT URDF --floating-base|--fixed-base [--independent-mimic]
#   PINOCCHIO_SRC  `git archive v3.7.0` of github.com/stack-of-tasks/pinocchio, outside the repository
#   OUT            scratch directory: OUT/gen (generated code), OUT/ROBOT/ (binary, runK.json, runK.txt)
#   ROBOT          name of the generated namespace and directory
# Environment: RUNS (default 3; 0 builds only), TIME_CPU (the core timing runs are pinned to, default 1),
# BENCHMARK_FLAGS (more Google Benchmark flags), and pinocchio_setup.sh's CXX, BUILD_CPU, RBDC_BUILD_DIR.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
peer="$root/bench/peer"
[ $# -ge 5 ] || { sed -n '2,11p' "$0" >&2; exit 2; }
pin="$(realpath "$1")" out="$(realpath -m "$2")" robot="$3" urdf="$(realpath "$4")"
shift 4
options=("$@")  # base and mimic flags: the same for `rbdc generate` and the binary's runtime model
opt=(-std=c++17 -O3 -march=native -DNDEBUG)  # every TU, Pinocchio's and rbdc's
# shellcheck source=pinocchio_setup.sh
source "$peer/pinocchio_setup.sh"

[ -x "$build/bin/rbdc-model" ] || rbdc_target rbdc-model
for scene in full derivatives; do
  RBDC_MODEL_TOOL="$build/bin/rbdc-model" nice -n 19 "$root/rbdc" generate "$urdf" "${options[@]}" --name "$robot" \
    --scene "$root/scenes/$scene.yaml" -o "$out/gen"
done
# The robot generated_side.cpp is compiled for; rewritten only when it changes, so that it stays older
# than an up-to-date object.
mkdir -p "$out/$robot"
cat > "$out/$robot/robot.hpp.new" << EOF
#include "$robot/full.hpp"
#include "$robot/derivatives.hpp"
namespace peer_robot {
namespace full = ::rbdc_gen::$robot::full;
namespace derivatives = ::rbdc_gen::$robot::derivatives;
constexpr const char* name = "$robot";
}  // namespace peer_robot
EOF
cmp -s "$out/$robot/robot.hpp.new" "$out/$robot/robot.hpp" || mv "$out/$robot/robot.hpp.new" "$out/$robot/robot.hpp"
rm -f "$out/$robot/robot.hpp.new"

runtime_headers=("$root"/runtime/include/rbdc/*.hpp)
mapfile -t generated < <(find "$out/gen/$robot" "$out/gen/rbdc_gen" -name '*.hpp')
compile "$out/pinocchio_side.o" "$peer/pinocchio_side.cpp" "$peer/generated_vs_pinocchio.hpp" \
  "$peer/pinocchio_conventions.hpp" "${runtime_headers[@]}" -- "${pin_flags[@]}" -I"$root/runtime/include"
compile "$out/generated_vs_pinocchio.o" "$peer/generated_vs_pinocchio.cpp" "$peer/generated_vs_pinocchio.hpp" \
  "${runtime_headers[@]}" -- "${opt[@]}" -I/usr/include/eigen3 -I"$root/runtime/include"
compile "$out/$robot/generated_side.o" "$peer/generated_side.cpp" "$peer/generated_vs_pinocchio.hpp" \
  "$out/$robot/robot.hpp" "${generated[@]}" "${runtime_headers[@]}" -- "${opt[@]}" -I/usr/include/eigen3 \
  -I"$root/runtime/include" -I"$out/gen" -include "$out/$robot/robot.hpp"
binary="$out/$robot/generated_vs_pinocchio"
nice -n 19 taskset -c "${BUILD_CPU:-0}" "$cxx" "$out/generated_vs_pinocchio.o" "$out/pinocchio_side.o" \
  "$out/$robot/generated_side.o" "${pin_objects[@]}" "$rbdc_runtime" -lbenchmark -lpthread \
  -lurdfdom_model -lyaml-cpp -lconsole_bridge -ltinyxml -Wl,-rpath,"$(dirname "$rbdc_runtime")" -o "$binary"

# Each run starts from a fresh copy of the binary: the same bytes timed from two files differed
# by 2x, run after run (arm7's forward_dynamics_derivatives 1.7 us from the linker's output, 0.8 us
# from a copy; physical placement of its pages, presumably: the generated code is larger than L1i).
# Copies (written sequentially) were fast in 17 of 18 tries; fresh copies also make the
# runs sample placements instead of repeating one.
rm -f "$out/$robot"/run*.json "$out/$robot"/run*.txt
runs=()
for k in $(seq 1 "${RUNS:-3}"); do
  echo "run $k of ${RUNS:-3} on core ${TIME_CPU:-1}: $out/$robot/run$k.txt" >&2
  cp "$binary" "$binary.run"
  # shellcheck disable=SC2086  # BENCHMARK_FLAGS is a space-separated flag list
  if ! nice -n 19 taskset -c "${TIME_CPU:-1}" "$binary.run" "$urdf" "${options[@]}" --benchmark_repetitions=7 \
      --benchmark_enable_random_interleaving=true --benchmark_min_time=0.05 \
      --benchmark_out="$out/$robot/run$k.json" --benchmark_out_format=json ${BENCHMARK_FLAGS:-} \
      > "$out/$robot/run$k.txt" 2>&1; then
    cat "$out/$robot/run$k.txt" >&2
    exit 1
  fi
  [ "$k" = 1 ] && grep -A1 '^agreement' "$out/$robot/run1.txt"
  runs+=("$out/$robot/run$k.json")
  rm "$binary.run"
done
# RUNS=0 only builds (bench/peer/alternate_runs.sh times two builds against each other).
[ ${#runs[@]} -eq 0 ] || python3 "$peer/peer_ratios.py" "${runs[@]}"
