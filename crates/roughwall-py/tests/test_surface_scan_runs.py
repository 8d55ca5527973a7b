"""Surfaces, scans, wall cards and runs: the library's numbers, the command line's outputs."""

import csv
import subprocess
import tomllib

import numpy as np
import pytest

import roughwall


def test_a_surface_has_its_rms_height_and_eq15_deviations():
    s = roughwall.surface(length_m=1024e-6, nodes=512, rms_height_m=0.37e-6, corr_length_x_m=12e-6,
                          corr_length_z_m=4e-6, seed=1)
    assert s.heights.shape == (512, 512) and s.dx == s.dz == 2e-6
    assert abs(s.heights.std() / 0.37e-6 - 1) < 0.05
    slope_z = np.diff(s.heights, axis=0) / s.dz
    delta_zeta = np.degrees(np.sqrt(2) * 0.37e-6 / 4e-6)  # Eq. 15
    assert abs(np.degrees(np.arctan(slope_z.std())) / delta_zeta - 1) < 0.1
    again = roughwall.surface(length_m=1024e-6, nodes=512, rms_height_m=0.37e-6, corr_length_x_m=12e-6,
                              corr_length_z_m=4e-6, seed=1, threads=1)
    assert np.array_equal(again.heights, s.heights)
    two_d = roughwall.surface(length_m=1e-3, nodes=64, rms_height_m=1e-6, corr_length_x_m=50e-6, corr_length_z_m=None)
    assert two_d.heights.shape == (1, 64)


@pytest.mark.parametrize(
    "kw,words",
    [(dict(nodes=8), "invalid `nodes` = 8"), (dict(length_m=-1.0), "invalid `length_m` = -1"),
     (dict(corr_length_x_m=1e-9), "rms slope"), (dict(rms_height_m=float("nan")), "rms_height_m")],
)
def test_a_bad_surface_is_one_line(kw, words):
    args = dict(length_m=1e-3, nodes=64, rms_height_m=1e-6, corr_length_x_m=50e-6, corr_length_z_m=50e-6)
    args.update(kw)
    with pytest.raises(ValueError) as e:
        roughwall.surface(**args)
    assert words in str(e.value)


def test_the_wall_card_is_rebound_scans(repo, rebound_bin, tmp_path):
    scan = repo / "tests/data/scans/x3p-2.x3p"
    out = tmp_path / "scan"
    subprocess.run([rebound_bin, "scan", "--scan", str(scan), "--diameter-um", "500", "--out", str(out),
                    "--quiet"], check=True)
    card = tomllib.loads((out / "wall_card.toml").read_text())
    py = roughwall.wall_card(scan, diameters_m=[500e-6])
    for k in ("delta_xi_deg", "delta_zeta_deg"):
        # The card holds 7 significant digits.
        assert py["wall"][k] == pytest.approx(card["wall"][k], rel=6e-7)
        assert py["diameters"][1][k] == pytest.approx(card["diameter"][0][k], rel=6e-7)
    assert py["lay"]["angle_deg"] == pytest.approx(card["lay"]["angle_deg"], rel=6e-7)
    assert py["notes"] == card["notes"]
    assert "; ".join(n.split(": the scan is ", 1)[1] for n in py["diameters"][1]["notes"]) == card["diameter"][0]["note"]
    s = roughwall.read_scan(scan)
    assert s.format == "x3p" and s.heights.ndim == 2
    again = roughwall.wall_card(s.heights, dx=s.dx, dy=s.dy, diameters_m=[500e-6], threads=1)
    assert again["wall"] == py["wall"] and again["notes"] == py["notes"]


def test_a_bad_scan_is_one_line(tmp_path):
    with pytest.raises(OSError) as e:
        roughwall.read_scan(tmp_path / "none.x3p")
    assert "none.x3p" in str(e.value)
    bad = tmp_path / "bad.x3p"
    bad.write_bytes(b"PK\x03\x04 not a zip")
    with pytest.raises(ValueError):
        roughwall.read_scan(bad)
    with pytest.raises(ValueError) as e:
        roughwall.read_scan(bad, format="nope")
    assert "invalid `format`" in str(e.value)
    with pytest.raises(ValueError):
        roughwall.wall_card(np.full((4, 4), np.nan), dx=1e-6, dy=1e-6)


def summary(path):
    with open(path) as f:
        return list(csv.DictReader(f))


@pytest.mark.parametrize("model", ["stochastic", "deterministic"])
def test_a_run_is_the_command_lines(repo, rebound_bin, tmp_path, model):
    case = tmp_path / "case.toml"
    case.write_text(
        'name = "py"\nseed = 2021\n[wall]\ndelta_xi_deg = 2.5\ndelta_zeta_deg = 7.5\n'
        "[incidence]\nalpha_deg = [-12.5, -32.5]\nbeta_deg = [0.0, 60.0]\n[particles]\ncount = 20000\n"
        '[collision]\nmodel = "elastic"\n[deterministic]\nside_per_corr_length = 20\n'
    )
    out = tmp_path / model
    subprocess.run([rebound_bin, model, "--case", str(case), "--out", str(out), "--quiet"], check=True)
    rows = summary(out / "summary.csv")
    wall = roughwall.Wall(delta_xi_deg=2.5, delta_zeta_deg=7.5, seed=2021)
    conditions = [(-12.5, 0.0), (-12.5, 60.0), (-32.5, 0.0), (-32.5, 60.0)]
    kw = dict(conditions=conditions, particles=20000)
    if model == "stochastic":
        res = roughwall.stochastic(wall, **kw)
    else:
        res = roughwall.deterministic(wall, side_per_corr_length=20, **kw)
    assert len(rows) == 4
    for k, row in enumerate(rows):
        assert (float(row["alpha_in_deg"]), float(row["beta_in_deg"])) == conditions[k]
        assert int(row["particles"]) == res["particles"][k]
        for q in ("alpha_out", "dbeta", "gamma"):
            col = f"mean_{q}_deg"
            name = "gamma_first" if q == "gamma" else q
            assert res["mean"][name][k] == pytest.approx(float(row[col]), rel=6e-7, abs=1e-12), (k, q)
        assert res["se"]["alpha_out"][k] > 0
    pdf = res["pdfs"][0]["alpha_out"]
    widths = pdf["hi_deg"] - pdf["lo_deg"]
    assert (pdf["value"] * widths).sum() == pytest.approx(1.0, rel=1e-9)


def test_runs_do_not_depend_on_the_thread_count():
    wall = roughwall.Wall(delta_xi_deg=3.8, delta_zeta_deg=7.5, law="sommerfeld-huber", preset="glass-steel", seed=3)
    a = roughwall.stochastic(wall, conditions=[(-5.0, 30.0)], particles=70_000, threads=1)
    b = roughwall.stochastic(wall, conditions=[(-5.0, 30.0)], particles=70_000, threads=2)
    for q in a["mean"]:
        assert np.array_equal(a["mean"][q], b["mean"][q], equal_nan=True)
    with pytest.raises(ValueError) as e:
        roughwall.stochastic(wall, conditions=[(5.0, 0.0)])
    assert "invalid `alpha_in_deg` = 5" in str(e.value)
