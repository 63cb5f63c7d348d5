#!/usr/bin/env bash
# Installs this build into a temporary prefix, then configures, builds and runs the examples/
# project with find_package(rbdc) + rbdc_generate(): the package works from a separate project.
# Usage: example_consumer.sh BUILD_DIR EXAMPLES_DIR
set -euo pipefail
build="$1"
examples="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
cmake -S "$examples" -B "$work/build" -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release > "$work/configure.log" \
  || { cat "$work/configure.log"; exit 1; }
cmake --build "$work/build" > "$work/build.log" 2>&1 || { cat "$work/build.log"; exit 1; }
output="$("$work/build/print_mass_matrix")"
echo "$output"
# M(0,0) is the trunk-and-legs rotational inertia about x: positive.
grep -q "18 x 18" <<< "$output"
first="$(sed -n 2p <<< "$output" | awk '{print $1}')"
awk -v m="$first" 'BEGIN { exit !(m > 0.01 && m < 1.0) }'
echo "the installed package generated and ran the Mini Cheetah example"
