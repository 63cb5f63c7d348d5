"""Back end for rbdc.compile: the C++ source of a Python extension module with one numpy function per
generated function, rendered from the same traced Function table as the headers (templates/
python_module.cpp.j2). The numpy boundary itself is python/rbdc/native/rbdc_py/batch_call.hpp."""
from .layout import Layout
from .names import cpp_identifier
from .render import BATCH_HEADER, GeneratedFile, input_records, template_environment
from .version import VERSION

QUATERNION_W = 3  # q = (p, quaternion w x y z, joints) for a floating base (docs/conventions.md)
# Lanes per call of the Pack kernels (rbdc_gen::Batch<T>: one AVX-512 register, two AVX2 ones).
PACK_LANES = {"double": 8, "float": 16}


def _shape_text(argument, is_input: bool) -> str:
    if argument.cols != 1:
        return f"({argument.rows}, {argument.cols})"
    return "()" if is_input and argument.rows == 1 else f"({argument.rows},)"


def _batch_shape_text(argument, is_input: bool) -> str:
    one = _shape_text(argument, is_input)
    return "(N)" if one == "()" else "(N, " + one[1:].rstrip(",)") + ")"


def docstring(function) -> str:
    """The Python docstring: call form, what it computes, every argument with its shapes."""
    names = [a.name for a in function.inputs]
    results = ", ".join(a.name for a in function.outputs)
    lines = [f"{function.name}({', '.join(names)}, *, out=None, threads=0) -> {results}", "",
             function.doc, "", "Arguments (one state, or a batch of N states; float64 or float32):"]
    lines += [f"  {a.name}: {_shape_text(a, True)} or {_batch_shape_text(a, True)}, {a.doc}" for a in function.inputs]
    lines += ["  out: optional preallocated output" + ("s (a tuple, in the order below)" if len(function.outputs) > 1 else ""),
              "  threads: threads for a batch (0: as many as the batch and the cores allow)", "Returns:"]
    lines += [f"  {a.name}: {_shape_text(a, False)} or {_batch_shape_text(a, False)}, {a.doc}" for a in function.outputs]
    return "\n".join(lines)


def _function_record(function, robot) -> dict:
    def argument(a, is_input):
        quaternion = QUATERNION_W if is_input and a.name == "q" and robot.floating_base else -1
        return {"name": a.name, "rows": a.rows, "cols": a.cols, "quaternion": quaternion}
    # Lane functions keep their own SIMD layout inside one state: they run state by state.
    lanes = 1 if function.lanes is not None else None
    return {"name": function.name, "docstring": docstring(function),
            "inputs": [argument(a, True) for a in function.inputs],
            "outputs": [argument(a, False) for a in function.outputs],
            "zero_outputs": any(e is None for a in function.outputs for e in function.values[a.name]),
            "lanes_double": lanes or PACK_LANES["double"], "lanes_float": lanes or PACK_LANES["float"]}


def render_python_module(compilation, layout: Layout, module_name: str) -> GeneratedFile:
    """`<module_name>.cpp`, to compile against the files of pipeline.render(compilation) and
    python/rbdc/native."""
    c = compilation
    robot_id, scene_id = c.robot_name, cpp_identifier(c.scene.name)
    text = template_environment(layout).get_template("python_module.cpp.j2").render(
        generator_version=VERSION, inputs=input_records(c.inputs, layout), scene_name=c.scene.name,
        module_name=module_name, umbrella_include=f"{robot_id}/{scene_id}.hpp", batch_include=BATCH_HEADER,
        namespace=f"rbdc_gen::{robot_id}::{scene_id}",
        robot={"name": robot_id, "floating_base": c.robot.floating_base},
        functions=[_function_record(f, c.robot) for f in c.functions])
    return GeneratedFile(f"{module_name}.cpp", text)
