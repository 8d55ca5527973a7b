//! Shards on a real Slurm cluster (issue 10): `scripts/slurm/test-local-cluster.sh` (with
//! Debian's slurm-wlm and munge, which `scripts/install-deps.sh` installs) starts a
//! single-node cluster on
//! 127.0.0.1, runs a deterministic and a stochastic case as 4-shard job arrays with a
//! dependent merge job, checks the merged CSVs byte for byte against one process and that a
//! failing shard cancels the merge, and stops the daemons by their process ids.

use crate::common::{rebound_bin, repo_root};
use std::process::Command;

#[test]
fn four_shards_on_a_local_slurm_cluster_merge_to_the_bytes_of_one_process() {
    crate::require(&["slurmctld", "slurmd", "munged", "sbatch"]);
    let out = Command::new("bash")
        .arg(repo_root().join("scripts/slurm/test-local-cluster.sh"))
        .env("REBOUND_BIN", rebound_bin())
        .output()
        .expect("run scripts/slurm/test-local-cluster.sh");
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{stdout}\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    for model in ["deterministic", "stochastic"] {
        assert!(
            stdout.contains(&format!("{model}: 4 Slurm shards merged = one process")),
            "{stdout}"
        );
    }
    assert!(stdout.contains("cancels the merge job"), "{stdout}");
}
