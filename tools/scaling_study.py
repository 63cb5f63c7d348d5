#!/usr/bin/python3
"""Paper 001 Fig. 8 for rbdc: FLOPs and time of the trunk operational-space quantities against the
number of links, for robot families grown from the Mini Cheetah.

Families (URDFs written to a temporary directory, never committed):
  - legs: 4 legs of 3 … 8 links (ab/ad, hip, then the shank split into 1 … 6 knee links);
  - width: 4 … 8 legs of 3 links (pairs spread along the trunk).
Every foot is in contact (m = 3 · legs constraints). For each robot:
  - generated recursion: FLOPs of the generated osc_closed_chain (`rbdc flops --json`);
  - generated closed form: the generator's FLOPs for H (mass_matrix), C (quadratic_velocity_terms),
    G (gravity_terms) and J_c (feet_jacobian), plus the dense matrix operations of Eqs. 20-26
    counted analytically (closed_form_dense_flops below): the generator has no closed-form
    function, so this is the paper's own way of counting;
  - runtime recursion: generic_ops of osc_closed_chain (dense 6x6 arithmetic, counted by rbdc);
  - times: the generated osc_closed_chain compiled with -O3 in a small harness, and the runtime's
    osc_closed_chain and osc_closed_form_constrained (rbdc-osc-scaling-timer), all as process CPU time.
Writes results/osc/scaling.md, scaling.json, scaling_flops.png, scaling_time.png.

Usage: tools/scaling_study.py [--build-dir DIR] [--out DIR] [--no-timing]
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile

from result_files import replacing, save_figure

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BUDGET_FLOPS = 200e3  # paper 001 Fig. 8: what the closed form could spend at 1 kHz

# Mini Cheetah parameters (robots/mini_cheetah.urdf), reused for every family member.
TRUNK = {"mass": 3.3, "size": (0.38, 0.098, 0.1)}
ABAD = {"mass": 0.54, "offset": 0.062}
THIGH = {"mass": 0.634, "length": 0.209}
SHANK = {"mass": 0.064, "length": 0.195}
HIP_X, HIP_Y = 0.19, 0.049


def box_inertia(mass, a, b, c):
    return (mass * (b * b + c * c) / 12, mass * (a * a + c * c) / 12, mass * (a * a + b * b) / 12)


def link_xml(name, mass, com, inertia):
    ixx, iyy, izz = inertia
    return (f'  <link name="{name}"><inertial><origin xyz="{com[0]} {com[1]} {com[2]}"/>'
            f'<mass value="{mass}"/><inertia ixx="{ixx:.6g}" ixy="0" ixz="0" iyy="{iyy:.6g}" '
            f'iyz="0" izz="{izz:.6g}"/></inertial></link>\n')


def joint_xml(name, parent, child, xyz, axis):
    return (f'  <joint name="{name}" type="revolute"><parent link="{parent}"/><child link="{child}"/>'
            f'<origin xyz="{xyz[0]} {xyz[1]} {xyz[2]}"/><axis xyz="{axis[0]} {axis[1]} {axis[2]}"/>'
            f'<limit lower="-3" upper="3" effort="30" velocity="30"/></joint>\n')


def robot_urdf(name, legs, links_per_leg):
    """A Mini Cheetah-like robot: `legs` legs of `links_per_leg` links (≥ 3)."""
    parts = [f'<?xml version="1.0"?>\n<robot name="{name}">\n']
    parts.append(link_xml("trunk", TRUNK["mass"], (0, 0, 0), box_inertia(TRUNK["mass"], *TRUNK["size"])))
    pairs = math.ceil(legs / 2)
    knee_links = links_per_leg - 2
    for k in range(legs):
        side = 1 if k % 2 == 0 else -1
        x = HIP_X if pairs == 1 else HIP_X - 2 * HIP_X * (k // 2) / (pairs - 1)
        leg = f"leg{k}"
        parts.append(joint_xml(f"{leg}_abad_joint", "trunk", f"{leg}_abad", (x, side * HIP_Y, 0), (1, 0, 0)))
        parts.append(link_xml(f"{leg}_abad", ABAD["mass"], (0, side * 0.036, 0), (4e-4, 4e-4, 4e-4)))
        parts.append(joint_xml(f"{leg}_hip_joint", f"{leg}_abad", f"{leg}_thigh", (0, side * ABAD["offset"], 0), (0, 1, 0)))
        parts.append(link_xml(f"{leg}_thigh", THIGH["mass"], (0, 0, -0.02), (1.8e-3, 1.8e-3, 4e-4)))
        parent, drop = f"{leg}_thigh", THIGH["length"]
        segment = SHANK["length"] / knee_links
        for s in range(knee_links):
            child = f"{leg}_shank{s}"
            m = SHANK["mass"] / knee_links
            parts.append(joint_xml(f"{leg}_knee{s}_joint", parent, child, (0, 0, -drop), (0, 1, 0)))
            parts.append(link_xml(child, m, (0, 0, -segment / 2), box_inertia(m, 0.02, 0.02, segment)))
            parent, drop = child, segment
        parts.append(f'  <joint name="{leg}_foot_joint" type="fixed"><parent link="{parent}"/>'
                     f'<child link="{leg}_foot"/><origin xyz="0 0 {-drop}"/></joint>\n'
                     f'  <link name="{leg}_foot"/>\n')
    parts.append("</robot>\n")
    return "".join(parts)


def closed_form_dense_flops(n, m):
    """Dense operations of Eqs. 20-26 for n = nv, m = 3 · feet, task dimension 6 (J_t a selector),
    one multiply-add counted as 2 FLOPs, H and Λ_c⁻¹ factorised by Cholesky."""
    t = 6
    terms = {
        "Cholesky of H": n ** 3 / 3,
        "H^-1 J_c^T (m solves)": 2 * n * n * m,
        "Lambda_c^-1 = J_c H^-1 J_c^T": 2 * m * m * n,
        "Cholesky of Lambda_c^-1": m ** 3 / 3,
        "Jbar_c^T = Lambda_c J_c H^-1 (n solves)": 2 * m * m * n,
        "N_c^T = 1 - J_c^T Jbar_c^T (Eq. 17)": 2 * n * n * m,
        "J_t H^-1 (t solves)": 2 * n * n * t,
        "J_t H^-1 N_c^T (Eq. 20/22)": 2 * t * n * n,
        "inverse of Lambda~^-1 (6x6)": 2 * t ** 3,
        "J~_t^T = Lambda~ J_t H^-1 N_c^T (Eq. 22)": 2 * t * t * n,
        "J~_t^T (C + G) (Eqs. 25-26)": 2 * t * n,
        "Lambda~ J_t H^-1 J_c^T Lambda_c Jdot_c v (Eq. 25)": 2 * m * m + 2 * m * n + 2 * t * n + 2 * t * t,
    }
    return sum(terms.values())


def run(cmd, **kw):
    result = subprocess.run(cmd, capture_output=True, text=True, **kw)
    if result.returncode != 0:
        sys.exit(f"scaling_study: {' '.join(cmd)} failed:\n{result.stderr}")
    return result.stdout


def flops(urdf, scene, env):
    out = run([os.path.join(ROOT, "rbdc"), "flops", urdf, "--scene", scene, "--json"], env=env)
    return json.loads(out)["functions"]


HARNESS = r"""
#include <cstdio>
#include <ctime>
#include <random>
#include "{robot}/timing.hpp"
namespace gen = rbdc_gen::{robot}::timing;
int main() {{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(-0.5, 0.5);
  static double q[16][gen::nq], v[16][gen::nv];
  for (int s = 0; s < 16; ++s) {{
    for (int i = 0; i < gen::nq; ++i) q[s][i] = i < 3 ? 0.0 : (i == 3 ? 1.0 : (i < 7 ? 0.0 : angle(rng)));
    for (int i = 0; i < gen::nv; ++i) v[s][i] = angle(rng);
  }}
  double Lambda[36], JbarT[6 * gen::n_joints], b[6], sink = 0, ground = 4.3e6;
  const int calls = 100000;
  for (int i = 0; i < 1000; ++i) gen::osc_closed_chain<double>(q[i % 16], v[i % 16], &ground, Lambda, JbarT, b);
  const std::clock_t start = std::clock();  // process CPU time: robust to other jobs on the machine
  for (int i = 0; i < calls; ++i) {{
    gen::osc_closed_chain<double>(q[i % 16], v[i % 16], &ground, Lambda, JbarT, b);
    sink += b[0];
  }}
  const double ns = 1e9 * double(std::clock() - start) / CLOCKS_PER_SEC / calls;
  std::printf("%.1f %d\n", ns, sink != sink);
}}
"""


def time_generated(urdf, name, work, env):
    scene = os.path.join(work, "timing.yaml")
    with open(scene, "w") as f:
        f.write("name: timing\nquantities: [osc_closed_chain]\n")
    out_dir = os.path.join(work, "gen")
    run([os.path.join(ROOT, "rbdc"), "generate", urdf, "--scene", scene, "-o", out_dir], env=env)
    source = os.path.join(work, f"{name}_timer.cpp")
    with open(source, "w") as f:
        f.write(HARNESS.format(robot=name))
    binary = os.path.join(work, f"{name}_timer")
    run(["g++", "-O3", "-DNDEBUG", "-std=c++17", "-I/usr/include/eigen3", "-I" + out_dir, source, "-o", binary])
    return float(run([binary]).split()[0])


def time_runtime(urdf, build_dir):
    timer = os.path.join(build_dir, "bin", "rbdc-osc-scaling-timer")
    return json.loads(run([timer, urdf]))


def plot(rows, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    styles = {"legs": ("o", "-"), "width": ("s", "--")}
    labels = {"legs": "4 legs, 3-8 links each", "width": "4-8 legs, 3 links each"}
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for family in ("legs", "width"):
        fam = [r for r in rows if r["family"] == family]
        x = [r["links"] for r in fam]
        marker, line = styles[family]
        ax.plot(x, [r["flops_generated_recursion"] for r in fam], marker + line, color="C0",
                label=f"generated recursion ({labels[family]})")
        ax.plot(x, [r["flops_closed_form"] for r in fam], marker + line, color="C3",
                label=f"closed form ({labels[family]})")
        ax.plot(x, [r["flops_runtime_recursion"] for r in fam], marker + line, color="C2",
                label=f"runtime recursion, generic ({labels[family]})")
    ax.axhline(BUDGET_FLOPS, color="k", linestyle=":", label="200 kFLOPs (1 kHz budget, paper 001)")
    ax.set_yscale("log")
    ax.set_xlabel("links (bodies without the trunk)")
    ax.set_ylabel("FLOPs")
    ax.set_title("Trunk operational-space quantities, every foot in contact (cf. paper 001 Fig. 8)")
    ax.legend(fontsize=7)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    save_figure(fig, os.path.join(out, "scaling_flops.png"), dpi=120)
    if not any("ns_generated_recursion" in r for r in rows):
        return
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for family in ("legs", "width"):
        fam = [r for r in rows if r["family"] == family]
        x = [r["links"] for r in fam]
        marker, line = styles[family]
        ax.plot(x, [r["ns_generated_recursion"] for r in fam], marker + line, color="C0",
                label=f"generated recursion ({labels[family]})")
        ax.plot(x, [r["ns_runtime_closed_form"] for r in fam], marker + line, color="C3",
                label=f"runtime closed form ({labels[family]})")
        ax.plot(x, [r["ns_runtime_recursion"] for r in fam], marker + line, color="C2",
                label=f"runtime recursion ({labels[family]})")
    ax.axhline(1e6, color="k", linestyle=":", label="1 ms (1 kHz)")
    ax.set_yscale("log")
    ax.set_xlabel("links (bodies without the trunk)")
    ax.set_ylabel("time per call (ns)")
    ax.set_title("Measured time per call (this machine)")
    ax.legend(fontsize=7)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    save_figure(fig, os.path.join(out, "scaling_time.png"), dpi=120)


def table(rows, timing):
    head = ("| family | legs | links/leg | links | nv | m | generated recursion | closed form (gen. H,C,G,J + dense) "
            "| runtime recursion (generic) |")
    sep = "|---|---|---|---|---|---|---|---|---|"
    if timing:
        head += " gen. recursion ns | runtime recursion ns | runtime closed form ns |"
        sep += "---|---|---|"
    lines = [head, sep]
    for r in rows:
        line = (f"| {r['family']} | {r['legs']} | {r['links_per_leg']} | {r['links']} | {r['nv']} | {r['m']} "
                f"| {r['flops_generated_recursion']:,} | {r['flops_closed_form']:,.0f} | {r['flops_runtime_recursion']:,} |")
        if timing:
            line += (f" {r['ns_generated_recursion']:,.0f} | {r['ns_runtime_recursion']:,.0f} "
                     f"| {r['ns_runtime_closed_form']:,.0f} |")
        lines.append(line)
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--build-dir", default=os.environ.get("RBDC_BUILD_DIR", os.path.join(ROOT, "build")),
                        help="build tree with rbdc-model and rbdc-osc-scaling-timer")
    parser.add_argument("--out", default=os.path.join(ROOT, "results", "osc"))
    parser.add_argument("--no-timing", action="store_true", help="FLOP counts only")
    args = parser.parse_args()
    env = dict(os.environ, RBDC_BUILD_DIR=os.path.abspath(args.build_dir))
    os.makedirs(args.out, exist_ok=True)
    family = [("legs", 4, links) for links in range(3, 9)] + [("width", legs, 3) for legs in range(4, 9)]
    rows = []
    with tempfile.TemporaryDirectory(prefix="rbdc-scaling-") as work:
        scene = os.path.join(work, "scaling.yaml")
        with open(scene, "w") as f:
            f.write("name: scaling\nquantities: [osc_closed_chain, mass_matrix, quadratic_velocity_terms, "
                    "gravity_terms, feet_jacobian]\n")
        for name_family, legs, links_per_leg in family:
            name = f"quad_{legs}x{links_per_leg}"
            urdf = os.path.join(work, name + ".urdf")
            with open(urdf, "w") as f:
                f.write(robot_urdf(name, legs, links_per_leg))
            counts = flops(urdf, scene, env)
            nv = 6 + legs * links_per_leg
            m = 3 * legs
            generated_parts = sum(counts[q]["generated"]["total"] for q in
                                  ("mass_matrix", "quadratic_velocity_terms", "gravity_terms", "feet_jacobian"))
            row = {"family": name_family, "legs": legs, "links_per_leg": links_per_leg,
                   "links": legs * links_per_leg, "nv": nv, "m": m,
                   "flops_generated_recursion": counts["osc_closed_chain"]["generated"]["total"],
                   "flops_runtime_recursion": counts["osc_closed_chain"]["generic"]["total"],
                   "flops_closed_form": generated_parts + closed_form_dense_flops(nv, m)}
            if not args.no_timing:
                row["ns_generated_recursion"] = time_generated(urdf, name, work, env)
                runtime = time_runtime(urdf, args.build_dir)
                row["ns_runtime_recursion"] = runtime["runtime_recursion_ns"]
                row["ns_runtime_closed_form"] = runtime["runtime_closed_form_ns"]
            print(json.dumps(row), file=sys.stderr)
            rows.append(row)
    with replacing(os.path.join(args.out, "scaling.json")) as partial, open(partial, "w") as f:
        json.dump(rows, f, indent=1, sort_keys=True)
        f.write("\n")
    with replacing(os.path.join(args.out, "scaling.md")) as partial, open(partial, "w") as f:
        f.write("# Scaling study (paper 001 Fig. 8), written by tools/scaling_study.py\n\n"
                "FLOPs: every operation counts one (rbdc flops). Closed form = generated H, C, G, J_c plus the "
                "dense operations of Eqs. 20-26 counted analytically. Times: mean CPU time per call over "
                "cycled random states on the machine that ran the script.\n\n")
        f.write(table(rows, not args.no_timing))
    plot(rows, args.out)


if __name__ == "__main__":
    main()
