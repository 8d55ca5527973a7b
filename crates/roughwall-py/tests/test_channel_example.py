"""The example client examples/python/channel.py, run small: its figure, and energy
conservation on a smooth elastic wall."""

import importlib.util

import numpy as np

import roughwall


def load(repo):
    spec = importlib.util.spec_from_file_location("channel", repo / "examples/python/channel.py")
    m = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(m)
    return m


def test_a_smooth_elastic_wall_conserves_energy(repo):
    channel = load(repo)
    run = channel.simulate(roughwall.Wall(), particles=300, steps=3000, drag=False, gravity=0.0)
    assert run["hits"] > 300
    e0, e1 = run["energy"]
    assert abs(e1 / e0 - 1) < 1e-13
    inc, reb = run["incident"], run["rebounded"]
    assert np.array_equal((inc ** 2).sum(axis=1), (reb ** 2).sum(axis=1))
    assert np.array_equal(reb[:, 1], -inc[:, 1])


def test_a_rough_elastic_wall_conserves_energy_at_each_hit(repo):
    channel = load(repo)
    wall = roughwall.Wall(delta_xi_deg=3.8, delta_zeta_deg=7.5, seed=2)
    run = channel.simulate(wall, particles=300, steps=3000, drag=False, gravity=0.0)
    inc, reb = run["incident"], run["rebounded"]
    ratio = (reb ** 2).sum(axis=1) / (inc ** 2).sum(axis=1)
    assert np.abs(ratio - 1).max() < 1e-12
    # The rough wall turns some wall-normal motion into spanwise motion.
    assert np.abs(reb[:, 2] - inc[:, 2]).max() > 0.01


def test_the_example_writes_its_figure(repo, tmp_path):
    channel = load(repo)
    out = tmp_path / "channel.svg"
    channel.main(["--particles", "200", "--steps", "300", "--out", str(out)])
    text = out.read_text()
    assert text.startswith("<?xml") and "<svg" in text and len(text) > 10_000
