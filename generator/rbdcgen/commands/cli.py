"""The `rbdc` command line: generate, flops, verify, eval, check. Bad input ends with "error: ..." on
stderr and exit code 2, never a traceback; `generate --check` and a failed `verify` exit with 1."""
import argparse
import gc
import os
import sys
from pathlib import Path

from . import subcommands
from ..errors import RbdcError
from ..frontend.ir import IRError
from ..frontend.layout import find_layout
from ..frontend.scene import SceneError
from ..passes.trace import TraceError

DESCRIPTION = """rbdc: a rigid-body dynamics compiler. Turns a robot (URDF, topology YAML or rbdc IR JSON)
and a scene (which quantities, feet, gravity, base, zero inputs, locked joints) into header-only,
fixed-size, templated C++ (docs/generated_api.md), reports its operation counts, and checks it
against the generic runtime."""


def _robot_arguments(parser, multiple=False):
    if multiple:
        parser.add_argument("robots", nargs="+", type=Path, metavar="ROBOT",
                            help="robot files (.urdf, topology .yaml or IR .json); several share one harness")
    else:
        parser.add_argument("robot", type=Path, help="robot file: .urdf, topology .yaml or IR .json")
    parser.add_argument("--topology", type=Path, metavar="FILE",
                        help="topology YAML (PRED/SUCC numbering and parameters) applied to the URDF")
    parser.add_argument("--scene", type=Path, metavar="FILE",
                        help="scene YAML (default: every quantity that applies, the robot's gravity)")
    base = parser.add_mutually_exclusive_group()
    base.add_argument("--floating-base", dest="base", action="store_const", const="floating",
                      help="6-DoF floating root joint (overrides the scene)")
    base.add_argument("--fixed-base", dest="base", action="store_const", const="fixed",
                      help="root welded to the world (overrides the scene)")
    _mimic_arguments(parser)


