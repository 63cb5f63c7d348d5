"""Long bodies cut into blocks (backend/blocks.py): values defined in one block and read in a later
one pass through the scratch array, scalars one entry each, a lane function's lane values
ex.LANES entries each after them; a lane function's blocks each declare the lane type and the lane
arrays they read. (The blocks' results are checked against the runtime by `rbdc verify` of
humanoid32's derivatives scene, whose ∂q̈ terms are lane code in blocks.)"""

import re
import unittest

import numeric_check  # noqa: F401  (puts the generator on sys.path)
from rbdcgen.backend.blocks import LANE_TYPE, SCRATCH, SPLIT_ABOVE, split
from rbdcgen.graph import expr as ex

LANE_ARRAYS = ["Lane lane_c[1] = {make_lanes(Scalar(1), Scalar(2), Scalar(3), Scalar(4))};",
               "Lane lane_v[1] = {make_lanes(v[0], v[1], v[2], v[3])};"]


def lane_body():
    """A lane function's statements: a scalar and a lane value defined first and read last, after
    more filler statements than one function may hold."""
    body = [LANE_TYPE, *LANE_ARRAYS, "Scalar s = v[0] * v[1];", "Lane l = lane_c[0] * s;"]
    body += ["Scalar f%d = s * Scalar(%d);" % (i, i) for i in range(SPLIT_ABOVE)]
    return body + ["out[0] = s + l[1];", "store_lanes(out + 4, l * lane_v[0]);"]


class LaneBlocks(unittest.TestCase):
    def setUp(self):
        self.blocks = split(lane_body(), ["v", "out"], "f")
        self.first, self.last = self.blocks.parts[0], self.blocks.parts[-1]

    def test_lane_values_pass_after_the_scalars(self):
        scalar = [int(m) for m in re.findall(r"%s\[(\d+)\] = s;" % SCRATCH, "\n".join(self.first))]
        lane = [int(m) for m in re.findall(r"store_lanes\(%s \+ (\d+), l\);" % SCRATCH, "\n".join(self.first))]
        self.assertEqual(len(scalar), 1)
        self.assertEqual(len(lane), 1)
        self.assertIn("Scalar s = %s[%d];" % (SCRATCH, scalar[0]), self.last)
        self.assertIn("Lane l = load_lanes(%s + %d);" % (SCRATCH, lane[0]), self.last)
        self.assertGreater(lane[0], scalar[0])  # ex.LANES entries past every scalar's
        self.assertEqual(self.blocks.scratch_size, lane[0] + ex.LANES)

    def test_each_block_declares_what_it_reads(self):
        for part in self.blocks.parts:
            self.assertEqual(part[0], LANE_TYPE)
        self.assertIn(LANE_ARRAYS[0], self.first)      # lane_c: read where l is defined
        self.assertNotIn(LANE_ARRAYS[1], self.first)   # lane_v: read by the last block only
        self.assertIn(LANE_ARRAYS[1], self.last)
        self.assertNotIn(LANE_ARRAYS[0], self.last)
        for part in self.blocks.parts[1:-1]:
            self.assertFalse(any(statement in part for statement in LANE_ARRAYS))

    def test_a_scalar_body_has_no_lane_setup(self):
        body = [s for s in lane_body() if "Lane" not in s and "lane" not in s and "l[1]" not in s]
        blocks = split(body, ["v", "out"], "f")
        for part in blocks.parts:
            self.assertNotIn(LANE_TYPE, part)
        self.assertEqual(blocks.scratch_size, 1)


if __name__ == "__main__":
    unittest.main()
