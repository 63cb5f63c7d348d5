#!/usr/bin/env python3
"""rbdc-eval command line: JSON layout, names, sizes, symmetry of M, the --a path, and exit code 2
with a clear message for wrong lengths, non-numbers and NaN. Usage: test_rbdc_eval.py RBDC_EVAL ROOT"""
import json
import subprocess
import sys

EVAL, ROOT = sys.argv[1], sys.argv[2]
CHEETAH = f"{ROOT}/robots/mini_cheetah.urdf"
STANDING = "0,0,0.3,1,0,0,0," + ",".join(["0,-0.8,1.6"] * 4)
failures = []
checks = 0


def run(*args):
    return subprocess.run([EVAL, *args], capture_output=True, text=True)


def check(condition, what):
    global checks
    checks += 1
    if not condition:
        failures.append(what)


result = run(CHEETAH, "--q", STANDING, "--v", ",".join(["0.1"] * 18))
check(result.returncode == 0, f"standing state: exit {result.returncode}: {result.stderr}")
out = json.loads(result.stdout)
check(out["nq"] == 19 and out["nv"] == 18, "sizes")
check(out["joint_names"][:6] == ["root_wx", "root_wy", "root_wz", "root_vx", "root_vy", "root_vz"],
      "floating-base coordinate names")
check(len(out["joint_names"]) == 18 and len(out["c"]) == 18 and len(out["g"]) == 18, "vector lengths")
M = out["M"]
check(len(M) == 18 and all(M[r][k] == M[k][r] for r in range(18) for k in range(18)), "M symmetric")
check(abs(M[3][3] - 8.252) < 1e-9, "total mass in M[3][3]")
check(len(out["feet"]["names"]) == 4 and len(out["feet"]["positions"]) == 4, "four feet")
check(len(out["feet"]["jacobian"]) == 12 and len(out["feet"]["jacobian"][0]) == 18, "Jacobian shape")
check(abs(out["g"][5] - 8.252 * 9.81) < 1e-9, "g: the trunk carries the weight upright")
check("tau" not in out, "no tau without --a")
check(len(out["feet"]["bias_accelerations"]) == 4, "feet J̇v, one row per foot")
cen = out["centroidal"]
check(len(cen["momentum_matrix"]) == 6 and len(cen["momentum_matrix"][0]) == 18, "A_G shape")
check(abs(cen["momentum_matrix"][3][3] - 8.252) < 1e-9, "A_G: linear momentum of the trunk's v is m")
check(len(out["M_inverse"]) == 18, "M_inverse rows")
MMinv = [[sum(M[r][k] * out["M_inverse"][k][c] for k in range(18)) for c in range(18)] for r in range(18)]
check(all(abs(MMinv[r][c] - (r == c)) < 1e-9 for r in range(18) for c in range(18)), "M · M⁻¹ = 1")
check("frames" not in out, "no frames without --frames")
framed = json.loads(run(CHEETAH, "--q", STANDING, "--frames", "LF_foot,trunk").stdout)["frames"]
check(list(framed) == ["LF_foot", "trunk"], "frames in the order asked")
check(len(framed["LF_foot"]["jacobian_world"]) == 6 and len(framed["LF_foot"]["jacobian_world"][0]) == 18,
      "frame Jacobian 6 x nv")
check(all(abs(a - b) < 1e-12 for a, b in zip(framed["LF_foot"]["position"], out["feet"]["positions"][0])),
      "the LF_foot link frame is the LF foot point")
unknown = run(CHEETAH, "--frames", "LF_shin")
check(unknown.returncode == 2 and "no frame 'LF_shin'" in unknown.stderr, "unknown frame: exit 2 naming it")

with_a = json.loads(run(CHEETAH, "--q", STANDING, "--a", ",".join(["0"] * 18)).stdout)
check(with_a["tau"] == with_a["g"], "tau at v = a = 0 equals g")

