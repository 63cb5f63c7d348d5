"""Random robots for testing: URDF text for a seed, covering what the loader and generator must get
right. Branching trees, oblique and negative axes, rotated joint origins and inertial frames, fixed
joints (some to massless links, merged away), prismatic joints, 1 to 40 moving bodies; with
--massless also massless bodies anywhere (the base, inner bodies, leaves; without any inertia or with
a pure rotational one), so that some have a singular M (docs/model.md, "Singular mass matrix"); with
--extremes masses over twelve decades and near-singular inertias; with --mimic mimic joints; or,
with --actuators, a standalone topology file whose joints carry geared rotors and armature.

    python3 -m rbdcgen.random_robot SEED [-o FILE] [--massless | --extremes | --mimic |
                                              --actuators floating|fixed]
"""
import argparse
import math
import random
import sys

AXES = ((1, 0, 0), (0, 1, 0), (0, 0, 1), (-1, 0, 0), (0, -1, 0), (0, 0, -1))


def _numbers(values) -> str:
    return " ".join(repr(round(float(v), 12)) for v in values)


def _oblique_or_signed_axis(rng: random.Random):
    if rng.random() < 0.5:
        return rng.choice(AXES)
    while True:
        axis = [rng.uniform(-1, 1) for _ in range(3)]
        norm = math.sqrt(sum(a * a for a in axis))
        if norm > 0.2:
            return [a / norm for a in axis]


def _inertial(rng: random.Random, extremes: bool = False) -> str:
    """A body with mass, a shifted and rotated inertial frame and box-like (physical) inertia;
    `extremes`: the mass scaled by 1e-6..1e6 and, one time in three, a thin rod whose inertia about
    its axis is ~1e-8 of the others (near-singular)."""
    mass = rng.uniform(0.1, 5.0)
    x, y, z = (rng.uniform(0.02, 0.4) for _ in range(3))
    if extremes:
        mass *= 10.0 ** rng.uniform(-6.0, 6.0)
        if rng.random() < 1 / 3:
            x, y = 1e-4 * z, 1e-4 * z
    ixx, iyy, izz = mass / 12 * (y * y + z * z), mass / 12 * (x * x + z * z), mass / 12 * (x * x + y * y)
    com = [rng.uniform(-0.1, 0.1) for _ in range(3)]
    rpy = [rng.uniform(-math.pi, math.pi) for _ in range(3)]
    return (f'    <inertial>\n      <origin xyz="{_numbers(com)}" rpy="{_numbers(rpy)}"/>\n'
            f'      <mass value="{_numbers([mass])}"/>\n'
            f'      <inertia ixx="{_numbers([ixx])}" ixy="0" ixz="0" iyy="{_numbers([iyy])}" iyz="0" '
            f'izz="{_numbers([izz])}"/>\n    </inertial>\n')


def _massless_inertial(rng: random.Random) -> str:
    """A massless link: no inertial at all, or zero mass with a pure rotational inertia."""
    if rng.random() < 0.5:
        return ""
    moments = [rng.uniform(1e-4, 1e-2) for _ in range(3)]
    return (f'    <inertial>\n      <mass value="0"/>\n      <inertia ixx="{_numbers([moments[0]])}" ixy="0" '
            f'ixz="0" iyy="{_numbers([moments[1]])}" iyz="0" izz="{_numbers([moments[2]])}"/>\n    </inertial>\n')


