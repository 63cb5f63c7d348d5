#!/usr/bin/python3
"""Where the looped RNEA derivatives spend a call, phase by phase (docs/performance.md, "The ∂τ
loop phase by phase"): copies a generated tree, puts a serialised time-stamp read (lfence; rdtsc)
before each phase of rnea_derivatives_loop (rbdc_gen/rnea_derivatives.hpp, found by the comments
that open them), builds a driver that calls the robot's inverse_dynamics_derivatives on 64 random
states, and prints each phase's share, the median over runs. The fences keep the phases apart and
cost a few percent of the call; the time-stamp counter runs at its own rate, so the table gives
nanoseconds (measured against the steady clock) as well.

Usage: tools/loop_phases.py GENERATED ROBOT [--floating] [--runs N] [--cxx CXX]
  GENERATED  a directory holding rbdc_gen/ and ROBOT/derivatives.hpp (`rbdc generate` -o), whose
             inverse_dynamics_derivatives is in its looped form (its header's schedule line says so)
  --floating the robot has a floating trunk (the driver normalises the quaternion q[3:7])
"""
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import generated_driver  # noqa: E402

# (phase name, the text that opens it in rnea_derivatives_loop); the last phase ends at the return
PHASES = [
    ("root frames and inertias", "  {\n    Scalar E0[9][NP], p0[3][NP];\n    root_frames"),
    ("outward: v, u, a", "  for (int k = 0; k < 6; ++k) {  // the root: the trunk"),
    ("c", "  // c = a_λ × S + v_λ × u = a × S + v × u"),
    ("forces, momenta, rates", "  for (int i = 0; i < NP; ++i) {  // each body"),
    ("inward sums", "  // Inward, leaves first"),
    ("rows and columns (ρ, G, D)", "  // ρ^I = I^C S, ρ^B"),
    ("outputs cleared", "  constexpr bool kFeet = !std::is_same_v<Feet, NoFeetForces>;\n  if constexpr (TakesVectors"),
    ("the trunk's rows and columns", "  // With the feet: χ component"),
    ("entries along the subtrees", "  // Body j with its subtree i = j"),
    ("the trunk's block", "  if (Floating) {  // the trunk's block"),
]
PROLOGUE = """#include <x86intrin.h>
inline unsigned long long rbdc_phase_ticks[16];
inline unsigned long long rbdc_phase_last;
#define RBDC_PHASE(k) do { _mm_lfence(); const unsigned long long t_ = __rdtsc(); \\
  if ((k) > 0) rbdc_phase_ticks[(k)] += t_ - rbdc_phase_last; rbdc_phase_last = t_; } while (0)
"""
DRIVER = """#include "{robot}/derivatives.hpp"
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
using namespace rbdc_gen::{robot}::derivatives;
int main() {{
  constexpr int S = 64, N = 20000;
  static double q[S][nq], v[S][nv], a[S][nv], dq[nv * nv], dv[nv * nv];
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int s = 0; s < S; ++s) {{
    for (auto& x : q[s]) x = u(rng);
    for (auto& x : v[s]) x = u(rng);
    for (auto& x : a[s]) x = u(rng);
    if ({floating}) {{
      double n = 0;
      for (int k = 3; k < 7; ++k) n += q[s][k] * q[s][k];
      for (int k = 3; k < 7; ++k) q[s][k] /= std::sqrt(n);
    }}
  }}
  const auto start = std::chrono::steady_clock::now();
  const unsigned long long ticks = __rdtsc();
  for (int i = 0; i < N; ++i) {{
    inverse_dynamics_derivatives(q[i % S], v[i % S], a[i % S], dq, dv);
    asm volatile("" ::: "memory");
  }}
  const double ns = std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - start).count();
  std::printf("call %.1f ns %.1f ticks\\n", ns / N, double(__rdtsc() - ticks) / N);
  for (int k = 1; k <= {phases}; ++k) std::printf("phase %d %.1f\\n", k, double(rbdc_phase_ticks[k]) / N);
}}
"""


def instrumented(text):
    """rnea_derivatives.hpp's text with RBDC_PHASE(k) before phase k and after the last."""
    for k, (name, opening) in enumerate(PHASES):
        if text.count(opening) != 1:
            sys.exit(f"loop_phases: the phase '{name}' no longer opens with the text this tool looks for")
        text = text.replace(opening, f"RBDC_PHASE({k});\n" + opening)
    end = "\n}\n\n}  // namespace rbdc_gen\n"
    if not text.endswith(end):
        sys.exit("loop_phases: rnea_derivatives_loop is no longer the header's last function")
    text = text[: -len(end)] + f"\nRBDC_PHASE({len(PHASES)});" + end
    return text.replace("#pragma once\n", "#pragma once\n" + PROLOGUE, 1)


def driver(robot, floating):
    return DRIVER.format(robot=robot, floating=int(floating), phases=len(PHASES))


def main():
    args = generated_driver.parser(__doc__).parse_args()
    with tempfile.TemporaryDirectory() as scratch:
        tree = Path(scratch) / "gen"
        shutil.copytree(args.generated, tree)
        header = tree / "rbdc_gen" / "rnea_derivatives.hpp"
        header.write_text(instrumented(header.read_text()))
        source = Path(scratch) / "driver.cpp"
        source.write_text(driver(args.robot, args.floating))
        binary = Path(scratch) / "driver"
        generated_driver.build(args.cxx, tree, source, binary)
        runs = [subprocess.run([str(binary)], check=True, capture_output=True, text=True).stdout
                for _ in range(args.runs)]
    calls = [re.search(r"call ([\d.]+) ns ([\d.]+) ticks", run).groups() for run in runs]
    ns = statistics.median(float(c[0]) for c in calls)
    ticks_per_ns = statistics.median(float(c[1]) / float(c[0]) for c in calls)
    phases = [statistics.median(float(re.search(rf"phase {k} ([\d.]+)", run).group(1)) for run in runs)
              for k in range(1, len(PHASES) + 1)]
    print(f"{args.robot}: inverse_dynamics_derivatives {ns:.0f} ns a call with the fences "
          f"(median of {args.runs} runs of 20 000 calls)")
    print("| phase | ns | share |\n|---|---:|---:|")
    for (name, _), ticks in zip(PHASES, phases):
        print(f"| {name} | {ticks / ticks_per_ns:.0f} | {100 * ticks / sum(phases):.1f} % |")
    print(f"| the traced part, the call and the fences | {ns - sum(phases) / ticks_per_ns:.0f} | |")


if __name__ == "__main__":
    main()
