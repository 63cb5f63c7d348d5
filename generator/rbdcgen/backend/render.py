"""Back end: renders one robot and scene into header files through the Jinja2 templates.

Templates see only plain data built here (names, dimensions, C++ statement lists, op counts); the
file layout, banner, namespaces, types and signatures live in templates/. Output is byte-stable:
no timestamps, sorted inputs, the input files' sha256 in the banner.

A function's body goes into <robot>/common/<function>_<hash>.hpp, named by a hash of everything the
file holds, so scenes whose function is the same code (feet_jacobian in full, kinematics_only and
stance_osc) share one file; each scene's <robot>/<scene>/<function>.hpp brings it into the scene's
namespace with a using-declaration and adds the Eigen overload (docs/generated_api.md).
"""
import hashlib
import json
import re
from dataclasses import dataclass, replace
from pathlib import Path

import jinja2

from .blocks import MAX_STATEMENTS, split
from .emit import emit_body
from ..errors import RbdcError
from ..graph.flops import KINDS, count_ops
from ..frontend.layout import Layout, display_path
from .names import cpp_identifier, unique_identifiers
from ..version import VERSION

SUPPORT_HEADER = "rbdc_gen/support.hpp"
COMMON_DIR = "common"  # <robot>/common/: function bodies shared by the robot's scenes
BATCH_HEADER = "rbdc_gen/batch.hpp"  # SIMD packs of states (docs/performance.md)
LANES_HEADER = "rbdc_gen/lanes.hpp"  # one SIMD lane per limb, for the lane functions only
# The loops' library headers (a looped form's `solve.headers`), each rendered from its template where
# some function of the scene includes it: looped solves, factors and M⁻¹'s rows, the tree loops' shared ground,
# the CRBA, the RNEA's derivatives and the operational-space columns as loops, the low-rank ∂q̈.
LOOP_HEADERS = {"rbdc_gen/solve.hpp": "solve.hpp.j2", "rbdc_gen/factor.hpp": "factor.hpp.j2",
                "rbdc_gen/body_tree.hpp": "body_tree.hpp.j2",
                "rbdc_gen/crba.hpp": "crba.hpp.j2", "rbdc_gen/rnea_derivatives.hpp": "rnea_derivatives.hpp.j2",
                "rbdc_gen/osc.hpp": "osc.hpp.j2", "rbdc_gen/low_rank.hpp": "low_rank.hpp.j2",
                "rbdc_gen/articulated_inverse.hpp": "articulated_inverse.hpp.j2"}

# The Eigen type aliases of docs/generated_api.md: name, rows, cols (as C++ expressions), doc.
ALIASES = (
    ("ConfigVector", "nq", "1", "q"),
    ("TangentVector", "nv", "1", "v, a, c, g, τ"),
    ("JointVector", "n_joints", "1", "joint torques"),
    ("MassMatrix", "nv", "nv", "M, full symmetric"),
    ("FeetMatrix", "3", "n_feet", "one column per foot, world frame"),
    ("FeetJacobian", "3 * n_feet", "nv", "stacked 3 x nv foot Jacobians"),
    ("OscInertia", "6", "6", "operational-space inertia Λ"),
    ("OscJacobianT", "6", "n_joints", "dynamically consistent inverse transposed, J̄ᵀ"),
    ("Wrench", "6", "1", "(moment; force)"),
)
# Arguments whose alias is fixed by their name (dimensions alone are ambiguous for a fixed base).
ALIAS_BY_NAME = {"q": "ConfigVector"}


@dataclass(frozen=True)
class GeneratedFile:
    path: str      # relative to the output directory, '/'-separated
    text: str


def template_environment(layout: Layout) -> jinja2.Environment:
    return jinja2.Environment(loader=jinja2.FileSystemLoader(str(layout.templates)),
                              undefined=jinja2.StrictUndefined, trim_blocks=True,
                              lstrip_blocks=True, keep_trailing_newline=True, autoescape=False)


def sha256_of(path: Path) -> str:
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


def input_records(inputs, layout: Layout) -> list[dict]:
    return [{"path": display_path(p, layout), "sha256": sha256_of(p)} for p in inputs]


def _alias_shapes(robot, scene) -> dict[str, tuple[int, int]]:
    """The numeric shape of every alias in ALIASES, for this robot and scene."""
    dims = {"nq": robot.nq, "nv": robot.nv, "n_joints": robot.n_joints, "n_feet": len(scene.feet_for(robot))}

    def value(expression: str) -> int:  # "nv", "6" or "3 * n_feet"
        factors = [dims[f.strip()] if f.strip() in dims else int(f) for f in expression.split("*")]  # n_feet may be 0
        return factors[0] * (factors[1] if len(factors) > 1 else 1)

    return {name: (value(rows), value(cols)) for name, rows, cols, _ in ALIASES}


