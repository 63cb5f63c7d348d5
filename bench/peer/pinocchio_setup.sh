# shellcheck shell=bash disable=SC2154  # root, pin, out, opt come from the sourcing script
# Sourced by runtime_vs_pinocchio.sh and generated_vs_pinocchio.sh: Pinocchio 3 (v3.7.0 used) from a
# source snapshot kept outside the repository, header-only. Nothing of Pinocchio is copied here: the
# four headers its CMake would generate (version, export macros) are written into $out/cfg as plain
# macro definitions, and its URDF parser is compiled from its sources.
# Expects: root (this repository), pin (the snapshot), out (scratch directory), opt (array: the
# optimisation flags, the same for every TU). Environment: CXX (default clang++-14), BUILD_CPU (the
# core compiles are pinned to, default 0), RBDC_BUILD_DIR (rbdc's build, default build/).
# Sets: cxx, build, pin_flags (for a TU including Pinocchio), pin_objects (its URDF parser),
# rbdc_runtime (librbdc_runtime, built if missing); defines compile and rbdc_target.
# Needs Debian's libboost-dev (headers), liburdfdom-dev, libconsole-bridge-dev, libtinyxml-dev.

cxx="${CXX:-clang++-14}"
build="${RBDC_BUILD_DIR:-$root/build}"

# compile OBJECT SOURCE [DEPENDENCY...] -- FLAG...: compiles unless OBJECT is newer than SOURCE and
# every DEPENDENCY and was built by the same command (kept in OBJECT.cmd): a TU with Pinocchio's
# derivatives takes minutes and over 1 GB. Low priority, on one core, one job at a time: the machine
# is shared and the other core is for timing.
compile() {
  local object="$1" deps=() dep
  shift
  while [ "$1" != -- ]; do deps+=("$1"); shift; done
  shift
  local command="$cxx $* -c ${deps[0]} -o $object"
  if [ -f "$object" ] && [ "$(cat "$object.cmd" 2> /dev/null)" = "$command" ]; then
    local stale=0
    for dep in "${deps[@]}"; do [ "$dep" -nt "$object" ] && stale=1; done
    [ "$stale" = 0 ] && return 0
  fi
  echo "compiling $(basename "${deps[0]}") -> $object" >&2
  /usr/bin/time -f "  %e s, %M KB" nice -n 19 taskset -c "${BUILD_CPU:-0}" "$cxx" "$@" -c "${deps[0]}" -o "$object"
  echo "$command" > "$object.cmd"
}

# rbdc_target TARGET: builds one of rbdc's targets, configuring the build first if needed; callers
# call it only for what is missing (someone else may be building there).
rbdc_target() {
  echo "building rbdc's $1 in $build" >&2
  [ -f "$build/CMakeCache.txt" ] || cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release > /dev/null
  nice -n 19 taskset -c "${BUILD_CPU:-0}" cmake --build "$build" --target "$1" -j 1 > /dev/null
}

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

pin_flags=("${opt[@]}" -DPINOCCHIO_WITH_URDFDOM -I"$out/cfg" -I"$pin/include" -I/usr/include/eigen3)
pin_objects=()
for part in model utils; do
  compile "$out/urdf_$part.o" "$pin/src/parsers/urdf/$part.cpp" -- "${pin_flags[@]}"
  pin_objects+=("$out/urdf_$part.o")
done

find_runtime() { find "$build" -name 'librbdc_runtime.*' 2> /dev/null | head -n 1; }
rbdc_runtime="$(find_runtime)"
[ -n "$rbdc_runtime" ] || { rbdc_target rbdc_runtime && rbdc_runtime="$(find_runtime)"; }
