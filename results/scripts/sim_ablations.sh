#!/bin/sh
# Regenerates results/sim/ablations.md: rbdc-mujoco-compare over 10 s with one thing changed at a
# time on either side (contact point, friction model and update, Table I's length unit, MuJoCo's
# solref and friction, the thigh inertia). Usage: results/scripts/sim_ablations.sh [BUILD_DIR]
set -eu
. "$(dirname "$0")/common.sh"
out="$root/results/sim/ablations.md"
duration="${DURATION:-10}"

{
  echo "# Agreement with MuJoCo: ablations ($duration s trot, dt 1e-4 s)"
  echo
  echo "One change per row against the default (ours: force at the contact point, Eq. 38 per axis,"
  echo "implicit friction, Table I in mm; MuJoCo: solref (-1600, -100), friction 1.6, balanced thigh"
  echo "inertia on both sides). Paper 000: position (63, 17, 4.6) mm, attitude (1.5, 1.3, 2.7) deg,"
  echo "LF normal force 5.65 N. Written by results/scripts/sim_ablations.sh."
  echo
  echo "| variant | options | pos MAE x, y, z (mm) | roll, pitch, yaw MAE (deg) | LF contact agreement | LF f_n MAE (N) |"
  echo "|---|---|---|---|---|---|"
} > "$(partial "$out")"

row() {
  name="$1"; shift
  dir="$scratch/ablation_$(echo "$name" | tr ' /' '__')"
  if "$build/bin/rbdc-mujoco-compare" --quiet --no-plots --no-timing --duration "$duration" --out "$dir" "$@" \
      > /dev/null 2> "$dir.log"; then
    awk -F, -v name="$name" -v opts="$*" '
      NR > 1 { v[$1] = $2 }
      END { printf "| %s | `%s` | %.1f, %.1f, %.1f | %.2f, %.2f, %.2f | %.1f %% | %.2f |\n", name, opts,
              v["pos_mae_x_mm"], v["pos_mae_y_mm"], v["pos_mae_z_mm"], v["roll_mae_deg"], v["pitch_mae_deg"],
              v["yaw_mae_deg"], 100 * v["lf_contact_agreement"], v["lf_normal_force_mae_n"] }' \
      "$dir/comparison_summary.csv" >> "$(partial "$out")"
  else
    echo "| $name | \`$*\` | failed: $(tail -1 "$dir.log") | | | |" >> "$(partial "$out")"
  fi
}

row "default"
row "force at the sphere centre (no rolling)" --contact-point off
row "isotropic friction" --friction isotropic
row "explicit friction" --friction-update explicit
row "previous model (centre, isotropic, explicit)" --contact-point off --friction isotropic --friction-update explicit
row "ours with MuJoCo's friction 1.6" --mu-static 1.6 --mu-dynamic 1.6
row "MuJoCo with our friction 2.0" --mj-friction 2.0
row "MuJoCo 10x stiffer (solref -16000)" --mj-stiffness 16000 --mj-damping 316
row "MuJoCo 100x stiffer (solref -160000)" --mj-stiffness 160000 --mj-damping 1000
row "MuJoCo softer damping (solref damping -40)" --mj-damping 40
row "ours on MIT's thigh inertia" --original-inertia
row "Table I in SI metres (K = 1e4 N/m^2.2)" --length-unit 1
commit "$out"
echo "results written to $out"
