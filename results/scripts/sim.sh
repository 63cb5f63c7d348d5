#!/bin/sh
# Regenerates results/sim/: the MuJoCo comparison (table, summary CSV, figures), the speed profile of
# rbdc-sim (sim_speed.sh, this build only) and the Table I unit check.
# Usage: results/scripts/sim.sh [BUILD_DIR]   (default: build)
set -eu
. "$(dirname "$0")/common.sh"
out="$root/results/sim"
mkdir -p "$out"

"$root/results/scripts/sim_speed.sh" "$build"

units="$(partial "$out/units.txt")"
echo "== Table I read in plain SI (length unit 1 m): the robot sinks, the trot fails" > "$units"
"$build/bin/rbdc-sim" --quiet --length-unit 1 >> "$units"
echo "== Table I read with the penetration in mm (our default)" >> "$units"
"$build/bin/rbdc-sim" --quiet >> "$units"
commit "$out/units.txt"

# Chatter: the share and RMS of the feet forces above 500 Hz over 1-10 s of trot, before (force at
# the sphere centre, isotropic explicit friction) and after (contact point, Eq. 38 per axis, implicit).
{
  echo "# Feet-force energy above 500 Hz, 10 s trot sampled at 1e-4 s (results/scripts/force_spectrum.py)"
  echo
  for variant in after before; do
    if [ "$variant" = before ]; then opts="--contact-point off --friction isotropic --friction-update explicit"
    else opts=""; fi
    # shellcheck disable=SC2086
    "$build/bin/rbdc-sim" --quiet --sample-interval 1e-4 $opts --out "$scratch/trot_$variant.csv" > /dev/null
    echo "## $variant: rbdc-sim $opts"
    echo
    /usr/bin/python3 "$root/results/scripts/force_spectrum.py" "$scratch/trot_$variant.csv" --label "$variant"
    echo
  done
} > "$(partial "$out/chatter.md")"
commit "$out/chatter.md"

# Full time series stay out of git (tens of MB); the table, summary and figures are committed.
"$build/bin/rbdc-mujoco-compare" --quiet --out "$scratch"
for f in comparison.md comparison_summary.csv trunk_pose.png lf_contact.png; do
  publish "$scratch/$f" "$out/$f"
done
echo "results written to $out"
