#!/usr/bin/python3
"""What the joint angles' sines cost a call (docs/performance.md, "The sines' latency in series"):
times a robot's generated inverse dynamics, c + g, M and forward dynamics as generated, and again
with `joint_sincos` replaced by a stand-in of one multiplication per angle (wrong values, the same
code after it), on 64 random states, runs of the two builds alternated. The same driver measures
the sines' latency (in registers, each vector of angles the last one's sines times 0.9 plus its
cosines) and the clock (a chain of multiply-adds, 4 cycles each on the cores measured here). Every
generated function waits on its sines before its first body; if no other work runs beside them (the
next call's included), the call takes the sines' latency plus the rest, and the rest runs at most
at the core's rate, so

    bound = (sines' latency + instructions / most a cycle) / clock

(instructions: the header's schedule count, tools/instruction_rates.py, less those that wait on no
sine, `beside_sines` in `rbdc flops --json`, with --flops; most a cycle: the multiplications' two
pipes or the mixed peak, whichever is less). The table gives it beside the times, in cycles too,
and what a peer's time over it allows with --peer QUANTITY=NS (in cycles at --peer-ghz, the clock
of the peer's run; default this run's).

Usage: tools/trig_latency.py GENERATED ROBOT [--floating] [--runs N] [--cxx CXX] [--peak RATE]
                             [--flops FLOPS_JSON] [--peer QUANTITY=NS ...] [--peer-ghz GHZ]
  GENERATED  a directory holding rbdc_gen/ and ROBOT/full/ (`rbdc generate` -o)
  --floating the robot has a floating trunk (the driver normalises the quaternion q[3:7])
  --peak     FMAs and additions a cycle, half and half (default 4.05: tools/machine_peak on Zen 5)
  --flops    `rbdc flops ROBOT --json` for the full scene: the operations beside the sines left out
  --peer     the peer's median ns for ID, c+g, M or FD: adds the most ratio the bound allows
  --peer-ghz the clock of the run that gave the peer's times (tools/machine_peak)
"""
import json
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import generated_driver  # noqa: E402
from instruction_rates import MIXED_PEAK, instructions, most_per_cycle, multiplication_share  # noqa: E402

QUANTITIES = {"ID": "inverse_dynamics", "c+g": "bias", "M": "mass_matrix", "FD": "forward_dynamics"}
# Opens the double overload of joint_sincos in rbdc_gen/support.hpp; the stand-in goes first in it.
OPENING = "RBDC_ALWAYS_INLINE JointTrig<double, N> joint_sincos(const double (&angle)[N]) noexcept {\n"
STAND_IN = """#ifdef RBDC_TRIG_STAND_IN
  JointTrig<double, N> stand_in;
  for (int i = 0; i < N; ++i) {
    stand_in.sin[i] = 0.5 * angle[i];
    stand_in.cos[i] = 0.25 * angle[i];
  }
  return stand_in;
#endif
"""
DRIVER = """#include "{robot}/full.hpp"
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
using namespace rbdc_gen::{robot}::full;
using Clock = std::chrono::steady_clock;

template <class Q, class V, class T, class F, class A>
void forward(const Q& q, const V& v, const T& tau, const F& feet, A& a) {{
  if constexpr (n_feet > 0) forward_dynamics(q, v, tau, feet, a);
  else forward_dynamics(q, v, tau, a);
}}

template <class Call>
double ns_per_call(Call call, int calls) {{
  const auto start = Clock::now();
  for (int i = 0; i < calls; ++i) {{
    call(i % 64);
    asm volatile("" ::: "memory");
  }}
  return std::chrono::duration<double, std::nano>(Clock::now() - start).count() / calls;
}}

int main() {{
  constexpr int S = 64, calls = 100000, chain = 2000000;
  static ConfigVector<double> q[S];
  static TangentVector<double> v[S], a[S], out;
  static JointVector<double> tau[S];
  static MassMatrix<double> M;
  const FeetMatrix<double> feet = FeetMatrix<double>::Zero();
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int s = 0; s < S; ++s) {{
    for (int k = 0; k < nq; ++k) q[s][k] = 3 * u(rng);
    for (int k = 0; k < nv; ++k) v[s][k] = u(rng), a[s][k] = u(rng);
    for (int k = 0; k < n_joints; ++k) tau[s][k] = u(rng);
    if ({floating}) q[s].segment<4>(3).normalize();
  }}
  std::printf("ID %.2f\\n", ns_per_call([&](int s) {{ inverse_dynamics(q[s], v[s], a[s], out); }}, calls));
  std::printf("c+g %.2f\\n", ns_per_call([&](int s) {{ bias(q[s], v[s], out); }}, calls));
  std::printf("M %.2f\\n", ns_per_call([&](int s) {{ mass_matrix(q[s], M); }}, calls));
  std::printf("FD %.2f\\n", ns_per_call([&](int s) {{ forward(q[s], v[s], tau[s], feet, out); }}, calls));
  // the sines' latency, in registers from angles to results (the loads before them and the
  // extractions after them left out, so a lower bound): each vector of angles the last one's sines
  // times 0.9 plus its cosines
  using Angles = rbdc_gen::simd::Vector<double, 4>;
  Angles angle = {{0.3, 1.1, -2.0, 0.7}};
  std::printf("sines %.3f\\n", ns_per_call([&](int) {{
    Angles s, c;
    rbdc_gen::simd::sincos_folded<4>(angle, s, c);
    angle = s * 0.9 + c;
    asm volatile("" : "+v"(angle));
  }}, chain));
  double x = angle[0];
  std::printf("fma %.3f\\n", ns_per_call([&](int) {{
    x = x * 0.9 + 0.1;
    asm volatile("" : "+v"(x));
  }}, chain));
}}
"""


