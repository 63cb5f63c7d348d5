"""The operation counts in a generated header are the operations its code executes: every function of
a scene is compiled with a scalar type that counts every arithmetic operator, sin, cos and sqrt, and
one call must match the header's table kind by kind. Run on the looped forms (passes/looped_crba.py,
looped_factor.py, looped_solve.py, looped_rnea_derivatives.py, looped_feet_forces.py, looped_inverse.py,
column_support.py, looped_osc.py, the low-rank product: loops counted by trip count, the traced parts node by node) on a
branched tree with revolute and prismatic joints and two feet in contact, floating and fixed, on a
mimic-coupled gripper's looped solve and RNEA derivatives, on a 12-link chain's RNEA derivatives, on a 32-link chain's ∂a/∂τ as M⁻¹'s rows,
on the Mini Cheetah's `full` scene (limb lanes: a lane operation counts four, a sum over the lanes three)
and on humanoid32's limbs in pairs (a pair's joint angle: two sines and two cosines, not four)."""
import re
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

from rbdc_cli import CXX, MINI_CHEETAH, ROOT, SCENES, run_rbdc

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
LOOPED_CRBA = ("name: counted\nquantities: [mass_matrix, mass_matrix_lower, mass_matrix_factor]\n"
               "derivatives: [forward_dynamics_derivatives]\n"
               "schedule: looped_crba\n")
LOOPED_RNEA = ("name: counted\nderivatives: [inverse_dynamics_derivatives, bias_derivatives, gravity_derivatives, "
               "forward_dynamics_derivatives, feet_force_term_derivatives]\nschedule: looped_rnea\n")
LOOPED_SOLVE = ("name: counted\nquantities: [forward_dynamics, contact_dynamics, impulse_dynamics]\n"
                "derivatives: [forward_dynamics_derivatives, contact_dynamics_derivatives]\nschedule: looped_solve\n")
LOOPED_OSC = "name: counted\nquantities: [osc_open_chain, osc_closed_chain]\nschedule: looped_osc\n"
COUPLED_LOOPED_SOLVE = "name: counted\nderivatives: [forward_dynamics_derivatives]\nschedule: looped_solve\n"
# The chain's scenes emit its ∂FD alone: its other functions (3 MB of straight-line M, factor and FD)
# made the two tests' -O0 driver take 41 s, against 16 without them.
CHAIN_INVERSE = "name: counted\nquantities: []\nderivatives: [forward_dynamics_derivatives]\nschedule: looped_rnea\n"
CHAIN_RNEA = ("name: counted\nquantities: []\nderivatives: [inverse_dynamics_derivatives, bias_derivatives, "
              "gravity_derivatives]\nschedule: looped_rnea\n")
LOW_RANK = "name: counted\nquantities: []\nderivatives: [forward_dynamics_derivatives]\nschedule: low_rank\n"
CHAIN_LOOP = ("name: counted\nquantities: [inverse_dynamics, bias, quadratic_velocity_terms, forward_dynamics]\n"
              "schedule: chain_loop\n")
PAIRED_LANES = "name: counted\nquantities: [inverse_dynamics, mass_matrix]\nschedule: limb_lanes\n"
COUPLED_LOOPED_RNEA = ("name: counted\nderivatives: [inverse_dynamics_derivatives, bias_derivatives, gravity_derivatives, "
                       "forward_dynamics_derivatives]\n"
                       "schedule: looped_rnea\n")
KINDS = ("mul", "add", "div", "sqrt", "trig", "neg")
# The inputs by name (the rest of the arguments get scratch arrays); q's quaternion is set apart.
INPUTS = {"q": "q", "v": "v", "a": "v", "tau": "tau", "f": "f"}

DRIVER = r"""
#include <cstdio>
#include "ROBOT/SCENE.hpp"
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
  namespace g = rbdc_gen::ROBOT::SCENE;
  static Counted q[g::nq], v[g::nv], tau[g::nv], f[3 * g::n_feet + 1], scratch[12][4096];
  for (int k = 0; k < g::nq; ++k) q[k] = 0.1 * k;
  if (g::nq > g::nv) q[3] = 1.0;  // the base quaternion's w
  for (int k = 0; k < g::nv; ++k) v[k] = 0.2 * k;
  for (int k = 0; k < g::nv; ++k) tau[k] = 0.3 * k;
  for (int k = 0; k < 3 * g::n_feet; ++k) f[k] = 0.1 * k;
  scratch[0][0] = 0.5;  // restitution, where a function reads it
CALLS
}
"""


