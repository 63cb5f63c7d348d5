#!/usr/bin/env python3
"""`rbdc check` (the ./rbdc front end) and `rbdc-model --check` (the one C++ loader behind it): every
warning and the refusal with file:line, the topology, exit 0 unless refused; both print the same.

usage: test_rbdc_check_cli.py RBDC_MODEL SOURCE_DIR
"""
import os
import subprocess
import sys
import unittest

RBDC_MODEL, SOURCE_DIR = sys.argv[1:3]
RBDC = os.path.join(SOURCE_DIR, "rbdc")
DATA = os.path.join(SOURCE_DIR, "tests", "data")
ENVIRONMENT = dict(os.environ, RBDC_MODEL_TOOL=RBDC_MODEL, PYTHONDONTWRITEBYTECODE="1")


def check(*args):
    """(front end, C++ tool) results of checking args."""
    front = subprocess.run([RBDC, "check", *args], capture_output=True, text=True, env=ENVIRONMENT)
    tool = subprocess.run([RBDC_MODEL, *args, "--check"], capture_output=True, text=True)
    return front, tool


class RbdcCheck(unittest.TestCase):
    def test_repairs_are_listed_with_file_and_line_and_exit_0(self):
        path = os.path.join(DATA, "appearance_faults.urdf")
        front, tool = check(path)
        self.assertEqual((front.returncode, tool.returncode), (0, 0), front.stderr)
        self.assertEqual(front.stdout, tool.stdout)
        self.assertIn(f"warning: {path}:8: link 'base': <visual> without <geometry>", front.stdout)
        self.assertIn(f"warning: {path}:12: link 'arm': <collision> without <geometry>", front.stdout)
        self.assertIn(f"{path}: 3 warnings, 0 errors", front.stdout)
        self.assertIn("PRED   = {0}\nSUCC   = {1}\nlambda = {0}", front.stdout)
        self.assertIn("1 joint DoF", front.stdout)
        self.assertIn("mass 1.5 kg", front.stdout)

    def test_couplings_and_dofs_follow_the_mimic_option(self):
        path = os.path.join(DATA, "two_finger_gripper.urdf")
        front, _ = check(path, "--fixed-base")
        self.assertIn("1 joint DoF (2 joints, 1 coupled), nq = 1, nv = 1", front.stdout)
        self.assertIn("coupling: joint 'finger_right_joint' (2) = 2 * joint 'finger_left_joint' (1) + 0.01",
                      front.stdout)
        front, tool = check(path, "--fixed-base", "--independent-mimic")
        self.assertIn("2 joint DoF (2 joints, 0 coupled)", front.stdout)
        self.assertEqual(front.stdout, tool.stdout)
        front, _ = check(path, "--fixed-base", "--lock-mimic")
        self.assertIn("1 joint DoF (1 joints, 0 coupled)", front.stdout)

    def test_a_refusal_is_listed_after_the_warnings_and_exits_non_zero(self):
        path = os.path.join(DATA, "slightly_indefinite.urdf")
        front, tool = check(path)
        self.assertEqual((front.returncode, tool.returncode), (2, 2))
        self.assertEqual(front.stdout, tool.stdout)
        self.assertIn(f"error: {path}:5: link 'arm': rotational inertia is not positive semi-definite",
                      front.stdout)
        self.assertIn("0 warnings, 1 error", front.stdout)
        self.assertNotIn("PRED", front.stdout)

    def test_every_bad_link_is_listed(self):
        path = os.path.join(DATA, "two_bad_links.urdf")
        front, tool = check(path)
        self.assertEqual((front.returncode, tool.returncode), (2, 2))
        self.assertEqual(front.stdout, tool.stdout)
        self.assertIn(f"error: {path}:5: link 'light': mass is negative\n"
                      f"error: {path}:6: link 'wobbly': rotational inertia is not positive semi-definite",
                      front.stdout)
        self.assertIn("0 warnings, 2 errors", front.stdout)

    def test_a_clean_robot_has_no_warnings(self):
        front, _ = check(os.path.join(DATA, "branched_robot.urdf"))
        self.assertEqual(front.returncode, 0, front.stdout + front.stderr)
        self.assertIn(": 0 warnings, 0 errors", front.stdout)
        self.assertNotIn("warning:", front.stdout)

    def test_missing_file(self):
        front, _ = check(os.path.join(DATA, "no_such_robot.urdf"))
        self.assertEqual(front.returncode, 2)
        self.assertIn("no_such_robot.urdf: no such file", front.stderr)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
