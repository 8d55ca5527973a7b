"""A scene's stochastic and deterministic runs, with their tallies as arrays."""

from __future__ import annotations

from typing import Optional, Sequence, Tuple

from . import _args, _roughwall
from ._wall import Wall


def _scene(wall, conditions, particles, speed_m_s, diameter_m, bin_width_deg, target_se_deg, seed, threads):
    if not isinstance(wall, Wall):
        raise TypeError(f"`wall` is {type(wall).__name__}: allowed a roughwall.Wall")
    num = _args.number
    return dict(
        wall._params,
        conditions=_args.pairs("conditions", conditions, ("alpha_in_deg", "beta_in_deg"), 10_000),
        speed_m_s=_args.pair("speed_m_s", speed_m_s, "(mean, standard deviation) in m/s"),
        diameter_m=num("diameter_m", diameter_m),
        particles=_args.count("particles", particles, 1, 100_000_000),
        bin_width_deg=num("bin_width_deg", bin_width_deg),
        target_se_deg=num("target_se_deg", target_se_deg, True),
        seed=wall.seed if seed is None else _args.seed(seed),
        threads=_args.threads(threads),
    )


_DOC_RESULT = """
    Returns a dict of arrays, one entry per condition (in the order given): "alpha_in_deg",
    "beta_in_deg", "particles" (histories tallied), "lost" (deterministic histories that
    could not be followed), "p_single" and "p_single_se"; "mean", "std", "se": dicts by
    quantity name (alpha_out, dbeta, beta_out, gamma_first, speed_ratio, …; angles in
    degrees) of arrays; "pdfs": one dict per condition, by quantity, of bin edges "lo_deg",
    "hi_deg", densities "value" (1/degree) and their "se". The names are those of
    moments.csv and pdfs.csv (docs/outputs.md). The same seed gives the same tallies on any
    number of threads.
"""


def stochastic(
    wall: Wall,
    *,
    conditions: Sequence[Tuple[float, float]],
    particles: int = 10_000,
    speed_m_s: Tuple[float, float] = (1.0, 0.0),
    diameter_m: float = 500e-6,
    bin_width_deg: float = 1.0,
    target_se_deg: Optional[float] = None,
    seed: Optional[int] = None,
    threads: Optional[int] = None,
) -> dict:
    """The stochastic model of `wall` on a scene (what `rebound stochastic` runs): for each
    incident condition (α⁻, β⁻) in degrees (α⁻ in [-90, 0), β⁻ measured from the lay),
    `particles` rebounds with horizontal speed ~ N(speed_m_s) (m/s) and no spin, each from
    its own random stream (seed: the wall's unless given), until `target_se_deg` if given.
    The scene is given by these keywords, not by a case file (case files are the command
    line's).""" + _DOC_RESULT
    return _roughwall.stochastic(
        _scene(wall, conditions, particles, speed_m_s, diameter_m, bin_width_deg, target_se_deg, seed, threads)
    )


def deterministic(
    wall: Wall,
    *,
    conditions: Sequence[Tuple[float, float]],
    particles: int = 10_000,
    speed_m_s: Tuple[float, float] = (1.0, 0.0),
    diameter_m: float = 500e-6,
    bin_width_deg: float = 1.0,
    target_se_deg: Optional[float] = None,
    seed: Optional[int] = None,
    threads: Optional[int] = None,
    max_collisions: int = 1000,
    spacing_per_corr_length: float = 8.0,
    side_per_corr_length: float = 100.0,
    surfaces: int = 1,
    triangulation: str = "alternating",
    wall_deviations: str = "normal-angles",
) -> dict:
    """The deterministic model on the scene (what `rebound deterministic` runs): particle
    centres bouncing on generated Garcia–Stoll surfaces with the wall's Δξ, Δζ (the grid
    chosen from the correlation lengths: `spacing_per_corr_length` nodes per shorter c_L, a
    side of `side_per_corr_length` longer c_L), `surfaces` realisations, the wall's collision
    law; the keywords as a case's [deterministic] section.""" + _DOC_RESULT
    scene = _scene(wall, conditions, particles, speed_m_s, diameter_m, bin_width_deg, target_se_deg, seed, threads)
    surface = dict(
        max_collisions=_args.count("max_collisions", max_collisions, 1, 1_000_000),
        spacing_per_corr_length=_args.number("spacing_per_corr_length", spacing_per_corr_length),
        side_per_corr_length=_args.number("side_per_corr_length", side_per_corr_length),
        surfaces=_args.count("surfaces", surfaces, 1, 1024),
        triangulation=_args.text("triangulation", triangulation),
        wall_deviations=_args.text("wall_deviations", wall_deviations),
    )
    return _roughwall.deterministic(scene, surface)
