//! The integration tests' harness (ripgrep's `tests/util.rs` is the model): run the binary
//! ([`rebound`], [`rebound_in`], [`TestCommand`]) and check how it ended ([`Run`]), write
//! cases into a temporary directory ([`Dir`], [`write_case`]), find the shipped cases under
//! `configs/` ([`shipped_case`]), read output CSVs by column name ([`Csv`], [`Row`]) and
//! check their columns ([`headers`]), and build C programs against the C library.
#![allow(dead_code)]

pub mod c_examples;
pub mod capped;

use std::ffi::OsStr;
use std::path::{Path, PathBuf};
use std::process::Command;

/// The repository's root (where `Cargo.toml` is).
pub fn repo_root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// The `rebound` binary under test.
pub fn rebound_bin() -> &'static Path {
    Path::new(env!("CARGO_BIN_EXE_rebound"))
}

/// A shipped case file: `rel` under `configs/` (e.g. `cases/aniso.toml`).
pub fn shipped_case(rel: &str) -> PathBuf {
    let p = repo_root().join("configs").join(rel);
    assert!(p.is_file(), "no shipped case {}", p.display());
    p
}

/// The text of a shipped case file (`rel` under `configs/`).
pub fn read_shipped_case(rel: &str) -> String {
    let p = shipped_case(rel);
    std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

/// What a run of the binary gave: exit status (−1 for a signal), stdout, stderr.
#[derive(Debug)]
pub struct Run {
    pub code: i32,
    pub stdout: String,
    pub stderr: String,
}

impl Run {
    /// Panics with stderr unless the run succeeded.
    pub fn ok(self) -> Run {
        assert_eq!(self.code, 0, "{}", self.stderr);
        self
    }

    /// Checks a refusal: exit status 2 and one line on stderr that contains `needle`.
    pub fn refused(&self, needle: &str) {
        assert_eq!(self.code, 2, "{needle}: {}", self.stderr);
        let lines: Vec<&str> = self.stderr.trim().lines().collect();
        assert_eq!(lines.len(), 1, "{needle}: {}", self.stderr);
        assert!(lines[0].contains(needle), "{needle}: {}", self.stderr);
    }
}

/// A `rebound` command line to build up and run (ripgrep's `TestCommand`).
pub struct TestCommand {
    cmd: Command,
}

impl TestCommand {
    /// `rebound` with no arguments yet, in the test's working directory.
    pub fn new() -> TestCommand {
        TestCommand {
            cmd: Command::new(rebound_bin()),
        }
    }

    pub fn arg<S: AsRef<OsStr>>(&mut self, arg: S) -> &mut TestCommand {
        self.cmd.arg(arg);
        self
    }

    pub fn args<I: IntoIterator<Item = S>, S: AsRef<OsStr>>(
        &mut self,
        args: I,
    ) -> &mut TestCommand {
        self.cmd.args(args);
        self
    }

    /// Runs in `dir` instead of the test's working directory.
    pub fn current_dir(&mut self, dir: &Path) -> &mut TestCommand {
        self.cmd.current_dir(dir);
        self
    }

    pub fn env<K: AsRef<OsStr>, V: AsRef<OsStr>>(&mut self, key: K, value: V) -> &mut TestCommand {
        self.cmd.env(key, value);
        self
    }

    /// The underlying command, e.g. to spawn it.
    pub fn cmd(&mut self) -> &mut Command {
        &mut self.cmd
    }

    /// Runs to the end and collects what it gave.
    pub fn run(&mut self) -> Run {
        let out = self.cmd.output().expect("run rebound");
        Run {
            code: out.status.code().unwrap_or(-1),
            stdout: String::from_utf8_lossy(&out.stdout).into_owned(),
            stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
        }
    }
}

impl Default for TestCommand {
    fn default() -> Self {
        Self::new()
    }
}

/// Runs `rebound ARGS…`.
pub fn rebound<S: AsRef<OsStr>>(args: &[S]) -> Run {
    TestCommand::new().args(args).run()
}

/// Runs `rebound ARGS…` in directory `cwd`.
pub fn rebound_in<S: AsRef<OsStr>>(cwd: &Path, args: &[S]) -> Run {
    TestCommand::new().current_dir(cwd).args(args).run()
}

/// A temporary directory for one test: cases are written into it and runs write below it.
/// Removed when dropped.
pub struct Dir {
    tmp: tempfile::TempDir,
}

impl Dir {
    pub fn new() -> Dir {
        Dir {
            tmp: tempfile::tempdir().expect("temporary directory"),
        }
    }

    pub fn path(&self) -> &Path {
        self.tmp.path()
    }

    /// `name` inside the directory (not created).
    pub fn join<P: AsRef<Path>>(&self, name: P) -> PathBuf {
        self.tmp.path().join(name)
    }

    /// Writes `body` as the case file `name` and returns its path.
    pub fn write_case(&self, name: &str, body: &str) -> PathBuf {
        write_case(self.path(), name, body)
    }

    /// `rebound` to be run with this directory as its working directory.
    pub fn command(&self) -> TestCommand {
        let mut c = TestCommand::new();
        c.current_dir(self.path());
        c
    }
}

impl Default for Dir {
    fn default() -> Self {
        Self::new()
    }
}

/// Runs `rebound merge --out OUT SHARD…`, which must succeed; returns `out`.
pub fn merge_shards(out: &Path, shards: &[PathBuf]) -> PathBuf {
    let mut args = vec![
        "merge".to_string(),
        "--out".into(),
        out.display().to_string(),
    ];
    args.extend(shards.iter().map(|d| d.display().to_string()));
    rebound(&args).ok();
    out.to_path_buf()
}

/// Runs `rebound COMMAND --case CASE --out OUT EXTRA…` and returns what it gave.
pub fn rebound_case(command: &str, case: &Path, out: &Path, extra: &[&str]) -> Run {
    let mut args = vec![
        command,
        "--case",
        case.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ];
    args.extend_from_slice(extra);
    rebound(&args)
}

/// Runs `rebound COMMAND --case CASE --out OUT EXTRA…`, which must succeed; returns `out`.
pub fn run_case(command: &str, case: &Path, out: &Path, extra: &[&str]) -> PathBuf {
    rebound_case(command, case, out, extra).ok();
    out.to_path_buf()
}

/// Runs `rebound COMMAND --case CASE`, which must be refused in one line containing
/// `needle` (exit 2) without writing its `--out`.
pub fn refuse_case(command: &str, case: &Path, dir: &Path, needle: &str) {
    let out = dir.join("never-written");
    rebound_case(command, case, &out, &[]).refused(needle);
    assert!(!out.exists(), "{needle}: wrote {}", out.display());
}

/// Writes `body` as `dir/name` and returns its path.
pub fn write_case(dir: &Path, name: &str, body: &str) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, body).unwrap();
    p
}

