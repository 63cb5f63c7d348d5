#!/usr/bin/env python3
"""rbdc verify on the random robots of seeds FIRST..LAST (generator/rbdcgen/random_robot.py): even
seeds with a floating base, odd seeds with a fixed base, each group in one harness (one compile).
Usage: verify_random_robots.py FIRST LAST [SCENE] [--actuators | --massless | --extremes | --mimic]
                              [--floating-only] [--max-links N] [--states N] [--tolerance T]
  SCENE: a scene file, e.g. the derivatives one; --actuators: the random standalone topology files
  with geared rotors and armature (random_actuated_topology) instead of the random URDFs;
  --massless: random URDFs with massless bodies anywhere (a singular M leaves the functions that
  need M⁻¹ out, docs/model.md; the rest is verified); --extremes: masses over twelve decades and
  near-singular inertias; --mimic: mimic joints (coupled, as rbdc loads them by default);
  --floating-only: the even seeds alone (a scene of floating-base quantities, the OSC recursions);
  --max-links: the random URDFs' size bound (default 40); --states: states per robot (default 20);
  --tolerance: the relative tolerance (default 1e-10)."""
import argparse
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "generator"))
from rbdcgen.frontend.random_robot import random_actuated_topology, random_urdf  # noqa: E402


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("first", type=int)
    parser.add_argument("last", type=int)
    parser.add_argument("scene", nargs="?")
    kind = parser.add_mutually_exclusive_group()
    kind.add_argument("--actuators", action="store_true")
    kind.add_argument("--massless", action="store_true")
    kind.add_argument("--extremes", action="store_true")
    kind.add_argument("--mimic", action="store_true")
    parser.add_argument("--floating-only", action="store_true")
    parser.add_argument("--max-links", type=int, default=40)
    parser.add_argument("--states", default="20")
    parser.add_argument("--tolerance", default="1e-10")
    args = parser.parse_args()
    scene = ["--scene", args.scene] if args.scene else []
    failed = 0
    mimic_joints = 0
    with tempfile.TemporaryDirectory(prefix="rbdc-random-") as directory:
        for base, parity in (("floating", 0), ("fixed", 1))[:1 if args.floating_only else 2]:
            files = []
            for seed in range(args.first, args.last + 1):
                if seed % 2 == parity:
                    if args.actuators:
                        path = Path(directory) / f"random_actuated_{seed}.yaml"
                        path.write_text(random_actuated_topology(seed, base == "floating"))
                    else:
                        path = Path(directory) / f"random_{seed}.urdf"
                        text = random_urdf(seed, max_links=args.max_links, massless=args.massless,
                                           extremes=args.extremes, mimic=args.mimic)
                        mimic_joints += text.count("<mimic")
                        path.write_text(text)
                    files.append(str(path))
            start = time.monotonic()
            result = subprocess.run([str(ROOT / "rbdc"), "verify", *files, f"--{base}-base", "--states", args.states,
                                     "--tolerance", args.tolerance, *scene])
            print(f"{len(files)} random robots, {base} base: exit {result.returncode}, "
                  f"{time.monotonic() - start:.1f} s", flush=True)
            failed += result.returncode != 0
    if args.mimic and mimic_joints == 0:
        print("no mimic joint in these seeds: nothing coupled was verified", flush=True)
        failed += 1
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
