# SPDX-License-Identifier: MIT
"""Sums from two Python threads at once: the same results, and the GIL is
released while the C++ library works."""

import threading
import time

import cvms


def test_two_threads_summing_at_once_give_the_same_results():
    a, b = cvms.geodesic_sphere(3), cvms.geodesic_sphere(3, rotated=True)
    c = cvms.cube()
    expected = [a + b, a + c]
    results = [None, None]
    barrier = threading.Barrier(2)

    def work(i):
        barrier.wait()
        for _ in range(3):
            results[i] = [a + b, a + c]

    threads = [threading.Thread(target=work, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert results[0] == expected and results[1] == expected


def test_the_gil_is_released_during_a_sum():
    a, b = cvms.geodesic_sphere(5), cvms.geodesic_sphere(5, rotated=True)
    calls = 10
    done = threading.Event()

    def work():
        for _ in range(calls):
            cvms.minkowski_sum(a, b)
        done.set()

    worker = threading.Thread(target=work)
    worker.start()
    ticks = 0
    while not done.is_set():
        time.sleep(0.001)  # needs the GIL to wake up
        ticks += 1
    worker.join()
    # A sum that held the GIL would let this loop run at most about once
    # between two calls; released, it runs every millisecond or two of the
    # calls (some 15 ms each).
    assert ticks >= 3 * calls, ticks