def random_urdf(seed: int, max_links: int = 40, massless: bool = False, extremes: bool = False,
                mimic: bool = False) -> str:
    """URDF text of the random robot for `seed`: sizes mostly small, sometimes up to max_links;
    `massless`: about a third of the bodies, the base included, are massless (_massless_inertial);
    `extremes`: masses over twelve decades and near-singular inertias (_inertial); `mimic`: about a
    third of the moving joints after the first mimic an earlier independent one of the same type."""
    rng = random.Random(seed)
    n_links = rng.choice((rng.randint(1, 8), rng.randint(1, 16), rng.randint(1, max_links)))
    leaders = {"revolute": [], "continuous": [], "prismatic": []}

    def inertial():
        return _massless_inertial(rng) if massless and rng.random() < 0.35 else _inertial(rng, extremes)

    links = ['  <link name="base">\n' + inertial() + "  </link>\n"]
    joints = []
    for k in range(1, n_links + 1):
        # Mostly extend a recent link (chains), sometimes branch from any earlier one.
        parent = k - 1 if rng.random() < 0.6 else rng.randint(0, k - 1)
        parent_name = "base" if parent == 0 else f"link{parent}"
        # The first joint moves, so that even a fixed-base robot has a degree of freedom.
        kind = rng.choices(("revolute", "continuous", "prismatic", "fixed"), (5, 2, 2, 0 if k == 1 else 2))[0]
        # Without `massless`, only links on fixed joints may be massless: they merge into their
        # parent, while a massless moving leaf would make M singular.
        is_massless = kind == "fixed" and rng.random() < 0.5
        name = f"link{k}"
        links.append(f'  <link name="{name}">\n' + ("" if is_massless else inertial()) + "  </link>\n")
        xyz = [rng.uniform(-0.3, 0.3) for _ in range(3)]
        rpy = [rng.uniform(-math.pi, math.pi) if rng.random() < 0.7 else 0.0 for _ in range(3)]
        text = (f'  <joint name="joint{k}" type="{kind}">\n    <parent link="{parent_name}"/>\n'
                f'    <child link="{name}"/>\n    <origin xyz="{_numbers(xyz)}" rpy="{_numbers(rpy)}"/>\n')
        if kind != "fixed":
            text += f'    <axis xyz="{_numbers(_oblique_or_signed_axis(rng))}"/>\n'
        if kind == "revolute":
            lower = rng.uniform(-3.0, 0.0)
            text += f'    <limit lower="{_numbers([lower])}" upper="{_numbers([lower + rng.uniform(0.2, 3.0)])}" effort="50" velocity="10"/>\n'
        if kind == "prismatic":
            text += '    <limit lower="-0.2" upper="0.3" effort="100" velocity="1"/>\n'
        if mimic and kind != "fixed" and leaders[kind] and rng.random() < 1 / 3:
            text += (f'    <mimic joint="{rng.choice(leaders[kind])}" multiplier="{_numbers([rng.uniform(-2, 2)])}" '
                     f'offset="{_numbers([rng.uniform(-0.1, 0.1)])}"/>\n')
        elif kind != "fixed":
            leaders[kind].append(f"joint{k}")
        joints.append(text + "  </joint>\n")
    return (f'<?xml version="1.0"?>\n<!-- rbdc random robot, seed {seed} -->\n'
            f'<robot name="random_{seed}">\n' + "".join(links) + "".join(joints) + "</robot>\n")


def _unit(rng: random.Random):
    while True:
        v = [rng.uniform(-1, 1) for _ in range(3)]
        norm = math.sqrt(sum(x * x for x in v))
        if norm > 0.2:
            return [x / norm for x in v]


def _matrix(rows) -> str:
    return "[" + ", ".join("[" + ", ".join(repr(float(x)) for x in row) + "]" for row in rows) + "]"


