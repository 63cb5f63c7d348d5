#!/usr/bin/python3
"""Writes robots/humanoid32.urdf: rbdc's own 32-DoF floating-base humanoid for the benchmarks.

The robot is authored here (no public model is copied): a pelvis, two 6-DoF legs, a 3-DoF waist, a
torso, a 3-DoF neck and two 7-DoF arms. Every link is a solid box whose inertia follows from its
mass and size, so the numbers are physically consistent. Each sole carries a foot point (a massless
link on a fixed joint, named *_foot); by the loader's default (one foot per leaf body, docs/model.md)
the hands and the head are contact points too, so the robot has 5 feet: a multi-contact benchmark.
The output is byte-stable: run it again and diff.

Usage: tools/make_humanoid.py [OUTPUT_DIR]   (default: robots/ next to this script's folder)
"""
import pathlib
import sys
import xml.etree.ElementTree as ET

LEFT, RIGHT = 1.0, -1.0


def number(x):
    """Short, exact-enough decimal text for URDF attributes (no -0)."""
    text = f"{x:.9g}"
    return "0" if text in ("-0", "0") else text


def triple(v):
    return " ".join(number(x) for x in v)


class Urdf:
    """Builds the XML tree link by link; joints are added in the order they are declared."""

    def __init__(self, name):
        self.robot = ET.Element("robot", name=name)

    def box_link(self, name, mass, size, com):
        """A link whose inertia is that of a solid box of `size` (x, y, z) centred at `com`."""
        link = ET.SubElement(self.robot, "link", name=name)
        inertial = ET.SubElement(link, "inertial")
        ET.SubElement(inertial, "origin", xyz=triple(com), rpy="0 0 0")
        ET.SubElement(inertial, "mass", value=number(mass))
        a, b, c = size
        ET.SubElement(inertial, "inertia",
                      ixx=number(mass * (b * b + c * c) / 12), ixy="0", ixz="0",
                      iyy=number(mass * (a * a + c * c) / 12), iyz="0",
                      izz=number(mass * (a * a + b * b) / 12))

    def revolute(self, name, parent, child, xyz, axis, limit, rpy=(0, 0, 0)):
        joint = ET.SubElement(self.robot, "joint", name=name, type="revolute")
        ET.SubElement(joint, "parent", link=parent)
        ET.SubElement(joint, "child", link=child)
        ET.SubElement(joint, "origin", xyz=triple(xyz), rpy=triple(rpy))
        ET.SubElement(joint, "axis", xyz=triple(axis))
        ET.SubElement(joint, "limit", lower=number(-limit), upper=number(limit),
                      effort="300", velocity="20")

    def foot(self, name, parent, xyz):
        """A contact point: a massless link on a fixed joint (merged into `parent` by the loader)."""
        ET.SubElement(self.robot, "link", name=name)
        joint = ET.SubElement(self.robot, "joint", name=name + "_joint", type="fixed")
        ET.SubElement(joint, "parent", link=parent)
        ET.SubElement(joint, "child", link=name)
        ET.SubElement(joint, "origin", xyz=triple(xyz), rpy="0 0 0")

    def text(self):
        ET.indent(self.robot, space="  ")
        return '<?xml version="1.0"?>\n' + ET.tostring(self.robot, encoding="unicode") + "\n"


def add_leg(urdf, prefix, side):
    """Hip yaw-roll-pitch, knee, ankle pitch-roll (6 DoF); the sole point is the foot."""
    urdf.box_link(f"{prefix}_hip_yaw_link", 1.1, (0.08, 0.08, 0.06), (0, 0, -0.03))
    urdf.revolute(f"{prefix}_hip_yaw", "pelvis", f"{prefix}_hip_yaw_link",
                  (0, side * 0.09, -0.07), (0, 0, 1), 0.8)
    urdf.box_link(f"{prefix}_hip_roll_link", 1.3, (0.1, 0.08, 0.08), (0, 0, -0.02))
    urdf.revolute(f"{prefix}_hip_roll", f"{prefix}_hip_yaw_link", f"{prefix}_hip_roll_link",
                  (0, 0, -0.06), (1, 0, 0), 0.6)
    urdf.box_link(f"{prefix}_thigh", 5.2, (0.11, 0.1, 0.38), (0, side * 0.01, -0.18))
    urdf.revolute(f"{prefix}_hip_pitch", f"{prefix}_hip_roll_link", f"{prefix}_thigh",
                  (0, 0, 0), (0, 1, 0), 2.0)
    urdf.box_link(f"{prefix}_shank", 3.1, (0.09, 0.09, 0.36), (0, 0, -0.17))
    urdf.revolute(f"{prefix}_knee", f"{prefix}_thigh", f"{prefix}_shank",
                  (0, 0, -0.4), (0, 1, 0), 2.4)
    urdf.box_link(f"{prefix}_ankle_link", 0.45, (0.05, 0.05, 0.05), (0, 0, 0))
    urdf.revolute(f"{prefix}_ankle_pitch", f"{prefix}_shank", f"{prefix}_ankle_link",
                  (0, 0, -0.38), (0, 1, 0), 1.0)
    urdf.box_link(f"{prefix}_sole", 1.0, (0.22, 0.1, 0.04), (0.03, 0, -0.05))
    urdf.revolute(f"{prefix}_ankle_roll", f"{prefix}_ankle_link", f"{prefix}_sole",
                  (0, 0, 0), (1, 0, 0), 0.5)
    urdf.foot(f"{prefix}_foot", f"{prefix}_sole", (0.03, 0, -0.07))


