#!/usr/bin/env bash
# Runs a rebound case on a Slurm cluster: a job array of N shards and a merge job that
# depends on it (afterok). Prints the two job ids ("ARRAY_ID MERGE_ID") on stdout.
#
# Usage: scripts/slurm/submit.sh [options] COMMAND CASE OUT [-- REBOUND_OPTIONS...]
#   COMMAND   deterministic | stochastic
#   CASE      case file (an absolute path is safest: jobs run from Slurm's spool)
#   OUT       results folder on a file system every node sees: OUT/shard-K, OUT/merged
#   options   --shards N (default 4)  --cpus-per-task C (default 1)  --time T (default 1:00:00)
#             --partition P  --account A  --bin PATH (default: target/release/rebound)
#             any other sbatch option after --sbatch (e.g. --sbatch --qos=long)
# Example: scripts/slurm/submit.sh --shards 16 --cpus-per-task 4 stochastic \
#            "$PWD/configs/cases/glass-steel.toml" /scratch/$USER/gs -- --particles 100000000
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
root=$(cd "$here/../.." && pwd)
shards=4 cpus=1 time=1:00:00 bin=$root/target/release/rebound
extra_sbatch=()
while [ $# -gt 0 ]; do
  case $1 in
    --shards) shards=$2; shift 2 ;;
    --cpus-per-task) cpus=$2; shift 2 ;;
    --time) time=$2; shift 2 ;;
    --partition) extra_sbatch+=("--partition=$2"); shift 2 ;;
    --account) extra_sbatch+=("--account=$2"); shift 2 ;;
    --bin) bin=$2; shift 2 ;;
    --sbatch) extra_sbatch+=("$2"); shift 2 ;;
    -h|--help) sed -n '2,14p' "$0"; exit 0 ;;
    *) break ;;
  esac
done
[ $# -ge 3 ] || { echo "usage: $0 [options] COMMAND CASE OUT [-- REBOUND_OPTIONS...]" >&2; exit 2; }
command=$1 case=$2 out=$3
shift 3
[ "${1:-}" = "--" ] && shift
case $command in deterministic|stochastic) ;; *) echo "COMMAND must be deterministic or stochastic, not '$command'" >&2; exit 2 ;; esac
[[ $shards =~ ^[1-9][0-9]*$ ]] || { echo "--shards must be a positive integer, not '$shards'" >&2; exit 2; }
[ -x "$bin" ] || { echo "rebound binary '$bin' not found (cargo build --release, or --bin PATH)" >&2; exit 2; }
bin=$(cd "$(dirname "$bin")" && pwd)/$(basename "$bin")
case_abs=$case
[ -f "$case" ] && case_abs=$(cd "$(dirname "$case")" && pwd)/$(basename "$case")
mkdir -p "$out"
out=$(cd "$out" && pwd)
export REBOUND_BIN=$bin REBOUND_COMMAND=$command REBOUND_CASE=$case_abs REBOUND_OUT=$out \
  REBOUND_SHARDS=$shards REBOUND_ARGS="$*"
array=$(sbatch --parsable --array="1-$shards" --cpus-per-task="$cpus" --time="$time" \
  --chdir="$root" --output="$out/slurm-shard-%a.log" "${extra_sbatch[@]}" "$here/shard.sbatch")
array=${array%%;*}
merge=$(sbatch --parsable --dependency="afterok:$array" --cpus-per-task="$cpus" --time="$time" \
  --chdir="$root" --output="$out/slurm-merge.log" "${extra_sbatch[@]}" "$here/merge.sbatch")
merge=${merge%%;*}
echo "$array $merge"
