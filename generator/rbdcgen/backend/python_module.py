"""Back end for rbdc.compile: the C++ source of a Python extension module with one numpy function per
generated function, rendered from the same traced Function table as the headers (templates/
python_module.cpp.j2). The numpy boundary itself is python/rbdc/native/rbdc_py/batch_call.hpp."""
from ..frontend.layout import Layout
from ..graph.flops import count_ops
from ..version import VERSION
from .names import cpp_identifier
from .render import ALIASES, BATCH_HEADER, GeneratedFile, eigen_type, input_records, template_environment

QUATERNION_W = 3  # q = (p, quaternion w x y z, joints) for a floating base (docs/conventions.md)
# Lanes per call of the Pack kernels: rbdc_gen::Batch<T>, one register of the target the module is
# compiled for.
PACK_LANES = {"double": "rbdc_gen::Batch<double>::lanes", "float": "rbdc_gen::Batch<float>::lanes"}


# Aliases that are matrices whatever their size (FeetMatrix of one foot is 3 x 1).
MATRIX_ALIASES = {f"{name}<Scalar>" for name, _, cols, _ in ALIASES if cols != "1"}


def _shape_text(argument, is_input: bool, matrix: bool) -> str:
    if argument.cols != 1 or matrix:
        return f"({argument.rows}, {argument.cols})"
    return "()" if is_input and argument.rows == 1 else f"({argument.rows},)"


def _batch_shape_text(argument, is_input: bool, matrix: bool) -> str:
    one = _shape_text(argument, is_input, matrix)
    return "(N)" if one == "()" else "(N, " + one[1:].rstrip(",)") + ")"


def docstring(function, is_matrix) -> str:
    """The Python docstring: call form, what it computes, every argument with its shapes."""
    names = [a.name for a in function.inputs]
    results = ", ".join(a.name for a in function.outputs)
    lines = [f"{function.name}({', '.join(names)}, *, out=None, threads=0) -> {results}", "",
             function.doc, "", "Arguments (one state, or a batch of N states; float64 or float32):"]
    lines += [f"  {a.name}: {_shape_text(a, True, is_matrix(a))} or {_batch_shape_text(a, True, is_matrix(a))}, {a.doc}"
              for a in function.inputs]
    lines += ["  out: optional preallocated output" + ("s (a tuple, in the order below)" if len(function.outputs) > 1 else ""),
              "  threads: threads for a batch (0: as many as the batch and the cores allow)", "Returns:"]
    lines += [f"  {a.name}: {_shape_text(a, False, is_matrix(a))} or {_batch_shape_text(a, False, is_matrix(a))}, {a.doc}"
              for a in function.outputs]
    return "\n".join(lines)


def _function_record(function, robot, scene, float32: bool) -> dict:
    def is_matrix(a):
        return a.cols != 1 or eigen_type(a, robot, scene) in MATRIX_ALIASES

    def argument(a, is_input):
        quaternion = QUATERNION_W if is_input and a.name == "q" and robot.floating_base else -1
        return {"name": a.name, "rows": a.rows, "cols": a.cols, "quaternion": quaternion,
                "matrix": "true" if is_matrix(a) else "false"}
    # Lane functions keep their own SIMD layout inside one state: they run state by state.
    lanes = 1 if function.lanes is not None else None
    return {"name": function.name, "docstring": docstring(function, is_matrix),
            "inputs": [argument(a, True) for a in function.inputs],
            "outputs": [argument(a, False) for a in function.outputs],
            "zero_outputs": any(e is None for a in function.outputs for e in function.values.get(a.name, ())),
            "lanes_double": lanes or PACK_LANES["double"], "lanes_float": (lanes or PACK_LANES["float"]) if float32 else 0}


def render_python_module(compilation, layout: Layout, module_name: str, float32: bool = False) -> list[GeneratedFile]:
    """The module's sources, to compile against the files of pipeline.render(compilation) and
    python/rbdc/native: `<module_name>.cpp` (the module) first, then `<module_name>_<function>.cpp`
    for each function (one translation unit each, so that they compile in parallel), most operations
    first: started longest first, a parallel build ends with short compiles, not one long one.
    `float32`: each function also instantiated in float (else float32 inputs run in double)."""
    c = compilation
    robot_id, scene_id = c.robot_name, cpp_identifier(c.scene.name)
    environment = template_environment(layout)
    common = {"generator_version": VERSION, "inputs": input_records(c.inputs, layout), "scene_name": c.scene.name,
              "namespace": f"rbdc_gen::{robot_id}::{scene_id}"}
    records = [_function_record(f, c.robot, c.scene, float32) for f in c.functions]
    costs = {f.name: count_ops(f)["total"] for f in c.functions}
    module = environment.get_template("python_module.cpp.j2").render(
        **common, module_name=module_name, umbrella_include=f"{robot_id}/{scene_id}.hpp",
        robot={"name": robot_id, "floating_base": c.robot.floating_base}, functions=records)
    function_template = environment.get_template("python_function.cpp.j2")
    return [GeneratedFile(f"{module_name}.cpp", module)] + [
        GeneratedFile(f"{module_name}_{r['name']}.cpp", function_template.render(
            **common, batch_include=BATCH_HEADER, function={**r, "include": f"{robot_id}/{scene_id}/{r['name']}.hpp"}))
        for r in sorted(records, key=lambda r: -costs[r["name"]])]
