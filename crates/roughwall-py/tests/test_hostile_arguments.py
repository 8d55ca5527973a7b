"""Hostile arguments and huge batches (issue 42): every argument of the public API names
itself in every error, whatever Python hands it (an int too large for a float or for 64 bits,
NaN, infinity, a string, None, a list, any object); outputs larger than the memory the process
may use are a MemoryError naming the argument, never an abort of the interpreter."""

import subprocess
import sys
import textwrap

import numpy as np
import pytest

import roughwall

HOSTILE = {
    "1e400": 10**400,
    "-1e400": -(10**400),
    "nan": float("nan"),
    "inf": float("inf"),
    "2**64": 2**64,
    "-1": -1,
    "str": "x",
    "None": None,
    "list": [],
    "object": object(),
}

#: Values no numeric argument may accept: not a number, or no float or 64-bit integer.
NEVER_ACCEPTED = {"1e400", "-1e400", "str", "list", "object"}

V, N, L = [5.0, -1.0, 0.5], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]
SH = dict(law="sommerfeld-huber", e_h=0.8, alpha_e_deg=20.0, mu_0=0.3, mu_h=0.2, alpha_mu_deg=20.0)
WALL = roughwall.Wall(delta_xi_deg=3.0, delta_zeta_deg=6.0, seed=1)
SCENE = dict(conditions=[(-30.0, 0.0)], particles=20)
DET = dict(SCENE, side_per_corr_length=4.0, spacing_per_corr_length=4.0)
HEIGHTS = np.random.default_rng(1).normal(scale=1e-7, size=(8, 8))


def _rebound(**kw):
    args = dict(velocity=V, normal=N, lay=L, diameter=1e-4, particle_id=1, collision_index=0)
    args.update(kw)
    return WALL.rebound(args.pop("velocity"), args.pop("normal"), args.pop("lay"), **args)


def _matrix_file(tmp_path):
    p = tmp_path / "scan.txt"
    np.savetxt(p, HEIGHTS * 1e6)
    return p


def targets(tmp_path):
    """(function, argument, call(value)): every numeric or named argument of the public
    API, and the elements of its pairs and lists; the other arguments valid."""
    scan = _matrix_file(tmp_path)
    out = []

    def add(fn, arg, call):
        out.append((fn, arg, call))

    for arg in ("delta_xi_deg", "delta_zeta_deg", "psi", "seed", "law", "preset", "model", "escape_table"):
        add("Wall", arg, lambda v, arg=arg: roughwall.Wall(**{arg: v}))
    for arg in ("e_h", "alpha_e_deg", "mu_0", "mu_h", "alpha_mu_deg"):
        add("Wall", arg, lambda v, arg=arg: roughwall.Wall(**dict(SH, **{arg: v})))
    add("Wall", "delta_gamma_deg", lambda v: roughwall.Wall(model="sommerfeld-huber-1999", delta_gamma_deg=v))
    for arg in ("velocity", "normal", "lay", "spin", "wall_velocity"):
        add("Wall.rebound", arg, lambda v, arg=arg: _rebound(**{arg: v}))
        add("Wall.rebound", arg, lambda v, arg=arg: _rebound(**{arg: [1.0, v, 0.0]}))
    for arg in ("diameter", "particle_id", "collision_index", "threads"):
        add("Wall.rebound", arg, lambda v, arg=arg: _rebound(**{arg: v}))
    for arg in ("diameter", "particle_id", "collision_index"):
        add("Wall.rebound", arg, lambda v, arg=arg: _rebound(**{arg: [v, v]}))
    grid = dict(length_m=1e-3, nodes=32, rms_height_m=1e-6, corr_length_x_m=200e-6, corr_length_z_m=200e-6)
    for arg in list(grid) + ["seed", "threads"]:
        add("surface", arg, lambda v, arg=arg: roughwall.surface(**dict(grid, **{arg: v})))
    mat = dict(format="matrix", pixel_m=(1e-6, 1e-6), height_unit_m=1e-6)
    add("read_scan", "path", lambda v: roughwall.read_scan(v, **mat))
    for arg in mat:
        add("read_scan", arg, lambda v, arg=arg: roughwall.read_scan(scan, **dict(mat, **{arg: v})))
    add("read_scan", "pixel_m", lambda v: roughwall.read_scan(scan, **dict(mat, pixel_m=(v, 1e-6))))
    add("read_scan", "pixel_m", lambda v: roughwall.read_scan(scan, **dict(mat, pixel_m=(1e-6, v))))
    card = dict(dx=1e-6, dy=1e-6, diameters_m=[1e-5], level_degree=1, threads=1)
    add("wall_card", "scan", lambda v: roughwall.wall_card(v, **card))
    add("wall_card", "scan", lambda v: roughwall.wall_card([[v] + row[1:] for row in HEIGHTS.tolist()], **card))
    for arg in card:
        add("wall_card", arg, lambda v, arg=arg: roughwall.wall_card(HEIGHTS, **dict(card, **{arg: v})))
    add("wall_card", "diameters_m", lambda v: roughwall.wall_card(HEIGHTS, **dict(card, diameters_m=[1e-5, v])))
    for run, base in (("stochastic", SCENE), ("deterministic", DET)):
        fn = getattr(roughwall, run)
        args = ["wall", "conditions", "particles", "speed_m_s", "diameter_m", "bin_width_deg", "target_se_deg",
                "seed", "threads"]
        if run == "deterministic":
            args += ["max_collisions", "spacing_per_corr_length", "side_per_corr_length", "surfaces",
                     "triangulation", "wall_deviations"]
        for arg in args:
            if arg == "wall":
                add(run, arg, lambda v, fn=fn, base=base: fn(v, **base))
            else:
                add(run, arg, lambda v, fn=fn, base=base, arg=arg: fn(WALL, **dict(base, **{arg: v})))
        add(run, "conditions", lambda v, fn=fn, base=base: fn(WALL, **dict(base, conditions=[v])))
        add(run, "alpha_in_deg", lambda v, fn=fn, base=base: fn(WALL, **dict(base, conditions=[(v, 0.0)])))
        add(run, "beta_in_deg", lambda v, fn=fn, base=base: fn(WALL, **dict(base, conditions=[(-30.0, v)])))
        add(run, "speed_m_s", lambda v, fn=fn, base=base: fn(WALL, **dict(base, speed_m_s=(v, 0.0))))
        add(run, "speed_m_s", lambda v, fn=fn, base=base: fn(WALL, **dict(base, speed_m_s=(1.0, v))))
    return out


