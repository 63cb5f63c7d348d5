#!/bin/sh
# Regenerates results/sim/rotors.md: the 10 s PD trot of rbdc-sim without the drive train (paper
# 000's model), with MIT's rotors reduced to armature, and with the rotors as bodies (--rotors,
# docs/simulator.md), all on the runtime dynamics, plus the generated dynamics without and with the
# rotors as a check that both implementations give the same runs; then rbdc-mujoco-compare with the same three drive
# trains (MuJoCo with the armature); then rbdc-osc-trot with and without the rotors in the plant.
# Usage: results/scripts/sim_rotors.sh [BUILD_DIR]
set -eu
. "$(dirname "$0")/common.sh"
out="$root/results/sim/rotors.md"
duration="${DURATION:-10}"
for rotors in none armature full; do
  "$build/bin/rbdc-sim" --quiet --duration "$duration" --dynamics runtime --rotors "$rotors" \
    --out "$scratch/$rotors.csv" > "$scratch/$rotors.txt"
done
"$build/bin/rbdc-sim" --quiet --duration "$duration" --out "$scratch/generated.csv" > "$scratch/generated.txt"
"$build/bin/rbdc-sim" --quiet --duration "$duration" --rotors full --out "$scratch/generated_full.csv" \
  > "$scratch/generated_full.txt"
{
  echo "# The trot with the drive train ($duration s, dt 1e-4 s, PD trot of paper 000)"
  echo
  echo "rbdc-sim --dynamics runtime --rotors none | armature | full (robots/mini_cheetah_rotors.topology.yaml:"
  echo "twelve rotors, 0.66 kg, reflected inertia 0.0023 kg m² at abad and hip, 0.0055 kg m² at the knee);"
  echo "the last two columns are the generated dynamics (generated/mini_cheetah and mini_cheetah_rotors) on"
  echo "the same runs as a check: they must match the runtime's columns. The controller is the same in every run"
  echo "(its gains and trajectories do not know the rotors). Written by results/scripts/sim_rotors.sh."
  echo
  python3 "$root/results/scripts/rotor_trot_table.py" "none (paper 000)=$scratch/none.csv" \
    "armature=$scratch/armature.csv" "full rotors=$scratch/full.csv" "none, generated=$scratch/generated.csv" \
    "full rotors, generated=$scratch/generated_full.csv"
  echo
  echo "## Against MuJoCo with the armature (rbdc-mujoco-compare --rotors)"
  echo
  echo "MuJoCo has no rotor bodies; it gets the rotors' reflected inertia as joint armature (gr² J) in"
  echo "the armature and full rows, nothing in the none row (the default comparison). Error measures of"
  echo "paper 000 (mean absolute errors over the run, ours against MuJoCo), both sides on MuJoCo's balanced"
  echo "thigh inertia as in comparison.md."
  echo
  echo "| ours | MuJoCo | pos MAE x, y, z (mm) | roll, pitch, yaw MAE (deg) | LF contact agreement | LF f_n MAE (N) |"
  echo "|---|---|---|---|---|---|"
  for rotors in none armature full; do
    mujoco=$([ "$rotors" = none ] && echo "no armature" || echo "armature")
    "$build/bin/rbdc-mujoco-compare" --quiet --no-plots --no-timing --duration "$duration" --rotors "$rotors" \
      --out "$scratch/compare_$rotors" > /dev/null 2> "$scratch/compare_$rotors.log"
    awk -F, -v ours="$rotors" -v theirs="$mujoco" '
      NR > 1 { v[$1] = $2 }
      END { printf "| %s | %s | %.1f, %.1f, %.1f | %.2f, %.2f, %.2f | %.1f %% | %.2f |\n", ours, theirs,
              v["pos_mae_x_mm"], v["pos_mae_y_mm"], v["pos_mae_z_mm"], v["roll_mae_deg"], v["pitch_mae_deg"],
              v["yaw_mae_deg"], 100 * v["lf_contact_agreement"], v["lf_normal_force_mae_n"] }' \
      "$scratch/compare_$rotors/comparison_summary.csv"
  done
  echo
  echo "## The operational-space trot of paper 001 with the rotors in the plant (rbdc-osc-trot --rotors)"
  echo
  echo "The plant simulates the rotors as bodies (generated/mini_cheetah_rotors); the controllers' trunk"
  echo "recursions (generated/mini_cheetah stance scenes) and gains do not model them: the mismatch a"
  echo "controller built on paper 001's model meets on the real robot."
  echo
  for rotors in none full; do
    echo "rbdc-osc-trot --duration $duration --rotors $rotors:"
    echo
    "$build/bin/rbdc-osc-trot" --duration "$duration" --rotors "$rotors" | tail -n +3
    echo
  done
  echo "Wall time per run (this machine, shared):"
  for run in none armature full generated generated_full; do
    echo "- $run: $(grep '^simulated' "$scratch/$run.txt")"
  done
} > "$(partial "$out")"
commit "$out"