def with_stand_in(support):
    """support.hpp's text with the stand-in first in joint_sincos's double overload."""
    if support.count(OPENING) != 1:
        sys.exit("trig_latency: joint_sincos's double overload no longer opens with the text this tool looks for")
    return support.replace(OPENING, OPENING + STAND_IN)


def driver(robot, floating):
    return DRIVER.format(robot=robot, floating=int(floating))


def measurements(output):
    return {name: float(value) for name, value in re.findall(r"^(\S+) ([\d.]+)$", output, re.M)}


def main():
    parser = generated_driver.parser(__doc__)
    parser.add_argument("--peak", type=float, default=MIXED_PEAK)
    parser.add_argument("--flops", type=Path)
    parser.add_argument("--peer", action="append", default=[], metavar="QUANTITY=NS")
    parser.add_argument("--peer-ghz", type=float)
    args = parser.parse_args()
    peer = {quantity: float(ns) for quantity, _, ns in (option.partition("=") for option in args.peer)}
    beside = ({name: counts["critical_path"]["beside_sines"]
               for name, counts in json.loads(args.flops.read_text())["functions"].items()} if args.flops else {})
    with tempfile.TemporaryDirectory() as scratch:
        tree = Path(scratch) / "gen"
        shutil.copytree(args.generated / "rbdc_gen", tree / "rbdc_gen")
        shutil.copytree(args.generated / args.robot, tree / args.robot)
        support = tree / "rbdc_gen" / "support.hpp"
        support.write_text(with_stand_in(support.read_text()))
        source = Path(scratch) / "driver.cpp"
        source.write_text(driver(args.robot, args.floating))
        binaries = {}
        for build, flags in (("generated", []), ("stand-in", ["-DRBDC_TRIG_STAND_IN"])):
            binaries[build] = Path(scratch) / build
            generated_driver.build(args.cxx, tree, source, binaries[build], flags)
        runs = {build: [] for build in binaries}
        for _ in range(args.runs):
            for build, binary in binaries.items():
                runs[build].append(measurements(subprocess.run([str(binary)], check=True, capture_output=True,
                                                               text=True).stdout))
    median = {build: {name: statistics.median(run[name] for run in results) for name in results[0]}
              for build, results in runs.items()}
    fma_ns = median["generated"]["fma"]
    ghz = 4 / fma_ns
    sines = (median["generated"]["sines"] - fma_ns) * ghz
    print(f"{args.robot}: clock {ghz:.2f} GHz (a multiply-add chain), the sines' latency {sines:.0f} cycles "
          f"({sines / ghz:.1f} ns); medians of {args.runs} alternated runs of each build")
    peer_ghz = args.peer_ghz or ghz
    print("| quantity | ns | ns, stand-in sines | difference | instructions | most a cycle | bound cycles | bound ns |"
          + (" most ratio |" if peer else ""))
    print("|---|---:|---:|---:|---:|---:|---:|---:|" + ("---:|" if peer else ""))
    for quantity, function in QUANTITIES.items():
        header = args.generated / args.robot / "full" / f"{function}.hpp"
        n = instructions(header) - beside.get(function, 0)
        most = most_per_cycle(multiplication_share(header), args.peak)
        bound = sines + n / most
        ours, stand_in = median["generated"][quantity], median["stand-in"][quantity]
        row = (f"| {quantity} | {ours:.1f} | {stand_in:.1f} | {ours - stand_in:.1f} | {n} | {most:.2f} "
               f"| {bound:.0f} | {bound / ghz:.1f} |")
        if peer:
            row += f" {peer[quantity] * peer_ghz / bound:.2f}× |" if quantity in peer else " – |"
        print(row)


if __name__ == "__main__":
    main()
