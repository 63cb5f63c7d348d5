"""rbdc.dask: a compiled function over a dask array on a dask.distributed LocalCluster."""
import numpy as np
import pytest

import rbdc
from conftest import random_states

da = pytest.importorskip("dask.array")
distributed = pytest.importorskip("dask.distributed")
import rbdc.dask  # noqa: E402


def test_map_on_a_local_cluster(arm7):
    q, v, a = random_states(np.random.default_rng(9), 5000, arm7.nq, arm7.nv, False)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=False,
                                  dashboard_address=None) as cluster, distributed.Client(cluster):
        Q, V, A = (da.from_array(x, chunks=(1000, -1)) for x in (q, v, a))
        tau = rbdc.dask.map(arm7, "inverse_dynamics", Q, V, A)
        M = rbdc.dask.map(arm7, "mass_matrix", Q)
        assert tau.shape == (5000, 7) and M.shape == (5000, 7, 7)
        np.testing.assert_array_equal(tau.compute(), arm7.inverse_dynamics(q, v, a))
        np.testing.assert_array_equal(M.compute(), arm7.mass_matrix(q))


def test_map_refuses_unknown_functions_and_ragged_batches(arm7):
    q = da.zeros((10, 7), chunks=5)
    with pytest.raises(ValueError, match="has no function 'bias'"):
        rbdc.dask.map(arm7, "bias", q)
    with pytest.raises(ValueError, match="same leading batch dimension"):
        rbdc.dask.map(arm7, "inverse_dynamics", q, q[:9], q)
