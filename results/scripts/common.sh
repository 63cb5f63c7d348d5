# Sourced by the results scripts: sets $root (the source tree), $build (the script's first argument,
# default build) and $scratch (a temporary folder for the full time series, removed on exit).
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-"$root/build"}
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
