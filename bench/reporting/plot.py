"""The run-time-against-error plot of bench/report (results/bench/error_vs_time.png)."""
from result_files import save_figure  # tools/, put on sys.path by bench/report

from .common import QUANTITY_TITLES

TITLES = dict(QUANTITY_TITLES, inverse_dynamics_derivatives="derivatives ∂τ/∂(q, v)",
              forward_dynamics_derivatives="derivatives ∂a/∂(q, v, τ, f)")


def worst_parts(rows):
    """One row per (robot, quantity, variant) of the derivative error study: the part with the largest
    median, its bar up to the largest max over the parts."""
    worst = {}
    for r in rows:
        if r["median"] is None:
            continue
        key = (r["robot"], r["quantity"], r["variant"])
        w = worst.get(key)
        if w is None:
            worst[key] = dict(r, part="")
        else:
            w["median"] = max(w["median"], r["median"])
            w["max"] = max(w["max"] or 0, r["max"] or 0)
    return list(worst.values())


def plot_error_vs_time(rows, derivative_rows, path):
    """Mini Cheetah: median relative error (bar up to the max) against ns/call, one point per variant;
    a derivative quantity's point is its worst output (largest median, bar to the largest max)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    chosen = [r for r in rows + worst_parts(derivative_rows) if r["robot"] == "mini_cheetah" and r["ns"]
              and r["median"] and r["part"] in ("", "Lambda")]
    figure, axes = plt.subplots(figsize=(13, 6.5))
    markers = {"inverse_dynamics": "o", "mass_matrix": "s", "forward_dynamics": "D",
               "osc_open_chain": "^", "osc_closed_chain": "v", "inverse_dynamics_derivatives": "P",
               "forward_dynamics_derivatives": "X"}
    colours = {"generated_double": "tab:blue", "generated_float": "tab:orange", "runtime": "tab:green",
               "runtime_closed_form": "tab:red", "dual_ad": "tab:brown", "finite_differences": "tab:gray"}
    for r in chosen:
        if r["quantity"] not in markers:
            continue
        sweep = r["variant"].startswith("generated_double_ground")
        colour = "tab:purple" if sweep else colours.get(r["variant"], "black")
        upper = max(r["max"] - r["median"], 0) if r["max"] else 0
        axes.errorbar([r["ns"]], [r["median"]], yerr=[[0], [upper]], fmt=markers[r["quantity"]],
                      color=colour, alpha=0.55 if sweep else 0.95, capsize=2, markersize=6)
        if sweep:
            axes.annotate(f"{r['ground_mass_over_total']:.0e}", (r["ns"], r["median"]), fontsize=6,
                          xytext=(4, 0), textcoords="offset points")
    for quantity, marker in markers.items():
        axes.plot([], [], marker, color="grey", label=TITLES[quantity])
    for variant, colour in colours.items():
        axes.plot([], [], "o", color=colour, label=variant.replace("_", " "))
    axes.plot([], [], "v", color="tab:purple", label="closed chain, double, ground mass × total (label)")
    axes.set_xscale("log")
    axes.set_yscale("log")
    axes.set_xlabel("time per call (ns, median CPU time)")
    axes.set_ylabel("relative error vs quad / long-double reference (median, bar to max)")
    axes.set_title("Mini Cheetah: run time against error (closed-chain OSC: Λ̃ part; derivatives: worst output)")
    axes.grid(True, which="major", alpha=0.3)
    axes.legend(fontsize=7, loc="center left", bbox_to_anchor=(1.01, 0.5))
    figure.tight_layout()
    save_figure(figure, path, dpi=120)
    plt.close(figure)
