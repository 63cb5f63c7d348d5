#!/usr/bin/env bash
# Builds bench/peer/runtime_vs_pinocchio.cpp against a Pinocchio 3 source snapshot kept outside the
# repository (header-only; its URDF parser compiled from its sources) and the runtime of an rbdc build,
# then runs it on the given URDFs. Nothing of Pinocchio is copied here: the four headers its CMake
# would generate (version, export macros) are written into OUT as plain macro definitions.
# Usage: bench/peer/runtime_vs_pinocchio.sh PINOCCHIO_SRC OUT URDF...
#   PINOCCHIO_SRC  a checkout or `git archive` of github.com/stack-of-tasks/pinocchio (v3.7.0 used)
#   OUT            scratch directory for the objects and the program
#   RBDC_BUILD_DIR the rbdc build holding librbdc_runtime (default build/, built by tools/build)
# Needs Debian's libboost-dev (headers), liburdfdom-dev, libconsole-bridge-dev, libtinyxml-dev.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
pin="$1" out="$2"; shift 2
build="${RBDC_BUILD_DIR:-$root/build}"
cxx="${CXX:-clang++-14}"
mkdir -p "$out/cfg/pinocchio/parsers"
cat > "$out/cfg/pinocchio/config.hpp" << 'EOF'
#pragma once
#define PINOCCHIO_MAJOR_VERSION 3
#define PINOCCHIO_MINOR_VERSION 7
#define PINOCCHIO_PATCH_VERSION 0
#define PINOCCHIO_VERSION "3.7.0"
#define PINOCCHIO_DLLAPI
#define PINOCCHIO_LOCAL
#define PINOCCHIO_EXPLICIT_INSTANTIATION_DECLARATION_DLLAPI
#define PINOCCHIO_EXPLICIT_INSTANTIATION_DEFINITION_DLLAPI
EOF
printf '#pragma once\n#define PINOCCHIO_DEPRECATED __attribute__((deprecated))\n#define PINOCCHIO_DEPRECATED_MESSAGE(m) __attribute__((deprecated(m)))\n' \
  > "$out/cfg/pinocchio/deprecated.hpp"
printf '#pragma once\n#define PINOCCHIO_WARNING(message)\n' > "$out/cfg/pinocchio/warning.hpp"
printf '#pragma once\n#define PINOCCHIO_PARSERS_DLLAPI\n#define PINOCCHIO_PARSERS_LOCAL\n' > "$out/cfg/pinocchio/parsers/config.hpp"

flags=(-std=c++17 -O2 -DNDEBUG -DPINOCCHIO_WITH_URDFDOM -I"$out/cfg" -I"$pin/include" -I/usr/include/eigen3)
for part in model utils; do
  [ -f "$out/urdf_$part.o" ] || nice -n 19 "$cxx" "${flags[@]}" -c "$pin/src/parsers/urdf/$part.cpp" -o "$out/urdf_$part.o"
done
runtime="$(find "$build" -name 'librbdc_runtime.*' | head -n 1)"
[ -n "$runtime" ] || { echo "no librbdc_runtime in $build: run tools/build rbdc_runtime" >&2; exit 1; }
nice -n 19 "$cxx" "${flags[@]}" -I"$root/runtime/include" "$root/bench/peer/runtime_vs_pinocchio.cpp" \
  "$out/urdf_model.o" "$out/urdf_utils.o" "$runtime" -lurdfdom_model -lyaml-cpp -lconsole_bridge -ltinyxml \
  -Wl,-rpath,"$(dirname "$runtime")" -o "$out/runtime_vs_pinocchio"
"$out/runtime_vs_pinocchio" "$@"