def may_accept(fn, arg, label):
    """Whether a call may take the value: a default (None), an empty list of hits or
    diameters, a hit its status reports (NaN, an infinite or negative diameter:
    INVALID_INPUT), a missing point (NaN) or a height in range in a scan, a number in range.
    Any other value must be refused."""
    if label == "list":
        return (fn, arg) in (("wall_card", "diameters_m"), ("Wall.rebound", "diameter"),
                             ("Wall.rebound", "particle_id"), ("Wall.rebound", "collision_index"))
    if label in NEVER_ACCEPTED:
        return False
    if label == "None":
        return arg in ("law", "preset", "model", "escape_table", "psi", "e_h", "alpha_e_deg", "mu_0", "mu_h",
                       "alpha_mu_deg", "delta_gamma_deg", "corr_length_x_m", "corr_length_z_m", "format",
                       "pixel_m", "height_unit_m", "target_se_deg", "threads", "seed", "spin", "wall_velocity")
    if fn == "Wall.rebound" and arg in ("velocity", "normal", "lay", "spin", "wall_velocity", "diameter"):
        return label in ("nan", "inf", "-1", "2**64")
    if fn == "read_scan" and arg in ("pixel_m", "height_unit_m"):
        return label == "2**64"  # read; wall_card refuses the pixel, a unit gives heights
    if (fn, arg) == ("wall_card", "scan"):
        return label in ("nan", "-1")  # missing points; heights of -1 m
    if arg == "target_se_deg":
        return label == "2**64"
    return label == "-1" and arg in ("alpha_in_deg", "beta_in_deg")


def test_every_argument_names_itself_in_every_error(tmp_path):
    failures = []
    checked = 0
    for fn, arg, call in targets(tmp_path):
        for label, value in HOSTILE.items():
            checked += 1
            where = f"{fn}({arg}={label})"
            try:
                call(value)
            except (ValueError, TypeError, MemoryError) as e:
                msg = str(e)
                if arg not in msg:
                    failures.append(f"{where}: {type(e).__name__} does not name `{arg}`: {msg}")
                elif "\n" in msg or len(msg) > 400:
                    failures.append(f"{where}: not one short line: {msg!r}")
            except OSError as e:
                # A path that names no file: the file is named.
                if not (arg in ("path", "scan") and label == "str" and f"{value}: " in str(e)):
                    failures.append(f"{where}: {type(e).__name__}: {e}")
            except BaseException as e:  # OverflowError, SystemError, RuntimeError, a PanicException
                failures.append(f"{where}: {type(e).__name__}: {e}")
            else:
                if not may_accept(fn, arg, label):
                    failures.append(f"{where}: accepted")
    assert checked > 800
    assert not failures, f"{len(failures)} of {checked}:\n" + "\n".join(failures)