/// A CSV file as its header and rows of cells.
pub struct Csv {
    pub header: Vec<String>,
    pub rows: Vec<Vec<String>>,
}

impl Csv {
    /// Reads the CSV file at `path`.
    pub fn read(path: &Path) -> Csv {
        let text =
            std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        Csv::parse(&text)
    }

    /// The CSV in `text`, quoted cells as the outputs write them (RFC 4180: a note or a path
    /// may hold a comma).
    pub fn parse(text: &str) -> Csv {
        let mut reader = csv::ReaderBuilder::new()
            .has_headers(false)
            .flexible(true)
            .from_reader(text.as_bytes());
        let mut records = reader.records().map(|r| {
            r.unwrap_or_else(|e| panic!("CSV: {e}"))
                .iter()
                .map(String::from)
                .collect::<Vec<String>>()
        });
        let header = records.next().unwrap_or_default();
        Csv {
            header,
            rows: records.collect(),
        }
    }

    /// The index of a column.
    pub fn col(&self, name: &str) -> usize {
        self.header
            .iter()
            .position(|h| h == name)
            .unwrap_or_else(|| panic!("no column {name}"))
    }

    /// The cell of `row` in column `name`.
    pub fn cell<'a>(&'a self, row: &'a [String], name: &str) -> &'a str {
        &row[self.col(name)]
    }

    /// The number in `row`, column `name`.
    pub fn num(&self, row: &[String], name: &str) -> f64 {
        let c = self.cell(row, name);
        c.parse()
            .unwrap_or_else(|_| panic!("{name} = {c:?} is not a number"))
    }

    /// Row `i` (0: the first after the header), its cells keyed by column name.
    pub fn row(&self, i: usize) -> Row<'_> {
        Row {
            csv: self,
            cells: self
                .rows
                .get(i)
                .unwrap_or_else(|| panic!("no row {i} (of {})", self.rows.len())),
        }
    }

    /// The rows, their cells keyed by column name.
    pub fn records(&self) -> impl Iterator<Item = Row<'_>> {
        self.rows.iter().map(move |cells| Row { csv: self, cells })
    }
}

