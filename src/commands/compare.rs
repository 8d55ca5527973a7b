//! `rebound compare --a DIR --b DIR --out DIR`: KS and L1 distances, means and stds of
//! the PDFs of two runs (see `crate::compare`, which reads and computes; this writes).

use crate::cli::CompareArgs;
use crate::commands::{begin_out, Summary};
use crate::compare::{compare_runs, comparison_table, read_run, unmatched_table};
use crate::output::{out_dir, write_atomic};
use roughwall::{Error, Result};
use std::collections::BTreeMap;
use std::path::Path;

/// Runs the subcommand.
pub fn run(args: &CompareArgs) -> Result<Summary> {
    let (rows, unmatched) = run_compare(&args.a, &args.b, &args.out, &args.label_a, &args.label_b)?;
    let unmatched = match unmatched {
        0 => String::new(),
        n => format!(", {n} unmatched"),
    };
    Ok(Summary {
        work: format!("{rows} rows compared{unmatched}"),
        rate: None,
        wrote: args.out.clone(),
    })
}

/// Writes `comparison.csv`, `unmatched.csv`, the overlays and a small `run.toml` into
/// `out`, as a whole (staging directory, lock, swap: [`crate::output::out_dir`]). `out` must
/// be a new directory or a previous rebound output other than `a_dir` and `b_dir`; both
/// inputs are read and checked before anything is written.
fn run_compare(
    a_dir: &Path,
    b_dir: &Path,
    out: &Path,
    label_a: &str,
    label_b: &str,
) -> Result<(usize, usize)> {
    out_dir::check_out(out, "--out")?;
    out_dir::check_distinct(out, "--out", &[("--a", a_dir), ("--b", b_dir)])?;
    let a = read_run(a_dir, "--a")?;
    let b = read_run(b_dir, "--b")?;
    let (rows, unmatched) = compare_runs(&a, &b);
    // Whole conditions one line each; quantities (model-specific curves such as
    // `gamma_model` or `dbeta_first`) one line per name.
    let mut only_q: BTreeMap<(String, &str), usize> = BTreeMap::new();
    for (al, be, q, w) in &unmatched {
        let run = if *w == "a" { a_dir } else { b_dir };
        if q.is_empty() {
            eprintln!(
                "warning: condition α⁻ = {al}°, β⁻ = {be}° is only in {} (listed in unmatched.csv)",
                run.display()
            );
        } else {
            *only_q.entry((q.clone(), *w)).or_default() += 1;
        }
    }
    for ((q, w), n) in &only_q {
        let run = if *w == "a" { a_dir } else { b_dir };
        eprintln!(
            "note: quantity `{q}` is only in {} ({n} condition(s), listed in unmatched.csv)",
            run.display()
        );
    }
    if rows.is_empty() {
        return Err(Error::Input(format!(
            "`--a` {} and `--b` {} have no incident condition and quantity in common",
            a_dir.display(),
            b_dir.display()
        )));
    }
    let staged = begin_out(out)?;
    let dir = staged.path();
    comparison_table(&rows).write(&dir.join("comparison.csv"))?;
    unmatched_table(&unmatched).write(&dir.join("unmatched.csv"))?;
    let figs = crate::figures::compare::write(dir, &a, &b, label_a, label_b)?;
    let mut run = toml::Table::new();
    run.insert("command".into(), "compare".into());
    run.insert("version".into(), crate::BUILD_VERSION.into());
    run.insert("a".into(), a_dir.display().to_string().into());
    run.insert("b".into(), b_dir.display().to_string().into());
    run.insert("label_a".into(), label_a.into());
    run.insert("label_b".into(), label_b.into());
    run.insert("rows".into(), toml::Value::Integer(rows.len() as i64));
    run.insert(
        "unmatched".into(),
        toml::Value::Integer(unmatched.len() as i64),
    );
    let mut root = toml::Table::new();
    root.insert("run".into(), toml::Value::Table(run));
    root.insert(
        "figures".into(),
        toml::Value::Array(figs.into_iter().map(toml::Value::String).collect()),
    );
    let text =
        toml::to_string_pretty(&root).map_err(|e| Error::Internal(format!("run.toml: {e}")))?;
    write_atomic(&dir.join("run.toml"), text.as_bytes())?;
    staged.commit()?;
    Ok((rows.len(), unmatched.len()))
}
