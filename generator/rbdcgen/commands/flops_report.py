"""Operation counts of a compilation, generated vs generic, as a readable table or as JSON.
A derivative quantity is also compared with its primal function (derivatives.PRIMAL, traced for the
same robot and scene): the targets of issue 12 are ratios to one primal call."""
from ..passes.differentiate import PRIMAL
from ..graph.flops import count_ops, generic_ops
from ..passes.trace import trace_function

KINDS = ("mul", "add", "div", "sqrt", "trig", "neg", "total")


def rows(compilation) -> list[dict]:
    result = []
    primal_counts = {}
    for f in compilation.functions:
        row = {"function": f.name, "generated": count_ops(f),
               "generic": generic_ops(compilation.robot, compilation.scene, f.computes)}
        if f.name in PRIMAL:
            name = PRIMAL[f.name]
            if name not in primal_counts:
                primal_counts[name] = count_ops(trace_function(compilation.robot, compilation.scene, name))
            row["primal"] = {"function": name, "ops": primal_counts[name]}
        result.append(row)
    return result


def as_json(compilation, table_rows) -> dict:
    def entry(r):
        out = {"generated": {k: r["generated"][k] for k in KINDS},
               "generic": {k: r["generic"][k] for k in KINDS}}
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
             f"{'function':<{width}}  {'':<9}{counts}  {'generic/generated':>17}"]
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
            lines.append(f"{name:<{width}}  {label:<9}{values}  {ratio}")
    if any("primal" in r for r in table_rows):
        lines.append("ratio: generic/generated; on a primal row, derivative/primal (both generated)")
    return "\n".join(lines)