def add_arm(urdf, prefix, side):
    """Shoulder pitch-roll-yaw, elbow, wrist yaw-pitch-roll (7 DoF); the shoulder is tilted 0.2 rad."""
    urdf.box_link(f"{prefix}_shoulder_pitch_link", 0.9, (0.07, 0.07, 0.07), (0, side * 0.02, 0))
    urdf.revolute(f"{prefix}_shoulder_pitch", "torso", f"{prefix}_shoulder_pitch_link",
                  (0, side * 0.21, 0.36), (0, 1, 0), 3.0, rpy=(side * 0.2, 0, 0))
    urdf.box_link(f"{prefix}_shoulder_roll_link", 0.8, (0.07, 0.07, 0.07), (0, 0, -0.02))
    urdf.revolute(f"{prefix}_shoulder_roll", f"{prefix}_shoulder_pitch_link",
                  f"{prefix}_shoulder_roll_link", (0, side * 0.05, 0), (1, 0, 0), 1.6)
    urdf.box_link(f"{prefix}_upper_arm", 2.1, (0.08, 0.08, 0.28), (0, 0, -0.13))
    urdf.revolute(f"{prefix}_shoulder_yaw", f"{prefix}_shoulder_roll_link", f"{prefix}_upper_arm",
                  (0, 0, -0.03), (0, 0, 1), 1.6)
    urdf.box_link(f"{prefix}_forearm", 1.2, (0.07, 0.07, 0.25), (0, 0, -0.11))
    urdf.revolute(f"{prefix}_elbow", f"{prefix}_upper_arm", f"{prefix}_forearm",
                  (0, 0, -0.28), (0, 1, 0), 2.3)
    urdf.box_link(f"{prefix}_wrist_yaw_link", 0.35, (0.05, 0.05, 0.05), (0, 0, -0.01))
    urdf.revolute(f"{prefix}_wrist_yaw", f"{prefix}_forearm", f"{prefix}_wrist_yaw_link",
                  (0, 0, -0.25), (0, 0, 1), 2.0)
    urdf.box_link(f"{prefix}_wrist_pitch_link", 0.3, (0.05, 0.05, 0.05), (0, 0, 0))
    urdf.revolute(f"{prefix}_wrist_pitch", f"{prefix}_wrist_yaw_link",
                  f"{prefix}_wrist_pitch_link", (0, 0, -0.03), (0, 1, 0), 1.2)
    urdf.box_link(f"{prefix}_hand", 0.5, (0.04, 0.09, 0.12), (0, 0, -0.07))
    urdf.revolute(f"{prefix}_wrist_roll", f"{prefix}_wrist_pitch_link", f"{prefix}_hand",
                  (0, 0, 0), (1, 0, 0), 1.2)


def humanoid():
    urdf = Urdf("humanoid32")
    urdf.box_link("pelvis", 8.0, (0.2, 0.3, 0.15), (0, 0, 0))
    add_leg(urdf, "l", LEFT)
    add_leg(urdf, "r", RIGHT)
    # Waist yaw-pitch-roll between pelvis and torso.
    urdf.box_link("waist_yaw_link", 1.4, (0.1, 0.1, 0.06), (0, 0, 0.02))
    urdf.revolute("waist_yaw", "pelvis", "waist_yaw_link", (0, 0, 0.1), (0, 0, 1), 1.0)
    urdf.box_link("waist_pitch_link", 1.2, (0.1, 0.1, 0.06), (0, 0, 0.01))
    urdf.revolute("waist_pitch", "waist_yaw_link", "waist_pitch_link", (0, 0, 0.05), (0, 1, 0), 0.7)
    urdf.box_link("torso", 16.0, (0.22, 0.36, 0.42), (0.01, 0, 0.2))
    urdf.revolute("waist_roll", "waist_pitch_link", "torso", (0, 0, 0), (1, 0, 0), 0.5)
    # Neck yaw-pitch-roll carrying the head.
    urdf.box_link("neck_yaw_link", 0.3, (0.05, 0.05, 0.05), (0, 0, 0.01))
    urdf.revolute("neck_yaw", "torso", "neck_yaw_link", (0, 0, 0.44), (0, 0, 1), 1.4)
    urdf.box_link("neck_pitch_link", 0.25, (0.05, 0.05, 0.05), (0, 0, 0))
    urdf.revolute("neck_pitch", "neck_yaw_link", "neck_pitch_link", (0, 0, 0.04), (0, 1, 0), 0.8)
    urdf.box_link("head", 3.2, (0.2, 0.17, 0.22), (0.02, 0, 0.1))
    urdf.revolute("neck_roll", "neck_pitch_link", "head", (0, 0, 0), (1, 0, 0), 0.5)
    add_arm(urdf, "l", LEFT)
    add_arm(urdf, "r", RIGHT)
    return urdf


def main(argv):
    default = pathlib.Path(__file__).resolve().parent.parent / "robots"
    output = pathlib.Path(argv[1]) if len(argv) > 1 else default
    urdf = humanoid()
    (output / "humanoid32.urdf").write_text(urdf.text())
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
