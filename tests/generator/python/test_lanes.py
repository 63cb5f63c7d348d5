"""Limbs in SIMD lanes (rbdcgen/limbs.py, algorithms/lane_model.py, lane_functions.py): detection,
and every lane function equal to its scalar namesake on random states (expr.evaluate, lane by lane),
on the Mini Cheetah. The emitted C++ is checked against the runtime by `rbdc verify`."""

import math
import os
import random
import re
import tempfile
import unittest
from dataclasses import replace
from unittest import mock

import mini_cheetah
from numeric_check import evaluate, max_relative_error, random_state

from rbdcgen.graph import expr as ex
from rbdcgen.backend.emit import ZERO_LANES, emit_body
from rbdcgen.graph.flops import count_ops
from rbdcgen.frontend.ir import Actuator
from rbdcgen.passes import lane_derivatives, schedule
from rbdcgen.passes.differentiate import padded
from rbdcgen.passes.lane_contact_derivatives import column_order
from rbdcgen.passes.lane_functions import ANY_GROUPS, LANE_NAME, PAIRED, SCALAR, available
from rbdcgen.views.limbs import LimbError, isomorphic_limbs, limb_groups
from rbdcgen.frontend.scene import default_scene
from rbdcgen.passes.schedule import scheduled_function
from rbdcgen.passes.trace import trace_function


class LaneConstants(unittest.TestCase):
    def test_folding(self):
        with ex.Graph() as graph:
            self.assertTrue(ex.lane_const((2.0,) * ex.LANES).is_const(2.0))  # lanes agree
            c = ex.lane_const((1.0, -1.0, 2.0, 0.5))
            self.assertTrue(c.lane)
            twice = ex.const(2.0) * c  # constants fold lane by lane
            self.assertEqual(graph.lane_constants[twice.value[1]], (2.0, -2.0, 4.0, 1.0))
            self.assertEqual(graph.lane_constants[(-c).value[1]], (-1.0, 1.0, -2.0, -0.5))
            self.assertTrue((c - c).is_const(0.0))
            x = ex.symbol("q", 0)
            self.assertEqual((x * c).op, "mul")  # no lane is 0 or 1 in every lane: a lane product
            self.assertEqual(ex.lane_sum(x).op, "mul")  # a scalar summed over the lanes: 4 x
            self.assertIs(ex.lane_get(x, 2), x)
            rotated = ex.lane_rotate(c, 1)  # a lane constant rotates by folding
            self.assertEqual(graph.lane_constants[rotated.value[1]], (-1.0, 2.0, 0.5, 1.0))
            self.assertIs(ex.lane_rotate(x, 3), x)  # a value the lanes share
            y = ex.symbol("lane_q", 0)
            self.assertEqual(ex.evaluate([ex.lane_rotate(y, 3)], {"lane_q": [(1.0, 2.0, 3.0, 4.0)]}),
                             [(4.0, 1.0, 2.0, 3.0)])


LANE_FRAMES = ("RF_foot", "trunk", "LH_hip", "LF_foot", "RF_hip", "RH_foot", "LF_hip", "LH_foot", "RH_hip")


def _in_lane_column_order(robot, terms, order, names):
    """The scalar terms' right-hand sides `names` (row-major) with their columns where the lane terms
    keep them (`order`: limb_lanes.lane_column_order)."""
    width = padded(len(order))
    source = list(order) + list(range(len(order), width))  # the padding stays
    placed = dict(terms)
    for name in names:
        values = terms[name]
        placed[name] = [values[start + source[c]] for start in range(0, len(values), width) for c in range(width)]
    return placed


