"""Origins slid along the joint axes (views/origins.py): arm7's placements lose non-zero entries and its
dynamics operations; on random robots (with mimic couplings, with geared rotors) and arm7 (frames, a
foot) the traced quantities equal those traced on the robot as given, and no placement or foot offset
gains a non-zero."""

import json
import os
import subprocess
import tempfile
import unittest

import mini_cheetah
from mini_cheetah import model_tool, skip_reason
from numeric_check import assert_agree, evaluate, random_state
from rbdcgen.frontend.ir import load_ir
from rbdcgen.frontend.random_robot import random_actuated_topology, random_urdf
from rbdcgen.frontend.scene import Scene
from rbdcgen.graph.flops import count_ops
from rbdcgen.passes.trace import trace_function
from rbdcgen.views import origins
from test_random_properties import load

ARM7 = os.path.join(mini_cheetah.ROOT, "robots", "arm7.urdf")
FUNCTIONS = ("inverse_dynamics", "mass_matrix", "forward_dynamics", "feet_positions", "feet_jacobian")
FRAMES = ("frame_placements", "frame_jacobians")  # for a scene with frames


def placement_nonzeros(robot):
    """Non-zero entries of the joints' placements and the feet's offsets (a foot slid along the axis it
    sits on would cost a lever arm whose torque about that axis is round-off, not an exact zero)."""
    return (sum(x != 0.0 for joint in robot.joints[1:] for x in joint.translation)
            + sum(x != 0.0 for foot in robot.feet for x in foot.offset))


def operations(robot, name):
    return count_ops(trace_function(robot, Scene(), name))["total"]


def actuated(seed, floating):
    """A random topology whose joints carry geared rotors (rotors ride on the parent, whose origin moves)."""
    with tempfile.NamedTemporaryFile("w", suffix=".yaml", delete=False) as handle:
        handle.write(random_actuated_topology(seed, floating, max_links=8))
    try:
        result = subprocess.run([model_tool(), handle.name], capture_output=True, text=True, check=True)
    finally:
        os.unlink(handle.name)
    return load_ir(json.loads(result.stdout))


def cases():
    """(label, robot, scene): random robots (two with mimic couplings, two with rotors, one with a foot
    on its joint axis), arm7 with all its frames."""
    for seed in range(4):
        base = "floating" if seed % 2 == 0 else "fixed"
        yield "random %d" % seed, load(random_urdf(seed, max_links=8, mimic=seed >= 2), base), Scene(base=base)
    # one link whose foot sits at its origin, on the joint axis: sliding it would move the foot
    yield "random 19", load(random_urdf(19), "fixed"), Scene(base="fixed")
    for seed in range(2):
        robot = actuated(seed, seed == 0)
        yield "actuated %d" % seed, robot, Scene(base="floating" if robot.floating_base else "fixed")
    arm7 = mini_cheetah.load("fixed", ARM7)
    yield "arm7", arm7, Scene(base="fixed", frames=tuple(f.name for f in arm7.frames))


@unittest.skipIf(skip_reason(), skip_reason())
class SlidOrigins(unittest.TestCase):
    def test_arm7s_placements_lose_entries_and_its_dynamics_operations(self):
        robot = mini_cheetah.load("fixed", ARM7)
        moved = origins.slid(robot)
        self.assertLess(placement_nonzeros(moved), placement_nonzeros(robot))
        for name in ("inverse_dynamics", "mass_matrix"):
            with self.subTest(function=name):
                self.assertLess(operations(moved, name), operations(robot, name))

    def test_no_placement_or_foot_gains_a_nonzero(self):
        for label, robot, _ in cases():
            with self.subTest(robot=label):
                self.assertLessEqual(placement_nonzeros(origins.slid(robot)), placement_nonzeros(robot))

    def test_the_traced_quantities_equal_those_on_the_robot_as_given(self):
        for label, robot, scene in cases():
            moved = origins.slid(robot)
            state = dict(random_state(robot, len(robot.feet), 7), f=[0.0] * 3 * len(robot.feet))
            names = FUNCTIONS + (() if robot.couplings else ("center_of_mass",)) + (FRAMES if scene.frames else ())
            for name in names:
                got = evaluate(trace_function(moved, scene, name), state)
                want = evaluate(trace_function(robot, scene, name), state)
                assert_agree(self, got, want, robot=label, function=name)


if __name__ == "__main__":
    unittest.main()
