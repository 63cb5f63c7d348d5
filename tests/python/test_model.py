"""rbdc.Model: the runtime's algorithms through the bindings (layouts, batches, errors, warnings)."""
import re
import warnings

import numpy as np
import pytest

import rbdc
from conftest import ARM7, CHEETAH, random_states

BAD_URDF = """<?xml version="1.0"?>
<robot name="bad">
  <link name="base"><inertial><mass value="1"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="arm"><inertial><mass value="-2"/><inertia ixx="1" iyy="1" izz="1" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="j" type="revolute"><parent link="base"/><child link="arm"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>
"""


def test_dimensions_and_default_base(cheetah_model, arm7_model):
    assert (cheetah_model.nq, cheetah_model.nv, cheetah_model.n_joints, cheetah_model.n_feet) == (19, 18, 12, 4)
    assert cheetah_model.floating_base  # the command-line tools' default
    assert (arm7_model.nq, arm7_model.nv, arm7_model.floating_base) == (7, 7, False)


def test_loader_warnings_are_python_warnings():
    with pytest.warns(rbdc.ModelWarning, match=r"mini_cheetah\.urdf:\d+: body 'LF_hip'"):
        rbdc.Model.from_urdf(CHEETAH)


def test_refusal_carries_file_and_line(tmp_path):
    path = tmp_path / "bad.urdf"
    path.write_text(BAD_URDF)
    with pytest.raises(rbdc.ModelError, match=re.escape(str(path)) + r":\d+: .*mass"):
        rbdc.Model.from_urdf(path)


def test_missing_file_and_bad_options(tmp_path):
    with pytest.raises(FileNotFoundError, match="nothing.urdf"):
        rbdc.Model.from_urdf(tmp_path / "nothing.urdf")
    with pytest.raises(ValueError, match="base must be"):
        rbdc.Model.from_urdf(ARM7, base="flying")


def test_mass_matrix_columns_are_inverse_dynamics(cheetah_model):
    """M e_k = ID(q, 0, e_k) - ID(q, 0, 0): checks the layout of every output through the bindings."""
    m = cheetah_model
    q, v, _ = random_states(np.random.default_rng(1), 1, m.nq, m.nv, True)
    M = m.mass_matrix(q[0])
    bias = m.inverse_dynamics(q[0], np.zeros(m.nv), np.zeros(m.nv))
    np.testing.assert_allclose(bias, m.gravity_terms(q[0]), atol=1e-12)
    columns = np.stack([m.inverse_dynamics(q[0], np.zeros(m.nv), e) - bias for e in np.eye(m.nv)], axis=1)
    np.testing.assert_allclose(M, columns, atol=1e-10)
    tau = m.inverse_dynamics(q[0], v[0], np.linspace(-1, 1, m.nv))
    f = np.zeros((3, m.n_feet))
    # forward dynamics undoes inverse dynamics when the trunk's wrench is zero: drive with the joint part
    a = m.forward_dynamics(q[0], v[0], tau[6:], f)
    np.testing.assert_allclose(m.inverse_dynamics(q[0], v[0], a)[6:], tau[6:], atol=1e-9)
    np.testing.assert_allclose(m.inverse_dynamics(q[0], v[0], a)[:6], 0, atol=1e-9)


def test_jacobian_and_derivatives_match_finite_differences(arm7_model):
    m, h = arm7_model, 1e-6
    q, v, a = (x[0] for x in random_states(np.random.default_rng(2), 1, m.nq, m.nv, False))
    J = m.feet_jacobian(q)
    dtau_dq, dtau_dv = m.inverse_dynamics_derivatives(q, v, a)
    for k, e in enumerate(np.eye(m.nv)):
        dp = (m.feet_positions(q + h * e) - m.feet_positions(q - h * e)) / (2 * h)
        np.testing.assert_allclose(J[:, k], dp.T.reshape(-1), atol=1e-7)  # rows foot-major
        dtau = (m.inverse_dynamics(q + h * e, v, a) - m.inverse_dynamics(q - h * e, v, a)) / (2 * h)
        np.testing.assert_allclose(dtau_dq[:, k], dtau, atol=1e-6)
        dtau = (m.inverse_dynamics(q, v + h * e, a) - m.inverse_dynamics(q, v - h * e, a)) / (2 * h)
        np.testing.assert_allclose(dtau_dv[:, k], dtau, atol=1e-6)


def test_batches_equal_single_calls(cheetah_model):
    m = cheetah_model
    q, v, a = random_states(np.random.default_rng(3), 11, m.nq, m.nv, True)
    taus = m.inverse_dynamics(q, v, a, threads=2)
    for k in range(len(q)):
        np.testing.assert_array_equal(taus[k], m.inverse_dynamics(q[k], v[k], a[k]))
    da_dq, da_dv, da_dtau, da_df = m.forward_dynamics_derivatives(q, v, np.zeros((11, 12)), np.zeros((3, 4)))
    assert da_dq.shape == (11, 18, 18) and da_dtau.shape == (11, 18, 12) and da_df.shape == (11, 18, 12)


def test_errors_name_the_argument(cheetah_model):
    m = cheetah_model
    q = np.zeros(19)
    q[3] = 1
    with pytest.raises(ValueError, match=r"rbdc: inverse_dynamics: v has shape \(17,\), expected \(18,\) or \(N, 18\)"):
        m.inverse_dynamics(q, np.zeros(17), np.zeros(18))
    with pytest.raises(TypeError, match="rbdc: mass_matrix: q has dtype complex128, expected float64 or float32"):
        m.mass_matrix(q.astype(complex))
    with pytest.raises(ValueError, match=r"rbdc: mass_matrix: q\[1\]: the quaternion q\[3:7\] has norm 0\.0+, expected a unit"):
        m.mass_matrix(np.stack([q, np.zeros(19)]))
    with pytest.raises(TypeError, match=r"takes \(q, v, a\)"):
        m.inverse_dynamics(q, np.zeros(18))
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # NaN in, NaN out: no exception, no warning
        bad = q.copy()
        bad[8] = np.nan
        assert np.isnan(m.mass_matrix(bad)).any()
