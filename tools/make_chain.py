#!/usr/bin/python3
"""Writes a long serial chain, rbdc's benchmark of depth (issue 20): N revolute links on a fixed base,
the joint axes cycling x, y, z and each joint frame tilted a little, so that no two consecutive
joints are parallel and nothing in the tree folds away. Every link is a solid box (the inertia of
make_humanoid's `Urdf.box_link`); the last carries a foot point, so the default scene has one foot.
Deep chains are where CRBA + LDLᵀ is O(n³) and the articulated-body algorithm O(n): the generator's
cost model must see that (docs/performance.md). Byte-stable output.

Usage: tools/make_chain.py N OUTPUT.urdf
"""
import argparse
import pathlib
import sys

from make_humanoid import Urdf

AXES = ((1, 0, 0), (0, 1, 0), (0, 0, 1))
TILT = (0.05, -0.03, 0.04)  # each joint frame's roll, pitch, yaw against its parent's


def chain(links):
    urdf = Urdf(f"chain{links}")
    urdf.box_link("base", 2.0, (0.1, 0.1, 0.1), (0, 0, 0))
    parent = "base"
    for k in range(links):
        name = f"link{k + 1}"
        mass = 1.0 - 0.5 * k / links  # lighter towards the tip, as a real arm
        urdf.box_link(name, mass, (0.04, 0.04, 0.1), (0, 0, 0.05))
        urdf.revolute(f"joint{k + 1}", parent, name, (0, 0, 0.1), AXES[k % 3], 3.0, rpy=TILT)
        parent = name
    urdf.foot("tip", parent, (0, 0, 0.1))
    return urdf


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("links", type=int, help="number of moving links (≥ 1)")
    parser.add_argument("output", type=pathlib.Path, help="URDF file to write")
    args = parser.parse_args(argv[1:])
    if args.links < 1:
        parser.error("a chain needs at least one link")
    args.output.parent.mkdir(parents=True, exist_ok=True)
    args.output.write_text(chain(args.links).text())
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
