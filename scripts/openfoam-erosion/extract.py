#!/usr/bin/env python3
"""Turn finished runs of ./case into the per-impact CSV (standard library only).

Usage: extract.py OUT.csv RUNDIR [RUNDIR ...]

For each RUNDIR (a solved copy of case/):
  * per-impact records: postProcessing/lagrangian/kinematicCloud/
    patchPostProcessing1/<time>/bottom.post (parcel U, d, rho, nParticle and
    the global face index at the moment of the hit, before the wall
    interaction);
  * eroded volume per bottom face: <latest time>/kinematicCloudQ,
    boundaryField bottom (ParticleErosion accumulates into the boundary
    values; only the internal field is zeroed each step);
  * p, psi, K, rho0: constant/erosionParameters (the file that
    kinematicCloudProperties #includes).
Every bottom face must be hit exactly once, so face Q == that impact's Q.

alpha and |U| are recomputed from the recorded U exactly as ParticleErosion.C
does (same IEEE operations, same libm):  magU = sqrt(Ux*Ux + Uy*Uy + Uz*Uz),
alpha = pi/2 - acos(nw & (U/magU)) with nw = (0, -1, 0), the outward normal of
the bottom wall (y = 0); the wall is at rest, so U is also the wall-relative
velocity.  mass_kg = nParticle * rho * (pi/6 * d^3), as used in the Q formula.
"""
import csv
import glob
import math
import os
import re
import sys

PATCH = "bottom"
NW = (0.0, -1.0, 0.0)          # outward unit normal of the bottom wall
COLUMNS = ["alpha_deg", "speed_m_s", "diameter_m", "density_kg_m3",
           "n_particle", "mass_kg", "p_pa", "psi", "k", "q_openfoam_m3"]


class ExtractError(Exception):
    pass


def read(path):
    try:
        with open(path) as f:
            return f.read()
    except OSError as e:
        raise ExtractError(f"cannot read {path}: {e.strerror}")


def strip_comments(text):
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    return re.sub(r"//[^\n]*", " ", text)


def erosion_parameters(rundir):
    text = strip_comments(read(os.path.join(rundir, "constant", "erosionParameters")))
    vals = dict(re.findall(r"^\s*(\w+)\s+([-+0-9.eE]+)\s*;", text, flags=re.M))
    try:
        return (float(vals["erosionP"]), float(vals["erosionPsi"]),
                float(vals["erosionK"]), float(vals["parcelRho"]))
    except KeyError as e:
        raise ExtractError(f"{rundir}/constant/erosionParameters lacks {e}")


def patch_range(rundir):
    text = strip_comments(read(os.path.join(rundir, "constant", "polyMesh", "boundary")))
    m = re.search(r"\b" + PATCH + r"\s*\{([^}]*)\}", text)
    if not m:
        raise ExtractError(f"patch {PATCH} not in {rundir}/constant/polyMesh/boundary")
    body = m.group(1)
    n = int(re.search(r"nFaces\s+(\d+)", body).group(1))
    start = int(re.search(r"startFace\s+(\d+)", body).group(1))
    return start, n


def latest_time(rundir):
    times = []
    for name in os.listdir(rundir):
        try:
            t = float(name)
        except ValueError:
            continue
        if t > 0 and os.path.isdir(os.path.join(rundir, name)):
            times.append((t, name))
    if not times:
        raise ExtractError(f"no time directory written in {rundir}")
    return max(times)[1]


def patch_q(rundir, nfaces):
    path = os.path.join(rundir, latest_time(rundir), "kinematicCloudQ")
    text = strip_comments(read(path))
    m = re.search(r"boundaryField\s*\{.*?\b" + PATCH + r"\s*\{(.*?)\}", text, flags=re.S)
    if not m:
        raise ExtractError(f"no {PATCH} entry in {path}")
    body = m.group(1)
    m = re.search(r"value\s+uniform\s+([-+0-9.eE]+)\s*;", body)
    if m:
        return [float(m.group(1))] * nfaces
    m = re.search(r"value\s+nonuniform\s+List<scalar>\s*(\d+)\s*\((.*?)\)\s*;", body, flags=re.S)
    if not m:
        raise ExtractError(f"cannot parse {PATCH} values in {path}")
    q = [float(x) for x in m.group(2).split()]
    if len(q) != int(m.group(1)) or len(q) != nfaces:
        raise ExtractError(f"{path}: {len(q)} {PATCH} values, expected {nfaces}")
    return q


