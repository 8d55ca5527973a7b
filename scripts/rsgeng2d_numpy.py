"""NumPy port of Bergström's rsgeng2D (MySimLabs), as users run it today.

Generates an N x N Gaussian random rough surface with rms height h and correlation
lengths clx, cly on a square of side rL: white noise, fft2 of the noise and of the
sampled Gaussian filter exp(-2x^2/clx^2 - 2y^2/cly^2), product, ifft2, prefactor
2/sqrt(pi) * rL/N / sqrt(clx*cly) (Radenkovic & Simonin 2021, Eqs. 1-2).

Usage: python rsgeng2d_numpy.py N rL h clx cly [seed]   (lengths in any one unit)
Prints the wall time of the generation and the rms height of the result.
"""
import sys
import time

import numpy as np


def rsgeng2D(N, rL, h, clx, cly, rng):
    x = np.linspace(-rL / 2, rL / 2, N)
    X, Y = np.meshgrid(x, x)
    Z = h * rng.standard_normal((N, N))  # uncorrelated Gaussian heights, std h
    F = np.exp(-(X**2 / (clx**2 / 2) + Y**2 / (cly**2 / 2)))  # Gaussian filter
    f = (
        2 / np.sqrt(np.pi) * rL / N / np.sqrt(clx) / np.sqrt(cly)
        * np.fft.ifft2(np.fft.fft2(Z) * np.fft.fft2(F))
    )
    return np.real(f), x


def main():
    N = int(sys.argv[1])
    rL, h, clx, cly = map(float, sys.argv[2:6])
    seed = int(sys.argv[6]) if len(sys.argv) > 6 else 1
    t = time.perf_counter()
    f, _ = rsgeng2D(N, rL, h, clx, cly, np.random.default_rng(seed))
    dt = time.perf_counter() - t
    print(f"numpy rsgeng2D N={N}: {dt:.3f} s, rms height {np.sqrt(np.mean(f**2)):.4f}")


if __name__ == "__main__":
    main()
