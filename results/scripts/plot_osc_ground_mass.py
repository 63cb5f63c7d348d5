#!/usr/bin/python3
"""Paper 001 Fig. 7 for the Mini Cheetah, with the 500-configuration study beside it.

Usage: results/scripts/plot_osc_ground_mass.py GROUND_MASS.json OUT_DIR
(results/scripts/osc_ground_mass.sh runs it on the output of rbdc-osc-ground-mass).
Writes OUT_DIR/ground_mass.png (left: relative error of the closed-chain recursion's Λ̃, J̃ᵀ, b̃
against the constrained closed form over the ground mass at one mid-stance configuration, trot pair
LF + RH pinned, Eq. 58's heuristic and Eq. 59's decade marked; right: where the Λ̃ and b̃ errors
are smallest over the random configurations) and OUT_DIR/ground_mass.md (the figures in words).
"""
import json
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
from result_files import replacing, save_figure  # noqa: E402


def within_a_decade(ratios):
    return sum(1 for r in ratios if 0.1 <= r <= 10)


def main(path, out_dir):
    with open(path) as f:
        d = json.load(f)
    heuristic = d["heuristic_ground_mass"] / d["total_mass"]  # as a multiple of the total mass
    n = d["configurations"]
    argmin = {"Λ̃": d["study_argmin_Lambda_over_heuristic"], "b̃": d["study_argmin_b_over_heuristic"]}

    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.2), gridspec_kw={"width_ratios": [1.4, 1]})
    for key, label, color in (("error_Lambda", "Λ̃ (Frobenius)", "C0"), ("error_JbarT", "J̃ᵀ (Frobenius)", "C1"),
                              ("error_b", "b̃ (Euclidean)", "C2")):
        left.loglog(d["ratios"], d[key], color=color, label=label)
    left.axvspan(heuristic / 10, heuristic * 10, color="0.85", label="Eq. 59: a decade around it")
    left.axvline(heuristic, color="k", linestyle="--", label="Eq. 58: m_min/√ε = %.2g × total" % heuristic)
    left.set_xlabel("ground mass / total robot mass (%.3f kg)" % d["total_mass"])
    left.set_ylabel("relative error vs closed form (Eqs. 20-26)")
    left.set_title("one mid-stance configuration, LF + RH pinned")
    left.grid(True, which="major", alpha=0.3)
    left.legend(fontsize=8)

    bins = [10 ** (k / 4) for k in range(-12, 13)]
    for (label, ratios), color in zip(argmin.items(), ("C0", "C2")):
        right.hist(ratios, bins=bins, alpha=0.6, color=color,
                   label="%s: %d / %d within a decade" % (label, within_a_decade(ratios), n))
    right.axvspan(0.1, 10, color="0.85", zorder=0)
    right.axvline(1, color="k", linestyle="--")
    right.set_xscale("log")
    right.set_xlabel("ground mass of minimum error / heuristic (Eq. 58)")
    right.set_ylabel("configurations")
    right.set_title("%d random trot configurations, LF + RH pinned" % n)
    right.legend(fontsize=8)
    fig.tight_layout()
    save_figure(fig, os.path.join(out_dir, "ground_mass.png"), dpi=120)

    i_best = {key: min(range(len(d["ratios"])), key=lambda i: d[key][i]) for key in ("error_Lambda", "error_b")}
    i_heur = min(range(len(d["ratios"])), key=lambda i: abs(math.log10(d["ratios"][i] / heuristic)))
    with replacing(os.path.join(out_dir, "ground_mass.md")) as partial, open(partial, "w") as f:
        f.write("# Paper 001 Fig. 7: closed-chain error against ground mass (Mini Cheetah, LF + RH pinned)\n\n")
        f.write("Written by `results/scripts/osc_ground_mass.sh` (`rbdc-osc-ground-mass`, runtime recursion of "
                "Table 2 against the constrained closed form of Eqs. 16-26, both in double). Figure: "
                "`ground_mass.png`.\n\n")
        f.write("Heuristic (Eq. 58): m_min/√ε = %.4g kg = %.3g × the total mass %.3f kg.\n\n"
                % (d["heuristic_ground_mass"], heuristic, d["total_mass"]))
        f.write("Mid-stance configuration: q = %s\n\n" % ", ".join("%.3g" % x for x in d["mid_stance_q"]))
        f.write("| quantity | error at the heuristic | smallest error | at ground mass / heuristic |\n|---|---|---|---|\n")
        for key, label in (("error_Lambda", "Λ̃"), ("error_b", "b̃")):
            f.write("| %s | %.2e | %.2e | %.3g |\n" % (label, d[key][i_heur], d[key][i_best[key]],
                                                     d["ratios"][i_best[key]] / heuristic))
        f.write("| J̃ᵀ | %.2e | keeps falling (%.2e at %.0e × total) | - |\n\n"
                % (d["error_JbarT"][i_heur], d["error_JbarT"][-1], d["ratios"][-1]))
        f.write("Study over %d random configurations within a trot's joint ranges (abad ±0.3, hip -1.3…-0.3, "
                "knee 0.8…2.4 rad, trunk tilted up to ±0.2 rad, pinned feet at rest): minimum within a decade "
                "of the heuristic (Eq. 59) for Λ̃ %d / %d and b̃ %d / %d (paper 001: every one of its 500); "
                "minima at %.3g … %.3g × the heuristic; the error at the heuristic is at most %.3g × the "
                "configuration's smallest error.\n"
                % (n, within_a_decade(argmin["Λ̃"]), n, within_a_decade(argmin["b̃"]), n,
                   min(argmin["Λ̃"] + argmin["b̃"]), max(argmin["Λ̃"] + argmin["b̃"]),
                   max(d["study_error_at_heuristic_over_minimum"])))


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