def _mimic_arguments(parser):
    """What URDF mimic joints become (docs/model.md, "Mimic joints"); args.mimic."""
    mimic = parser.add_mutually_exclusive_group()
    mimic.set_defaults(mimic="couple")
    mimic.add_argument("--lock-mimic", dest="mimic", action="store_const", const="lock",
                       help="lock each mimic joint at its offset (default: couple it to its leader, "
                            "q = multiplier * q_leader + offset, which removes its coordinate)")
    mimic.add_argument("--independent-mimic", dest="mimic", action="store_const", const="independent",
                       help="load mimic joints as independent joints (the <mimic> tag is ignored)")


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="rbdc", description=DESCRIPTION)
    sub = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")

    generate = sub.add_parser(
        "generate", help="write the C++ headers for a robot and scene",
        description="Writes DIR/rbdc_gen/support.hpp, DIR/<robot>/<scene>.hpp and one header per "
                    "quantity in DIR/<robot>/<scene>/. Files whose content is unchanged are not "
                    "touched; stale quantity headers of the same robot and scene are removed.")
    _robot_arguments(generate)
    generate.add_argument("--name", help="robot name for the directory and namespace (default: the URDF's)")
    generate.add_argument("-o", "--output", type=Path, required=True, metavar="DIR", help="output root")
    mode = generate.add_mutually_exclusive_group()
    mode.add_argument("--list-outputs", action="store_true",
                      help="print the files that would be written (for build systems) and stop")
    mode.add_argument("--dry-run", action="store_true",
                      help="say what would be written or changed, write nothing")
    mode.add_argument("--check", action="store_true",
                      help="regenerate in memory and compare with DIR; exit 1 on any difference")
    generate.add_argument("--verbose", action="store_true",
                          help="print each function as it is traced: its form (schedule) and seconds, on stderr")

    flops = sub.add_parser(
        "flops", help="operation counts per function, generated vs generic",
        description="Counts multiplications, additions, divisions, square roots and trig calls of each "
                    "generated function (from its expression DAG) and of the generic runtime algorithm "
                    "(dense 6x6 arithmetic, counted analytically), and gives each generated function's "
                    "critical path: the cycles of its longest chain of dependent operations on a current "
                    "x86 core, a lower bound on one call's latency.")
    _robot_arguments(flops)
    flops.add_argument("--json", action="store_true", help="print JSON instead of a table")

    verify = sub.add_parser(
        "verify", help="check generated code against the runtime on random and edge states",
        description="Generates into a temporary directory, compiles a harness with the generated "
                    "headers and the runtime library, evaluates both on N random states plus the zero "
                    "state and joint-limit states, and prints the largest absolute and relative error "
                    "per quantity. Exit 1 when a relative error exceeds the tolerance.")
    _robot_arguments(verify, multiple=True)
    verify.add_argument("--also-scene", type=Path, action="append", default=[], metavar="FILE",
                        help="verify the robots with this scene too, in the same harness (repeatable)")
    verify.add_argument("--states", type=int, default=100, metavar="N", help="random states (default 100)")
    verify.add_argument("--seed", type=int, default=1, help="random seed of the states (default 1)")
    verify.add_argument("--tolerance", type=float, default=1e-9,
                        help="largest accepted relative error (default 1e-9)")
    verify.add_argument("--keep", type=Path, metavar="DIR",
                        help="write the generated code and harness here instead of a temporary dir")

    check = sub.add_parser(
        "check", help="lint a robot file: every warning and error with file:line, the resulting topology",
        description="Loads the robot with the one C++ loader (rbdc-model --check) and lists every "
                    "warning (repairs, ignored faults) and the refusal, if any, each with file:line, then "
                    "PRED, SUCC, lambda, the DoF, couplings and the mass. Exit 0 unless the robot is "
                    "refused (exit 2). Checks and tolerances: docs/model.md.")
    check.add_argument("robot", type=Path, help="robot file: .urdf or topology .yaml")
    check.add_argument("--topology", type=Path, metavar="FILE", help="topology YAML applied to the URDF")
    base = check.add_mutually_exclusive_group()
    base.add_argument("--floating-base", dest="base", action="store_const", const="floating")
    base.add_argument("--fixed-base", dest="base", action="store_const", const="fixed")
    _mimic_arguments(check)

    evaluate = sub.add_parser(
        "eval", help="the runtime's M, c, g and feet Jacobian at one state, as JSON",
        description="Runs the runtime (rbdc-eval) at the given state and prints its JSON, keyed by "
                    "joint names, for comparison with other libraries.")
    evaluate.add_argument("robot", type=Path, help="robot file: .urdf or topology .yaml")
    evaluate.add_argument("--q", help="configuration, comma-separated (nq values; default: zero, identity quaternion)")
    evaluate.add_argument("--v", help="velocity, comma-separated (nv values; default zero)")
    evaluate.add_argument("--a", help="acceleration, comma-separated (nv values); adds inverse dynamics as tau")
    evaluate.add_argument("--derivatives", action="store_true",
                          help="adds the runtime's analytic derivatives (dtau_dq … dtau_e_dq, docs/runtime.md)")
    evaluate.add_argument("--tau", help="joint torques (n_joints values; default zero); adds forward dynamics "
                          "(qdd and the trunk's acceleration, docs/runtime.md) and feeds the derivatives")
    evaluate.add_argument("--f", help="world foot forces, foot-major (3·n_feet values; default zero)")
    evaluate.add_argument("--contacts", metavar="FOOT,…",
                          help="feet in contact (names; a repeat is a redundant contact): adds contact_dynamics "
                               "(qdd, lambda) at --tau, impulse_dynamics (v_plus, impulse) at --v and, with "
                               "--derivatives, contact_dynamics_derivatives (docs/runtime.md)")
    evaluate.add_argument("--restitution", metavar="E", help="restitution of impulse_dynamics, in [0, 1] (default 0)")
    evaluate.add_argument("--kd", metavar="KD", help="Baumgarte velocity gain of contact_dynamics (default 0)")
    evaluate.add_argument("--body-wrenches", type=Path, metavar="FILE.json",
                          help="external wrenches {\"BODY\": [nx, ny, nz, fx, fy, fz]} at each body's origin, "
                               "body coordinates; adds forward dynamics")
    evaluate.add_argument("--armature", action="append", default=[], metavar="JOINT=VALUE",
                          help="reflected rotor inertia added to M's diagonal (repeatable; docs/model.md)")
    evaluate.add_argument("--topology", type=Path, metavar="FILE", help="topology YAML applied to the URDF")
    base = evaluate.add_mutually_exclusive_group()
    base.add_argument("--floating-base", dest="base", action="store_const", const="floating")
    base.add_argument("--fixed-base", dest="base", action="store_const", const="fixed")
    _mimic_arguments(evaluate)
    return parser


def main(argv=None) -> int:
    args = build_parser().parse_args(argv)
    layout = find_layout()
    # The traced graphs are the command's only reference cycles (node <-> graph) and stay alive until
    # their code is written: the cyclic collector would only walk them again and again (a 200-body
    # chain's full scene: 1.0 s of 8.4). What they leave is collected once the command is done.
    collecting = gc.isenabled()
    gc.disable()
    try:
        return subcommands.COMMANDS[args.command](args, layout)
    except (RbdcError, IRError, SceneError, TraceError) as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    except BrokenPipeError:
        # The reader went away (e.g. `rbdc flops ... | head`): stop quietly, as other tools do.
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 1
    except OSError as error:
        print(f"error: {error.filename or ''}: {error.strerror}", file=sys.stderr)
        return 2
    finally:
        if collecting:
            gc.enable()