/// One row of a [`Csv`]: `row["alpha_in_deg"]` is its cell in that column, `row.num(..)` the
/// cell as a number. Panics on an unknown column.
#[derive(Clone, Copy)]
pub struct Row<'a> {
    csv: &'a Csv,
    cells: &'a [String],
}

impl<'a> Row<'a> {
    /// The cell in column `name` as a number.
    pub fn num(&self, name: &str) -> f64 {
        self.csv.num(self.cells, name)
    }

    /// The cells in file order.
    pub fn cells(&self) -> &'a [String] {
        self.cells
    }
}

impl std::ops::Index<&str> for Row<'_> {
    type Output = str;
    fn index(&self, name: &str) -> &str {
        &self.cells[self.csv.col(name)]
    }
}

impl std::fmt::Debug for Row<'_> {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_map()
            .entries(self.csv.header.iter().zip(self.cells))
            .finish()
    }
}

/// The files of a directory that hold results (CSV), sorted, with their bytes.
pub fn csv_files(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut v: Vec<(String, Vec<u8>)> = std::fs::read_dir(dir)
        .unwrap()
        .filter_map(|e| e.ok())
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|x| x == "csv"))
        .map(|p| {
            (
                p.file_name().unwrap().to_string_lossy().into_owned(),
                std::fs::read(&p).unwrap(),
            )
        })
        .collect();
    v.sort();
    v
}

/// The directory holding the C library `libroughwall.so` built with this test binary.
/// `cargo test` writes it to `deps/` and leaves the copy next to the binary (made by an
/// earlier `cargo build`) as it was, possibly from older sources: the newer of the two.
pub fn c_library_dir() -> PathBuf {
    let bin = rebound_bin();
    let dir = bin.parent().unwrap();
    let modified = |d: &Path| {
        std::fs::metadata(d.join("libroughwall.so"))
            .and_then(|m| m.modified())
            .ok()
    };
    [dir.join("deps"), dir.to_path_buf()]
        .into_iter()
        .filter_map(|d| modified(&d).map(|t| (t, d)))
        .max_by_key(|(t, _)| *t)
        .map(|(_, d)| d)
        .unwrap_or_else(|| panic!("libroughwall.so not found next to {}", bin.display()))
}

/// Compiles `sources` with `compiler` against `include/` and `libroughwall.so` into
/// `out`; panics with the compiler's message on failure. The library's directory goes in as
/// an RPATH (not a RUNPATH), which the loader searches before `LD_LIBRARY_PATH`: `cargo
/// test` puts `target/debug` first there, whose `libroughwall.so` (left by an earlier
/// `cargo build`) may be older than the one this test was built with.
pub fn build_with_roughwall(compiler: &str, sources: &[&Path], out: &Path, extra: &[&str]) {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let lib = c_library_dir();
    let o = Command::new(compiler)
        .args(["-O2", "-Wall"])
        .arg("-I")
        .arg(root.join("include"))
        .args(extra)
        .args(sources)
        .arg("-L")
        .arg(&lib)
        .arg("-lroughwall")
        .arg(format!("-Wl,--disable-new-dtags,-rpath,{}", lib.display()))
        .arg("-lm")
        .arg("-o")
        .arg(out)
        .output()
        .expect("run the compiler");
    assert!(
        o.status.success(),
        "{compiler} failed: {}",
        String::from_utf8_lossy(&o.stderr)
    );
}

/// `x` as a TOML number, non-finite values included (TOML has `nan`, `inf` and `-inf`).
pub fn toml_number(x: f64) -> String {
    if x.is_nan() {
        "nan".into()
    } else if x.is_infinite() {
        if x > 0.0 { "inf" } else { "-inf" }.into()
    } else {
        format!("{x:?}")
    }
}

