"""Batches of states on a Dask cluster: a compiled function mapped over dask arrays chunk by chunk.

    import rbdc, rbdc.dask, dask.array as da
    from dask.distributed import Client
    client = Client("tcp://scheduler:8786")        # or Client(LocalCluster(...))
    cheetah = rbdc.compile("robots/mini_cheetah.urdf")
    Q = da.from_array(states, chunks=(250_000, 19))
    M = rbdc.dask.map(cheetah, "mass_matrix", Q)   # lazy dask array (N, 18, 18)
    M.compute()

Dask does the scheduling; each chunk runs the compiled function's C++ batch loop. What travels to a
worker is the compile target (the robot, topology and scene files' bytes and options), so a worker
needs rbdc and a compiler but not the robot files; each worker process loads the module from its
user's cache once (building it on a miss, under the cache's file lock), then reuses it.
docs/python.md.
"""
import numpy as np
import dask.array as da

from .compiled import compile_target

_loaded = {}  # Target → module, per worker process


def _module(target):
    module = _loaded.get(target)
    if module is None:
        module = _loaded[target] = compile_target(target)
    return module


def _run_chunk(target, name, input_shapes, sizes, threads, *blocks):
    """One chunk on a worker: the function over its states (blocks of shape (n, entries)), the
    outputs flattened side by side."""
    blocks = [b.reshape((b.shape[0],) + shape) for b, shape in zip(blocks, input_shapes)]
    outputs = getattr(_module(target), name)(*blocks, threads=threads)
    outputs = outputs if isinstance(outputs, tuple) else (outputs,)
    n = blocks[0].shape[0]
    return np.concatenate([o.reshape(n, size) for o, size in zip(outputs, sizes)], axis=1)


def _output_shapes(module, name, inputs):
    """The outputs' one-state shapes, from a call on the first state of each input."""
    outputs = getattr(module, name)(*(np.asarray(x[:1]) for x in inputs))
    outputs = outputs if isinstance(outputs, tuple) else (outputs,)
    return [o.shape[1:] for o in outputs], outputs[0].dtype


def map(module, name, *states, threads=1):
    """The compiled function `name` of `module` (from rbdc.compile) over dask arrays of states (every
    input with a leading batch dimension N, chunked along it only); lazy, like any dask array: one
    dask array per output (a tuple when the function has several). `threads`: C++ threads per chunk
    (1: let Dask's workers and threads provide the parallelism)."""
    if name not in module.functions:
        raise ValueError(f"rbdc.dask.map: {module.robot}/{module.scene} has no function {name!r} "
                         f"(it has {', '.join(module.functions)})")
    target = module.target
    arrays = [x if isinstance(x, da.Array) else da.from_array(np.asarray(x)) for x in states]
    if any(x.ndim < 1 for x in arrays) or len({x.shape[0] for x in arrays}) != 1:
        raise ValueError(f"rbdc.dask.map: {name}: every input needs the same leading batch dimension N, got "
                         f"shapes {[x.shape for x in arrays]}")
    chunks = arrays[0].chunks[0]
    flat_inputs = [x.reshape(x.shape[0], -1).rechunk((chunks, -1)) for x in arrays]
    shapes, dtype = _output_shapes(module, name, [x[:1].compute() for x in arrays])
    sizes = [int(np.prod(s, dtype=int)) for s in shapes]
    flat = da.map_blocks(_run_chunk, target, name, [x.shape[1:] for x in arrays], sizes, threads, *flat_inputs,
                         dtype=dtype, chunks=(chunks, (sum(sizes),)))
    offsets = np.cumsum([0] + sizes)
    results = tuple(flat[:, offsets[k]:offsets[k + 1]].reshape((-1,) + shapes[k]) for k in range(len(shapes)))
    return results if len(results) > 1 else results[0]