def test_a_huge_integer_is_shown_short():
    with pytest.raises(ValueError) as e:
        roughwall.Wall(delta_xi_deg=10**400)
    assert str(e.value).startswith("invalid `delta_xi_deg` = 1e+400: allowed a real number")
    with pytest.raises(ValueError) as e:
        roughwall.surface(length_m=1e-3, nodes=-(10**5000), rms_height_m=1e-6, corr_length_x_m=None,
                          corr_length_z_m=None)
    assert "invalid `nodes` = -1e+5000" in str(e.value) and len(str(e.value)) < 200


def run_child(script, timeout=120):
    """`script` in a child interpreter; its completed process (a signal is a negative
    return code)."""
    return subprocess.run([sys.executable, "-c", textwrap.dedent(script)], capture_output=True, text=True,
                          timeout=timeout)


LIMITED = """
    import resource
    limit = 2 << 30  # 2 GiB of address space
    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
    import numpy as np
    import roughwall
    wall = roughwall.Wall(delta_xi_deg=3.0, delta_zeta_deg=6.0, seed=1)
    try:
        {call}
    except MemoryError as e:
        print("MemoryError:", e)
    else:
        print("no error")
"""


@pytest.mark.parametrize(
    "call,words",
    [
        # 0.8 GB of keys, 7.2 GB of outputs under a 2 GiB limit.
        ("wall.rebound([5.0, -1.0, 0.0], [0, 1, 0], [1, 0, 0], diameter=1e-4, "
         "particle_id=np.arange(10**8, dtype=np.uint64), collision_index=0)",
         "invalid `particle_id` = 100000000 hits: allowed a size that fits in memory"),
        # 2⁴⁰ hits of broadcast (1-row) inputs: 72 TiB of outputs.
        ("one = np.array([[5.0, -1.0, 0.0]]); z = np.zeros((1, 3)); k = np.zeros(1, dtype=np.uint64)\n"
         "        wall._core.rebound(2**40, one, np.array([[0.0, 1.0, 0.0]]), np.array([[1.0, 0.0, 0.0]]), z, z, "
         "np.full(1, 1e-4), k, k, 1)",
         "invalid `n` = 1099511627776: allowed a size that fits in memory"),
        # n · 72 bytes beyond 2⁶⁴.
        ("one = np.array([[5.0, -1.0, 0.0]]); z = np.zeros((1, 3)); k = np.zeros(1, dtype=np.uint64)\n"
         "        wall._core.rebound(2**63, one, one, one, z, z, np.full(1, 1e-4), k, k, 1)",
         "invalid `n` = "),
        # 0.7 GB of float32 velocities whose float64 copy does not fit.
        ("wall.rebound(np.zeros((60_000_000, 3), dtype=np.float32), [0, 1, 0], [1, 0, 0], diameter=1e-4, "
         "particle_id=0, collision_index=0)",
         "invalid `velocity` = an array of shape (60000000, 3): allowed a size that fits in memory"),
        # 1.1 GB of heights: their copy for the levelling does not fit beside them.
        ("roughwall.wall_card(np.zeros((12000, 12000)), dx=1e-6, dy=1e-6)",
         "invalid `scan` = 12000 × 12000 points: allowed a size that fits in memory"),
        # A 40000² surface: the library's own check, a MemoryError too.
        ("roughwall.surface(length_m=1e-2, nodes=40000, rms_height_m=1e-6, corr_length_x_m=1e-4, "
         "corr_length_z_m=1e-4)",
         "invalid `nodes` = 40000: allowed a size that fits in memory"),
    ],
    ids=["public-particle_id-1e8", "core-n-2**40", "core-n-2**63", "public-velocity-copy", "wall_card-heights",
         "surface-nodes"],
)
def test_outputs_too_large_are_a_memory_error_not_an_abort(call, words):
    p = run_child(LIMITED.format(call=call))
    assert p.returncode == 0, f"the interpreter died (status {p.returncode}): {p.stderr[-2000:]}"
    line = p.stdout.strip()
    assert line.startswith("MemoryError: ") and words in line and "\n" not in line, (line, p.stderr[-2000:])


def test_a_large_batch_that_fits_still_runs():
    n = 200_000
    r = WALL.rebound(V, N, L, diameter=1e-4, particle_id=np.arange(n, dtype=np.uint64), collision_index=0)
    assert r.velocity.shape == (n, 3) and (r.status == roughwall.OK).all()
