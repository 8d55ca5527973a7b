"""The measured-wall model from Python: a table built from a height array, the wall that
reads it bit for bit the C library's, and its refusals the C library's messages."""

import numpy as np
import pytest

import roughwall
from clib import CWall, outputs
from conftest import random_hits

MEASURED_WALL = roughwall.MODELS.index("measured-wall")


@pytest.fixture(scope="module")
def table():
    s = roughwall.surface(length_m=128e-6, nodes=128, rms_height_m=0.37e-6,
                          corr_length_x_m=12e-6, corr_length_z_m=4e-6, seed=3)
    dx = 128e-6 / 128
    return roughwall.measured_wall_table(s.heights, dx=dx, dy=dx, histories_per_cell=1024, seed=5)


def test_the_table_is_the_same_for_any_thread_count(table):
    s = roughwall.surface(length_m=128e-6, nodes=128, rms_height_m=0.37e-6,
                          corr_length_x_m=12e-6, corr_length_z_m=4e-6, seed=3)
    dx = 128e-6 / 128
    again = roughwall.measured_wall_table(s.heights, dx=dx, dy=dx, histories_per_cell=1024, seed=5, threads=1)
    assert again == table
    assert table.startswith("# roughwall measured-wall table v5\n")


def test_every_bit_is_the_c_librarys(c_library, table):
    hits = random_hits(20_000, seed=11)
    cwall = CWall(c_library, model=MEASURED_WALL, seed=4, wall_table=table)
    assert cwall.status == 0, cwall.message
    cols, batch = cwall.batch_inputs(**hits)
    assert cwall.run_batch(batch, 1) == 0
    expected = outputs(cols)
    wall = roughwall.Wall(model="measured-wall", wall_table=table, seed=4)
    got = wall.rebound(**hits, threads=2)
    for name, a, b in zip(roughwall.Rebound._fields, got, expected):
        assert np.array_equal(a.view(np.uint8), np.ascontiguousarray(b).view(np.uint8)), name
    assert (got.status == roughwall.OK).mean() > 0.4
    # Elastic: the speed relative to the wall is kept, hit by hit.
    ok = got.status == roughwall.OK
    rel_in = hits["velocity"][ok] - hits["wall_velocity"][ok]
    rel_out = got.velocity[ok] - hits["wall_velocity"][ok]
    assert np.allclose(np.linalg.norm(rel_in, axis=1), np.linalg.norm(rel_out, axis=1), rtol=1e-12)


@pytest.mark.parametrize("wall_table, words", [(None, "needs `stochastic.wall_table`"),
                                               ("alpha,beta\n", "not a measured-wall table")])
def test_a_missing_or_bad_table_is_the_c_librarys_message(c_library, wall_table, words):
    cw = CWall(c_library, model=MEASURED_WALL, wall_table=wall_table)
    assert cw.status == 3  # RW_INVALID_PARAMETER
    with pytest.raises(ValueError) as e:
        roughwall.Wall(model="measured-wall", wall_table=wall_table)
    assert str(e.value) == cw.message and words in str(e.value)
    assert "\n" not in str(e.value)


def test_a_table_argument_that_does_not_apply_is_refused():
    with pytest.raises(ValueError, match="applies to model = \"measured-wall\" only"):
        roughwall.Wall(delta_xi_deg=2.0, delta_zeta_deg=3.0, wall_table="x")
