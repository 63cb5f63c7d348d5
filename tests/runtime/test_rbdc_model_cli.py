#!/usr/bin/env python3
"""rbdc-model / rbdc-info command lines: IR on stdout (or -o), warnings and errors on stderr, exit codes.

usage: test_rbdc_model_cli.py RBDC_MODEL RBDC_INFO SOURCE_DIR
"""
import json
import os
import subprocess
import sys
import tempfile
import unittest

RBDC_MODEL, RBDC_INFO, SOURCE_DIR = sys.argv[1:4]
MINI_CHEETAH = os.path.join(SOURCE_DIR, "robots", "mini_cheetah.urdf")
DATA = os.path.join(SOURCE_DIR, "tests", "data")


def run(*args):
    return subprocess.run(list(args), capture_output=True, text=True, check=False)


class RbdcModelCli(unittest.TestCase):
    def test_writes_sorted_ir_and_prefixed_warnings(self):
        r = run(RBDC_MODEL, MINI_CHEETAH)
        self.assertEqual(r.returncode, 0, r.stderr)
        ir = json.loads(r.stdout)
        self.assertEqual(list(ir), sorted(ir))
        self.assertEqual(ir["format"], "rbdc-ir-1")
        self.assertEqual(ir["lambda"], [0, 1, 2, 0, 4, 5, 0, 7, 8, 0, 10, 11])
        self.assertAlmostEqual(sum(b["mass"] for b in ir["bodies"]), 8.252, places=12)
        warnings = r.stderr.splitlines()
        self.assertEqual(len(warnings), 4)
        self.assertTrue(all(w.startswith("warning: ") and "triangle inequality" in w for w in warnings))

    def test_output_file_equals_stdout_and_is_byte_stable(self):
        with tempfile.TemporaryDirectory() as tmp:
            out = os.path.join(tmp, "ir.json")
            r = run(RBDC_MODEL, MINI_CHEETAH, "--topology",
                    os.path.join(SOURCE_DIR, "robots", "mini_cheetah.topology.yaml"), "-o", out)
            self.assertEqual(r.returncode, 0, r.stderr)
            with open(out, encoding="utf-8") as f:
                self.assertEqual(f.read(), run(RBDC_MODEL, MINI_CHEETAH).stdout)

    def test_standalone_topology_input(self):
        r = run(RBDC_MODEL, os.path.join(DATA, "mini_cheetah_standalone.yaml"))
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertEqual(r.stdout, run(RBDC_MODEL, MINI_CHEETAH).stdout)

    def test_options_change_the_model(self):
        fixed = json.loads(run(RBDC_MODEL, MINI_CHEETAH, "--fixed-base").stdout)
        self.assertEqual((fixed["nq"], fixed["joints"][0]["type"]), (12, "fixed"))
        locked = json.loads(run(RBDC_MODEL, os.path.join(DATA, "split_body.urdf"), "--lock", "elbow=0.5").stdout)
        self.assertEqual(locked["nb"], 2)
        mimic = os.path.join(DATA, "mimic.urdf")
        coupled = json.loads(run(RBDC_MODEL, mimic).stdout)
        self.assertEqual((coupled["nb"], coupled["nv"]), (3, 8))  # the IR keeps the tree
        self.assertEqual(coupled["couplings"], [{"follower": 2, "leader": 1, "multiplier": -1, "offset": 0.25}])
        self.assertEqual(json.loads(run(RBDC_MODEL, mimic, "--lock-mimic").stdout)["nb"], 2)
        self.assertEqual(json.loads(run(RBDC_MODEL, mimic, "--independent-mimic").stdout)["couplings"], [])

    def test_errors_exit_2_with_one_message(self):
        for args, message in [
            ((os.path.join(DATA, "two_parents.urdf"),), "link 'b' has two parents"),
            ((os.path.join(DATA, "mimic_cycle.urdf"),), "its mimic joints form a cycle"),
            ((MINI_CHEETAH, "--bogus"), "unknown option '--bogus'"),
            ((MINI_CHEETAH, "--lock", "nothing"), "--lock expects NAME=VALUE"),
            ((), "no robot file given"),
        ]:
            r = run(RBDC_MODEL, *args)
            self.assertEqual(r.returncode, 2, args)
            self.assertEqual(r.stdout, "")
            self.assertTrue(r.stderr.startswith("error: "), r.stderr)
            self.assertIn(message, r.stderr)

    def test_help(self):
        r = run(RBDC_MODEL, "--help")
        self.assertEqual(r.returncode, 0)
        for option in ("--lock-mimic", "--independent-mimic", "--check"):
            self.assertIn(option, r.stdout)


class RbdcInfoCli(unittest.TestCase):
    def test_prints_arrays_and_feet(self):
        r = run(RBDC_INFO, MINI_CHEETAH)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("nb = 13, nq = 19, nv = 18", r.stdout)
        self.assertIn("total mass 8.252 kg", r.stdout)
        self.assertIn("PRED   = {0, 1, 2, 0, 4, 5, 0, 7, 8, 0, 10, 11}", r.stdout)
        self.assertIn("mu(0) = {1, 4, 7, 10}", r.stdout)
        self.assertIn("RH_foot  12 (RH_knee)", r.stdout)

    def test_mini_cheetah_with_rotors(self):
        rotors = os.path.join(SOURCE_DIR, "robots", "mini_cheetah_rotors.topology.yaml")
        r = run(RBDC_INFO, MINI_CHEETAH, "--topology", rotors)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("total mass 8.912 kg (links 8.252 kg, rotors 0.66 kg)", r.stdout)
        self.assertEqual(r.stdout.count("rotor: joint "), 12)
        self.assertIn("rotor: joint LF_knee_joint, gear ratio 9.33", r.stdout)
        ir = json.loads(run(RBDC_MODEL, MINI_CHEETAH, "--topology", rotors).stdout)
        knee = ir["joints"][3]["actuator"]
        self.assertEqual((knee["armature"], knee["rotor"]["gear_ratio"]), (0, 9.33))
        self.assertNotIn("actuator", json.loads(run(RBDC_MODEL, MINI_CHEETAH).stdout)["joints"][3])

    def test_armature_from_the_command_line(self):
        r = run(RBDC_INFO, MINI_CHEETAH, "--armature", "LF_knee_joint=0.0055")
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertIn("armature: joint LF_knee_joint 0.0055", r.stdout)
        for spec, message in [("LF_elbow_joint=1", "--armature LF_elbow_joint=1: actuator of joint "
                                                    "'LF_elbow_joint': no such moving joint"),
                              ("LF_knee_joint=-1", "armature must be finite and ≥ 0"),
                              ("LF_knee_joint", "--armature expects NAME=VALUE")]:
            bad = run(RBDC_INFO, MINI_CHEETAH, "--armature", spec)
            self.assertEqual(bad.returncode, 2, spec)
            self.assertIn(message, bad.stderr)

    def test_q_must_have_nq_numbers(self):
        r = run(RBDC_INFO, MINI_CHEETAH, "--q", "1", "2")
        self.assertEqual(r.returncode, 2)
        self.assertIn("--q has 2 numbers, the model needs nq = 19", r.stderr)


if __name__ == "__main__":
    unittest.main(argv=sys.argv[:1])
