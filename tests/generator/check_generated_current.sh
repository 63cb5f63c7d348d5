#!/usr/bin/env bash
# generated/ must be exactly what tools/regenerate writes now: regenerate into a temporary directory
# and compare every byte (generated/CMakeLists.txt is hand-written and not compared).
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
"$root/tools/regenerate" "$out"
if ! diff -r --exclude=CMakeLists.txt "$root/generated" "$out" > "$out.diff"; then
  head -n 40 "$out.diff"
  rm -f "$out.diff"
  echo "generated/ is out of date: run tools/regenerate and commit the result" >&2
  exit 1
fi
rm -f "$out.diff"
echo "generated/ is current ($(find "$out" -name '*.hpp' | wc -l) headers)"
