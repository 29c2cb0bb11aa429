# SPDX-License-Identifier: MIT
"""The configuration-space batch of examples/python/cspace_batch_dask.py on a
dask.distributed LocalCluster of two worker processes."""

import importlib.util
import logging
import pathlib

import pytest

import cvms

distributed = pytest.importorskip("dask.distributed")

EXAMPLE = pathlib.Path(__file__).resolve().parents[2] / "examples" / "python" / "cspace_batch_dask.py"


def load_example():
    spec = importlib.util.spec_from_file_location("cspace_batch_dask", EXAMPLE)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_cspace_batch_on_a_local_cluster_of_processes():
    example = load_example()
    robot, obstacles = example.make_robot(), example.make_obstacles(5, seed=3)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None,
                                  silence_logs=logging.ERROR) as cluster, distributed.Client(cluster) as client:
        spaces = example.cspace_batch(client, robot, obstacles)
        # the workers are other processes, with their own copy of the module
        worker_pids = set(client.run(lambda: __import__("os").getpid()).values())
    assert len(worker_pids) == 2
    assert len(spaces) == len(obstacles)
    for obstacle, space in zip(obstacles, spaces):
        assert space == cvms.minkowski_difference(obstacle, robot)
        assert space == obstacle + (-robot)
        # a configuration collides iff the moved robot meets the obstacle
        for t in [v for v in space.exact_vertices()[:3]]:
            assert cvms.intersects(obstacle, robot.translated(t))
            assert not cvms.intersects(obstacle, robot.translated((t[0] + 100, t[1], t[2])))