def impact_records(rundir):
    pattern = os.path.join(rundir, "postProcessing", "lagrangian", "kinematicCloud",
                           "patchPostProcessing1", "*", PATCH + ".post")
    files = sorted(glob.glob(pattern))
    if not files:
        raise ExtractError(f"no patchPostProcessing output {pattern}")
    records = []
    for path in files:
        lines = read(path).splitlines()
        names = lines[0].lstrip("#").replace("(", " ").replace(")", " ").split()
        for line in lines[1:]:
            if not line.strip():
                continue
            vals = line.replace("(", " ").replace(")", " ").split()
            if len(vals) != len(names):
                raise ExtractError(f"{path}: {len(vals)} values for {len(names)} columns")
            records.append(dict(zip(names, vals)))
    return records


def impact_angle(U):
    """alpha and |U| exactly as ParticleErosion<CloudType>::postPatch."""
    mag_u = math.sqrt(U[0] * U[0] + U[1] * U[1] + U[2] * U[2])
    udir = (U[0] / mag_u, U[1] / mag_u, U[2] / mag_u)
    cos_n = NW[0] * udir[0] + NW[1] * udir[1] + NW[2] * udir[2]
    if cos_n < 0:
        raise ExtractError("recorded parcel moves away from the wall")
    return math.pi / 2.0 - math.acos(cos_n), mag_u


def rows_for(rundir):
    p, psi, k, rho0 = erosion_parameters(rundir)
    start, nfaces = patch_range(rundir)
    q = patch_q(rundir, nfaces)
    records = impact_records(rundir)
    seen = {}
    rows = []
    for rec in records:
        local = int(rec["facei"]) - start
        if not 0 <= local < nfaces:
            raise ExtractError(f"{rundir}: impact on face {rec['facei']} outside patch {PATCH}")
        if local in seen:
            raise ExtractError(f"{rundir}: bottom face {local} hit more than once")
        seen[local] = True
        U = (float(rec["U0"]), float(rec["U1"]), float(rec["U2"]))
        d, rho, n = float(rec["d"]), float(rec["rho"]), float(rec["nParticle"])
        if rho != rho0:
            raise ExtractError(f"{rundir}: parcel rho {rho} != rho0 {rho0}")
        alpha, mag_u = impact_angle(U)
        mass = n * (rho * (math.pi / 6.0 * (d * (d * d))))
        rows.append([math.degrees(alpha), mag_u, d, rho, n, mass, p, psi, k, q[local]])
    if len(seen) != nfaces:
        raise ExtractError(f"{rundir}: {len(seen)} impacts recorded, expected one on each "
                           f"of the {nfaces} {PATCH} faces")
    return rows


def finnie(alpha_deg, speed, mass, p, psi, k):
    a = math.radians(alpha_deg)
    c = mass * speed ** 2 / (p * psi * k)
    if math.tan(a) < k / 6.0:
        return c * (math.sin(2.0 * a) - 6.0 / k * math.sin(a) ** 2), c
    return c * k * math.cos(a) ** 2 / 6.0, c


def main(argv):
    if len(argv) < 3:
        raise ExtractError("usage: extract.py OUT.csv RUNDIR [RUNDIR ...]")
    out = argv[1]
    rows = []
    for rundir in argv[2:]:
        rows.extend(rows_for(rundir))
    rows.sort(key=lambda r: (r[8], round(r[1], 9), r[0]))   # K, speed, alpha

    # Sanity check of the attribution against the Finnie formula: relative to
    # the prefactor m|U|^2/(p psi K), because at alpha = 90 deg Q is cos^2 of
    # a rounding residue (~1e-33 * prefactor).
    worst = 0.0
    for r in rows:
        ref, scale = finnie(r[0], r[1], r[5], r[6], r[7], r[8])
        worst = max(worst, abs(r[9] - ref) / scale)
    if worst > 1e-9:
        raise ExtractError(f"OpenFOAM Q differs from the Finnie formula by {worst:.3g} "
                           "(relative to m|U|^2/(p psi K)); attribution or formula mismatch")

    tmp = out + ".tmp"
    with open(tmp, "w", newline="") as f:
        w = csv.writer(f, lineterminator="\n")
        w.writerow(COLUMNS)
        for r in rows:
            w.writerow([repr(float(x)) for x in r])
    os.replace(tmp, out)
    print(f"wrote {len(rows)} impacts to {out}; max |Q_openfoam - Q_finnie| / "
          f"(m|U|^2/(p psi K)) = {worst:.3g}", file=sys.stderr)


if __name__ == "__main__":
    try:
        main(sys.argv)
    except ExtractError as e:
        print(f"openfoam-erosion/extract.py: {e}", file=sys.stderr)
        sys.exit(1)
    except Exception as e:  # noqa: BLE001 - one line, not a traceback
        print(f"openfoam-erosion/extract.py: {type(e).__name__}: {e}", file=sys.stderr)
        sys.exit(1)
