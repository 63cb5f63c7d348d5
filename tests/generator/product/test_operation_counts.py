"""The operation counts in a generated header are the operations its code executes: the header is
compiled with a scalar type that counts every arithmetic operator, sin, cos and sqrt, and one call
must match the header's table kind by kind. Run on the looped CRBA and the looped factor it feeds
(passes/looped_crba.py, looped_factor.py: the loops are counted by trip count, the traced transforms
node by node), floating and fixed, on forward dynamics (straight-line) with its derivatives in the
looped solve (looped_solve.py), and on contact and impulse dynamics with the contact derivatives'
looped solve; revolute and prismatic joints, a branched tree with two feet in contact."""
import os
import re
import subprocess
import tempfile
import unittest
from pathlib import Path

from rbdc_cli import ROOT, run_rbdc

# A branched tree: a trunk, two chains of revolute and prismatic joints with tilted placements.
URDF = """<robot name="counted">
<link name="trunk"><inertial><mass value="3"/><inertia ixx="0.1" iyy="0.2" izz="0.3" ixy="0.01" ixz="0" iyz="0"/></inertial></link>
{links}
</robot>"""
LINK = ('<link name="l{i}"><inertial><origin xyz="0.02 0.01 0.1"/><mass value="0.{i}5"/>'
        '<inertia ixx="0.01" iyy="0.012" izz="0.008" ixy="0.001" ixz="0" iyz="0.0005"/></inertial></link>'
        '<joint name="j{i}" type="{kind}"><parent link="{parent}"/><child link="l{i}"/>'
        '<origin xyz="0 0.01 0.2" rpy="0.1 0 0.2"/><axis xyz="{axis}"/>'
        '<limit lower="-1" upper="1" effort="1" velocity="1"/></joint>')
SCENE = "name: counted\nquantities: [mass_matrix, mass_matrix_factor]\nschedule: looped_crba\n"
KINDS = ("mul", "add", "div", "sqrt", "trig", "neg")

DRIVER = r"""
#include <cstdio>
#include "counted/counted.hpp"
struct Counted {
  double v;
  static long count[6];  // KINDS
  Counted() = default;
  Counted(double x) : v(x) {}
};
long Counted::count[6];
Counted operator*(Counted a, Counted b) { ++Counted::count[0]; return a.v * b.v; }
Counted operator+(Counted a, Counted b) { ++Counted::count[1]; return a.v + b.v; }
Counted operator-(Counted a, Counted b) { ++Counted::count[1]; return a.v - b.v; }
Counted operator/(Counted a, Counted b) { ++Counted::count[2]; return a.v / b.v; }
Counted operator-(Counted a) { ++Counted::count[5]; return -a.v; }
Counted& operator+=(Counted& a, Counted b) { return a = a + b; }
Counted& operator-=(Counted& a, Counted b) { return a = a - b; }
Counted sqrt(Counted a) { ++Counted::count[3]; return std::sqrt(a.v); }
Counted sin(Counted a) { ++Counted::count[4]; return std::sin(a.v); }
Counted cos(Counted a) { ++Counted::count[4]; return std::cos(a.v); }
template <class F>
void report(const char* name, F call) {
  for (long& c : Counted::count) c = 0;
  call();
  std::printf("%s", name);
  for (long c : Counted::count) std::printf(" %ld", c);
  std::printf("\n");
}
int main() {
  namespace g = rbdc_gen::counted::counted;
  static Counted q[g::nq], v[g::nv], tau[g::n_joints], f[3 * g::n_feet];
  static Counted A[g::nv * g::nv], B[g::nv * g::nv], C[g::nv * g::nv], E[g::nv * 3 * g::n_feet];
  for (int k = 0; k < g::nq; ++k) q[k] = 0.1 * k;
  if (g::nq > g::nv) q[3] = 1.0;  // the base quaternion's w
  for (int k = 0; k < g::nv; ++k) v[k] = 0.2 * k;
  for (int k = 0; k < g::n_joints; ++k) tau[k] = 0.3 * k;
  for (int k = 0; k < 3 * g::n_feet; ++k) f[k] = 0.1 * k;
  CALLS
}
"""
# The scenes checked, each with the calls of its functions.
LOOPED_CRBA = (SCENE, """
  report("mass_matrix", [&] { g::mass_matrix(q, A); });
  report("mass_matrix_factor", [&] { g::mass_matrix_factor(q, A, B, C); });""")
