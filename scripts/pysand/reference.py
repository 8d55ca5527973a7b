#!/usr/bin/env python3
"""Reference values of Equinor pysand's DNV RP-O501 erosion model.

Usage: reference.py OUTDIR  (run by reference.sh, which installs pysand in a venv)
Writes into OUTDIR:
  dnv_pysand.csv     full grid: material x impact angle x particle speed
  dnv_pysand_F.csv   angle function only (ductile and brittle), one row per angle

pysand (Equinor, GPL-3.0) is only imported and called here; nothing of it is copied
into rebound.

Everything model-specific (F(alpha), K, n, rho_t) is taken from pysand's code:
  pysand.erosion.F(a_rad, angle_dependency)
  pysand.erosion.get_material_properties(material) -> (rho_t, K, n, angle_dependency)
pysand has NO function returning erosion per unit particle mass; that quantity
(E_m = K * F(alpha) * U_p**n, kg/kg, and E_v = E_m / rho_t, m^3/kg) is formed here
in the same operation order pysand uses inside its geometry models
(`K * F(a_rad, ad) * v_m ** n / (rho_t * At)`).
As an independent cross-check it is also recovered from pysand's public
geometry model pysand.erosion.probes() (see NOTES.md).

Floats are written with repr(): the shortest decimal string that parses back
to the identical IEEE-754 double (<= 17 significant digits).
"""
import csv
import logging
import math
import os
import sys

import numpy as np
import pysand
import pysand.erosion as er

EXPECTED_VERSION = "2.0.0"

ANGLES_DEG = [0, 0.01, 0.1, 0.5, 1, 2, 5, 10, 15, 20, 30, 45, 60, 75, 89, 90]
SPEEDS = [0.1, 1, 5, 10, 30, 100]
# carbon_steel: the K=2e-9, n=2.6, rho_t=7800 set; duplex: pysand's default
# material (rho_t=7850); aluminium and grp_epoxy: other ductile K/n/rho_t sets.
MATERIALS = ["carbon_steel", "duplex", "aluminium", "grp_epoxy"]

# probes() cross-check inputs: D = 1 m, rho_m = 1 kg/m3, d_p = 1 mm give
# C2 = 1e6*d_p/1000/(30*sqrt(rho_m)) = 33.3 -> clamped to 1, so
# E_rel [mm/t] = K*F*U^n/(rho_t*At)*1e6 with At = pi/4*D^2/sin(alpha).
PROBE_D, PROBE_RHO_M, PROBE_DP = 1.0, 1.0, 1.0


def r(x):
    """repr of a float as a plain Python float (round-trip exact)."""
    if x is None:
        return ""
    return repr(float(x))


def main():
    logging.getLogger("pysand").setLevel(logging.ERROR)  # probes() warns for alpha<10
    if pysand.__version__ != EXPECTED_VERSION:
        print(f"WARNING: pysand {pysand.__version__} != expected {EXPECTED_VERSION}",
              file=sys.stderr)
    if len(sys.argv) != 2:
        sys.exit("usage: reference.py OUTDIR")
    here = sys.argv[1]

    # ---- angle function only --------------------------------------------------
    f_path = os.path.join(here, "dnv_pysand_F.csv")
    with open(f_path, "w", newline="") as fh:
        w = csv.writer(fh, lineterminator="\n")
        w.writerow(["alpha_deg", "alpha_rad", "sin_alpha", "F_ductile", "F_brittle"])
        for deg in ANGLES_DEG:
            a = np.deg2rad(float(deg))  # == deg * (pi/180), bit-identical
            w.writerow([r(deg), r(a), r(np.sin(a)),
                        r(er.F(a, "ductile")), r(er.F(a, "brittle"))])

    # ---- full grid ---------------------------------------------------------------
    out_path = os.path.join(here, "dnv_pysand.csv")
    nrows = 0
    max_rel = 0.0
    with open(out_path, "w", newline="") as fh:
        w = csv.writer(fh, lineterminator="\n")
        w.writerow([
            "material", "angle_dependency", "K", "n", "rho_t",
            "alpha_deg", "alpha_rad", "F",
            "U_p", "U_p_pow_n",
            "E_m_kg_per_kg", "E_v_m3_per_kg",
            "E_rel_probes_mm_per_t", "E_v_from_probes_m3_per_kg", "rel_diff_probes",
        ])
        for mat in MATERIALS:
            rho_t, K, n, ad = er.get_material_properties(mat)
            for deg in ANGLES_DEG:
                a = np.deg2rad(float(deg))
                F = er.F(a, ad)
                for U in SPEEDS:
                    U = float(U)
                    Upn = U ** n
                    E_m = K * F * U ** n          # kg lost per kg of particles
                    E_v = E_m / rho_t             # m^3 lost per kg of particles
                    # cross-check through pysand's own geometry model
                    with np.errstate(divide="ignore"):  # At = inf at alpha = 0
                        E_rel = er.probes(U, PROBE_RHO_M, PROBE_D, PROBE_DP,
                                          alpha=float(deg), material=mat)
                    s = np.sin(a)
                    if s > 0:
                        At = np.pi / 4 * PROBE_D ** 2 * 1 / s
                        E_v_p = E_rel / 1e6 * At
                        rel = abs(E_v_p - E_v) / abs(E_v) if E_v != 0 else abs(E_v_p)
                        max_rel = max(max_rel, rel)
                    else:
                        E_v_p, rel = None, None
                    w.writerow([mat, ad, r(K), r(n), r(rho_t),
                                r(deg), r(a), r(F), r(U), r(Upn),
                                r(E_m), r(E_v), r(E_rel), r(E_v_p), r(rel)])
                    nrows += 1
    print(f"pysand {pysand.__version__} (numpy {np.__version__}, python "
          f"{sys.version.split()[0]})")
    print(f"wrote {out_path} ({nrows} rows) and {f_path} ({len(ANGLES_DEG)} rows)")
    print(f"max relative difference E_v vs probes()-derived: {max_rel:.3e}")
    if not max_rel < 1e-12:
        print("ERROR: cross-check with pysand.erosion.probes() failed", file=sys.stderr)
        sys.exit(1)


if __name__ == "__main__":
    main()
