#!/usr/bin/env bash
# Runs rebound on a real single-node Slurm cluster (Debian's slurm-wlm and munge, which
# scripts/install-deps.sh installs; daemons on 127.0.0.1 only, started directly, without systemd): a
# deterministic and a stochastic case as 4 shards each through submit.sh (job array plus
# afterok merge job), then checks that every CSV the merge wrote is byte-identical to a
# one-process run, and that a failing shard cancels the merge instead of leaving it
# pending. The daemons are stopped by their process ids on exit. Needs root.
#
# Usage: scripts/slurm/test-local-cluster.sh   (env REBOUND_BIN: the binary to test)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
bin=${REBOUND_BIN:-$root/target/release/rebound}
[ -x "$bin" ] || { echo "no rebound binary at $bin" >&2; exit 1; }
export PATH=$PATH:/usr/sbin
# shellcheck source=local-slurm.sh
source "$here/local-slurm.sh"
LOCAL_SLURM_QUIET=1
slurm_check
work=$(mktemp -d /tmp/rbslurm.XXXXXX)   # short: the munge socket path must stay < 108 bytes
cleanup() { slurm_down "$work/c" || true; rm -rf "$work"; }
trap cleanup EXIT
mkdir -p "$work/c"
t0=$(date +%s.%N)
# More CPUs than cores: the 4 shards of both runs start in one scheduling round.
LOCAL_SLURM_CPUS=8 slurm_up "$work/c"
cat > "$work/case.toml" <<'TOML'
name = "slurm-test"
seed = 7
[wall]
delta_xi_deg = 3.8
delta_zeta_deg = 7.5
[incidence]
alpha_deg = [-5.0, -25.0]
beta_deg = [0.0, 60.0]
speed_mean_m_s = 5.91
speed_std_m_s = 1.16
[particles]
count = 150000
[collision]
model = "sommerfeld-huber"
preset = "glass-steel"
[deterministic]
side_per_corr_length = 20.0
TOML
ids=()
for model in deterministic stochastic; do
  read -r array merge < <("$here/submit.sh" --bin "$bin" --shards 4 "$model" "$work/case.toml" "$work/$model")
  ids+=("$array" "$merge")
  echo "$model: shard array $array, merge job $merge"
done
slurm_wait_jobs -t 300 "${ids[@]}"
for model in deterministic stochastic; do
  "$bin" "$model" --case "$work/case.toml" --out "$work/$model-one" 2> /dev/null
  for f in summary.csv pdfs.csv moments.csv; do
    cmp "$work/$model-one/$f" "$work/$model/merged/$f"
  done
  grep -q 'merged_shards = 4' "$work/$model/merged/run.toml"
  echo "$model: 4 Slurm shards merged = one process, byte for byte (summary.csv, pdfs.csv, moments.csv)"
done
# A shard that fails (a case file that does not exist) must cancel the merge job.
read -r array merge < <("$here/submit.sh" --bin "$bin" --shards 2 stochastic "$work/missing.toml" "$work/broken")
if slurm_wait_jobs -t 120 "$array" "$merge" > "$work/broken.states"; then
  echo "a failing shard did not fail the run" >&2
  exit 1
fi
grep -q "^$merge CANCELLED" "$work/broken.states" || { cat "$work/broken.states" >&2; exit 1; }
[ ! -e "$work/broken/merged" ] || { echo "the merge ran after a failed shard" >&2; exit 1; }
echo "a failed shard cancels the merge job (DependencyNeverSatisfied)"
printf 'slurm test: %.1f s\n' "$(awk -v a="$(date +%s.%N)" -v b="$t0" 'BEGIN {print a - b}')"
