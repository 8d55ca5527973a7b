#!/usr/bin/env python3
"""Compare particle trajectory CSVs of two code_saturne runs (check (a)).

Usage: compare_traj.py RUNDIR_A RUNDIR_B [--tol T] [--hits RUNDIR_WITH_HITS]
       compare_traj.py RUNDIR_SMOOTH RUNDIR_ROUGH --rough

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
the default, bitwise).  With --hits, the hook's calls are counted: every
particle must have as many logged hits as code_saturne's built-in rebounds
of run A gave it (a wall hit in the box reverses one velocity component of
the straight-line trajectory, so the sign changes of u, v, w between steps
count the built-in rebounds).

--rough (check (c)): run B has the rough wall, run A the smooth one, the same
particles: every particle's trajectory must be identical up to its first wall
hit, and the trajectories that follow a hit must differ (at least 90 % of the
particles that hit a wall).  Exit status 0 on pass, 1 on failure.
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


# The injection velocities of scene 1 (cs_user_lagr_boundary_conditions.c): the state before
# a particle's first step, which the trajectory files (written after each step) do not hold.
INJECTED = [(0.5, 1.0, 0.7), (0.6, -0.9, -0.5)]


def velocity_sequences(rows):
    """Per particle, its velocities (u, v, w) step by step, led by its injection velocity
    (the set whose magnitudes the first step has; drag changes them by ~1e-4)."""
    by_pid = {}
    for (step, pid), r in rows.items():
        by_pid.setdefault(pid, []).append((step, [float(r[c]) for c in ("u", "v", "w")]))
    for pid, seq in by_pid.items():
        seq.sort()
        v1 = seq[0][1]
        start = min(INJECTED, key=lambda s: sum((abs(a) - abs(b)) ** 2 for a, b in zip(v1, s)))
        seq.insert(0, (0, list(start)))
    return by_pid


def rebounds_per_particle(rows):
    """Built-in rebounds per particle: sign changes of u, v, w from step to step."""
    return {
        pid: sum(
            sum(1 for x, y in zip(a, b) if x * y < 0) for (_, a), (_, b) in zip(seq, seq[1:])
        )
        for pid, seq in velocity_sequences(rows).items()
    }


def logged_hits_per_particle(rundir, last_step):
    """Logged hook calls per particle up to its last recorded trajectory step (`last_step`);
    and the calls in the step a particle left the domain, which no trajectory row shows."""
    count, trailing = {}, 0
    for fn in sorted(glob.glob(os.path.join(rundir, "wall_hits_rank*.csv"))):
        with open(fn, newline="") as f:
            for r in csv.DictReader(f):
                pid = int(r["particle_id"])
                if int(r["step"]) > last_step.get(pid, -1):
                    trailing += 1
                    continue
                count[pid] = count.get(pid, 0) + 1
    return count, trailing


def first_hit_step(rows):
    """Per particle, the first step at which its velocity changed sign (its first hit)."""
    first = {}
    for pid, seq in velocity_sequences(rows).items():
        for (_, a), (s, b) in zip(seq, seq[1:]):
            if any(x * y < 0 for x, y in zip(a, b)):
                first[pid] = s
                break
    return first


def rough(smooth_dir, rough_dir):
    A, B = load(smooth_dir), load(rough_dir)
    first = first_hit_step(A)
    before_equal, before_total = 0, 0
    hit, changed = 0, 0
    for pid, s_hit in first.items():
        hit += 1
        differs = False
        for (s, p), ra in A.items():
            if p != pid:
                continue
            rb = B.get((s, p))
            if s < s_hit:
                before_total += 1
                if rb is not None and all(ra[c] == rb[c] for c in FIELDS[:6]):
                    before_equal += 1
            elif rb is None or any(ra[c] != rb[c] for c in ("u", "v", "w")):
                differs = True
        changed += differs
    print("rough wall: %d particles hit a wall; before the first hit %d of %d rows identical"
          % (hit, before_equal, before_total))
    print("rough wall: trajectories changed after the hit for %d of %d particles" % (changed, hit))
    ok = hit > 0 and before_equal == before_total and changed >= 0.9 * hit
    print("CHECK (c): %s" % ("PASS" if ok else "FAIL"))
    return 0 if ok else 1


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
    ap.add_argument("--rough", action="store_true")
    args = ap.parse_args()
    if args.rough:
        return rough(args.a, args.b)

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

    calls_ok = True
    if args.hits:
        built_in = rebounds_per_particle(A)
        last_step = {}
        for (step, pid) in A:
            last_step[pid] = max(step, last_step.get(pid, -1))
        logged, trailing = logged_hits_per_particle(args.hits, last_step)
        pids_all = set(built_in) | set(logged)
        off = [p for p in pids_all if built_in.get(p, 0) != logged.get(p, 0)]
        print("hook calls per particle equal code_saturne's built-in rebounds: %d particles, "
              "%d rebounds, %d hook calls, %d particles differ (%d calls in the step a "
              "particle left the domain, not in any trajectory row)"
              % (len(pids_all), sum(built_in.values()), sum(logged.values()), len(off),
                 trailing))
        calls_ok = not off and sum(logged.values()) > 0
    ok = (not only_a and not only_b and n_cell_diff == 0 and calls_ok and
          (n_text_diff == 0 if args.tol == 0.0 else mx <= args.tol))
    print("CHECK (a): %s" % ("PASS" if ok else "FAIL"))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())
