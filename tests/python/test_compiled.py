"""rbdc.compile: the generated code through its extension module (against the runtime, batches,
dtypes, strides, threads, errors) and the cache (hit, miss, concurrent builds)."""
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import rbdc
from rbdc.compiled import Target, cache_key
from conftest import ARM7, ARM7_SCENE, CHEETAH, CHEETAH_SCENE, ROOT, random_states

N = 37  # not a multiple of the pack lanes: whole packs and a scalar tail


@pytest.fixture(scope="module")
def states(arm7):
    q, v, a = random_states(np.random.default_rng(4), N, arm7.nq, arm7.nv, False)
    return {"q": q, "v": v, "a": a, "tau": np.random.default_rng(5).uniform(-1, 1, (N, arm7.n_joints)),
            "f": np.random.default_rng(6).uniform(-1, 1, (N, 3, arm7.n_feet))}


def test_module_describes_the_scene(arm7):
    assert arm7.functions == ("feet_positions", "feet_jacobian", "gravity_terms", "inverse_dynamics",
                              "mass_matrix", "forward_dynamics")
    assert (arm7.nq, arm7.nv, arm7.n_joints, arm7.floating_base) == (7, 7, 7, False)
    assert "inverse_dynamics(q, v, a, *, out=None, threads=0) -> tau" in arm7.inverse_dynamics.__doc__


def test_generated_matches_runtime(arm7, arm7_model, states):
    s, m = states, arm7_model
    pairs = [(arm7.inverse_dynamics(s["q"], s["v"], s["a"]), m.inverse_dynamics(s["q"], s["v"], s["a"])),
             (arm7.mass_matrix(s["q"]), m.mass_matrix(s["q"])),
             (arm7.gravity_terms(s["q"]), m.gravity_terms(s["q"])),
             (arm7.feet_positions(s["q"]), m.feet_positions(s["q"])),
             (arm7.feet_jacobian(s["q"]), m.feet_jacobian(s["q"])),
             (arm7.forward_dynamics(s["q"], s["v"], s["tau"], s["f"]),
              m.forward_dynamics(s["q"], s["v"], s["tau"], s["f"]))]
    for generated, runtime in pairs:
        np.testing.assert_allclose(generated, runtime, rtol=1e-9, atol=1e-9)


def test_batches_equal_single_calls(arm7, states):
    s = states
    batch = arm7.forward_dynamics(s["q"], s["v"], s["tau"], s["f"])
    for k in range(N):
        single = arm7.forward_dynamics(s["q"][k], s["v"][k], s["tau"][k], s["f"][k])
        np.testing.assert_allclose(batch[k], single, rtol=1e-12, atol=1e-12)  # packs may contract differently
    M = arm7.mass_matrix(s["q"])
    np.testing.assert_array_equal(M[N - 1], arm7.mass_matrix(s["q"][N - 1]))  # the scalar tail


def test_layouts_dtypes_and_broadcast(arm7, states):
    s = states
    reference = arm7.mass_matrix(s["q"])
    np.testing.assert_array_equal(arm7.mass_matrix(np.asfortranarray(s["q"])), reference)
    wide = np.zeros((N, 2 * arm7.nq))
    wide[:, ::2] = s["q"]
    np.testing.assert_array_equal(arm7.mass_matrix(wide[:, ::2]), reference)  # strided view
    np.testing.assert_array_equal(arm7.mass_matrix(s["q"].tolist()), reference)
    single = arm7.mass_matrix(s["q"].astype(np.float32))
    assert single.dtype == np.float32
    np.testing.assert_allclose(single, reference, rtol=1e-4, atol=1e-4)
    mixed = arm7.inverse_dynamics(s["q"].astype(np.float32), s["v"], s["a"])
    assert mixed.dtype == np.float64
    zero = np.zeros(arm7.nv)  # one state given for every state of the batch
    np.testing.assert_allclose(arm7.inverse_dynamics(s["q"], zero, zero), arm7.gravity_terms(s["q"]), atol=1e-12)


def test_out_argument(arm7, states):
    s = states
    out = np.empty((N, arm7.nv))
    assert arm7.inverse_dynamics(s["q"], s["v"], s["a"], out=out) is out
    np.testing.assert_array_equal(out, arm7.inverse_dynamics(s["q"], s["v"], s["a"]))
    transposed = np.empty((N, arm7.nv, arm7.nv)).transpose(0, 2, 1)  # any strides
    arm7.mass_matrix(s["q"], out=transposed)
    np.testing.assert_array_equal(transposed, arm7.mass_matrix(s["q"]))


def test_threads(arm7):
    q, v, a = random_states(np.random.default_rng(7), 20000, arm7.nq, arm7.nv, False)
    one = arm7.inverse_dynamics(q, v, a, threads=1)
    np.testing.assert_array_equal(arm7.inverse_dynamics(q, v, a, threads=2), one)
    np.testing.assert_array_equal(arm7.inverse_dynamics(q, v, a, threads=3), one)
    with ThreadPoolExecutor(4) as pool:  # concurrent calls from Python threads
        parts = list(pool.map(lambda k: arm7.inverse_dynamics(q[k::4], v[k::4], a[k::4]), range(4)))
    for k in range(4):
        np.testing.assert_array_equal(parts[k], one[k::4])


