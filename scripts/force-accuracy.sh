#!/usr/bin/env bash
# Accuracy report of `rebound force-sweep` (issue 5), written to results/force/:
#   accuracy.csv       hertz-rigid and hertz-dynamic against hu2021 (Hu et al. 2021, Eqs. 7–8),
#                      mean and max relative deviation over β = 0…90° (1° steps) for λ = 1.5, 2, 3
#                      (Fig. 6 setup); copied from the hu-fig6 run's own accuracy.csv.
#   dynamic_speed.csv  hertz-dynamic speed versus error: steps per contact, relative error of the
#                      peak force and contact time against 20000 steps per contact, wall time per
#                      impact (single thread), for 2.45 µm glass at 0.0457 m/s and 5 mm steel at 2 m/s.
#   <case>/            every shipped Hu et al. case (figures, force_sweep.csv, accuracy.csv, …).
# Usage: scripts/force-accuracy.sh   (honours CARGO_TARGET_DIR)
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet
BIN="${CARGO_TARGET_DIR:-target}/release/rebound"
OUT=results/force
mkdir -p "$OUT"

for c in hu-fig4 hu-fig6 hu-fig8 hu-fig9 hu-fig10 hu-fig10b hu-fig11 hu-fig11b hu-fig12; do
  "$BIN" force-sweep --case "cases/$c.toml" --out "$OUT/$c"
done

# Millimetre steel: same models, contact times of microseconds instead of nanoseconds.
cat > "$OUT/steel-5mm.toml" <<'TOML'
name = "steel-5mm"
[particle]
density_kg_m3 = 7850.0
youngs_pa = 210e9
poisson = 0.3
diameter_um = 5000.0
[sweep]
lambda = [1.5, 2.0, 3.0]
beta_deg = { start = 0.0, stop = 90.0, step = 5.0 }
u_n_m_s = [2.0]
models = ["hertz-rigid", "hertz-dynamic"]
TOML
"$BIN" force-sweep --case "$OUT/steel-5mm.toml" --out "$OUT/steel-5mm"

cp "$OUT/hu-fig6/accuracy.csv" "$OUT/accuracy.csv"

# Join the deterministic error table with the wall times that run.toml keeps.
python3 - "$OUT" <<'PY'
import csv, sys, tomllib, pathlib
out = pathlib.Path(sys.argv[1])
rows = []
for case, label in [("hu-fig6", "glass 2.45 um, U_N = 0.0457 m/s"), ("steel-5mm", "steel 5 mm, U_N = 2 m/s")]:
    run = tomllib.loads((out / case / "run.toml").read_text())
    times = {(t["lambda"], t["steps_per_contact"]): t["time_per_impact_s"] for t in run["dynamic_convergence"]}
    with open(out / case / "dynamic_convergence.csv") as f:
        for r in csv.DictReader(f):
            key = (float(r["lambda"]), int(r["steps_per_contact"]))
            rows.append([label, r["lambda"], r["beta_deg"], r["steps_per_contact"], r["steps"],
                         r["rel_err_f_max"], r["rel_err_contact_time"], f"{times[key]:.3e}"])
with open(out / "dynamic_speed.csv", "w", newline="") as f:
    w = csv.writer(f, lineterminator="\n")
    w.writerow(["particle", "lambda", "beta_deg", "steps_per_contact", "steps", "rel_err_f_max",
                "rel_err_contact_time", "time_per_impact_s"])
    w.writerows(rows)
PY
echo "wrote $OUT/accuracy.csv and $OUT/dynamic_speed.csv"
cat "$OUT/accuracy.csv"
