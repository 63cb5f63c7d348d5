"""Derives the constants of the polynomial sincos functions in templates/support.hpp.j2 in exact
rational arithmetic and checks that the template holds exactly these doubles (printed by repr).

- sincos_reduced: 2/π and the three-part π/2 of the Cody-Waite reduction: p1 and p2 carry 33
  significant bits each (so k·p1 and k·p2 are exact for |k| < 2^20), p3 is the rest rounded to a
  double. sin r = r + r³·P(z) and cos r = 1 − z/2 + z²·Q(z), z = r², with P (degree 6) and Q
  (degree 5) interpolating (sin r − r)/r³ and (cos r − 1 + z/2)/z² at Chebyshev nodes of
  [0, (π/4)²]: close to the minimax polynomials, and the script checks that their error is below
  2^-56 relative (sin) and 2^-58 absolute (cos), far under the half ulp that rounding costs.
- sincos_folded: π's high and low parts, and P and Q of degree 7 on [0, (π/2)²], their errors below
  2^-55 (relative for sin, absolute for cos), far under the function's 3.5e-16 absolute error.
Run: python3 tests/generator/sincos_coefficients.py [--print]
"""
import math
import sys
from fractions import Fraction
from pathlib import Path

TEMPLATE = Path(__file__).resolve().parents[2] / "templates" / "support.hpp.j2"
PI = Fraction("3.14159265358979323846264338327950288419716939937510582097494459230781640628620899863")
HALF_PI = PI / 2
# a little beyond each range's end: |r| may exceed it by round-off
REDUCED_Z_MAX = (PI / 4) ** 2 * Fraction(10001, 10000)
FOLDED_Z_MAX = (PI / 2) ** 2 * Fraction(10001, 10000)


def round_to_bits(x, bits):
    """x rounded to `bits` significant bits (to nearest)."""
    exponent = math.floor(math.log2(abs(float(x))))
    scale = Fraction(2) ** (bits - 1 - exponent)
    return Fraction(round(x * scale)) / scale


def sin_remainder(z, terms=30):
    """(sin r − r)/r³ at z = r², from its Taylor series (exact rationals)."""
    total, term = Fraction(0), Fraction(-1, 6)
    for k in range(1, terms):
        total += term
        term = -term * z / ((2 * k + 2) * (2 * k + 3))
    return total


def cos_remainder(z, terms=30):
    """(cos r − 1 + z/2)/z² at z = r²."""
    total, term = Fraction(0), Fraction(1, 24)
    for k in range(2, terms):
        total += term
        term = -term * z / ((2 * k + 1) * (2 * k + 2))
    return total


def interpolate(function, degree, z_max):
    """Coefficients (lowest first, rounded to double) of the polynomial through the Chebyshev nodes of
    [0, z_max]."""
    n = degree + 1
    nodes = [Fraction((1 - math.cos(math.pi * (2 * j + 1) / (2 * n))) / 2) * z_max for j in range(n)]
    rows = [[z ** i for i in range(n)] + [function(z)] for z in nodes]
    for col in range(n):  # Gauss-Jordan elimination, exact
        pivot = max(range(col, n), key=lambda r: abs(rows[r][col]))
        rows[col], rows[pivot] = rows[pivot], rows[col]
        for r in range(n):
            if r != col:
                factor = rows[r][col] / rows[col][col]
                rows[r] = [a - factor * b for a, b in zip(rows[r], rows[col])]
    return [float(rows[i][n] / rows[i][i]) for i in range(n)]


def max_error(function, coefficients, weight, z_max):
    """Largest |polynomial − function| · weight(z) on 401 points of [0, z_max]."""
    worst = Fraction(0)
    for j in range(401):
        z = z_max * j / 400
        value = sum(Fraction(c) * z ** i for i, c in enumerate(coefficients))
        worst = max(worst, abs(value - function(z)) * weight(z))
    return float(worst)


def constants():
    p1 = round_to_bits(HALF_PI, 33)
    p2 = round_to_bits(HALF_PI - p1, 33)
    p3 = float(HALF_PI - p1 - p2)
    return {"2/pi": float(1 / HALF_PI), "p1": float(p1), "p2": float(p2), "p3": p3,
            "sin": interpolate(sin_remainder, 6, REDUCED_Z_MAX),
            "cos": interpolate(cos_remainder, 5, REDUCED_Z_MAX),
            "pi": float(PI), "pi low": float(PI - Fraction(float(PI))),
            "folded sin": interpolate(sin_remainder, 7, FOLDED_Z_MAX),
            "folded cos": interpolate(cos_remainder, 7, FOLDED_Z_MAX)}


def main():
    c = constants()
    if "--print" in sys.argv:
        for name, value in c.items():
            print(name, value if isinstance(value, float) else [repr(x) for x in value])
    # The polynomials are accurate far below round-off: relative for sin (r³P against r), absolute for cos.
    errors = {}
    for prefix, z_max, sin_bound, cos_bound in (("", REDUCED_Z_MAX, 2.0 ** -56, 2.0 ** -58),
                                                ("folded ", FOLDED_Z_MAX, 2.0 ** -55, 2.0 ** -55)):
        sin_error = max_error(sin_remainder, c[prefix + "sin"], lambda z: z, z_max)
        cos_error = max_error(cos_remainder, c[prefix + "cos"], lambda z: z * z, z_max)
        assert sin_error < sin_bound, "%ssin polynomial error %g" % (prefix, sin_error)
        assert cos_error < cos_bound, "%scos polynomial error %g" % (prefix, cos_error)
        errors[prefix] = (sin_error, cos_error)
    text = TEMPLATE.read_text()
    values = [c["2/pi"], c["p1"], c["p2"], c["p3"], c["pi"], c["pi low"]] + [
        x for name in ("sin", "cos", "folded sin", "folded cos") for x in c[name]]
    missing = [repr(v) for v in values if repr(v) not in text]
    assert not missing, "templates/support.hpp.j2 lacks the derived constants " + ", ".join(missing)
    print("sincos constants: %d derived and present; polynomial errors sin %.3g (rel), cos %.3g (abs); "
          "folded sin %.3g, cos %.3g" % ((len(values),) + errors[""] + errors["folded "]))


if __name__ == "__main__":
    main()