def tree_urdf():
    links, axes = [], ("0 0 1", "0 1 0", "1 0 0", "0.6 0 0.8")
    for i in range(1, 9):
        parent = "trunk" if i in (1, 5) else "l%d" % (i - 1)
        links.append(LINK.format(i=i, kind="prismatic" if i % 4 == 3 else "revolute", parent=parent,
                                 axis=axes[i % 4]))
    return URDF.format(links="\n".join(links))


def scene_bodies(directory, robot, scene):
    """{function: (its operations table, the C++ call of it)} for each function of the scene."""
    functions = {}
    for header in sorted((directory / robot / scene).glob("*.hpp")):
        body = re.search(rf'#include "({robot}/common/[^"]+)"', header.read_text())
        text = (directory / body.group(1)).read_text()
        table = re.search(r"/// operations.*\n///\s+([\d\s]+)\n", text).group(1).split()
        name, parameters = re.search(r"/// operations[\s\S]*?inline void (\w+)\(([^)]*)\) noexcept", text).groups()
        arguments = [INPUTS.get(p.split("*")[-1].strip(), "scratch[%d]" % k) if p.strip().startswith("const")
                     else "scratch[%d]" % k for k, p in enumerate(parameters.split(","))]
        call = f'  report("{name}", [&] {{ g::{name}({", ".join(arguments)}); }});'
        functions[name] = (dict(zip(KINDS, map(int, table))), call)
    return functions


