#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Configuration-space obstacles of one robot against many obstacles, as a
batch on dask.distributed.

A robot B that moves by translation collides with an obstacle A exactly when
its position t lies in C = A + (-B) (cvms.minkowski_difference(A, B)). Each
C is an independent exact sum, so a batch spreads over a cluster's workers:
the sets travel as their exact text (pickling), the sums run in the workers.

Without --scheduler the batch runs on a LocalCluster of worker processes on
this machine; with --scheduler tcp://host:8786 the same code runs on a real
cluster (every worker needs `import cvms`: scripts/python.sh on each).

    /usr/bin/python3 examples/python/cspace_batch_dask.py --obstacles 8
"""

import argparse
import logging
import random
from fractions import Fraction

import cvms


def make_obstacles(count, seed):
    """count random convex obstacles (hulls of 12 integer points) on a grid."""
    rng = random.Random(seed)
    obstacles = []
    for i in range(count):
        cx, cy = 10 * (i % 4), 10 * (i // 4)
        points = [(cx + rng.randint(-3, 3), cy + rng.randint(-3, 3), rng.randint(0, 4)) for _ in range(12)]
        obstacles.append(cvms.hull(points))
    return obstacles


def make_robot():
    """A small robot: a box with a pointed top, reference point at the origin."""
    return cvms.hull([(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0), (0, 0, Fraction(3, 2))])


def cspace_batch(client, robot, obstacles):
    """The configuration-space obstacles A + (-robot) of every obstacle A,
    computed by the client's workers; returned in the order of obstacles."""
    robot_on_workers = client.scatter(robot, broadcast=True)
    futures = client.map(cvms.minkowski_difference, obstacles, b=robot_on_workers, pure=False)
    return client.gather(futures)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--scheduler", help="address of a dask scheduler (default: a LocalCluster here)")
    parser.add_argument("--workers", type=int, default=2, help="LocalCluster worker processes (default 2)")
    parser.add_argument("--obstacles", type=int, default=8, help="number of obstacles (default 8)")
    parser.add_argument("--seed", type=int, default=1, help="seed of the obstacles (default 1)")
    args = parser.parse_args()

    from dask.distributed import Client, LocalCluster  # Debian: python3-distributed

    robot, obstacles = make_robot(), make_obstacles(args.obstacles, args.seed)
    if args.scheduler:
        client = Client(args.scheduler)
        cluster = None
    else:
        cluster = LocalCluster(n_workers=args.workers, threads_per_worker=1, processes=True,
                               dashboard_address=None, silence_logs=logging.ERROR)
        client = Client(cluster)
    try:
        spaces = cspace_batch(client, robot, obstacles)
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    for i, (obstacle, space) in enumerate(zip(obstacles, spaces)):
        # the robot at the origin's configuration t = (x, y, 0) collides iff t is in the space
        probe = (10 * (i % 4), 10 * (i // 4), 0)
        print(f"obstacle {i}: {obstacle.num_vertices} vertices -> C-space obstacle with "
              f"{space.num_vertices} vertices, {len(space.faces)} facets, volume {space.volume()}, "
              f"robot at {probe} {'collides' if space.contains(probe) else 'is free'}")


if __name__ == "__main__":
    main()
