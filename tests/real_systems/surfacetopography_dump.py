"""Reads instrument files with SurfaceTopography (the reference reader of
tests/real_systems/surfacetopography.rs) and writes what it read, one dump per file.

Usage: surfacetopography_dump.py OUTDIR FILE[:SX:SY:UNIT] ...
       surfacetopography_dump.py --write-x3p DTYPE SRC OUT

SX, SY, UNIT are given to read_topography for files that state no physical size (a plain
matrix). Each dump, OUTDIR/<file name>.dump, is text lines `key value` up to the line `end`,
then nx * ny little-endian float64 heights in metres, row-major (index iy * nx + ix), NaN where
SurfaceTopography masks the point. Keys: version, nx, ny, unit, unit_m (metres per
unit; 1 when the file has no unit), sx_m, sy_m (physical sizes in metres), dx_m, dy_m.
SurfaceTopography's arrays are indexed [x, y]: the dump writes their transpose. Keys sq_m and
sdq: Sq (rms_height_from_area, metres) and Sdq (rms_gradient) of the scan less its
least-squares plane (detrend_mode "height"); "nan" where SurfaceTopography cannot compute them.

--write-x3p reads SRC and writes it to OUT as X3P with SurfaceTopography's writer, heights of
data type DTYPE (I, L: 16-, 32-bit integers with increment and offset; F, D: floats) and its
masked points in a validity mask (bindata/valid.bin).
"""

import os
import sys

import numpy as np
import SurfaceTopography
from SurfaceTopography import read_topography
from SurfaceTopography.Support.UnitConversion import get_unit_conversion_factor


def dump(path, outdir, physical_sizes=None, unit=None):
    kwargs = {}
    if physical_sizes is not None:
        kwargs = {"physical_sizes": physical_sizes, "unit": unit}
    t = read_topography(path, **kwargs)
    nx, ny = t.nb_grid_pts
    sx, sy = t.physical_sizes
    unit_m = 1.0 if t.unit is None else float(get_unit_conversion_factor(t.unit, "m"))
    sx, sy = float(sx), float(sy)
    h = t.heights()
    mask = np.ma.getmaskarray(h)
    heights = np.where(mask, np.nan, np.ma.getdata(h).astype(np.float64) * unit_m)
    assert heights.shape == (nx, ny), heights.shape
    try:
        levelled = t.detrend(detrend_mode="height")
        sq = float(levelled.rms_height_from_area()) * unit_m
        sdq = float(levelled.rms_gradient())
    except Exception:  # e.g. too few points for a plane
        sq = sdq = float("nan")
    lines = [
        f"version {SurfaceTopography.__version__}",
        f"nx {nx}",
        f"ny {ny}",
        f"unit {t.unit}",
        f"unit_m {unit_m!r}",
        f"sx_m {sx * unit_m!r}",
        f"sy_m {sy * unit_m!r}",
        f"dx_m {sx * unit_m / nx!r}",
        f"dy_m {sy * unit_m / ny!r}",
        f"sq_m {sq!r}",
        f"sdq {sdq!r}",
        "end",
    ]
    out = os.path.join(outdir, os.path.basename(path) + ".dump")
    with open(out, "wb") as f:
        f.write(("\n".join(lines) + "\n").encode())
        f.write(np.ascontiguousarray(heights.T, dtype="<f8").tobytes())


def main():
    if len(sys.argv) == 5 and sys.argv[1] == "--write-x3p":
        _, _, dtype, src, out = sys.argv
        read_topography(src).to_x3p(out, dtype=dtype)
        return
    if len(sys.argv) < 3:
        sys.exit("usage: surfacetopography_dump.py OUTDIR FILE[:SX:SY:UNIT] ...")
    outdir = sys.argv[1]
    for arg in sys.argv[2:]:
        parts = arg.split(":")
        if len(parts) == 4:
            dump(parts[0], outdir, (float(parts[1]), float(parts[2])), parts[3])
        else:
            dump(arg, outdir)


if __name__ == "__main__":
    main()
