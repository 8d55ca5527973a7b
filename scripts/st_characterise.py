"""SurfaceTopography on one scan, as `rebound scan` characterises it: read, level by the
least-squares plane, Sq and Sdq (the reference of scripts/bench-scan.sh).

Usage: st_characterise.py FILE           prints "nx ny sq_m sdq"
       st_characterise.py --make FILE N  writes an N x N Gaussian scan (X3P, float64)
"""

import sys

import numpy as np
from SurfaceTopography import Topography, read_topography


def make(path, n):
    # A Gaussian field with correlation lengths of 16 and 6 pixels (filtered white noise), rms
    # 0.25 um: deviations of about 2.3 and 5.7 degrees, within the wall models' range, so
    # that `rebound scan` runs its scan check on it as on a user's wall.
    rng = np.random.default_rng(1)
    q = np.fft.rfftn(rng.standard_normal((n, n)))
    kx = np.fft.fftfreq(n)[:, None]
    ky = np.fft.rfftfreq(n)[None, :]
    q *= np.exp(-((np.pi * 16 * kx) ** 2 + (np.pi * 6 * ky) ** 2) / 2)
    h = np.fft.irfftn(q, s=(n, n), axes=(0, 1))
    h *= 0.25e-6 / h.std()
    Topography(h, physical_sizes=(n * 0.5e-6, n * 0.5e-6), unit="m").to_x3p(path, dtype="D")


def main():
    if sys.argv[1] == "--make":
        make(sys.argv[2], int(sys.argv[3]))
        return
    t = read_topography(sys.argv[1]).detrend(detrend_mode="height")
    nx, ny = t.nb_grid_pts
    print(nx, ny, t.rms_height_from_area(), t.rms_gradient())


if __name__ == "__main__":
    main()
