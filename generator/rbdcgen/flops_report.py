"""Operation counts of a compilation, generated vs generic, as a readable table or as JSON."""
from .flops import count_ops, generic_ops

KINDS = ("mul", "add", "div", "sqrt", "trig", "neg", "total")


def rows(compilation) -> list[dict]:
    return [{"function": f.name, "generated": count_ops(f), "generic": generic_ops(compilation.robot, compilation.scene, f.name)}
            for f in compilation.functions]


def as_json(compilation, table_rows) -> dict:
    return {"robot": compilation.robot_name, "scene": compilation.scene.name,
            "functions": {r["function"]: {"generated": {k: r["generated"][k] for k in KINDS},
                                          "generic": {k: r["generic"][k] for k in KINDS}}
                          for r in table_rows}}


def table(compilation, table_rows) -> str:
    width = max([len("function")] + [len(r["function"]) for r in table_rows])
    counts = "".join(f"{k:>8}" for k in KINDS)
    lines = [f"{compilation.robot_name}, scene {compilation.scene.name}: operations per call",
             f"{'function':<{width}}  {'':<9}{counts}  {'generic/generated':>17}"]
    for r in table_rows:
        for label in ("generated", "generic"):
            values = "".join(f"{r[label][k]:>8}" for k in KINDS)
            name = r["function"] if label == "generated" else ""
            ratio = ""
            if label == "generic" and r["generated"]["total"]:
                ratio = f"{r['generic']['total'] / r['generated']['total']:>16.1f}x"
            lines.append(f"{name:<{width}}  {label:<9}{values}  {ratio}")
    return "\n".join(lines)