LOOPED_SOLVE = ("name: counted\nquantities: [forward_dynamics]\nderivatives: [forward_dynamics_derivatives]\n"
                "schedule: looped_solve\n", """
  report("forward_dynamics", [&] { g::forward_dynamics(q, v, tau, f, A); });
  report("forward_dynamics_derivatives", [&] { g::forward_dynamics_derivatives(q, v, tau, f, A, B, C, E); });""")
LOOPED_CONTACT_SOLVE = ("name: counted\nquantities: [contact_dynamics, impulse_dynamics]\n"
                        "derivatives: [contact_dynamics_derivatives]\nschedule: looped_solve\n", """
  static Counted X[6][g::nv * g::nv];
  Counted e[1] = {0.5};
  report("contact_dynamics", [&] { g::contact_dynamics(q, v, tau, A, B); });
  report("impulse_dynamics", [&] { g::impulse_dynamics(q, v, e, A, B); });
  report("contact_dynamics_derivatives", [&] {
    g::contact_dynamics_derivatives(q, v, tau, X[0], X[1], X[2], X[3], X[4], X[5]);
  });""")


def tree_urdf():
    links, axes = [], ("0 0 1", "0 1 0", "1 0 0", "0.6 0 0.8")
    for i in range(1, 9):
        parent = "trunk" if i in (1, 5) else "l%d" % (i - 1)
        links.append(LINK.format(i=i, kind="prismatic" if i % 4 == 3 else "revolute", parent=parent,
                                 axis=axes[i % 4]))
    return URDF.format(links="\n".join(links))


def header_counts(directory):
    """{function: {kind: n}} from the operations tables of the generated bodies."""
    counts = {}
    for path in (directory / "counted" / "common").glob("*.hpp"):
        text = path.read_text()
        name = re.search(r"inline void (\w+)\(", text.split("/// operations")[1]).group(1)
        values = re.search(r"/// operations.*\n///\s+([\d\s]+)\n", text).group(1).split()
        counts[name] = dict(zip(KINDS, map(int, values)))
    return counts


class OperationCountTest(unittest.TestCase):
    def check(self, base, scene=LOOPED_CRBA):
        text, calls = scene
        with tempfile.TemporaryDirectory() as tmp:
            directory = Path(tmp)
            (directory / "counted.urdf").write_text(tree_urdf())
            (directory / "counted.yaml").write_text(text)
            result = run_rbdc("generate", directory / "counted.urdf", f"--{base}-base",
                              "--scene", directory / "counted.yaml", "-o", directory)
            self.assertEqual(result.returncode, 0, result.stderr)
            (directory / "driver.cpp").write_text(DRIVER.replace("CALLS", calls))
            compiler = os.environ.get("CXX", "c++")
            build = subprocess.run([compiler, "-std=c++17", "-O0", "-I", str(directory), "-I", "/usr/include/eigen3",
                                    str(directory / "driver.cpp"), "-o", str(directory / "driver")],
                                   capture_output=True, text=True)
            self.assertEqual(build.returncode, 0, build.stderr)
            run = subprocess.run([str(directory / "driver")], capture_output=True, text=True, check=True)
            expected = header_counts(directory)
            lines = run.stdout.splitlines()
            self.assertEqual(len(lines), calls.count("report("))
            for line in lines:
                name, *values = line.split()
                self.assertEqual(dict(zip(KINDS, map(int, values))), expected[name], f"{base} {name}")
            return "".join(p.read_text() for p in (directory / "counted" / "common").glob("*.hpp"))

    def test_looped_crba_floating_base(self):
        self.assertIn("looped CRBA", self.check("floating"))

    def test_looped_crba_fixed_base(self):
        self.assertIn("looped CRBA", self.check("fixed"))

    def test_looped_solve_and_straight_line(self):
        self.assertIn("schedule: looped solve", self.check("floating", LOOPED_SOLVE))

    def test_contact_dynamics_and_the_looped_contact_solve(self):
        self.assertIn("schedule: looped solve", self.check("floating", LOOPED_CONTACT_SOLVE))


if __name__ == "__main__":
    unittest.main()
