#!/usr/bin/env python3
"""Compare particle trajectory CSVs of two code_saturne runs (check (a)).

Usage: compare_traj.py RUNDIR_A RUNDIR_B [--tol T] [--hits RUNDIR_WITH_HITS]

Each RUNDIR contains traj_rank*.csv written by cs_user_lagr_particle.c:
  step,time,particle_id,n_coll,cell_id,x,y,z,u,v,w,sx,sy,sz   (%.17g)
Rows are keyed by (step, particle_id) (buffer order and rank are ignored).
Compared: the set of keys, cell_id, x, y, z, u, v, w and the private
tracking restart point sx, sy, sz (n_coll is only maintained in user mode
and is not compared).

Pass criterion ("equal to printed precision"): same keys, same cell ids and
every compared value textually identical as printed (%.17g, i.e. bitwise
equal doubles), unless --tol T > 0 is given, in which case
max |a-b| <= T is accepted (for experiments; run_checks.sh and the test use
the default, bitwise).  Exit status 0 on pass, 1 on failure.
"""
import argparse
import csv
import glob
import math
import os
import sys

FIELDS = ["x", "y", "z", "u", "v", "w", "sx", "sy", "sz"]


def load(rundir):
    files = sorted(glob.glob(os.path.join(rundir, "traj_rank*.csv")))
    if not files:
        sys.exit("no traj_rank*.csv in %s" % rundir)
    rows = {}
    for fn in files:
        with open(fn, newline="") as f:
            for r in csv.DictReader(f):
                key = (int(r["step"]), int(r["particle_id"]))
                if key in rows:
                    sys.exit("duplicate row %s in %s" % (key, rundir))
                rows[key] = r
    return rows


def hits_summary(rundir):
    files = sorted(glob.glob(os.path.join(rundir, "wall_hits_rank*.csv")))
    n = 0
    nd_out = []
    nlen_dev = 0.0
    spec_dev = 0.0
    keys = set()
    for fn in files:
        with open(fn, newline="") as f:
            for r in csv.DictReader(f):
                n += 1
                keys.add((int(r["particle_id"]), int(r["collision_index"])))
                nv = [float(r[c]) for c in ("n_x", "n_y", "n_z")]
                ui = [float(r[c]) for c in ("u_in_x", "u_in_y", "u_in_z")]
                uo = [float(r[c]) for c in ("u_out_x", "u_out_y", "u_out_z")]
                nd_out.append(float(r["n_dot_outward"]))
                nlen = math.sqrt(sum(c * c for c in nv))
                nlen_dev = max(nlen_dev, abs(nlen - 1.0))
                # CS_LAGR_REBOUND's specular rebound, operation for operation:
                # tmp = 2 (u.n); u_k -= tmp n_k (face_norm used as given)
                tmp = 2.0 * (ui[0] * nv[0] + ui[1] * nv[1] + ui[2] * nv[2])
                spec = [a - tmp * b for a, b in zip(ui, nv)]
                spec_dev = max(spec_dev, max(abs(a - b) for a, b in zip(spec, uo)))
    return n, len(keys), nd_out, nlen_dev, spec_dev


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("a")
    ap.add_argument("b")
    ap.add_argument("--tol", type=float, default=0.0)
    ap.add_argument("--hits", default=None)
    args = ap.parse_args()

    A, B = load(args.a), load(args.b)
    ka, kb = set(A), set(B)
    only_a, only_b = ka - kb, kb - ka
    common = sorted(ka & kb)

    maxdiff = {c: 0.0 for c in FIELDS}
    n_text_diff = 0
    n_cell_diff = 0
    worst = None
    for k in common:
        ra, rb = A[k], B[k]
        if ra["cell_id"] != rb["cell_id"]:
            n_cell_diff += 1
        for c in FIELDS:
            if ra[c] != rb[c]:
                n_text_diff += 1
            d = abs(float(ra[c]) - float(rb[c]))
            if d > maxdiff[c]:
                maxdiff[c] = d
                if worst is None or d > worst[0]:
                    worst = (d, k, c, ra[c], rb[c])
    mx = max(maxdiff.values()) if maxdiff else 0.0

    steps = sorted({k[0] for k in ka | kb})
    pids = sorted({k[1] for k in ka | kb})
    print("rows: A=%d B=%d common=%d only_A=%d only_B=%d" %
          (len(A), len(B), len(common), len(only_a), len(only_b)))
    print("particles: %d, steps: %d..%d" % (len(pids), steps[0], steps[-1]))
    print("cell_id mismatches: %d" % n_cell_diff)
    print("values differing as printed (%%.17g): %d of %d" %
          (n_text_diff, len(common) * len(FIELDS)))
    print("max abs diff: " + "  ".join("%s=%.3e" % (c, maxdiff[c]) for c in FIELDS))
    mx_traj = max(maxdiff[c] for c in FIELDS[:6])
    mx_rst = max(maxdiff[c] for c in FIELDS[6:])
    print("MAX ABS DIFF trajectories (x,y,z m; u,v,w m/s): %.6e" % mx_traj)
    print("MAX ABS DIFF tracking restart point (sx,sy,sz m): %.6e" % mx_rst)
    if worst:
        print("worst: step=%d pid=%d %s: %s vs %s" % (worst[1][0], worst[1][1],
                                                     worst[2], worst[3], worst[4]))
    if args.hits:
        n, nk, nd, nlen_dev, spec_dev = hits_summary(args.hits)
        nin = sum(1 for v in nd if v < 0)
        print("wall hits logged (user mode): %d (distinct (particle,collision) keys: %d)"
              % (n, nk))
        print("  face_norm . outward_normal: %d negative (points INTO domain), %d positive"
              % (nin, n - nin))
        print("  max | |face_norm| - 1 | = %.3e ; max |u_out - specular(u_in)| = %.3e"
              % (nlen_dev, spec_dev))
        # collisions per particle in the final user-mode state
        last = {}
        for (s, p), r in B.items():
            if p not in last or s > last[p][0]:
                last[p] = (s, int(r["n_coll"]))
        hist = {}
        for s, c in last.values():
            hist[c] = hist.get(c, 0) + 1
        print("  collisions per particle (last recorded state): " +
              ", ".join("%d:%d" % (c, hist[c]) for c in sorted(hist)))

    ok = (not only_a and not only_b and n_cell_diff == 0 and
          (n_text_diff == 0 if args.tol == 0.0 else mx <= args.tol))
    print("CHECK (a): %s" % ("PASS" if ok else "FAIL"))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
