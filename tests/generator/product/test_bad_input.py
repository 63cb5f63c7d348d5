"""Bad input through the command line: exit code 2 and a message naming the file, the element and
the problem (forwarded from rbdc-model or the scene reader), never a Python traceback."""
import unittest

from rbdc_cli import DATA, MINI_CHEETAH, run_rbdc


class BadInputTest(unittest.TestCase):
    def assert_refused(self, args, *fragments):
        result = run_rbdc(*args)
        self.assertEqual(result.returncode, 2, result.stderr)
        self.assertNotIn("Traceback", result.stderr)
        self.assertTrue(result.stderr.startswith("error: ") or "\nerror: " in result.stderr, result.stderr)
        for fragment in fragments:
            self.assertIn(fragment, result.stderr)

    def test_missing_file(self):
        self.assert_refused(["generate", DATA / "no_such_robot.urdf", "-o", "/nonexistent"],
                            "no_such_robot.urdf", "no such file")

    def test_joint_with_unknown_child_link(self):
        self.assert_refused(["generate", DATA / "missing_link.urdf", "-o", "/nonexistent"],
                            "missing_link.urdf", "elbow", "forearm")

    def test_malformed_xml(self):
        self.assert_refused(["flops", DATA / "truncated.urdf"], "truncated.urdf", "XML")

    def test_zero_axis(self):
        self.assert_refused(["flops", DATA / "zero_axis.urdf"], "zero_axis.urdf", "shoulder", "axis")

    def test_misspelt_scene_key(self):
        self.assert_refused(["flops", MINI_CHEETAH, "--scene", DATA / "typo_scene.yaml"],
                            "typo_scene.yaml", "quantitites", "unknown key")

    def test_unknown_quantity(self):
        self.assert_refused(["generate", MINI_CHEETAH, "--scene", DATA / "unknown_quantity_scene.yaml",
                             "-o", "/nonexistent"], "unknown_quantity_scene.yaml", "teleport")

    def test_locking_an_unknown_joint(self):
        self.assert_refused(["flops", MINI_CHEETAH, "--scene", DATA / "lock_scene.yaml"], "no_such_joint")

    def test_incomplete_ir_json(self):
        self.assert_refused(["flops", DATA / "incomplete_ir.json"], "missing key")

if __name__ == "__main__":
    unittest.main()