class OperationCountTest(unittest.TestCase):
    def check(self, robot_file, base, scene_text, robot, scene):
        """The scene's functions counted; returns their bodies' text."""
        with tempfile.TemporaryDirectory() as tmp:
            directory = Path(tmp)
            (directory / "scene.yaml").write_text(scene_text)
            result = run_rbdc("generate", robot_file, f"--{base}-base", "--scene", directory / "scene.yaml",
                              "-o", directory)
            self.assertEqual(result.returncode, 0, result.stderr)
            functions = scene_bodies(directory, robot, scene)
            calls = "\n".join(call for _, call in functions.values())
            driver = DRIVER.replace("ROBOT", robot).replace("SCENE", scene).replace("CALLS", calls)
            (directory / "driver.cpp").write_text(driver)
            build = subprocess.run([*CXX, "-std=c++17", "-O0", "-I", str(directory),
                                    "-I", "/usr/include/eigen3", str(directory / "driver.cpp"),
                                    "-o", str(directory / "driver")], capture_output=True, text=True)
            self.assertEqual(build.returncode, 0, build.stderr)
            run = subprocess.run([str(directory / "driver")], capture_output=True, text=True, check=True)
            lines = run.stdout.splitlines()
            self.assertEqual(len(lines), len(functions))
            for line in lines:
                name, *values = line.split()
                self.assertEqual(dict(zip(KINDS, map(int, values))), functions[name][0], f"{robot} {base} {name}")
            return "".join(p.read_text() for p in (directory / robot / "common").glob("*.hpp"))

    def tree(self, base, scene_text):
        with tempfile.TemporaryDirectory() as tmp:
            urdf = Path(tmp) / "counted.urdf"
            urdf.write_text(tree_urdf())
            return self.check(urdf, base, scene_text, "counted", "counted")

    def test_looped_crba_floating_base(self):
        self.assertEqual(self.tree("floating", LOOPED_CRBA).count("schedule: looped CRBA"), 4)

    def test_looped_crba_fixed_base(self):
        self.assertEqual(self.tree("fixed", LOOPED_CRBA).count("schedule: looped CRBA"), 4)

    def test_looped_rnea_derivatives_floating_base(self):
        self.assertEqual(self.tree("floating", LOOPED_RNEA).count("schedule: looped RNEA derivatives"), 4)

    def test_looped_rnea_derivatives_fixed_base(self):
        text = self.tree("fixed", LOOPED_RNEA)
        self.assertEqual(text.count("schedule: looped RNEA derivatives"), 4)
        self.assertIn("ltdl_solve_column_range", text)  # ∂q̈'s blocks of columns on their own rows

    def test_looped_operational_space_columns(self):
        self.assertEqual(self.tree("floating", LOOPED_OSC).count("schedule: looped operational-space columns"), 2)

    def test_looped_solves_of_forward_and_contact_dynamics(self):
        self.assertEqual(self.tree("floating", LOOPED_SOLVE).count("schedule: looped solve"), 2)

    def test_looped_forms_of_a_coupled_robot(self):
        """A gripper on an arm: ∂q̈'s solve over the independent dofs' tree (passes/project.py), ∂τ's
        loop on the tree, expanded and projected (looped_rnea_derivatives.py)."""
        fingers = ROOT / "tests" / "data" / "mimic_fingers.urdf"
        self.assertEqual(self.check(fingers, "floating", COUPLED_LOOPED_SOLVE, "mimic_fingers", "counted")
                         .count("schedule: looped solve"), 1)
        self.assertEqual(self.check(fingers, "floating", COUPLED_LOOPED_RNEA, "mimic_fingers", "counted")
                         .count("schedule: looped RNEA derivatives"), 4)

    def test_tau_columns_as_rows_of_the_inverse_on_a_chain(self):
        """A 32-link chain: ∂a/∂τ as M⁻¹'s rows Zᵀ D⁻¹ Z (passes/looped_inverse.py), counted by its
        blocks' trip counts."""
        with tempfile.TemporaryDirectory() as tmp:
            urdf = Path(tmp) / "chain32.urdf"
            subprocess.run([sys.executable, str(ROOT / "tools" / "make_chain.py"), "32", str(urdf)], check=True)
            text = self.check(urdf, "fixed", CHAIN_INVERSE, "chain32", "counted")
        self.assertIn("ltdl_inverse<Scalar, 32, 0>", text)

    def test_low_rank_product_on_a_chain(self):
        """The same chain's ∂a/∂q and ∂a/∂v as M⁻¹ times ∂τ's low-rank blocks (InverseTimesVectors,
        looped_rnea_derivatives.low_rank_counts), the solve over the feet's columns only."""
        with tempfile.TemporaryDirectory() as tmp:
            urdf = Path(tmp) / "chain32.urdf"
            subprocess.run([sys.executable, str(ROOT / "tools" / "make_chain.py"), "32", str(urdf)], check=True)
            text = self.check(urdf, "fixed", LOW_RANK, "chain32", "counted")
        self.assertIn("InverseTimesVectors<Scalar, 32>", text)

    def test_chain_loops(self):
        """A 12-link chain's RNEA and forward dynamics as one loop (chain_inverse_dynamics;
        articulated_forward_dynamics: the RNEA with the foot's wrench, then the recursion), counted as
        chain_loop.ChainLoop counts them."""
        with tempfile.TemporaryDirectory() as tmp:
            urdf = Path(tmp) / "chain12.urdf"
            subprocess.run([sys.executable, str(ROOT / "tools" / "make_chain.py"), "12", str(urdf)], check=True)
            text = self.check(urdf, "fixed", CHAIN_LOOP, "chain12", "counted")
        self.assertIn("articulated_forward_dynamics<Scalar, 13, 12, 1>", text)
        self.assertEqual(text.count("chain_inverse_dynamics<Scalar, 13, 12"), 3)

    def test_looped_rnea_derivatives_on_a_chain(self):
        """A 12-link chain's ∂τ loops, which write the entries above the diagonal column by column
        (rbdc_gen::ColumnsAbove; looped_rnea_derivatives.column_lanes), fixed and floating."""
        with tempfile.TemporaryDirectory() as tmp:
            urdf = Path(tmp) / "chain12.urdf"
            subprocess.run([sys.executable, str(ROOT / "tools" / "make_chain.py"), "12", str(urdf)], check=True)
            for base in ("fixed", "floating"):
                text = self.check(urdf, base, CHAIN_RNEA, "chain12", "counted")
                self.assertEqual(text.count("schedule: looped RNEA derivatives"), 3, base)

    def test_mini_cheetah_full_scene_in_limb_lanes(self):
        self.assertIn("limb lanes", self.check(MINI_CHEETAH, "floating", (SCENES / "full.yaml").read_text(),
                                               "mini_cheetah", "full"))

    def test_limbs_in_pairs(self):
        text = self.check(ROOT / "robots" / "humanoid32.urdf", "floating", PAIRED_LANES, "humanoid32", "counted")
        self.assertEqual(text.count("schedule: limb lanes"), 2)
        self.assertIn("load_repeated_lanes<2>(joint_trig.sin", text)


if __name__ == "__main__":
    unittest.main()