def eigen_type(argument, robot, scene) -> str:
    """The Eigen type of an argument: its alias by shape (the name decides where the shape cannot:
    q of a fixed base has the shape of v), else a plain fixed-size matrix."""
    shapes = _alias_shapes(robot, scene)
    shape = (argument.rows, argument.cols)
    preferred = ALIAS_BY_NAME.get(argument.name)
    if preferred and shapes[preferred] == shape:
        return f"{preferred}<Scalar>"
    for name, *_ in ALIASES:
        if shapes[name] == shape and name not in ALIAS_BY_NAME.values():
            return f"{name}<Scalar>"
    return f"Eigen::Matrix<Scalar, {argument.rows}, {argument.cols}>"


def _argument_record(argument, is_input: bool, robot, scene) -> dict:
    return {"name": argument.name, "rows": argument.rows, "cols": argument.cols, "doc": argument.doc,
            "is_input": is_input, "is_scalar": is_input and argument.rows == 1 and argument.cols == 1,
            "eigen_type": eigen_type(argument, robot, scene)}


def _unused_inputs(arguments, body: list[str]) -> list[str]:
    text = "\n".join(body)
    return [a["name"] for a in arguments if a["is_input"] and not re.search(rf"\b{a['name']}\b", text)]


def angle_names(robot) -> dict:
    """Each joint angle's input symbol ("q", k) → the joint's identifier (as in `enum class Joint`)."""
    joint_ids = unique_identifiers([j.name for j in robot.joints])
    return {("q", j.q_index): joint_ids[i] for i, j in enumerate(robot.joints) if i > 0}


def ops_table(ops: dict) -> list[str]:
    """The operation counts as a two-line table with aligned columns."""
    widths = [max(len(k), len(str(ops[k]))) for k in KINDS + ("total",)]
    header = "".join(f"  {k:>{w}}" for k, w in zip(KINDS + ("total",), widths))
    values = "".join(f"  {ops[k]:>{w}}" for k, w in zip(KINDS + ("total",), widths))
    return [f"operations{header}", f"{'':10}{values}"]


def _straight_line(function, arguments: list[dict], robot) -> dict:
    """The emitted code of `function`: its body, cut into blocks when it is long."""
    body = emit_body(function, angle_names(robot))
    # An input the scene made irrelevant is still part of the signature; say so to the compiler.
    body = [f"static_cast<void>({name});" for name in _unused_inputs(arguments, body)] + body
    code = {"body": body}
    blocks = split(body, [a["name"] for a in arguments], function.name)
    if blocks is not None:
        code.update(body=blocks.main, parts=blocks.parts, emission=(
            "%d blocks of at most %d statements (%d values passed in scratch), each a function of its own: "
            "one straight-line function of %d statements would compile in time growing faster than its "
            "length" % (len(blocks.parts), MAX_STATEMENTS, blocks.scratch_size, len(body))))
    return code


def _looped_solve(function, arguments: list[dict], robot) -> dict:
    """The code of a function in looped-solve form (passes/looped_solve.py): a helper `<name>_terms`,
    straight-line code writing the right-hand sides and the factor into local arrays, then the loop
    that solves them and the copies of the solved columns into the outputs."""
    solve = function.solve
    terms_arguments = [a for a in arguments if a["is_input"]] + [
        {"name": t.name, "rows": t.rows, "cols": t.cols, "doc": t.doc, "is_input": False} for t in solve.terms]
    unread = getattr(solve, "unread", None)  # LoopedSolve: the columns the low-rank form leaves
    terms = replace(function, name=function.name + "_terms", outputs=solve.terms, solve=None,
                    unread=tuple((t.name, unread(t.name)) for t in solve.terms) if unread else ())
    helper = {"name": terms.name, "arguments": terms_arguments,
              "doc": f"The traced part of {function.name}: what the loop below solves.",
              **_straight_line(terms, terms_arguments, robot)}
    local = {t.name: f"solve_{t.name}" for t in solve.terms}
    body = [f"alignas(64) Scalar {local[t.name]}[{t.size}];" for t in solve.terms]  # rows start on a cache line
    body.append("%s(%s);" % (terms.name, ", ".join(local.get(a["name"], a["name"]) for a in terms_arguments)))
    body += solve.loops()
    emission = solve.emission(terms.name)
    return {"body": body, "helpers": [helper], "emission": emission}


def body_record(function, arguments: list[dict], robot, robot_id: str, robot_inputs: list[dict]) -> dict:
    """The scene-independent part of a function: signature, body, counts. `key` and the file name
    come from a hash of all of it, so equal functions of different scenes are one file."""
    code = (_looped_solve if function.solve is not None else _straight_line)(function, arguments, robot)
    record = {"name": function.name, "doc": function.doc, **code, "robot": robot_id,
              "arguments": [{k: a[k] for k in ("name", "rows", "cols", "doc", "is_input")} for a in arguments],
              "ops_table": ops_table(count_ops(function)), "inputs": robot_inputs,
              "generator_version": VERSION}
    if function.lanes is not None:
        record["lanes"] = True  # the body includes LANES_HEADER
    if function.solve is not None:  # the body includes the loops' headers
        record["loop_headers"] = list(function.solve.headers)
    if function.schedule:
        record["schedule"] = function.schedule  # the view passes/schedule.py chose, and why
    digest = hashlib.sha256(json.dumps(record, sort_keys=True).encode()).hexdigest()
    key = f"{function.name}_{digest[:12]}"
    return {**record, "key": key, "include": f"{robot_id}/{COMMON_DIR}/{key}.hpp",
            "namespace": f"rbdc_gen::{robot_id}::{COMMON_DIR}::{key}"}


