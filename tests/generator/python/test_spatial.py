"""Structured spatial algebra equals the dense 6×6 forms of conventions.md (reference.py):
transforms on motion and force vectors, inertia congruence, the articulated inertias' congruence (a
transform, a chain of two factor by factor and merged), rotations of ±coordinate axes."""

import math
import random
import unittest

import reference as ref
from numeric_check import max_relative_error
from rbdcgen.graph import expr as ex
from rbdcgen.graph import spatial as sp

ROTATION = ref.transpose(ref.axis_rotation([0.2, -0.5, 0.7], 0.8))
TRANSLATION = [0.1, -0.25, 0.3]


def numbers(values):
    return [x.value for x in values]


class DenseAgreement(unittest.TestCase):
    def setUp(self):
        self.graph = ex.Graph().__enter__()
        rng = random.Random(3)
        self.m = [rng.uniform(-1, 1) for _ in range(6)]
        self.X = sp.Transform(sp.mat(ROTATION), sp.vec(TRANSLATION))
        self.dense = ref.motion_transform(ROTATION, TRANSLATION)

    def tearDown(self):
        self.graph.__exit__(None, None, None)

    def test_motion_and_force_transforms(self):
        self.assertLess(max_relative_error(numbers(self.X.motion(sp.vec(self.m))),
                                           ref.matvec(self.dense, self.m)), 1e-15)
        self.assertLess(max_relative_error(numbers(self.X.force_T(sp.vec(self.m))),
                                           ref.matvec(ref.transpose(self.dense), self.m)), 1e-15)

    def test_inertia_congruence(self):
        class Body:
            mass, com = 1.3, (0.05, -0.02, 0.1)
            inertia_com = ((0.02, 0.001, 0.0), (0.001, 0.03, -0.002), (0.0, -0.002, 0.025))
        inertia = sp.Inertia.of(Body.mass, [Body.mass * c for c in Body.com], sp.inertia_at_origin(Body))
        got = inertia.congruence(self.X).dense()
        want = ref.matmul(ref.transpose(self.dense),
                          ref.matmul(ref.spatial_inertia(Body), self.dense))
        self.assertLess(max_relative_error([x.value for row in got for x in row],
                                           [x for row in want for x in row]), 1e-14)
        applied = numbers(inertia.apply(sp.vec(self.m)))
        self.assertLess(max_relative_error(applied, ref.matvec(ref.spatial_inertia(Body), self.m)),
                        1e-15)

    def test_articulated_inertia_congruence(self):
        rng = random.Random(5)
        a = [[rng.uniform(-1, 1) for _ in range(6)] for _ in range(6)]
        symmetric = ref.matmul(ref.transpose(a), a)
        M = sp.mat(symmetric)
        joint = sp.Transform(sp.coordinate_rotation([0, 1, 0], ex.const(math.cos(0.3)), ex.const(math.sin(0.3))))
        chain = sp.Chain(self.X, joint)  # the placement first, then the joint: X = X_J X_T
        dense_chain = ref.matmul(ref.motion_transform(ref.transpose(ref.axis_rotation([0, 1, 0], 0.3)), [0, 0, 0]),
                                 self.dense)
        for got, X in ((sp.congruence6(self.X, M), self.dense), (chain.congruence6(M), dense_chain),
                       (sp.congruence6(self.X.then(joint), M), dense_chain)):
            want = ref.matmul(ref.transpose(X), ref.matmul(symmetric, X))
            self.assertLess(max_relative_error([x.value for row in got for x in row], sum(want, [])), 1e-14)

    def test_coordinate_axis_rotations_are_exact_and_right(self):
        c, s = ex.const(math.cos(0.4)), ex.const(math.sin(0.4))
        for axis in ([1, 0, 0], [0, -1, 0], [0, 0, 1], [0.6, 0.0, 0.8]):
            got = [[x.value for x in row] for row in sp.coordinate_rotation(axis, c, s)]
            want = ref.transpose(ref.axis_rotation(axis, 0.4))
            self.assertLess(max_relative_error(sum(got, []), sum(want, [])), 1e-15, axis)
        with ex.Graph():
            q = ex.symbol("q", 0)
            E = sp.coordinate_rotation([0, 1, 0], ex.cos(q), ex.sin(q))
            self.assertIs(E[1][1], ex.const(1.0))
            self.assertIs(E[0][1], ex.const(0.0))

    def test_round_off_rotation_entries_are_snapped(self):
        rotation = ((-1.0, 1.2246467991473532e-16, 0.0), (-1.2246467991473532e-16, -1.0, 0.0),
                    (0.0, 0.0, 1.0))
        self.assertEqual(sp.snap_rotation(rotation), ((-1.0, 0.0, 0.0), (0.0, -1.0, 0.0),
                                                      (0.0, 0.0, 1.0)))
        self.assertEqual(sp.snap_rotation(ROTATION), tuple(tuple(r) for r in ROTATION))
        self.assertEqual(sp.snap_axis((1e-17, 0.0, -1.0000000000000002)), (0.0, 0.0, -1.0))
        self.assertEqual(sp.snap_axis((0.6, 0.0, 0.8)), (0.6, 0.0, 0.8))


if __name__ == "__main__":
    unittest.main()