/// The columns of the outputs, as `docs/outputs.md` documents them: a test that reads an
/// output checks its header against these, so a changed column is a failing test until the
/// docs and this list say the same.
pub mod headers {
    /// `summary.csv` of `deterministic` and `stochastic`.
    pub const SUMMARY: &str = "alpha_in_deg,beta_in_deg,delta_xi_deg,delta_zeta_deg,particles,mean_alpha_out_deg,std_alpha_out_deg,mean_dbeta_deg,std_dbeta_deg,mean_dbeta_first_deg,std_dbeta_first_deg,mean_gamma_deg,std_gamma_deg,mean_gamma_star_deg,std_gamma_star_deg,p_single,mean_collisions,max_collisions,mean_speed_ratio,lost,se_mean_alpha_out_deg,se_mean_dbeta_deg,se_mean_dbeta_first_deg,se_mean_gamma_deg,se_mean_gamma_star_deg,se_p_single,se_mean_collisions,se_mean_speed_ratio";
    /// The columns `summary.csv` adds with `[erosion]`.
    pub const SUMMARY_EROSION: &str = "erosion_per_mass,se_erosion_per_mass,mean_impacts,se_mean_impacts,erosion_per_mass_rejected,se_erosion_per_mass_rejected,erosion_per_particle_m3,se_erosion_per_particle_m3";
    /// `pdfs.csv`.
    pub const PDFS: &str = "alpha_in_deg,beta_in_deg,quantity,bin_lo,bin_hi,value,se";
    /// `moments.csv`.
    pub const MOMENTS: &str = "alpha_in_deg,beta_in_deg,quantity,n,mean,std,se,se_histories";
    /// `comparison.csv` of `compare`.
    pub const COMPARISON: &str =
        "alpha_in_deg,beta_in_deg,quantity,ks,l1,mean_a,mean_b,std_a,std_b,se_mean_a,se_mean_b,z";
    /// `effective_roughness.csv` of `surface`.
    pub const EFFECTIVE: &str = "diameter_um,d_over_cl_x,d_over_cl_z,delta_xi_eff_deg,delta_zeta_eff_deg,delta_xi_ratio,delta_zeta_ratio,contact_fraction,sqrt_h_over_d_deg,delta_xi_eff_over_sqrt_h_over_d,delta_zeta_eff_over_sqrt_h_over_d";
    /// `scan_summary.csv` of `scan`.
    pub const SCAN_SUMMARY: &str = "file,format,nx,ny,dx_um,dy_um,valid_points,missing_fraction,level_degree,sq_um,ssk,sku,sdq,sdq_x,sdq_y,lay_deg,delta_xi_deg,delta_zeta_deg,rho_xi_zeta,skewness_xi,skewness_zeta,kurtosis_xi,kurtosis_zeta,delta_scan_x_deg,delta_scan_y_deg,corr_length_along_um,corr_length_across_um";
    /// `wall_card_diameters.csv` of `scan` with diameters.
    pub const WALL_CARD_DIAMETERS: &str = "diameter_um,delta_xi_deg,delta_zeta_deg,delta_xi_deg_2x_pixel,delta_zeta_deg_2x_pixel,change_xi_2x_pixel,change_zeta_2x_pixel,exact_fraction,reach_x_um,reach_y_um,footprint_um,correlation_areas,delta_rel_se,note";
    /// `force_sweep.csv` of `force-sweep`.
    pub const FORCE_SWEEP: &str = "model,lambda,beta_deg,u_n_m_s,diameter_um,density_kg_m3,youngs_pa,poisson,f_max_n,xi,contact_time_s";
}

/// The bins `(lo, hi, value)` of `quantity` in the `pdfs.csv` of the run in `dir`, for its
/// first condition.
pub fn pdf_bins(dir: &Path, quantity: &str) -> Vec<(f64, f64, f64)> {
    let c = Csv::read(&dir.join("pdfs.csv"));
    let first = c.rows.first().expect("pdfs.csv has rows");
    let key = (
        c.cell(first, "alpha_in_deg").to_string(),
        c.cell(first, "beta_in_deg").to_string(),
    );
    c.rows
        .iter()
        .filter(|r| {
            c.cell(r, "alpha_in_deg") == key.0
                && c.cell(r, "beta_in_deg") == key.1
                && c.cell(r, "quantity") == quantity
        })
        .map(|r| (c.num(r, "bin_lo"), c.num(r, "bin_hi"), c.num(r, "value")))
        .collect()
}

/// Wall deviations `(Δξ, Δζ)` given in degrees.
pub fn dev(dxi_deg: f64, dzeta_deg: f64) -> roughwall::Deviations {
    roughwall::Deviations {
        delta_xi: dxi_deg.to_radians(),
        delta_zeta: dzeta_deg.to_radians(),
    }
}

/// The Kolmogorov–Smirnov distance between the histogram `h` and the PDF of `quantity` in
/// the `pdfs.csv` of the run in `dir` (its first condition).
pub fn ks_against_run(h: &roughwall::tally::Histogram, dir: &Path, quantity: &str) -> f64 {
    use roughwall::tally::{distances, BinnedPdf};
    let mine = BinnedPdf::new(h.density().iter().map(|b| (b.lo, b.hi, b.value)).collect());
    distances(&mine, &BinnedPdf::new(pdf_bins(dir, quantity))).0
}
