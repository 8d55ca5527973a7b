"""Generated and measured walls: Garcia–Stoll surfaces, instrument scans, wall cards."""

from __future__ import annotations

import os
from typing import NamedTuple, Optional, Sequence, Union

import numpy as np

from . import _args, _roughwall


class Surface(NamedTuple):
    """A height field: heights[iz, ix] (m) at (ix·dx, iz·dz); x along the first correlation
    length (Δξ), z across it. A generated surface is periodic; a scan's rows are its y."""

    heights: np.ndarray
    dx: float
    dz: float


def surface(
    *,
    length_m: float,
    nodes: int,
    rms_height_m: float,
    corr_length_x_m: Optional[float],
    corr_length_z_m: Optional[float],
    seed: int = 0,
    threads: Optional[int] = None,
) -> Surface:
    """A Garcia–Stoll Gaussian rough surface (Radenkovic & Simonin 2021, Eqs. 1–2): a square
    periodic `nodes` × `nodes` grid of side `length_m` (m), rms height `rms_height_m` (m),
    Gaussian autocorrelation with correlation lengths `corr_length_x_m`, `corr_length_z_m`
    (m; None: constant along that axis, e.g. 2-D roughness with `corr_length_z_m=None`,
    stored as one row). Its normal angles have Δ ≈ √2 h/c_L (Eq. 15). The same seed gives the
    same surface on any number of threads (`roughwall::surface::generate`, the generator of
    `rebound surface`)."""
    num = _args.number
    heights, dx, dz = _roughwall.surface(
        num("length_m", length_m),
        _args.count("nodes", nodes, 16, 40_000),
        num("rms_height_m", rms_height_m),
        num("corr_length_x_m", corr_length_x_m, True),
        num("corr_length_z_m", corr_length_z_m, True),
        _args.seed(seed),
        _args.threads(threads),
    )
    return Surface(heights, dx, dz)


class Scan(NamedTuple):
    """A measured height field: heights[iy, ix] (m, NaN where the instrument measured
    nothing) at (ix·dx, iy·dy); the file's format and what it states beside the heights."""

    heights: np.ndarray
    dx: float
    dy: float
    format: str
    info: list


def read_scan(
    path: Union[str, os.PathLike],
    *,
    format: Optional[str] = None,
    pixel_m: Optional[Sequence[float]] = None,
    height_unit_m: Optional[float] = None,
) -> Scan:
    """Reads an instrument scan (X3P, Digital Surf SUR, Gwyddion GSF and text, phase-map
    text, Zygo MetroPro, Wyko OPD, Sensofar PLU; the readers of `rebound scan`) into heights
    in metres. `format` None detects it; a plain "matrix" or "xyz" text states no units, so
    give `pixel_m=(dx, dy)` and `height_unit_m` with it. A file that cannot be read (or is
    no regular file: a FIFO, a directory, a device) raises OSError, one that is malformed
    ValueError, with one line naming the file."""
    heights, dx, dy, fmt, info = _roughwall.read_scan(
        _args.path("path", path),
        _args.name("format", format),
        None if pixel_m is None else _args.pair("pixel_m", pixel_m, "(dx, dy) in m"),
        _args.number("height_unit_m", height_unit_m, True),
    )
    return Scan(heights, dx, dy, fmt, info)


def wall_card(
    scan,
    *,
    dy: Optional[float] = None,
    dx: Optional[float] = None,
    diameters_m: Sequence[float] = (),
    level_degree: int = 1,
    threads: Optional[int] = None,
) -> dict:
    """The wall card of a measured wall, as `rebound scan` writes it (wall_card.toml): the
    scan levelled by its least-squares polynomial of `level_degree` (1: plane), ISO 25178
    parameters, the lay, the normal-angle deviations along and across it (the Δξ, Δζ a Wall
    takes) and, for each particle diameter in `diameters_m` (m), those of the surface that
    sphere's centre rides on, with where the scan is too small for it and the resolution
    check (the same deviations at twice the pixel, their change, `resolution_limited`).

    `scan` is a Scan (from read_scan), a path to one, or a 2-D height array (m, NaN for a
    missing point; then give `dx`, `dy` in m). Returns a dict: "wall" (delta_xi_deg,
    delta_zeta_deg; None without a lay), "lay" (angle_deg in the scan's axes,
    direction_scan_xy, …), "parameters" (sq_m, sdq, …), "correlation", "diameters" (one
    dict per particle, the point particle first), "notes", "levelled", "spacing_m".
    Angles in degrees, lengths in metres. A refusal (a scan the models cannot take, a size
    that does not fit in memory: MemoryError) names the argument, and the file of a path."""
    file, heights, dx, dy = _heights(scan, dx, dy)
    args = (
        heights,
        _args.number("dx", dx),
        _args.number("dy", dy),
        _args.count("level_degree", level_degree, 1, 3),
        _args.numbers("diameters_m", diameters_m, 64),
        _args.threads(threads),
    )
    try:
        return _roughwall.wall_card(*args)
    except (ValueError, MemoryError) as e:
        if file is None:
            raise
        raise type(e)(f"{file}: {e}") from None


def measured_wall_table(
    scan,
    *,
    dy: Optional[float] = None,
    dx: Optional[float] = None,
    diameter_m: Optional[float] = None,
    level_degree: int = 1,
    histories_per_cell: int = 17711,
    seed: int = 2021,
    threads: Optional[int] = None,
) -> str:
    """The wall's own stochastic model: the measured-wall table (its text, for
    ``Wall(model="measured-wall", wall_table=...)``) of a measured wall, as
    ``rebound scan --measured-wall`` builds it. The deterministic reference on the scan
    itself (levelled by its polynomial of `level_degree`; in place, its incident directions
    turned by its lay; for a sphere of `diameter_m` m, on its centre surface; None: the point
    particle) is run over the table's grid of incident directions, `histories_per_cell`
    (1024 … 1000000) each, and the law of each direction's effective wall element kept.
    About 15 s for a 4096² scan on 2 cores. `scan` is as for wall_card. A scan too small for
    the reference at every incident angle raises ValueError."""
    file, heights, dx, dy = _heights(scan, dx, dy)
    args = (
        heights,
        _args.number("dx", dx),
        _args.number("dy", dy),
        _args.count("level_degree", level_degree, 1, 3),
        _args.number("diameter_m", diameter_m, True),
        _args.count("histories_per_cell", histories_per_cell, 1024, 1_000_000),
        _args.seed(seed),
        _args.threads(threads),
    )
    try:
        return _roughwall.measured_wall_table(*args)
    except (ValueError, MemoryError) as e:
        if file is None:
            raise
        raise type(e)(f"{file}: {e}") from None


def _heights(scan, dx, dy):
    """`(file, heights, dx, dy)` of a Scan, a path to one (read; `file` names it) or a 2-D
    height array with its pixel sizes (`file` None)."""
    file = None
    if isinstance(scan, (str, os.PathLike)):
        file = _args.path("scan", scan)
        scan = read_scan(file)
    if isinstance(scan, Scan):
        return file, scan.heights, scan.dx, scan.dy
    heights = _args.float_array("scan", scan)
    if heights.ndim != 2:
        raise ValueError(f"`scan` has shape {heights.shape}: allowed a 2-D array (ny, nx)")
    if dx is None or dy is None:
        raise TypeError("`dx` and `dy`: give the pixel sizes (m) of a height array")
    return file, heights, dx, dy
