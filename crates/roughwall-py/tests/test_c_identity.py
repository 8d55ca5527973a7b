"""Wall.rebound against the C library: every output bit for bit, for 10^5 keys."""

import numpy as np
import pytest

import roughwall
from clib import CWall, outputs
from conftest import random_hits

WALLS = [
    dict(kw=dict(delta_xi_deg=3.8, delta_zeta_deg=7.5, law="sommerfeld-huber", preset="glass-steel", seed=2021), model=0),
    dict(kw=dict(delta_xi_deg=2.5, delta_zeta_deg=7.5, seed=7), model=0),
    dict(kw=dict(delta_xi_deg=0.0, delta_zeta_deg=0.0, law="sommerfeld-huber", preset="glass-steel"), model=0),
    dict(kw=dict(delta_xi_deg=5.0, delta_zeta_deg=5.0, model="calibrated", seed=3), model=5),
]


@pytest.mark.parametrize("case", WALLS, ids=["glass-steel", "elastic", "smooth-sh", "calibrated"])
def test_every_bit_is_the_c_librarys(c_library, case):
    n = 100_000 if case["model"] == 0 and case["kw"].get("seed") == 2021 else 20_000
    hits = random_hits(n, seed=len(case["kw"]))
    kw = dict(case["kw"])
    cwall = CWall(c_library, model=case["model"], **{k: v for k, v in kw.items() if k != "model"})
    assert cwall.status == 0, cwall.message
    cols, batch = cwall.batch_inputs(**hits)
    assert cwall.run_batch(batch, 1) == 0
    expected = outputs(cols)
    got = roughwall.Wall(**kw).rebound(**hits, threads=2, element_angle=True)
    for name, a, b in zip(roughwall.Rebound._fields, got, expected):
        assert a.dtype == b.dtype or name == "status", name
        assert np.array_equal(a.view(np.uint8), np.ascontiguousarray(b).view(np.uint8)), name
    assert (got.status == roughwall.OK).mean() > 0.4
    # A few single rw_rebound calls too.
    for i in range(0, n, n // 50):
        r = cwall.rebound_one(hits["velocity"][i], hits["normal"][i], hits["lay"][i], hits["diameter"][i],
                              int(hits["particle_id"][i]), int(hits["collision_index"][i]),
                              hits["spin"][i], hits["wall_velocity"][i])
        assert list(r.velocity) == list(got.velocity[i]) and r.status == got.status[i]
        # The facet's impact angle: the C library's rw_element_impact_angle, bit for bit.
        a = cwall.element_angle(hits["velocity"][i], hits["normal"][i], hits["lay"][i], hits["diameter"][i],
                                int(hits["particle_id"][i]), int(hits["collision_index"][i]),
                                hits["spin"][i], hits["wall_velocity"][i])
        assert a == got.alpha_element[i]
    assert np.all(np.isfinite(got.alpha_element)) and np.all(got.alpha_element <= np.pi / 2)
    assert np.all(got.alpha_element[got.status != roughwall.OK] == 0.0)
    # Not asked for: not computed, and every other output the same.
    plain = roughwall.Wall(**kw).rebound(**hits, threads=2)
    assert plain.alpha_element is None
    for name, a, b in zip(roughwall.Rebound._fields[:-1], plain, got):
        assert np.array_equal(a, b), name


@pytest.mark.parametrize(
    "kw",
    [dict(delta_xi_deg=25.0), dict(delta_xi_deg=float("nan")), dict(delta_zeta_deg=-1.0),
     dict(psi=0.0), dict(psi=1e9), dict(law="sommerfeld-huber", preset="glass-steel", e_h=1.5),
     dict(law="sommerfeld-huber", preset="glass-steel", mu_0=-0.1), dict(law="elastic", e_h=0.5)],
)
def test_a_bad_parameter_is_the_c_librarys_message(c_library, kw):
    cw = CWall(c_library, **kw)
    assert cw.status == 3  # RW_INVALID_PARAMETER
    with pytest.raises(ValueError) as e:
        roughwall.Wall(**kw)
    assert str(e.value) == cw.message
    assert "\n" not in str(e.value)


def test_a_warning_is_the_c_librarys(c_library):
    cw = CWall(c_library, delta_xi_deg=9.0)
    with pytest.warns(roughwall.RoughwallWarning) as w:
        wall = roughwall.Wall(delta_xi_deg=9.0)
    assert str(w[0].message) == cw.message
    assert wall.warnings == [cw.message]
