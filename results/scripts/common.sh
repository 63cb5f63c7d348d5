# Sourced by the results scripts: sets $root (the source tree), $build (the script's first argument,
# default build) and $scratch (a temporary folder for the full time series, removed on exit).
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-"$root/build"}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
# Result files (docs/runtime.md, "Result files"): a script writes FILE as "$(partial FILE)" and then
# `commit FILE` renames it onto FILE, so an interrupted script leaves the previous FILE intact;
# `publish SOURCE FILE` copies a finished file that way.
partial() { echo "$1.$$.partial"; }
commit() { for f in "$@"; do mv "$(partial "$f")" "$f"; done; }
publish() { cp "$1" "$(partial "$2")" && commit "$2"; }