# --derivatives: every output of rbdc/derivatives.hpp with its shape; one column of each kind checked
# against central differences of the plain outputs (joint coordinates: the manifold step is q + δ).
TAU = ",".join(str(0.5 * k - 3) for k in range(12))
V = ",".join(str(0.1 * ((k % 5) + 1) * (-1) ** k) for k in range(18))
derived = run(CHEETAH, "--q", STANDING, "--v", V, "--tau", TAU, "--derivatives")
check(derived.returncode == 0, f"--derivatives: exit {derived.returncode}: {derived.stderr}")
d = json.loads(derived.stdout)["derivatives"]
shapes = {"dtau_dq": (18, 18), "dtau_dv": (18, 18), "dbias_dq": (18, 18), "dbias_dv": (18, 18),
          "dg_dq": (18, 18), "da_dq": (18, 18), "da_dv": (18, 18), "da_dtau": (18, 12),
          "da_df": (18, 12), "dpdot_dq": (12, 18), "dtau_e_dq": (18, 18)}
check({k: (len(m), len(m[0])) for k, m in d.items()} == shapes, "derivative names and shapes")
check(all(row[3:6] == [0, 0, 0] for row in d["dg_dq"]), "trunk position columns of dg_dq are zero")
check("derivatives" not in out, "no derivatives without --derivatives")
H = 1e-6
JOINT = 7  # the LF knee's column in v (q index 8)


def at_knee(delta):
    q = [float(x) for x in STANDING.split(",")]
    q[JOINT + 1] += delta
    return json.loads(run(CHEETAH, "--q", ",".join(map(repr, q)), "--v", V).stdout)


plus, minus = at_knee(H), at_knee(-H)
fd_g = [(p - m) / (2 * H) for p, m in zip(plus["g"], minus["g"])]
check(max(abs(fd_g[r] - d["dg_dq"][r][JOINT]) for r in range(18)) < 1e-6 * max(1, max(map(abs, fd_g))),
      "dg_dq knee column vs central differences of g")
fd_bias = [(pc + pg - mc - mg) / (2 * H)
           for pc, pg, mc, mg in zip(plus["c"], plus["g"], minus["c"], minus["g"])]
check(max(abs(fd_bias[r] - d["dbias_dq"][r][JOINT]) for r in range(18)) < 1e-6 * max(1, max(map(abs, fd_bias))),
      "dbias_dq knee column vs central differences of c + g")
bad_tau = run(CHEETAH, "--derivatives", "--tau", "1,2")
check(bad_tau.returncode == 2 and "error: --tau has 2 values, the model needs 12" in bad_tau.stderr,
      f"--tau length: {bad_tau.stderr!r}")

for args, message in [
    (["--q", "1,2"], "--q has 2 values, the model needs 19"),
    (["--v", "nan" + ",0" * 17], "--v has a NaN or Inf value"),
    (["--v", "1,x"], "--v: 'x' is not a number"),
]:
    bad = run(CHEETAH, *args)
    check(bad.returncode == 2, f"{args}: exit code {bad.returncode}")
    check(f"error: {message}" in bad.stderr, f"{args}: message {bad.stderr!r}")

# Coupled mimic joints have no coordinate of their own: refused, naming the options that give one.
MIMIC = f"{ROOT}/tests/data/mimic.urdf"
coupled = run(MIMIC)
check(coupled.returncode == 2 and "use --independent-mimic or --lock-mimic" in coupled.stderr,
      f"coupled mimic: {coupled.stderr!r}")
independent = run(MIMIC, "--independent-mimic")
check(independent.returncode == 0 and json.loads(independent.stdout)["joint_names"][-2:] == ["ja", "jb"],
      f"independent mimic: {independent.stderr!r}")

