"""Operation counts of a compilation, generated vs generic, as a readable table or as JSON, with the
generated code's critical path (graph/latency.py: the cycles no schedule of it can beat in one call).
A derivative quantity is also compared with its primal function (derivatives.PRIMAL, traced for the
same robot and scene, on the tree trace_scene traces: passes/schedule.traced_tree): the targets of issue 12 are
ratios to one primal call."""
from ..passes.differentiate import PRIMAL
from ..graph.flops import count_ops, generic_ops
from ..graph.latency import critical_path
from ..passes.trace import trace_function
from ..passes.schedule import beside_sines, traced_tree

KINDS = ("mul", "add", "div", "sqrt", "trig", "neg", "total")


def rows(compilation) -> list[dict]:
    result = []
    primal_counts = {}
    traced = traced_tree(compilation.robot)
    for f in compilation.functions:
        row = {"function": f.name, "generated": count_ops(f), "critical_path": critical_path(f),
               "beside_sines": beside_sines(f), "looped": f.solve is not None,
               "generic": generic_ops(compilation.robot, compilation.scene, f.computes)}
        if f.name in PRIMAL:
            name = PRIMAL[f.name]
            if name not in primal_counts:
                primal_counts[name] = count_ops(trace_function(traced, compilation.scene, name))
            row["primal"] = {"function": name, "ops": primal_counts[name]}
        result.append(row)
    return result


def as_json(compilation, table_rows) -> dict:
    def entry(r):
        out = {"generated": {k: r["generated"][k] for k in KINDS},
               "generic": {k: r["generic"][k] for k in KINDS},
               "critical_path": {"cycles": r["critical_path"], "traced_part_only": r["looped"],
                                 "beside_sines": r["beside_sines"]}}
        if "primal" in r:
            out["primal"] = {"function": r["primal"]["function"],
                             **{k: r["primal"]["ops"][k] for k in KINDS}}
        return out

    return {"robot": compilation.robot_name, "scene": compilation.scene.name,
            "functions": {r["function"]: entry(r) for r in table_rows}}


def table(compilation, table_rows) -> str:
    width = max([len("function")] + [len(r["function"]) for r in table_rows])
    counts = "".join(f"{k:>8}" for k in KINDS)
    lines = [f"{compilation.robot_name}, scene {compilation.scene.name}: operations per call",
             f"{'function':<{width}}  {'':<9}{counts}  {'path':>6}  {'generic/generated':>17}"]
    for r in table_rows:
        ratio = f"{r['generic']['total'] / max(1, r['generated']['total']):>16.1f}x"
        compared = [("generated", r["generated"], ""), ("generic", r["generic"], ratio)]
        if "primal" in r:   # a derivative: its primal function and derivative/primal
            primal = r["primal"]["ops"]
            compared.append(("primal", primal, f"{r['generated']['total'] / max(1, primal['total']):>7.1f}x "
                                               f"{r['primal']['function']}"))
        for label, ops, ratio in compared:
            values = "".join(f"{ops[k]:>8}" for k in KINDS)
            name = r["function"] if label == "generated" else ""
            path = f"{r['critical_path']}{'+' if r['looped'] else ''}" if label == "generated" else ""
            lines.append(f"{name:<{width}}  {label:<9}{values}  {path:>6}  {ratio}")
    lines.append("path: the generated code's critical path in cycles (graph/latency.py), a lower bound on one "
                 "call's latency; +: a looped form, its traced part only")
    if any("primal" in r for r in table_rows):
        lines.append("ratio: generic/generated; on a primal row, derivative/primal (both generated)")
    return "\n".join(lines)
