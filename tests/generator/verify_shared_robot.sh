#!/usr/bin/env bash
# rbdc verify on one public robot of the shared reference material, floating base, full scene,
# mimic joints locked. Exit 77 (CTest: skipped) when the loader refuses the robot.
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
urdf="$1"
if ! message="$("$RBDC_MODEL_TOOL" "$urdf" --lock-mimic 2>&1 >/dev/null)"; then
  echo "skipped: the loader refuses $urdf: $message"
  exit 77
fi
exec "$root/rbdc" verify "$urdf" --lock-mimic --states 50 --tolerance 1e-10