# Forward dynamics with rotors (robots/mini_cheetah_rotors.topology.yaml), joint torques and a body
# wrench: inverse dynamics at the printed qdd gives back (trunk wrench; tau), since a wrench on the
# trunk (moment; force at its origin, trunk coordinates) enters τ_e's trunk rows only.
import os
import tempfile
ROTORS = ["--topology", f"{ROOT}/robots/mini_cheetah_rotors.topology.yaml"]
WRENCH = [0.3, -0.2, 0.1, 5.0, -4.0, 30.0]
with tempfile.TemporaryDirectory() as tmp:
    wrench_file = os.path.join(tmp, "wrenches.json")
    with open(wrench_file, "w", encoding="utf-8") as handle:
        json.dump({"trunk": WRENCH}, handle)
    fd = run(CHEETAH, *ROTORS, "--q", STANDING, "--v", V, "--tau", TAU, "--body-wrenches", wrench_file)
    check(fd.returncode == 0, f"forward dynamics: exit {fd.returncode}: {fd.stderr}")
    fd_out = json.loads(fd.stdout)
    check(abs(fd_out["M"][3][3] - 8.912) < 1e-9, "with rotors the trunk block carries 8.912 kg")
    qdd = fd_out["forward_dynamics"]["qdd"]
    back = json.loads(run(CHEETAH, *ROTORS, "--q", STANDING, "--v", V,
                          "--a", ",".join(map(repr, qdd))).stdout)["tau"]
    expected = WRENCH + [0.5 * k - 3 for k in range(12)]
    check(max(abs(b - e) for b, e in zip(back, expected)) < 1e-9, f"ID(qdd) = (wrench; tau): {back}")
    vel = [float(x) for x in V.split(",")]
    w, lin = vel[0:3], vel[3:6]
    cross = [w[1] * lin[2] - w[2] * lin[1], w[2] * lin[0] - w[0] * lin[2], w[0] * lin[1] - w[1] * lin[0]]
    spatial = fd_out["forward_dynamics"]["trunk_spatial_acceleration"]
    check(fd_out["forward_dynamics"]["trunk_classical_acceleration"] == qdd[:6], "classical = qdd[0:6]")
    check(all(abs(spatial[3 + k] - (qdd[3 + k] - cross[k])) < 1e-12 for k in range(3)) and
          spatial[:3] == qdd[:3], "spatial = classical - (0, w x v)")
    plain = json.loads(run(CHEETAH, "--q", STANDING, "--v", V, "--tau", TAU).stdout)["forward_dynamics"]["qdd"]
    check(max(abs(a - b) for a, b in zip(plain, qdd)) > 1e-3, "rotors and the wrench change qdd")
    with open(wrench_file, "w", encoding="utf-8") as handle:
        json.dump({"LF_elbow": WRENCH}, handle)
    bad_body = run(CHEETAH, "--tau", TAU, "--body-wrenches", wrench_file)
    check(bad_body.returncode == 2 and "no body named 'LF_elbow'" in bad_body.stderr,
          f"unknown body: {bad_body.stderr!r}")
    with open(wrench_file, "w", encoding="utf-8") as handle:
        json.dump({"trunk": [1, 2, 3]}, handle)
    short = run(CHEETAH, "--body-wrenches", wrench_file)
    check(short.returncode == 2 and "expected 6 numbers (moment; force)" in short.stderr,
          f"short wrench: {short.stderr!r}")
# --derivatives with rotors and an armature: c + g's knee column against central differences, and
# M · ∂a/∂τ = Sᵀ (M with the rotors and the armature, from the same call).
ACTUATED = ROTORS + ["--armature", "LF_knee_joint=0.01"]
rotor_run = run(CHEETAH, *ACTUATED, "--q", STANDING, "--v", V, "--tau", TAU, "--derivatives")
check(rotor_run.returncode == 0, f"derivatives with rotors: exit {rotor_run.returncode}: {rotor_run.stderr}")
rotor_out = json.loads(rotor_run.stdout)
rd = rotor_out["derivatives"]


def actuated_at_knee(delta):
    q = [float(x) for x in STANDING.split(",")]
    q[JOINT + 1] += delta
    return json.loads(run(CHEETAH, *ACTUATED, "--q", ",".join(map(repr, q)), "--v", V).stdout)


