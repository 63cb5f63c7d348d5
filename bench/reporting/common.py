"""What every part of bench/report shares: where things are, the bundled robots, the quantity titles,
and number formatting."""
import json
import pathlib

ROOT = pathlib.Path(__file__).resolve().parent.parent.parent
RESULTS = ROOT / "results" / "bench"
# robot name → base, from the one list of bundled robots
ROBOTS = {r["name"]: r["base"] for r in json.loads((ROOT / "robots" / "bundled.json").read_text())["robots"]}
QUANTITY_TITLES = {
    "kinematics": "kinematics with velocities (feet velocities)",
    "feet_positions_jacobian": "feet positions + Jacobian",
    "quadratic_velocity_terms": "c (velocity products)",
    "gravity_terms": "g (gravity)",
    "bias": "c + g",
    "inverse_dynamics": "inverse dynamics M a + c + g",
    "mass_matrix": "M (CRBA)",
    "mass_matrix_lower": "M, lower triangle only",
    "forward_dynamics": "forward dynamics",
    "osc_open_chain": "open-chain OSC (Table 1)",
    "osc_closed_chain": "closed-chain OSC (Table 2)",
    "osc_closed_form": "closed-form constrained OSC (Eqs. 16-26)",
}



def say(message):
    print(f"[bench/report] {message}", flush=True)


def format_ns(ns):
    if ns is None:
        return "–"
    return f"{ns:.0f}" if ns >= 100 else f"{ns:.1f}"


def ratio(a, b):
    return f"{a / b:.1f}×" if a and b else "–"
