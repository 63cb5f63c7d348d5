"""Body frames turned about their joint axes (views/turns.py): a turn given at random is undone by the
chosen one; on random robots (with mimic couplings, with geared rotors, oblique axes), arm7 (frames, a
foot) and the Mini Cheetah turned at random, the traced quantities equal those traced on the robot as
given, the limb-lane functions too (each limb's angles offset by its own lane constants), and the
emitted angle offset costs one addition in joint_sincos's array, no sine of its own."""

import random
import unittest

import mini_cheetah
from numeric_check import assert_agree, evaluate, random_state
from rbdcgen.backend.emit import emit_body
from rbdcgen.frontend.scene import Scene, default_scene
from rbdcgen.passes.lane_functions import LANE_NAME
from rbdcgen.passes.schedule import scheduled_function
from rbdcgen.passes.trace import trace_function
from rbdcgen.views import turns
from test_lanes import _scrambled_limbs
from test_origins import ARM7, FRAMES, FUNCTIONS, cases, operations


def at_random(robot, seed):
    """The robot with every body turned by a random angle and every revolute placement by another."""
    rng = random.Random(seed)
    psi = [0.0] + [rng.uniform(-3.0, 3.0) for _ in robot.joints[1:]]
    chi = [0.0] + [rng.uniform(-3.0, 3.0) if j.type == "revolute" else psi[i]
                   for i, j in enumerate(robot.joints[1:], start=1)]
    return turns.turn(robot, psi, chi)


def rotation_entries(robot):
    """Multiplications by the joints' placement rotations: non-zero entries and non-unit ones."""
    return sum((x != 0.0) + (x not in (0.0, 1.0, -1.0))
               for joint in robot.joints[1:] for row in joint.rotation for x in row)


def mini_cheetahs():
    yield "Mini Cheetah", mini_cheetah.load("floating"), default_scene()
    yield "Mini Cheetah fixed", mini_cheetah.load("fixed"), Scene(base="fixed")


@unittest.skipIf(mini_cheetah.skip_reason(), mini_cheetah.skip_reason())
class TurnedFrames(unittest.TestCase):
    def test_a_turn_at_random_is_undone(self):
        for label, robot, _ in list(mini_cheetahs()) + [("arm7", mini_cheetah.load("fixed", ARM7), None)]:
            scrambled = at_random(robot, 3)
            chosen = turns.turned(scrambled)
            with self.subTest(robot=label):
                self.assertGreater(rotation_entries(scrambled), rotation_entries(robot))
                self.assertLessEqual(rotation_entries(chosen), rotation_entries(robot))
                self.assertLess(operations(chosen, "inverse_dynamics"), operations(scrambled, "inverse_dynamics"))

    def test_the_traced_quantities_equal_those_on_the_robot_as_given(self):
        every = list(cases()) + list(mini_cheetahs())
        for label, robot, scene in every:
            state = dict(random_state(robot, len(robot.feet), 7), f=[0.0] * 3 * len(robot.feet))
            names = FUNCTIONS + (() if robot.couplings else ("center_of_mass",)) + (FRAMES if scene.frames else ())
            for how, changed in (("chosen", turns.turned(robot)), ("at random", at_random(robot, 5))):
                for name in names:
                    got = evaluate(trace_function(changed, scene, name), state)
                    want = evaluate(trace_function(robot, scene, name), state)
                    assert_agree(self, got, want, robot=label, turn=how, function=name)

    def test_limb_lanes_of_turned_limbs(self):
        """Each leg's knee and hip turned by its own angles: the lanes' angle offsets differ."""
        for label, robot, scene in mini_cheetahs():
            for how, changed in (("at random", at_random(robot, 9)),
                                 ("chosen", turns.turned(_scrambled_limbs(robot, random.Random(4))))):
                given = robot if how == "at random" else _scrambled_limbs(robot, random.Random(4))
                state = random_state(given, len(given.feet), 2)
                for name in ("inverse_dynamics", "mass_matrix", "forward_dynamics"):
                    lanes = trace_function(changed, scene, LANE_NAME[name])
                    got = evaluate(lanes, lanes.lanes.with_lanes(state))
                    want = evaluate(trace_function(given, scene, name), state)
                    assert_agree(self, got, want, robot=label, turn=how, function=name)

    def test_an_angle_offset_is_one_addition_in_the_sines_array(self):
        """arm7's in the array's initialiser; the Mini Cheetah's limb lanes' after their angles are
        stored as vectors, one addition per lane."""
        arm7 = turns.turned(at_random(mini_cheetah.load("fixed", ARM7), 1))
        self.assertTrue(any(joint.angle_offset for joint in arm7.joints))
        legs = turns.turned(at_random(mini_cheetah.load("floating"), 1))
        for robot, scene, offset in (
                (arm7, Scene(base="fixed"), r"joint_angle\[\d+\] = \{[^}]*(q\[\d\] [-+] Scalar\(|Scalar\([^)]*\) \+ q\[\d\])"),
                (legs, default_scene(), r"store_lanes\(joint_angle[^\n]*\n(joint_angle\[\d+\] [-+]= Scalar\([^)]*\);\n){4}")):
            fn = scheduled_function(robot, scene, "inverse_dynamics")
            text = "\n".join(emit_body(fn))
            with self.subTest(robot=robot.name, schedule=fn.schedule):
                self.assertRegex(text, offset)
                self.assertNotRegex(text, r"\b(sin|cos)\(")


if __name__ == "__main__":
    unittest.main()