@unittest.skipIf(mini_cheetah.skip_reason(), mini_cheetah.skip_reason())
class MiniCheetahLanes(unittest.TestCase):
    def test_limbs(self):
        robot = mini_cheetah.load()
        self.assertEqual(isomorphic_limbs(robot), ((1, 2, 3), (4, 5, 6), (7, 8, 9), (10, 11, 12)))

    def test_lane_functions_equal_scalar(self):
        robot = mini_cheetah.load()
        for lanes, scalar in self._check_equal(robot, SCALAR, seeds=(1, 2, 3)):
            # a lane operation counts once per lane
            self.assertGreaterEqual(count_ops(lanes)["total"], count_ops(scalar)["total"] * 0.95)

    def test_limbs_with_different_constants(self):
        """Limbs equal only in shape: every offset, joint frame, mass, inertia and armature differs
        between limbs (lane constants everywhere), oblique axes shared by the lanes. The bias and
        gravity derivatives, the same recursion as ∂τ at a = 0 and v = 0, only on the Mini Cheetah
        (each costs 0.5 s here)."""
        names = [n for n in SCALAR if n not in ("bias_derivatives_lanes", "gravity_derivatives_lanes")]
        for base, seed in (("floating", 4), ("fixed", 5)):
            robot = _scrambled_limbs(mini_cheetah.load(base), random.Random(seed))
            self._check_equal(robot, names)

    def test_frames_in_lanes_only_on_every_limb(self):
        """`auto` takes the lane frame Jacobians for the four feet and keeps the scalar tree when
        the frames are not the same on every limb."""
        robot = mini_cheetah.load()
        feet = replace(default_scene(), frames=("LF_foot", "RF_foot", "LH_foot", "RH_foot"))
        self.assertTrue(scheduled_function(robot, feet, "frame_jacobians").schedule.startswith("limb lanes"))
        two = replace(default_scene(), frames=("LF_foot", "RF_foot"))
        self.assertFalse(scheduled_function(robot, two, "frame_jacobians").schedule.startswith("limb lanes"))

    def test_contacts_in_lanes_only_with_one_foot_per_limb(self):
        """The lane contact dynamics needs the kept feet one per limb; two feet kept: the scalar
        tree."""
        robot = mini_cheetah.load()
        self.assertTrue(scheduled_function(robot, default_scene(), "contact_dynamics").schedule.startswith("limb lanes"))
        two = replace(default_scene(), feet=("LF_foot", "RH_foot"))
        self.assertFalse(scheduled_function(robot, two, "impulse_dynamics").schedule.startswith("limb lanes"))

    def test_contact_functions_on_a_subset_of_the_feet(self):
        """Two contacts (RF, LH: lanes 1 and 2, out of the scene's foot order): the lanes without a
        contact carry no force, contact k's rows land on its own lane's columns."""
        robot = mini_cheetah.load()
        names = ("contact_dynamics_lanes", "contact_dynamics_derivative_terms_lanes")
        self._check_equal(robot, names, scene=replace(default_scene(), contacts=("RF_foot", "LH_foot")))

    def test_limb_lanes_forces_the_contact_derivatives_lane_terms(self):
        """The contact derivatives have no limb-lane form of their own: `schedule: limb_lanes` gives
        them their looped solve with the terms in lanes."""
        robot = mini_cheetah.load()
        scene = replace(default_scene(), schedule="limb_lanes")
        fn = scheduled_function(robot, scene, "contact_dynamics_derivatives")
        self.assertEqual(fn.schedule, "limb lanes and a looped solve, as the scene asks")
        self.assertIsNotNone(fn.solve)

    def _check_equal(self, robot, names, seeds=(7,), scene=None):
        """The lane functions `names` equal their scalar namesakes on random states; returns the
        traced (lane, scalar) pairs. The frames: the trunk's and two per limb, in an order that
        is not the limbs' (each output row must land on its frame's)."""
        scene = replace(scene or default_scene(), frames=LANE_FRAMES)
        pairs = []
        for name in names:
            lanes = trace_function(robot, scene, name)
            scalar = trace_function(robot, scene, SCALAR[name])
            pairs.append((lanes, scalar))
            for seed in seeds:
                state = random_state(robot, len(robot.feet), seed)
                got = evaluate(lanes, lanes.lanes.with_lanes(state))
                want = evaluate(scalar, state)
                if name == "contact_dynamics_derivative_terms_lanes":
                    want = _in_lane_column_order(robot, want, column_order(robot), ("R1", "R2"))
                if name == "forward_dynamics_derivative_terms_lanes":
                    order = lane_derivatives.column_order(robot, 3 * len(scene.feet_for(robot)))
                    want = _in_lane_column_order(robot, want, order, ("rhs",))
                for output in want:
                    self.assertLess(max_relative_error(got[output], want[output]), 1e-12,
                                    (name, output, seed))
        return pairs

    def test_outputs_stored_four_at_a_time_once_each(self):
        """Emission of a lane function: the limbs' runs of the same lanes of several lane values are
        transposed stores (the Mini Cheetah's M: a leg's column, its rows at the trunk's dofs; τ: the
        legs' torques), each other four consecutive output entries one store_lanes if they are constants
        or lanes of lane values, the rest one by one; every entry written exactly once (M's lower triangle alone, nothing above it, for
        mass_matrix_lower and its lanes), each store after the temporaries it reads (the scalar
        functions keep one store per entry)."""
        robot = mini_cheetah.load()
        for name in ("mass_matrix_lanes", "inverse_dynamics_lanes", "mass_matrix_lower_lanes",
                     "mass_matrix_lower"):
            fn = trace_function(robot, default_scene(), name)
            lines = emit_body(fn)
            defined = set()
            written = {arg.name: [] for arg in fn.outputs}
            vector_stores, transposed, interleaved = 0, set(), {}
            for line in (l for l in lines if not l.startswith("//")):
                declared = re.match(r"(?:Scalar|Lane) (t\d+) = ", line)
                if declared:
                    defined.add(declared.group(1))
                    continue
                block = re.match(r"store_transposed_lanes<(\d+)>\(\{(\w+) \+ (\d+), \w+ \+ (\d+), \w+ \+ (\d+), "
                                 r"\w+ \+ (\d+)\}, \{(.*)\}\);$", line)
                if block:
                    size, arg, starts, values = int(block.group(1)), block.group(2), block.group(3, 4, 5, 6), block.group(7)
                    self.assertEqual(len(values.split(", ")), size, line)
                    entries = [int(s) + k for s in starts for k in range(size)]
                    written[arg] += entries
                    transposed |= {(arg, k) for k in entries}
                    self.assertLessEqual(set(re.findall(r"\bt\d+\b", values)), defined, line)
                    continue
                block = re.match(r"store_interleaved_lanes<(\d+)>\((\w+) \+ (\d+), \{(.*)\}\);$", line)
                if block:  # the limbs' runs one after the other: 4·K entries from the start
                    size, arg, start = int(block.group(1)), block.group(2), int(block.group(3))
                    values = block.group(4).replace(ZERO_LANES, "zeros").split(", ")
                    self.assertEqual(len(values), size, line)
                    entries = list(range(start, start + 4 * size))
                    for k, value in enumerate(values):  # zero lanes only where the output is zero
                        if value == "zeros":
                            self.assertTrue(all(fn.values[arg][e].is_const(0.0) for e in entries[k::size]), line)
                    written[arg] += entries
                    transposed |= {(arg, k) for k in entries}
                    interleaved[name] = interleaved.get(name, 0) + 1
                    self.assertLessEqual(set(re.findall(r"\bt\d+\b", block.group(4))), defined, line)
                    continue
                vector = re.match(r"store_lanes\((\w+) \+ (\d+), make_lanes\((.*)\)\);$", line)
                scalar = re.match(r"(\w+)\[(\d+)\] = (.*);$", line)
                match = vector or scalar
                if match is None or match.group(1) not in written:
                    continue
                first = int(match.group(2))
                written[match.group(1)] += range(first, first + (ex.LANES if vector else 1))
                vector_stores += bool(vector)
                self.assertLessEqual(set(re.findall(r"\bt\d+\b", match.group(3))), defined, line)
            for arg in fn.outputs:
                expected = [k for k, e in enumerate(fn.values[arg.name]) if e is not None]
                self.assertEqual(sorted(written[arg.name]), expected, (name, arg.name))
            # the entries no transposed store writes: each four from a run's start in one vector store
            # if they are constants or lanes of lane values, else one by one, as the last size % 4 of
            # each run (M's lower triangle: runs of 4 within each column)
            vector_chunks = 0
            for arg, run in _written_runs(fn, transposed):
                for i in range(0, len(run) - len(run) % ex.LANES, ex.LANES):
                    ops = {fn.values[arg][k].op for k in run[i:i + ex.LANES]}
                    vector_chunks += ops in ({"const"}, {"lane_get"})
            self.assertEqual(vector_stores, vector_chunks if fn.lanes else 0, name)
            if name == "mass_matrix_lanes":  # a leg's entries beside the others' zeros: one by one
                self.assertGreater(sum(len(run) // ex.LANES for _, run in _written_runs(fn, transposed)),
                                   vector_chunks, name)
            self.assertEqual(bool(transposed), fn.lanes is not None, name)
            # interleaved: τ's twelve leg entries; M's six trunk columns at the legs' rows (column 3
            # with its zero at every leg's abduction row), in M and in its lower triangle
            self.assertEqual(interleaved.get(name, 0), {"mass_matrix_lanes": 6, "mass_matrix_lower_lanes": 6,
                                                        "inverse_dynamics_lanes": 1}.get(name, 0), name)
        scalar_lines = emit_body(trace_function(robot, default_scene(), "mass_matrix"))
        self.assertFalse(any(line.startswith(("store_lanes(", "store_transposed_lanes", "store_interleaved_lanes"))
                             for line in scalar_lines))

    def test_lane_angle_names_unique(self):
        """The lanes' sin/cos are named by what the limbs' joint names share (prefix and suffix);
        names that share only a suffix (pybullet's torso_to_abduct_fr_j, abduct_fr_to_thigh_fr_j,
        thigh_fr_to_knee_fr_j all end in _j) still give one name per lane joint."""
        robot = mini_cheetah.load()
        legs = ("fr", "fl", "hr", "hl")
        cases = {
            "mini_cheetah": (None, ["lanes_abad_joint", "lanes_hip_joint", "lanes_knee_joint"]),
            "pybullet": (lambda leg: ("torso_to_abduct_%s_j" % leg, "abduct_%s_to_thigh_%s_j" % (leg, leg),
                                      "thigh_%s_to_knee_%s_j" % (leg, leg)),
                         ["lanes_torso_to_abduct_j", "lanes_abduct_j", "lanes_thigh_j"]),
            "nothing shared": (lambda leg: (leg, leg.upper(), leg * 2),
                               ["lanes_joint_1", "lanes_joint_2", "lanes_joint_3"]),
            "same shared part": (lambda leg: ("a_%s_j" % leg, "a_%s%s_j" % (leg, leg[-1]), "k_%s" % leg),
                                 ["lanes_a_j", "lanes_joint_2", "lanes_k"]),
        }
        for case, (names_of, expected) in cases.items():
            renamed = robot
            if names_of:
                joints = list(robot.joints)
                for k, leg in enumerate(legs):
                    for j, name in enumerate(names_of(leg)):
                        joints[1 + 3 * k + j] = replace(joints[1 + 3 * k + j], name=name)
                renamed = replace(robot, joints=tuple(joints))
            fn = trace_function(renamed, default_scene(), "inverse_dynamics_lanes")
            got = [fn.lanes.angle_names[("lane_q", l)] for l in range(3)]
            self.assertEqual(got, expected, case)

    def test_limbs_must_match(self):
        robot = mini_cheetah.load()
        joints = list(robot.joints)
        joints[12] = replace(joints[12], type="prismatic")  # RH knee: no longer the same chain
        with self.assertRaises(LimbError):
            isomorphic_limbs(replace(robot, joints=tuple(joints)))



@unittest.skipIf(mini_cheetah.skip_reason(), mini_cheetah.skip_reason())
class HumanoidPairs(unittest.TestCase):
    """humanoid32: its legs (of the pelvis) and arms (of the torso) are isomorphic pairs, each pair
    in lanes 0-1 and again in 2-3; the torso and head stay scalar."""

    def test_groups(self):
        robot = mini_cheetah.load(urdf=mini_cheetah.HUMANOID32)
        legs, arms = limb_groups(robot)
        self.assertEqual((legs.parent, arms.parent), (0, 15))
        self.assertEqual(legs.limbs, (tuple(range(1, 7)), tuple(range(7, 13))))
        self.assertEqual(arms.limbs, (tuple(range(19, 26)), tuple(range(26, 33))))
        self.assertEqual(arms.lanes, arms.limbs * 2)
        with self.assertRaises(LimbError):  # three subtrees of the trunk: no quadruped
            isomorphic_limbs(robot)

    def test_lane_functions_equal_scalar(self):
        """The feet of the default scene sit on both pairs (soles, hands) and on the spine (head):
        forward dynamics takes all three kinds of foot force."""
        robot = mini_cheetah.load(urdf=mini_cheetah.HUMANOID32)
        for name in ANY_GROUPS:
            lanes = trace_function(robot, default_scene(), LANE_NAME[name])
            scalar = trace_function(robot, default_scene(), name)
            for seed in (1, 2):
                state = random_state(robot, len(robot.feet), seed)
                got = evaluate(lanes, lanes.lanes.with_lanes(state))
                want = evaluate(scalar, state)
                for output in want:
                    self.assertLess(max_relative_error(got[output], want[output]), 1e-12, (name, output, seed))

    def test_paired_forms_equal_scalar(self):
        """The pairs' spare lanes used (lane_functions.PAIRED): rnea.pair_step's a and v in one lane
        value, crba's walks of a body's column and a child's together; both pairs of humanoid32 at
        once, each form fewer instructions than the plain lane form (bias and ID 5-6 % fewer since the
        regrouped inertias made the shared inertia product cheaper, M 15 %)."""
        robot = mini_cheetah.load(urdf=mini_cheetah.HUMANOID32)
        for name, paired in PAIRED.items():
            lanes = trace_function(robot, default_scene(), paired)
            plain = trace_function(robot, default_scene(), LANE_NAME[name])
            self.assertLess(schedule.straight_line_instructions(lanes), 0.96 * schedule.straight_line_instructions(plain), name)
            scalar = trace_function(robot, default_scene(), name)
            for seed in (1, 2):
                state = random_state(robot, len(robot.feet), seed)
                got, want = evaluate(lanes, lanes.lanes.with_lanes(state)), evaluate(scalar, state)
                for output in want:
                    self.assertLess(max_relative_error(got[output], want[output]), 1e-12, (name, output, seed))

    def test_pairs_together_chosen_by_cost(self):
        """The paired form has fewer instructions (humanoid32's ID 1 847 against 1 955) but a lane
        rotation on each body's chain, a critical path of 284 cycles against 241; at
        schedule.LATENCY_WEIGHT its cost is the higher here (it measured 4 % slower), without that
        weight auto would take it. M's paired walks need no
        rotation (their lanes 2-3 are read where stored): auto takes them."""
        robot = mini_cheetah.load(urdf=mini_cheetah.HUMANOID32)
        fn = scheduled_function(robot, default_scene(), "inverse_dynamics")
        self.assertTrue(fn.schedule.startswith("limb lanes ("), fn.schedule)
        paired = re.search(r"limb lanes with the pairs' spare lanes used (\d+) \(path \d+, cost (\d+)\)", fn.schedule)
        self.assertIsNotNone(paired, fn.schedule)
        self.assertLess(int(paired.group(1)), int(re.search(r": (\d+) arithmetic", fn.schedule).group(1)))
        with mock.patch.object(schedule, "LATENCY_WEIGHT", 0):
            fn = scheduled_function(robot, default_scene(), "inverse_dynamics")
        self.assertTrue(fn.schedule.startswith("limb lanes with the pairs' spare lanes used"), fn.schedule)
        fn = scheduled_function(robot, default_scene(), "mass_matrix")
        self.assertTrue(fn.schedule.startswith("limb lanes with the pairs' spare lanes used"), fn.schedule)
        self.assertNotIn("lane_rotate", {node.op for node in ex.reachable(fn.output_exprs())})

    def test_pair_angles_read_as_interleaved_runs(self):
        """A limb pair's lane angles sit in joint_angle as (left, right) pairs; where each limb's
        angles are consecutive in q (humanoid32's legs q[7…12] and q[13…18], arms q[25…31] and
        q[32…38]) they are read by store_interleaved_pairs, the rest entry by entry, every slot once
        (entry by entry, clang 14 gathered them)."""
        robot = mini_cheetah.load(urdf=mini_cheetah.HUMANOID32)
        lines = emit_body(scheduled_function(robot, default_scene(), "mass_matrix"))
        size = int(next(re.match(r"Scalar joint_angle\[(\d+)\];", l).group(1) for l in lines
                        if l.startswith("Scalar joint_angle[")))
        written = []
        runs = []
        for line in lines:
            pair = re.match(r"store_interleaved_pairs<(\d+)>\(joint_angle \+ (\d+), q \+ (\d+), q \+ (\d+)\);$", line)
            if pair:
                count, start, a, b = map(int, pair.groups())
                runs.append((count, a, b))
                written += range(start, start + 2 * count)
            single = re.match(r"joint_angle\[(\d+)\] = q\[\d+\];$", line)
            if single:
                written.append(int(single.group(1)))
        self.assertEqual(runs, [(6, 7, 13), (7, 25, 32)])
        self.assertEqual(sorted(written), list(range(size)))

    def test_auto_takes_the_pairs(self):
        robot = mini_cheetah.load(urdf=mini_cheetah.HUMANOID32)
        fn = scheduled_function(robot, default_scene(), "inverse_dynamics")
        self.assertTrue(fn.schedule.startswith("limb lanes (the isomorphic limbs in SIMD lanes: 2 of pelvis, 2 "
                                               "of torso"), fn.schedule)
        one_foot = replace(default_scene(), feet=("l_foot",))  # not on both legs: no lane feet
        self.assertTrue(scheduled_function(robot, one_foot, "inverse_dynamics").schedule.startswith("limb lanes"))
        self.assertNotIn("in limb lanes", scheduled_function(robot, one_foot, "forward_dynamics").schedule)

    def test_long_lane_code_in_blocks_up_to_the_limit(self):
        """∂q̈'s terms in lanes are 21 828 straight-line instructions for humanoid32: a candidate (cut
        into blocks, test_blocks.py), under schedule.LANE_CODE_LIMIT, though auto takes the looped RNEA
        derivatives under lane terms of 8 164 by cost; past the limit the form is not emitted, and the
        banner says why."""
        robot = mini_cheetah.load(urdf=mini_cheetah.HUMANOID32)
        fn = scheduled_function(robot, default_scene(), "forward_dynamics_derivatives")
        self.assertTrue(fn.schedule.startswith("limb lanes and looped RNEA derivatives"), fn.schedule)
        self.assertIsNotNone(fn.solve.rnea)
        self.assertRegex(fn.schedule, r"limb lanes and a looped solve \d+ \(path \d+, cost \d+\)")
        with mock.patch.object(schedule, "LANE_CODE_LIMIT", 20000):
            fn = scheduled_function(robot, default_scene(), "forward_dynamics_derivatives")
        self.assertTrue(fn.schedule.startswith("limb lanes and looped RNEA derivatives"), fn.schedule)
        self.assertIn("limb lanes and a looped solve not emitted", fn.schedule)

    def test_quadruped_functions_refused(self):
        """The lane forms that solve limb columns, or put frames and contacts in lanes, need the
        quadruped's four limbs of the trunk."""
        robot = mini_cheetah.load(urdf=mini_cheetah.HUMANOID32)
        for name in ("forward_dynamics_derivatives", "contact_dynamics", "frame_jacobians", "osc_open_chain"):
            with self.assertRaises(LimbError):
                available(robot, default_scene(), name)


def _hexapod_urdf():
    """A floating trunk with six 3-joint legs of one shape (yaw, pitch, pitch) around it, each with
    its own offsets and masses, and a foot at each leg's tip."""
    links, joints = ['<link name="trunk"><inertial><mass value="4"/><inertia ixx="0.1" iyy="0.2" izz="0.25" '
                     'ixy="0" ixz="0" iyz="0"/></inertial></link>'], []
    for k in range(6):
        angle = math.pi / 3 * k
        parent, origin = "trunk", "%.3f %.3f 0" % (0.3 * math.cos(angle), 0.2 * math.sin(angle))
        for j, axis in enumerate(("0 0 1", "0 1 0", "0 1 0")):
            name = "leg%d_%d" % (k, j)
            links.append('<link name="%s"><inertial><origin xyz="0.05 0 -0.02"/><mass value="%.2f"/><inertia '
                         'ixx="0.01" iyy="0.012" izz="0.008" ixy="0.001" ixz="0" iyz="0"/></inertial></link>'
                         % (name, 0.5 + 0.1 * k + 0.05 * j))
            joints.append('<joint name="%s_joint" type="revolute"><parent link="%s"/><child link="%s"/>'
                          '<origin xyz="%s"/><axis xyz="%s"/><limit lower="-3" upper="3" effort="50" '
                          'velocity="10"/></joint>' % (name, parent, name, origin, axis))
            parent, origin = name, "0.15 0 %.3f" % (-0.01 * k)
        links.append('<link name="foot%d"/>' % k)
        joints.append('<joint name="foot%d_fixed" type="fixed"><parent link="%s"/><child link="foot%d"/>'
                      '<origin xyz="0.2 0 0"/></joint>' % (k, parent, k))
    return '<robot name="hexapod">%s%s</robot>' % ("".join(links), "".join(joints))


@unittest.skipIf(mini_cheetah.skip_reason(), mini_cheetah.skip_reason())
class HexapodGroups(unittest.TestCase):
    def test_six_legs_in_a_group_of_four_and_a_pair(self):
        with tempfile.TemporaryDirectory() as folder:
            path = os.path.join(folder, "hexapod.urdf")
            with open(path, "w", encoding="utf-8") as handle:
                handle.write(_hexapod_urdf())
            robot = mini_cheetah.load(urdf=path)
        four, two = limb_groups(robot)
        self.assertEqual((len(four.limbs), len(two.limbs)), (4, 2))
        self.assertEqual(len(robot.feet), 6)
        forms = [(name, LANE_NAME[name]) for name in ("inverse_dynamics", "mass_matrix", "forward_dynamics")]
        for name, lane_name in forms + [(name, PAIRED[name]) for name in ("inverse_dynamics", "mass_matrix")]:
            lanes = trace_function(robot, default_scene(), lane_name)
            scalar = trace_function(robot, default_scene(), name)
            state = random_state(robot, len(robot.feet), 3)
            got, want = evaluate(lanes, lanes.lanes.with_lanes(state)), evaluate(scalar, state)
            for output in want:
                self.assertLess(max_relative_error(got[output], want[output]), 1e-12, (name, output))


def _written_runs(fn, left_out=frozenset()):
    """Each output's maximal runs of consecutive written entries, but those in `left_out`
    ((argument, index) pairs): (argument name, [index, …]) each."""
    runs = []
    for arg in fn.outputs:
        previous = None
        for k, e in enumerate(fn.values[arg.name]):
            if e is None or (arg.name, k) in left_out:
                continue
            if previous != k - 1:
                runs.append((arg.name, []))
            runs[-1][1].append(k)
            previous = k
    return runs

def _rotation(rng):
    """A random rotation matrix (Gram-Schmidt of a random 3×3, the last row turned to make it proper:
    a reflection is no joint frame, and the articulated-body algorithm and the CRBA disagree on one)."""
    rows = []
    while len(rows) < 3:
        row = [rng.gauss(0, 1) for _ in range(3)]
        for other in rows:
            dot = sum(a * b for a, b in zip(row, other))
            row = [a - dot * b for a, b in zip(row, other)]
        norm = math.sqrt(sum(a * a for a in row))
        if norm > 0.1:
            rows.append(tuple(a / norm for a in row))
    x, y, z = rows
    if sum(a * b for a, b in zip(z, (x[1] * y[2] - x[2] * y[1], x[2] * y[0] - x[0] * y[2], x[0] * y[1] - x[1] * y[0]))) < 0:
        rows[2] = tuple(-a for a in z)
    return tuple(rows)


def _scrambled_limbs(robot, rng):
    """robot with every limb body's constants drawn at random; joint l of every limb gets the same
    random oblique axis."""
    limbs = isomorphic_limbs(robot)
    bodies, joints = list(robot.bodies), list(robot.joints)
    axes = [_rotation(rng)[0] for _ in limbs[0]]
    for limb in limbs:
        for l, b in enumerate(limb):
            R = _rotation(rng)
            moments = [rng.uniform(0.01, 0.1) for _ in range(3)]
            inertia = tuple(tuple(sum(R[k][i] * moments[k] * R[k][j] for k in range(3)) for j in range(3))
                            for i in range(3))
            bodies[b] = replace(bodies[b], mass=rng.uniform(0.1, 2.0), inertia_com=inertia,
                                com=tuple(rng.uniform(-0.1, 0.1) for _ in range(3)))
            joints[b] = replace(joints[b], axis=axes[l], rotation=_rotation(rng),
                                translation=tuple(rng.uniform(-0.3, 0.3) for _ in range(3)),
                                actuator=Actuator(armature=rng.uniform(0.0, 0.1)))
    return replace(robot, bodies=tuple(bodies), joints=tuple(joints))


if __name__ == "__main__":
    unittest.main()
