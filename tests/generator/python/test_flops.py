"""Operation counts: the counter sees exactly the emitted operations, the generic dense count is
larger, and the Mini Cheetah counts are printed (the team's prototype reached ~1.9k flops for the
folded RNEA and ~0.8k for the CRBA)."""

import os
import unittest

import mini_cheetah
from numeric_check import DATA, operator_count
from rbdcgen.backend.emit import emit_body
from rbdcgen.graph.flops import count_ops, generic_ops
from rbdcgen.frontend.ir import load_ir
from rbdcgen.frontend.scene import default_scene, load_scene
from rbdcgen.passes.trace import trace_function
from rbdcgen.passes.schedule import trace_scene

ROBOT = load_ir(os.path.join(DATA, "tiny_floating.json"))


def table(robot, scene):
    rows = ["%-26s %6s %6s %5s %5s %5s %4s %7s %9s %6s" % (
        "function", "mul", "add", "div", "sqrt", "trig", "neg", "total", "generic", "ratio")]
    counts = {}
    for fn in trace_scene(robot, scene):
        c, g = count_ops(fn), generic_ops(robot, scene, fn.computes)
        counts[fn.name] = c
        rows.append("%-26s %6d %6d %5d %5d %5d %4d %7d %9d %5.1fx" % (
            fn.name, c["mul"], c["add"], c["div"], c["sqrt"], c["trig"], c["neg"], c["total"],
            g["total"], g["total"] / max(1, c["total"])))
    return "\n".join(rows), counts


class Counts(unittest.TestCase):
    def test_count_matches_the_operators_in_the_emitted_text(self):
        for name in ("inverse_dynamics", "mass_matrix", "forward_dynamics", "osc_open_chain"):
            fn = trace_function(ROBOT, default_scene(), name)
            total = sum(operator_count(line) for line in emit_body(fn))
            self.assertEqual(total, count_ops(fn)["total"], name)

    def test_generic_dense_count_is_larger_for_every_function(self):
        scene = default_scene()
        for fn in trace_scene(ROBOT, scene):
            ours, generic = count_ops(fn), generic_ops(ROBOT, scene, fn.computes)
            self.assertEqual(set(ours), set(generic))
            self.assertLess(ours["total"], generic["total"], fn.name)
            self.assertEqual(ours["total"], sum(v for k, v in ours.items() if k != "total"))


@unittest.skipIf(mini_cheetah.skip_reason(), mini_cheetah.skip_reason())
class MiniCheetah(unittest.TestCase):
    def test_full_scene_counts_are_reported_and_near_the_prototype(self):
        text, counts = table(mini_cheetah.load(), default_scene())
        print("\nMini Cheetah, scene full (generated vs generic dense 6x6):\n" + text)
        self.assertLess(counts["inverse_dynamics"]["total"], 2000)
        self.assertLess(counts["mass_matrix"]["total"], 900)
        self.assertEqual(counts["inverse_dynamics"]["trig"], 24)  # 12 joints: one sin, one cos

    def test_bundled_scenes(self):
        robot = mini_cheetah.load()
        full = {fn.name: count_ops(fn)["total"] for fn in trace_scene(robot, default_scene())}
        for name in ("gravity_compensation", "stance_osc", "kinematics_only"):
            scene = load_scene(os.path.join(mini_cheetah.SCENES, name + ".yaml"))
            text, counts = table(robot, scene)
            print("\nMini Cheetah, scene %s:\n%s" % (name, text))
            for fn_name, c in counts.items():
                self.assertLessEqual(c["total"], full[fn_name], fn_name)
        compensation = load_scene(os.path.join(mini_cheetah.SCENES, "gravity_compensation.yaml"))
        id_comp = trace_function(robot, compensation, "inverse_dynamics")
        self.assertLess(count_ops(id_comp)["total"], full["inverse_dynamics"])


if __name__ == "__main__":
    unittest.main()