def test_errors_name_the_argument(arm7, states):
    s = states
    with pytest.raises(ValueError, match=r"rbdc: inverse_dynamics: a has shape \(6,\), expected \(7,\) or \(N, 7\)"):
        arm7.inverse_dynamics(s["q"][0], s["v"][0], np.zeros(6))
    with pytest.raises(ValueError, match="rbdc: inverse_dynamics: v holds 36 states, q 37"):
        arm7.inverse_dynamics(s["q"], s["v"][1:], s["a"])
    with pytest.raises(TypeError, match="rbdc: mass_matrix: q has dtype <U1, expected float64 or float32"):
        arm7.mass_matrix(np.array(["a"] * 7))
    with pytest.raises(TypeError, match=r"rbdc: mass_matrix: out has dtype float32, expected float64"):
        arm7.mass_matrix(s["q"], out=np.empty((N, 7, 7), np.float32))
    with pytest.raises(ValueError, match=r"rbdc: mass_matrix: out holds 36 states, the inputs 37 states"):
        arm7.mass_matrix(s["q"], out=np.empty((36, 7, 7)))
    with pytest.raises(ValueError, match="rbdc: mass_matrix: out is read-only"):
        out = np.empty((N, 7, 7))
        out.flags.writeable = False
        arm7.mass_matrix(s["q"], out=out)


def test_quaternion_policy_and_nan(cheetah_feet, cheetah_model):
    """The generated code assumes a unit quaternion (the runtime normalises): both refuse another."""
    q, _, _ = random_states(np.random.default_rng(8), 20, 19, 18, True)
    np.testing.assert_allclose(cheetah_feet.feet_positions(q), cheetah_model.feet_positions(q), atol=1e-12)
    in_double = cheetah_feet.feet_positions(q.astype(np.float32))  # compiled without float32=True
    assert in_double.dtype == np.float64
    np.testing.assert_allclose(in_double, cheetah_model.feet_positions(q), atol=1e-5)  # float32 unit quaternions pass
    scaled = q.copy()
    scaled[13, 3:7] *= 3
    for module in (cheetah_feet, cheetah_model):
        with pytest.raises(ValueError, match=r"rbdc: feet_positions: q\[13\]: the quaternion q\[3:7\] has norm "
                                             r"3\.0+, expected a unit quaternion"):
            module.feet_positions(scaled)
    q[5, 10] = np.nan
    p = cheetah_feet.feet_positions(q)
    assert np.isnan(p[5]).any() and np.isfinite(np.delete(p, 5, axis=0)).all()


def test_single_states_equal_batch_rows(cheetah_feet, cheetah_model):
    """One float64 state takes the fast path (single_call.hpp), which transposes matrices between
    numpy's C order and the C++ column-major layout: (3, n_feet) outputs and inputs in either order."""
    rng = np.random.default_rng(9)
    q, v, _ = random_states(rng, 5, 19, 18, True)
    tau, f = rng.uniform(-1, 1, (5, 12)), rng.uniform(-1, 1, (5, 3, 4))
    feet, accelerations = cheetah_feet.feet_positions(q), cheetah_model.forward_dynamics(q, v, tau, f)
    for k in range(5):
        single = cheetah_feet.feet_positions(q[k])
        assert single.shape == (3, 4) and single.flags.c_contiguous
        np.testing.assert_allclose(single, feet[k], rtol=1e-12, atol=1e-12)  # packs may contract differently
        for f_k in (f[k], np.asfortranarray(f[k]), np.repeat(f[k], 2, axis=1)[:, ::2]):  # C, F, strided
            np.testing.assert_array_equal(cheetah_model.forward_dynamics(q[k], v[k], tau[k], f_k), accelerations[k])
    for out in (np.empty((3, 4)), np.empty((3, 4), order="F"), np.empty((3, 8))[:, ::2]):  # C, F, strided
        assert cheetah_feet.feet_positions(q[0], out=out) is out
        np.testing.assert_array_equal(out, cheetah_feet.feet_positions(q[0]))
    scaled = q[0].copy()
    scaled[3:7] *= 3
    with pytest.raises(ValueError, match=r"rbdc: feet_positions: q: the quaternion q\[3:7\] has norm 3\.0+"):
        cheetah_feet.feet_positions(scaled)


def test_cache_hit_and_changed_urdf_miss(arm7, tmp_path):
    start = time.perf_counter()
    assert rbdc.compile(ARM7, scene=ARM7_SCENE, base="fixed", float32=True) is arm7  # same process
    assert time.perf_counter() - start < 0.5
    code = (f"import sys, time; sys.path.insert(0, {str(ROOT / 'python')!r}); import rbdc; t = time.perf_counter(); "
            f"m = rbdc.compile({str(ARM7)!r}, scene={str(ARM7_SCENE)!r}, base='fixed', float32=True); "
            "print(time.perf_counter() - t, m.cache_entry)")
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    seconds, entry = run.stdout.split()
    assert entry == str(arm7.cache_entry) and float(seconds) < 2  # ≤ 0.2 s unloaded (docs/python.md)
    changed = tmp_path / "arm7.urdf"
    changed.write_text(ARM7.read_text().replace('<mass value="', '<mass value="1', 1))
    assert cache_key(Target.from_files(changed, ARM7_SCENE, base="fixed")) != cache_key(
        Target.from_files(ARM7, ARM7_SCENE, base="fixed"))
    assert cache_key(Target.from_files(ARM7, ARM7_SCENE, base="fixed")) != arm7.cache_entry.name  # float32 differs
    assert cache_key(Target.from_files(ARM7, ARM7_SCENE, base="fixed", float32=True)) == arm7.cache_entry.name


def test_compile_from_a_model_and_bad_targets(arm7, arm7_model, tmp_path):
    assert rbdc.compile(arm7_model, scene=ARM7_SCENE, float32=True) is arm7
    with pytest.raises(FileNotFoundError, match="scene file .*nothing.yaml does not exist"):
        rbdc.compile(ARM7, scene=tmp_path / "nothing.yaml")
    with pytest.raises(FileNotFoundError, match="scene file .*no_such_scene.yaml does not exist"):
        rbdc.compile(ARM7, scene="no_such_scene")
