"""Wall.rebound against the C library's rw_rebound_batch on the same 10^6 hits (the Sec. 4
glass–steel wall, Sommerfeld–Huber, in a rotated frame), both on the same thread count:
medians of alternating rounds. Run by scripts/bench-python.sh."""

import datetime
import os
import pathlib
import platform
import statistics
import sys
import time

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "tests"))
import clib  # noqa: E402

import roughwall  # noqa: E402


def hits(n, seed=2021):
    rng = np.random.default_rng(seed)
    q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
    alpha = np.radians(rng.uniform(-60, -1, n))
    beta = np.radians(rng.uniform(-90, 90, n))
    speed = rng.normal(5.91, 1.16, n).clip(0.5)
    local = np.stack([np.cos(alpha) * np.cos(beta), np.sin(alpha), -np.cos(alpha) * np.sin(beta)], axis=1)
    velocity = (local * speed[:, None]) @ q.T
    normal = np.tile(q[:, 1], (n, 1))
    lay = np.tile(q[:, 0], (n, 1))
    return dict(velocity=np.ascontiguousarray(velocity), normal=normal, lay=lay,
                diameter=np.full(n, 500e-6), particle_id=np.arange(n, dtype=np.uint64),
                collision_index=np.zeros(n, dtype=np.uint64))


def main():
    n = int(os.environ.get("BENCH_HITS", 1_000_000))
    threads = int(os.environ.get("BENCH_THREADS", 2))
    rounds = int(os.environ.get("BENCH_ROUNDS", 7))
    kw = dict(delta_xi_deg=3.8, delta_zeta_deg=7.5, law="sommerfeld-huber", preset="glass-steel", seed=2021)
    wall = roughwall.Wall(**kw)
    cwall = clib.CWall(clib.load(), **kw)
    h = hits(n)
    cols, batch = cwall.batch_inputs(**h)
    py_t, c_t = [], []
    for _ in range(rounds):
        t0 = time.perf_counter()
        r = wall.rebound(**h, threads=threads)
        py_t.append(time.perf_counter() - t0)
        t0 = time.perf_counter()
        assert cwall.run_batch(batch, threads) == 0
        c_t.append(time.perf_counter() - t0)
    assert np.array_equal(r.velocity, clib.outputs(cols)[0]), "not the C library's rebounds"
    py, c = statistics.median(py_t), statistics.median(c_t)
    cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), platform.processor())
    print(f"date {datetime.date.today()}, CPU {cpu}, {os.cpu_count()} cores, {n} hits, {threads} threads, median of {rounds} alternating rounds")
    print(f"Wall.rebound       {py:.3f} s  {n / py / 1e6:.2f} M rebounds/s")
    print(f"rw_rebound_batch   {c:.3f} s  {n / c / 1e6:.2f} M rebounds/s")
    print(f"ratio (Python rate / C rate): {c / py:.3f} (target >= 0.8)")


if __name__ == "__main__":
    main()