def function_record(function, robot, scene, robot_id: str, scene_id: str, robot_inputs: list[dict]) -> dict:
    arguments = [_argument_record(a, True, robot, scene) for a in function.inputs] + \
                [_argument_record(a, False, robot, scene) for a in function.outputs]
    return {"name": function.name, "doc": function.doc, "arguments": arguments,
            "body": body_record(function, arguments, robot, robot_id, robot_inputs),
            "include": f"{robot_id}/{scene_id}/{function.name}.hpp"}


def robot_record(robot, feet, robot_id: str) -> dict:
    """Names and numbering for the umbrella header; `feet` are the feet the scene keeps."""
    body_ids = unique_identifiers([b.name for b in robot.bodies])
    joint_ids = unique_identifiers([j.name for j in robot.joints])
    foot_ids = unique_identifiers([f.name for f in feet])
    return {
        "name": robot_id, "floating_base": robot.floating_base, "nq": robot.nq, "nv": robot.nv,
        "nb": robot.nb, "n_joints": robot.n_joints, "n_feet": len(feet),
        "bodies": [{"id": body_ids[i], "index": i, "name": b.name} for i, b in enumerate(robot.bodies)],
        "joints": [{"id": joint_ids[i], "index": i, "name": j.name, "type": j.type,
                    "q_index": j.q_index, "v_index": j.v_index} for i, j in enumerate(robot.joints)],
        "feet": [{"id": foot_ids[k], "index": k, "body": body_ids[f.body],
                  "offset": [repr(float(x)) for x in f.offset]} for k, f in enumerate(feet)],
    }


def _gravity_text(scene, robot) -> str:
    return "(" + ", ".join(repr(float(g)) for g in scene.gravity_for(robot)) + ")"


def render_robot_scene(robot, scene, functions, robot_name: str, inputs, layout: Layout,
                       robot_inputs=None) -> list[GeneratedFile]:
    """All files for one robot and scene: the support headers, the umbrella, one per function and
    one shared body per function. `inputs` name every input file, `robot_inputs` those of the robot
    alone (the bodies' banner; default: all)."""
    environment = template_environment(layout)
    robot_id, scene_id = cpp_identifier(robot_name), cpp_identifier(scene.name)
    if scene_id == COMMON_DIR:
        raise RbdcError(f"{scene.source}: name: '{COMMON_DIR}' is reserved for the shared function bodies")
    robot_inputs = input_records(inputs if robot_inputs is None else robot_inputs, layout)
    umbrella = f"{robot_id}/{scene_id}.hpp"
    common = {"generator_version": VERSION, "inputs": input_records(inputs, layout),
              "scene_name": scene.name, "scene_gravity": _gravity_text(scene, robot),
              "robot": robot_record(robot, scene.feet_for(robot), robot_id), "namespace": f"rbdc_gen::{robot_id}::{scene_id}",
              "umbrella_include": umbrella,
              "aliases": [{"name": n, "rows": r, "cols": c, "doc": d} for n, r, c, d in ALIASES]}
    records = [function_record(f, robot, scene, robot_id, scene_id, robot_inputs) for f in functions]
    lane_files = [lanes_file(layout)] if any(f.lanes is not None for f in functions) else []
    loop_headers = {h for f in functions if f.solve is not None for h in f.solve.headers}
    loop_files = [_library_file(layout, template, path) for path, template in LOOP_HEADERS.items() if path in loop_headers]
    files = [support_file(layout), batch_file(layout), *lane_files, *loop_files,
             GeneratedFile(umbrella, environment.get_template("robot_scene.hpp.j2").render(
                 **common, functions=records))]
    function_template = environment.get_template("function.hpp.j2")
    files += [GeneratedFile(r["include"], function_template.render(**common, function=r)) for r in records]
    body_template = environment.get_template("function_body.hpp.j2")
    files += [GeneratedFile(r["body"]["include"], body_template.render(
        generator_version=VERSION, inputs=robot_inputs, function=r["body"])) for r in records]
    return files


def _library_file(layout: Layout, template: str, path: str) -> GeneratedFile:
    text = template_environment(layout).get_template(template).render(generator_version=VERSION, inputs=[])
    return GeneratedFile(path, text)


def support_file(layout: Layout) -> GeneratedFile:
    return _library_file(layout, "support.hpp.j2", SUPPORT_HEADER)


def batch_file(layout: Layout) -> GeneratedFile:
    return _library_file(layout, "batch.hpp.j2", BATCH_HEADER)


def lanes_file(layout: Layout) -> GeneratedFile:
    return _library_file(layout, "lanes.hpp.j2", LANES_HEADER)