plus, minus = actuated_at_knee(H), actuated_at_knee(-H)
fd_bias = [(pc + pg - mc - mg) / (2 * H)
           for pc, pg, mc, mg in zip(plus["c"], plus["g"], minus["c"], minus["g"])]
check(max(abs(fd_bias[r] - rd["dbias_dq"][r][JOINT]) for r in range(18)) < 1e-6 * max(1, max(map(abs, fd_bias))),
      "with rotors: dbias_dq knee column vs central differences of c + g")
M_rotor = rotor_out["M"]
M_da_dtau = [[sum(M_rotor[r][k] * rd["da_dtau"][k][c] for k in range(18)) for c in range(12)] for r in range(18)]
check(max(abs(M_da_dtau[r][c] - (1.0 if r == c + 6 else 0.0)) for r in range(18) for c in range(12)) < 1e-9,
      "with rotors and armature: M da_dtau = S^T")
check(max(abs(a - b) for a, b in zip(rd["dbias_dq"][JOINT], d["dbias_dq"][JOINT])) > 1e-6,
      "the rotors change the derivatives")

# --contacts: contact and impulse dynamics of the four stance feet, checked with the printed M, g, J
# (v = 0: c = 0): M qdd + g − Sᵀτ − Jᵀλ = 0, J qdd = 0 (J̇v = 0 at v = 0), M (v⁺ − v) = JᵀΛ.
FEET = "LF_foot,RF_foot,LH_foot,RH_foot"
stance = run(CHEETAH, "--q", STANDING, "--tau", TAU, "--contacts", FEET, "--restitution", "0.3",
             "--derivatives")
check(stance.returncode == 0, f"--contacts: exit {stance.returncode}: {stance.stderr}")
so = json.loads(stance.stdout)
qdd, lam = so["contact_dynamics"]["qdd"], so["contact_dynamics"]["lambda"]
J, M, g = so["feet"]["jacobian"], so["M"], so["g"]
tau_full = [0.0] * 6 + [float(t) for t in TAU.split(",")]
row1 = [sum(M[r][k] * qdd[k] for k in range(18)) + g[r] - tau_full[r] - sum(J[c][r] * lam[c] for c in range(12))
        for r in range(18)]
check(max(map(abs, row1)) < 1e-9 * max(map(abs, g)), "contact dynamics: M qdd + g − Sᵀτ − Jᵀλ = 0")
check(max(abs(sum(J[c][k] * qdd[k] for k in range(18))) for c in range(12)) < 1e-9, "contact dynamics: J qdd = 0")
check(len(lam) == 12 and max(map(abs, lam)) > 1, "contact forces: twelve entries, not all zero")
check(so["impulse_dynamics"]["v_plus"] == [0.0] * 18 or max(map(abs, so["impulse_dynamics"]["impulse"])) < 1e-12,
      "no impulse at rest")
shapes = {"da_dq": (18, 18), "da_dv": (18, 18), "da_dtau": (18, 12), "dlambda_dq": (12, 18),
          "dlambda_dv": (12, 18), "dlambda_dtau": (12, 12)}
cd = so["contact_dynamics_derivatives"]
check({k: (len(m), len(m[0])) for k, m in cd.items()} == shapes, "contact derivative names and shapes")
for bad_args, what in (((("--contacts", "LF_foot,XX")), "is not a foot"),
                       (("--contacts", FEET, "--restitution", "2"), "not in [0, 1]"),
                       (("--kd", "3"), "need --contacts")):
    bad = run(CHEETAH, *bad_args)
    check(bad.returncode == 2 and what in bad.stderr and bad.stdout == "", f"refused: {bad_args}: {bad.stderr}")

for f in failures:
    print("FAILED:", f)
print(f"{checks - len(failures)} passed, {len(failures)} failed")
sys.exit(1 if failures else 0)
