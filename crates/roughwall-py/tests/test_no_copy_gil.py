"""What issue 32 promises about the cost of a call: a C-contiguous float64 array reaches the
extension as it is (no copy), and the GIL is released while the hits run."""

import threading

import numpy as np

import roughwall
from roughwall import _args


def test_contiguous_float64_arrays_are_not_copied():
    v = np.random.default_rng(1).normal(size=(1000, 3))
    a, n = _args.vec3("velocity", v)
    assert n == 1000 and a is v
    d = np.full(1000, 1e-4)
    b, _ = _args.per_hit_float("diameter", d)
    assert b is d
    # what does need a copy gets one: another dtype, a strided view
    c, _ = _args.vec3("velocity", v.astype(np.float32))
    assert not np.shares_memory(c, v)
    s, _ = _args.vec3("velocity", np.asfortranarray(v))
    assert s.flags["C_CONTIGUOUS"]


def test_the_gil_is_released_while_the_hits_run():
    wall = roughwall.Wall(delta_xi_deg=3.8, delta_zeta_deg=7.5, law="sommerfeld-huber",
                          preset="glass-steel", seed=3)
    n = 600_000
    rng = np.random.default_rng(2)
    velocity = np.column_stack([rng.uniform(1, 10, n), -rng.uniform(0.1, 3, n), np.zeros(n)])
    ids = np.arange(n, dtype=np.uint64)
    ticks = 0
    stop = False

    def count():
        nonlocal ticks
        while not stop:
            ticks += 1

    t = threading.Thread(target=count)
    t.start()
    try:
        before = ticks
        wall.rebound(velocity, [0.0, 1.0, 0.0], [1.0, 0.0, 0.0], diameter=1e-4,
                     particle_id=ids, collision_index=0, threads=1)
        during = ticks - before
        print(f"counting thread: {during} ticks during the call")
    finally:
        stop = True
        t.join()
    # With the GIL held for the whole call the other thread could not count at all (it
    # would get the GIL back only after the call); released, it counts all along.
    assert during > 50_000, f"the counting thread advanced {during} times during the call"
