"""Bad hits are statuses; bad arguments are one-line exceptions; nothing crashes."""

import numpy as np
import pytest

import roughwall

W = roughwall.Wall(delta_xi_deg=3.0, delta_zeta_deg=6.0, law="sommerfeld-huber", preset="glass-steel", seed=1)
V, N, L = [5.0, -1.0, 0.5], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]
KEY = dict(diameter=1e-4, particle_id=1, collision_index=0)


@pytest.mark.parametrize(
    "change,status",
    [
        (dict(velocity=[np.nan, -1.0, 0.0]), roughwall.INVALID_INPUT),
        (dict(velocity=[np.inf, -1.0, 0.0]), roughwall.INVALID_INPUT),
        (dict(normal=[0.0, 0.0, 0.0]), roughwall.INVALID_INPUT),
        (dict(lay=[0.0, 2.0, 0.0]), roughwall.INVALID_INPUT),
        (dict(diameter=-1.0), roughwall.INVALID_INPUT),
        (dict(diameter=np.nan), roughwall.INVALID_INPUT),
        (dict(spin=[0.0, np.nan, 0.0]), roughwall.INVALID_INPUT),
        (dict(wall_velocity=[0.0, -np.inf, 0.0]), roughwall.INVALID_INPUT),
        (dict(velocity=[5.0, 0.0, 1.0]), roughwall.NOT_APPROACHING),
        (dict(velocity=[0.0, 0.0, 0.0]), roughwall.NOT_APPROACHING),
    ],
)
def test_a_bad_hit_is_a_status_with_finite_outputs(change, status):
    args = dict(velocity=V, normal=N, lay=L, **KEY)
    args.update(change)
    r = W.rebound(args.pop("velocity"), args.pop("normal"), args.pop("lay"), **args)
    assert r.status == status
    assert np.isfinite(r.velocity).all() and np.isfinite(r.spin).all()
    # In a batch, the good hits around it are rebounded.
    n = 5
    batch = dict(velocity=np.tile(V, (n, 1)), normal=np.tile(N, (n, 1)), lay=np.tile(L, (n, 1)),
                 spin=np.zeros((n, 3)), wall_velocity=np.zeros((n, 3)), diameter=np.full(n, 1e-4),
                 particle_id=np.arange(n), collision_index=0)
    for k, v in change.items():
        batch[k][2] = v
    r = W.rebound(batch.pop("velocity"), batch.pop("normal"), batch.pop("lay"), **batch)
    assert r.status[2] == status and (np.delete(r.status, 2) == roughwall.OK).all()


@pytest.mark.parametrize(
    "args,exc,words",
    [
        (dict(velocity=np.zeros((4, 2))), ValueError, "`velocity` has shape (4, 2)"),
        (dict(velocity=np.zeros((2, 3, 3))), ValueError, "`velocity` has shape"),
        (dict(normal=np.zeros(4)), ValueError, "`normal` has shape (4,)"),
        (dict(velocity=np.ones((4, 3)), normal=np.ones((5, 3))), ValueError, "do not broadcast"),
        (dict(velocity=np.ones(3, dtype=complex)), TypeError, "dtype complex128"),
        (dict(velocity=["a", "b", "c"]), TypeError, "`velocity` has dtype"),
        (dict(velocity=np.ones(3, dtype=bool)), TypeError, "dtype bool"),
        (dict(particle_id=1.5), TypeError, "`particle_id` has dtype float64"),
        (dict(particle_id=-3), ValueError, "invalid `particle_id` = -3"),
        (dict(particle_id=2**70), ValueError, "invalid `particle_id`"),
        (dict(collision_index=np.array([1.0, 2.0])), TypeError, "`collision_index` has dtype"),
        (dict(diameter=np.ones((2, 2))), ValueError, "`diameter` has shape (2, 2)"),
        (dict(threads=0), ValueError, "invalid `threads` = 0"),
        (dict(threads=2.5), TypeError, "`threads`"),
    ],
)
def test_a_bad_argument_is_one_line_naming_it(args, exc, words):
    a = dict(velocity=V, normal=N, lay=L, **KEY)
    a.update(args)
    with pytest.raises(exc) as e:
        W.rebound(a.pop("velocity"), a.pop("normal"), a.pop("lay"), **a)
    assert words in str(e.value) and "\n" not in str(e.value)


def test_non_contiguous_and_other_dtypes_give_the_same_rebounds():
    n = 500
    rng = np.random.default_rng(0)
    v = rng.normal(size=(n, 3)) + [0, -3, 0]
    base = W.rebound(v, N, L, diameter=1e-4, particle_id=np.arange(n), collision_index=0)
    fortran = np.asfortranarray(v)
    strided = np.zeros((n, 6))
    strided[:, ::2] = v
    for other in (fortran, strided[:, ::2], v.tolist(), v[::1]):
        r = W.rebound(other, N, L, diameter=1e-4, particle_id=np.arange(n, dtype=np.int32), collision_index=0)
        assert np.array_equal(r.velocity, base.velocity)
    r = W.rebound(v[::-1], N, L, diameter=1e-4, particle_id=np.arange(n)[::-1], collision_index=0)
    assert np.array_equal(r.velocity[::-1], base.velocity)
    single = W.rebound(v.astype(np.float32), N, L, diameter=1e-4, particle_id=np.arange(n), collision_index=0)
    assert (single.status == roughwall.OK).all()
    ints = W.rebound(np.array([5, -1, 0]), np.array([0, 1, 0]), np.array([1, 0, 0]), **KEY)
    assert ints.status == roughwall.OK


def test_no_hits_is_empty_arrays():
    r = W.rebound(np.zeros((0, 3)), N, L, diameter=1e-4, particle_id=0, collision_index=0)
    assert r.velocity.shape == (0, 3) and r.status.shape == (0,)


@pytest.mark.parametrize(
    "kw,exc,words",
    [
        (dict(delta_xi_deg="3"), TypeError, "`delta_xi_deg` = '3'"),
        (dict(seed=-1), ValueError, "invalid `seed` = -1"),
        (dict(seed=1.5), TypeError, "`seed`"),
        (dict(model="nope"), ValueError, "invalid `stochastic.model`"),
        (dict(law="elastic", preset="glass-steel"), ValueError, "preset"),
    ],
)
def test_a_bad_wall_argument_is_one_line(kw, exc, words):
    with pytest.raises(exc) as e:
        roughwall.Wall(**kw)
    assert words in str(e.value) and "\n" not in str(e.value)
