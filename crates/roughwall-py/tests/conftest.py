"""Fixtures of the Python package's tests: the C library (ROUGHWALL_CLIB) and the command
line (REBOUND_BIN) the package is checked against, and random hits. A missing reference is
a failed test naming how to provide it, never a skipped one."""

from __future__ import annotations

import os
import pathlib
import sys

import numpy as np
import pytest

sys.path.insert(0, str(pathlib.Path(__file__).parent))
import clib  # noqa: E402

REPO = pathlib.Path(__file__).resolve().parents[3]


@pytest.fixture(scope="session")
def c_library():
    return clib.load()


@pytest.fixture(scope="session")
def rebound_bin():
    path = os.environ.get("REBOUND_BIN")
    if not path or not os.path.exists(path):
        pytest.fail(f"REBOUND_BIN={path!r}: set it to the rebound binary (cargo build --release)")
    return path


@pytest.fixture(scope="session")
def repo():
    return REPO


def random_unit(rng, n):
    v = rng.normal(size=(n, 3))
    return v / np.linalg.norm(v, axis=1)[:, None]


def random_hits(n, seed=1):
    """n hits of random directions, normals of either orientation, lay directions, spins,
    wall velocities, diameters and keys."""
    rng = np.random.default_rng(seed)
    normal = random_unit(rng, n) * rng.uniform(0.5, 2.0, size=(n, 1))
    lay = random_unit(rng, n)
    velocity = rng.normal(scale=5.0, size=(n, 3))
    spin = rng.normal(scale=300.0, size=(n, 3))
    wall_velocity = rng.normal(scale=0.3, size=(n, 3))
    diameter = rng.uniform(50e-6, 1e-3, size=n)
    pid = rng.integers(0, 2**63, size=n, dtype=np.uint64) * np.uint64(2) + np.uint64(1)
    cix = rng.integers(0, 50, size=n, dtype=np.uint64)
    return dict(velocity=velocity, normal=normal, lay=lay, spin=spin, wall_velocity=wall_velocity,
                diameter=diameter, particle_id=pid, collision_index=cix)