def _rotated_inertia(rng: random.Random, moments):
    """R diag(moments) Rᵀ for a random rotation R (columns: an orthonormal frame)."""
    a = _unit(rng)
    b = _unit(rng)
    dot = sum(x * y for x, y in zip(a, b))
    b = [y - dot * x for x, y in zip(a, b)]
    norm = math.sqrt(sum(y * y for y in b)) or 1.0
    b = [y / norm for y in b]
    c = [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    frame = (a, b, c)
    return [[sum(frame[k][r] * moments[k] * frame[k][col] for k in range(3)) for col in range(3)]
            for r in range(3)]


def _actuator(rng: random.Random, joint: str) -> str:
    """A rotor (placement, orientation and spin axis random, inertia symmetric about the axis),
    an armature, both, or nothing, for joint `joint` (docs/model.md, "Actuators")."""
    kind = rng.choice(("rotor", "rotor", "armature", "both", "none"))
    if kind == "none":
        return ""
    entry = [f"joint: {joint}"]
    if kind in ("armature", "both"):
        entry.append(f"armature: {rng.uniform(0.0, 0.05)!r}")
    if kind in ("rotor", "both"):
        axis = _unit(rng)
        J = rng.uniform(1e-5, 1e-4)
        Jt = J * rng.uniform(0.5, 2.0)   # axisymmetric and within the triangle inequality
        inertia = [[J * axis[r] * axis[c] + Jt * ((1.0 if r == c else 0.0) - axis[r] * axis[c])
                    for c in range(3)] for r in range(3)]
        entry += [f"gear_ratio: {rng.uniform(1.0, 12.0)!r}", f"rotor_mass: {rng.uniform(0.0, 0.3)!r}",
                  f"xyz: [{_numbers(rng.uniform(-0.2, 0.2) for _ in range(3)).replace(' ', ', ')}]",
                  f"rpy: [{_numbers(rng.uniform(-math.pi, math.pi) for _ in range(3)).replace(' ', ', ')}]",
                  f"axis: [{', '.join(repr(x) for x in axis)}]", f"rotor_inertia: {_matrix(inertia)}"]
    return "  - {" + ", ".join(entry) + "}\n"


def random_actuated_topology(seed: int, floating_base: bool, max_links: int = 12) -> str:
    """A standalone topology file (docs/model.md) of a random tree for `seed`: revolute and prismatic
    joints with oblique axes and rotated origins, rotated inertias, a foot or two, and on its joints a
    random mix of geared rotors, armature, both and neither."""
    rng = random.Random(seed)
    n = rng.randint(1, max_links)
    bodies = ["base"] + [f"link{k}" for k in range(1, n + 1)]
    pred = [k - 1 if rng.random() < 0.6 else rng.randint(0, k - 1) for k in range(1, n + 1)]
    joints, inertias, actuators = [], [], []
    for k in range(1, n + 1):
        kind = "prismatic" if rng.random() < 0.2 else "revolute"
        axis = _oblique_or_signed_axis(rng)
        xyz = [rng.uniform(-0.3, 0.3) for _ in range(3)]
        rpy = [rng.uniform(-math.pi, math.pi) for _ in range(3)]
        joints.append(f"  - {{name: joint{k}, type: {kind}, axis: [{', '.join(repr(float(a)) for a in axis)}], "
                      f"xyz: [{_numbers(xyz).replace(' ', ', ')}], rpy: [{_numbers(rpy).replace(' ', ', ')}]}}\n")
        actuators.append(_actuator(rng, f"joint{k}"))
    for name in bodies:
        mass = rng.uniform(0.1, 5.0)
        x, y, z = (rng.uniform(0.02, 0.4) for _ in range(3))
        moments = (mass / 12 * (y * y + z * z), mass / 12 * (x * x + z * z), mass / 12 * (x * x + y * y))
        com = [rng.uniform(-0.1, 0.1) for _ in range(3)]
        inertias.append(f"  {name}: {{mass: {mass!r}, com: [{_numbers(com).replace(' ', ', ')}], "
                        f"inertia: {_matrix(_rotated_inertia(rng, moments))}}}\n")
    feet = [f"  - {{name: foot{f}, body: {rng.choice(bodies[1:])}, "
            f"offset: [{_numbers(rng.uniform(-0.2, 0.2) for _ in range(3)).replace(' ', ', ')}]}}\n"
            for f in range(rng.randint(1, 2))]
    text = (f"# rbdc random robot with actuators, seed {seed}\nname: random_actuated_{seed}\n"
            f"floating_base: {'true' if floating_base else 'false'}\ngravity: [0, 0, -9.81]\n"
            f"bodies: [{', '.join(bodies)}]\nPRED: {pred}\nSUCC: {list(range(1, n + 1))}\n"
            "joints:\n" + "".join(joints) + "inertias:\n" + "".join(inertias) + "feet:\n" + "".join(feet))
    if any(actuators):
        text += "actuators:\n" + "".join(actuators)
    return text


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python3 -m rbdcgen.random_robot", description=__doc__.split("\n\n")[0])
    parser.add_argument("seed", type=int)
    parser.add_argument("-o", "--output", help="write here instead of stdout")
    kind = parser.add_mutually_exclusive_group()
    kind.add_argument("--massless", action="store_true", help="massless bodies anywhere in the tree")
    kind.add_argument("--extremes", action="store_true", help="masses over 12 decades, near-singular inertias")
    kind.add_argument("--mimic", action="store_true", help="mimic joints")
    kind.add_argument("--actuators", choices=("floating", "fixed"),
                      help="a standalone topology YAML with rotors and armature, this base")
    args = parser.parse_args(argv)
    text = (random_actuated_topology(args.seed, args.actuators == "floating") if args.actuators
            else random_urdf(args.seed, massless=args.massless, extremes=args.extremes, mimic=args.mimic))
    if args.output:
        with open(args.output, "w", encoding="utf-8") as handle:
            handle.write(text)
    else:
        sys.stdout.write(text)
    return 0


if __name__ == "__main__":
    sys.exit(main())
