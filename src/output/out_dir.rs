//! Output directories written as a whole: a run writes every output into a hidden staging
//! directory beside `--out` and swaps it in at the end, so that `--out` holds either the old
//! complete result or the new one, also when a run fails, is killed (even with `kill -9`) or
//! runs concurrently with another one on the same `--out`.
//!
//! For an output directory `PARENT/NAME` ([`OutputDir`]):
//!
//! - every output path is validated before anything is computed ([`check_out`],
//!   [`place_file`], [`check_distinct`]): `--out` must be a directory or not exist, and an
//!   existing non-empty `--out` must be a previous rebound output (a `run.toml` with a
//!   `[run] command = …` table, a shard directory with `partial.toml`, or a directory holding
//!   only such directories), so that a user's unrelated directory is never swapped away;
//! - `PARENT/.NAME.lock` is locked (`flock(LOCK_EX | LOCK_NB)`) from before the computation
//!   until after the swap; a second run on the same `--out` is refused. The lock file is
//!   created if missing and deliberately left in place (deleting lock files races);
//! - outputs go to `PARENT/.NAME.staging-<pid>-<random>`; [`OutputDir::commit`] exchanges it
//!   with `PARENT/NAME` in one `renameat2(RENAME_EXCHANGE)` (Linux), or renames it into place
//!   when `NAME` does not exist, then removes the staging directory (which then holds the old
//!   result) and syncs `PARENT`. Without `RENAME_EXCHANGE` (`EINVAL`/`ENOSYS`, e.g. NFS, or
//!   another Unix) it renames `NAME` to `PARENT/.NAME.old-<pid>`, the staging directory to
//!   `NAME`, and removes the old one: between the two renames (two system calls) `NAME` does
//!   not exist; a run killed exactly there leaves the old result in `.NAME.old-<pid>`, which
//!   the next run on the same `--out` puts back before anything else;
//! - subdirectories of the old result that the new one does not have (e.g. the
//!   `shard-K-of-N` directories of shard runs without `--out`, or a `compare` output written
//!   inside a run's directory) and the lock files of such nested outputs are carried into the
//!   new result (hard links, or copies where the file system has none);
//! - a run that fails after staging began removes its staging directory (a drop guard) and
//!   leaves `--out` untouched; so does a run stopped by SIGINT, SIGTERM or SIGHUP (Ctrl-C, a
//!   batch system's cancel or time limit): [`remove_staging_on_signals`] removes the staging
//!   directories of the process and exits with status 128 + the signal; staging and old directories left by killed runs are removed
//!   (or, for an old directory whose `NAME` is missing, put back) by the next run on the same
//!   `--out`, which holds the lock and so knows that no live run owns them.

use roughwall::Warning;
use roughwall::{Error, Result};
use std::ffi::{OsStr, OsString};
use std::fs::{self, File};
use std::io;
use std::path::{Component, Path, PathBuf};

/// File name of a partial tally inside a shard's output directory (written by
/// `tally::partial`; here so that a shard directory is recognised as a rebound output).
pub const PARTIAL_FILE: &str = "partial.toml";

/// Where a run writes: the target `--out`, the staging directory (see the module
/// documentation) and the lock held until the swap.
pub struct OutputDir {
    /// `--out` with symbolic links of its existing part resolved.
    target: PathBuf,
    /// `--out` as the user gave it (for messages).
    shown: PathBuf,
    parent: PathBuf,
    key: String,
    staging: PathBuf,
    _lock: Option<File>,
    committed: bool,
    /// What the caller should tell the user (a file system without locks).
    warnings: Vec<Warning>,
}

impl OutputDir {
    /// Validates `target` (given as option `option`, e.g. `--out`), creates its parent,
    /// locks it, cleans what killed runs left, and creates the staging directory. Input
    /// problems are one-line [`Error::Input`]s (exit 2) raised before anything is created,
    /// except the lock refusal (the lock file stays, by design).
    pub fn begin(target: &Path, option: &str) -> Result<OutputDir> {
        check_out(target, option)?;
        let resolved = resolve(target).map_err(|e| Error::io(target, e))?;
        let (parent, name) = split(&resolved, target, option)?;
        fs::create_dir_all(&parent).map_err(|e| Error::io(&parent, e))?;
        let key = key_of(&name);
        let lock_path = parent.join(format!(".{key}.lock"));
        let mut warnings = Vec::new();
        let lock = lock(&lock_path, target, &mut warnings)?;
        recover(&parent, &key, &resolved)?;
        // The state may have changed while we were not holding the lock.
        check_out(target, option)?;
        let staging = create_staging(&parent, &key)?;
        remember_staging(&staging);
        Ok(OutputDir {
            target: resolved,
            shown: target.to_path_buf(),
            parent,
            key,
            staging,
            _lock: lock,
            committed: false,
            warnings,
        })
    }

    /// The warnings of [`Self::begin`], for the caller to print (taken once).
    pub fn take_warnings(&mut self) -> Vec<Warning> {
        std::mem::take(&mut self.warnings)
    }

    /// Where the run writes its outputs (the staging directory).
    pub fn path(&self) -> &Path {
        &self.staging
    }

    /// Swaps the staging directory in as the output directory (see the module
    /// documentation) and returns the output directory as given.
    pub fn commit(mut self) -> Result<PathBuf> {
        let exists = fs::symlink_metadata(&self.target).is_ok();
        if exists {
            carry_nested(&self.target, &self.staging, true)
                .map_err(|e| Error::io(&self.target, format!("carrying subdirectories: {e}")))?;
        }
        sync_tree(&self.staging).map_err(|e| Error::io(&self.staging, e))?;
        // Held across the swap: a signal's cleanup (which takes it first) cannot remove a
        // staging directory that is being swapped in.
        let mut registered = STAGING.lock().unwrap_or_else(|e| e.into_inner());
        registered.retain(|q| q != &self.staging);
        if exists {
            match exchange(&self.staging, &self.target) {
                Ok(()) => {}
                Err(e) if matches!(e.raw_os_error(), Some(c) if exchange_unsupported(c)) => {
                    self.swap_by_renames()?;
                }
                Err(e) => return Err(Error::io(&self.target, e)),
            }
        } else {
            fs::rename(&self.staging, &self.target).map_err(|e| Error::io(&self.target, e))?;
        }
        self.committed = true;
        drop(registered);
        sync_dir(&self.parent).map_err(|e| Error::io(&self.parent, e))?;
        // After an exchange the staging path holds the old result; a failure here only
        // leaves a hidden directory that the next run removes.
        if exists {
            let _ = fs::remove_dir_all(&self.staging);
        }
        Ok(self.shown.clone())
    }

    /// The fallback without `RENAME_EXCHANGE`: old away, new in, old removed.
    fn swap_by_renames(&self) -> Result<()> {
        let old = self
            .parent
            .join(format!(".{}.old-{}", self.key, std::process::id()));
        fs::rename(&self.target, &old).map_err(|e| Error::io(&self.target, e))?;
        if let Err(e) = fs::rename(&self.staging, &self.target) {
            let _ = fs::rename(&old, &self.target);
            return Err(Error::io(&self.target, e));
        }
        let _ = sync_dir(&self.parent);
        let _ = fs::remove_dir_all(&old);
        Ok(())
    }
}

impl Drop for OutputDir {
    fn drop(&mut self) {
        if !self.committed {
            let _ = fs::remove_dir_all(&self.staging);
        }
        forget_staging(&self.staging);
    }
}

/// The staging directories this process is writing (what a signal must remove).
static STAGING: std::sync::Mutex<Vec<PathBuf>> = std::sync::Mutex::new(Vec::new());

fn remember_staging(p: &Path) {
    STAGING
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .push(p.to_path_buf());
}

fn forget_staging(p: &Path) {
    STAGING
        .lock()
        .unwrap_or_else(|e| e.into_inner())
        .retain(|q| q != p);
}

/// On SIGINT, SIGTERM or SIGHUP, removes the staging directories of the process and exits
/// with status 128 + the signal, as a process killed by it would: `--out` keeps its old
/// result, and nothing hidden is left beside it. (A run killed by SIGKILL cannot clean up: the
/// next run on the same `--out` does.) A thread waits for the signals; call once, early.
pub fn remove_staging_on_signals() {
    use signal_hook::consts::{SIGHUP, SIGINT, SIGTERM};
    let Ok(mut signals) = signal_hook::iterator::Signals::new([SIGINT, SIGTERM, SIGHUP]) else {
        return; // without the handler a signal ends the run as before
    };
    std::thread::spawn(move || {
        if let Some(sig) = signals.forever().next() {
            let dirs = STAGING.lock().unwrap_or_else(|e| e.into_inner()).clone();
            for d in dirs {
                let _ = fs::remove_dir_all(&d);
            }
            std::process::exit(128 + sig);
        }
    });
}

/// What an existing path is, for messages.
fn kind(ft: &fs::FileType) -> &'static str {
    roughwall::check::file_type_name(ft)
}

/// Checks an output directory without writing anything: it must not exist, or be a
/// directory (a symbolic link to one is followed) that is empty or a previous rebound output.
pub fn check_out(target: &Path, option: &str) -> Result<()> {
    let shown = target.display();
    let refuse = |what: &str| {
        Error::Input(format!(
            "invalid `{option}` = {shown}: it is {what}; allowed a new directory or an existing rebound output directory"
        ))
    };
    if target.as_os_str().is_empty() {
        return Err(refuse("empty"));
    }
    match fs::metadata(target) {
        Ok(md) if md.is_dir() => {}
        Ok(md) => {
            let link = fs::symlink_metadata(target).is_ok_and(|m| m.file_type().is_symlink());
            let what = kind(&md.file_type());
            return Err(refuse(&if link {
                format!("a symbolic link to {what}")
            } else {
                what.to_string()
            }));
        }
        Err(e) if e.kind() == io::ErrorKind::NotFound => {
            if fs::symlink_metadata(target).is_ok() {
                return Err(refuse("a dangling symbolic link"));
            }
            return Ok(());
        }
        Err(e) => return Err(refuse(&format!("not usable ({e})"))),
    }
    match classify(target, 0) {
        Ok(Content::Empty | Content::Output) => Ok(()),
        Ok(Content::Foreign) => Err(Error::Input(format!(
            "`{option}` {shown} holds files that are not a rebound output; give a new or empty directory"
        ))),
        Err(e) => Err(Error::io(target, e)),
    }
}

/// What an existing directory holds.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Content {
    /// Nothing but hidden lock, staging or old entries of nested outputs.
    Empty,
    /// A rebound output, or only directories that are rebound outputs (or empty).
    Output,
    Foreign,
}

/// Entries rebound itself leaves beside an output directory: `.NAME.lock`,
/// `.NAME.staging-…`, `.NAME.old-…`.
fn is_own_hidden(name: &OsStr) -> bool {
    let Some(s) = name.to_str() else {
        return false;
    };
    s.starts_with('.') && (s.ends_with(".lock") || s.contains(".staging-") || s.contains(".old-"))
}

/// Whether `dir/run.toml` is a rebound manifest (a `[run]` table with a `command`).
fn has_manifest(dir: &Path) -> bool {
    let p = dir.join("run.toml");
    if !fs::symlink_metadata(&p).is_ok_and(|m| m.is_file()) {
        return false;
    }
    let Ok(text) = fs::read_to_string(&p) else {
        return false;
    };
    let Ok(t) = text.parse::<toml::Table>() else {
        return false;
    };
    matches!(
        t.get("run").and_then(|r| r.get("command")),
        Some(toml::Value::String(_))
    )
}

/// Whether `dir/partial.toml` is a partial tally (a shard directory).
fn has_partial(dir: &Path) -> bool {
    use std::io::Read;
    let p = dir.join(PARTIAL_FILE);
    if !fs::symlink_metadata(&p).is_ok_and(|m| m.is_file()) {
        return false;
    }
    let mut head = Vec::new();
    let ok = File::open(&p).and_then(|f| f.take(4096).read_to_end(&mut head));
    ok.is_ok() && String::from_utf8_lossy(&head).contains("format = \"rebound partial tally\"")
}

fn classify(dir: &Path, depth: usize) -> io::Result<Content> {
    let mut names = Vec::new();
    for e in fs::read_dir(dir)? {
        let e = e?;
        if !is_own_hidden(&e.file_name()) {
            names.push(e);
        }
    }
    if names.is_empty() {
        return Ok(Content::Empty);
    }
    if has_manifest(dir) || has_partial(dir) {
        return Ok(Content::Output);
    }
    if depth >= 3 {
        return Ok(Content::Foreign);
    }
    let mut any = false;
    for e in names {
        if !e.file_type()?.is_dir() {
            return Ok(Content::Foreign);
        }
        match classify(&e.path(), depth + 1)? {
            Content::Foreign => return Ok(Content::Foreign),
            Content::Output => any = true,
            Content::Empty => {}
        }
    }
    Ok(if any {
        Content::Output
    } else {
        Content::Foreign
    })
}

/// `p` as an absolute path: symbolic links, `.` and `..` of its existing part resolved
/// (`canonicalize`), `.` and `..` of the rest applied to the text.
pub fn resolve(p: &Path) -> io::Result<PathBuf> {
    let abs = if p.is_absolute() {
        p.to_path_buf()
    } else {
        std::env::current_dir()?.join(p)
    };
    let mut out = PathBuf::new();
    for comp in abs.components() {
        match comp {
            Component::Prefix(_) | Component::RootDir => out.push(comp.as_os_str()),
            Component::CurDir => {}
            Component::ParentDir => {
                out.pop();
            }
            Component::Normal(n) => {
                let next = out.join(n);
                out = match fs::canonicalize(&next) {
                    Ok(c) => c,
                    Err(e) if e.kind() == io::ErrorKind::NotFound => next,
                    Err(e) => return Err(e),
                };
            }
        }
    }
    Ok(out)
}

/// The parent and the name of a resolved output directory.
fn split(resolved: &Path, shown: &Path, option: &str) -> Result<(PathBuf, OsString)> {
    match (resolved.parent(), resolved.file_name()) {
        (Some(p), Some(n)) => Ok((p.to_path_buf(), n.to_os_string())),
        _ => Err(Error::invalid(
            option,
            shown.display(),
            "a directory that has a parent (not the root)",
        )),
    }
}

/// The name the hidden entries beside `NAME` are built from: `NAME` itself, or a digest of
/// it when it is not UTF-8 or too long for `.NAME.staging-…` to be a valid file name.
fn key_of(name: &OsStr) -> String {
    match name.to_str() {
        Some(s) if s.len() <= 200 => s.to_string(),
        _ => {
            let hex = super::sha256_hex(name.as_encoded_bytes());
            format!("~{}", &hex[..40])
        }
    }
}

/// Opens (creating it if needed) and locks the lock file of `shown`; a file system that has no
/// locks is a warning in `warnings`, not an error.
fn lock(path: &Path, shown: &Path, warnings: &mut Vec<Warning>) -> Result<Option<File>> {
    let mut opts = fs::OpenOptions::new();
    opts.read(true).write(true).create(true).truncate(false);
    #[cfg(unix)]
    {
        use std::os::unix::fs::OpenOptionsExt;
        opts.custom_flags(libc::O_NOFOLLOW);
    }
    let file = opts.open(path).map_err(|e| Error::io(path, e))?;
    #[cfg(unix)]
    {
        use std::os::unix::io::AsRawFd;
        // SAFETY: a valid open file descriptor; flock has no memory effects.
        let rc = unsafe { libc::flock(file.as_raw_fd(), libc::LOCK_EX | libc::LOCK_NB) };
        if rc != 0 {
            let e = io::Error::last_os_error();
            return match e.raw_os_error() {
                Some(c) if c == libc::EWOULDBLOCK || c == libc::EAGAIN => {
                    Err(Error::Input(format!(
                        "another rebound run is writing `{}` (lock `{}`)",
                        shown.display(),
                        path.display()
                    )))
                }
                Some(c) if c == libc::ENOLCK || c == libc::EOPNOTSUPP || c == libc::ENOSYS => {
                    warnings.push(Warning(format!(
                        "`{}` cannot be locked ({e}): concurrent runs on `{}` are not detected",
                        path.display(),
                        shown.display()
                    )));
                    Ok(Some(file))
                }
                _ => Err(Error::io(path, e)),
            };
        }
    }
    Ok(Some(file))
}

/// Whether process `pid` is alive (another process than this one).
fn alive(pid: u32) -> bool {
    if pid == std::process::id() {
        return false;
    }
    #[cfg(unix)]
    {
        let Ok(p) = libc::pid_t::try_from(pid) else {
            return false;
        };
        if p <= 0 {
            return false;
        }
        // SAFETY: signal 0 only checks that the process exists.
        let rc = unsafe { libc::kill(p, 0) };
        rc == 0 || io::Error::last_os_error().raw_os_error() == Some(libc::EPERM)
    }
    #[cfg(not(unix))]
    {
        true
    }
}

/// The pid of `.KEY.staging-<pid>-<hex>` or `.KEY.old-<pid>`, if `name` is one of them.
fn hidden_pid(name: &str, key: &str, tag: &str) -> Option<u32> {
    let rest = name
        .strip_prefix('.')?
        .strip_prefix(key)?
        .strip_prefix('.')?;
    let rest = rest.strip_prefix(tag)?;
    let (pid, tail) = match tag {
        "staging-" => {
            let (p, r) = rest.split_once('-')?;
            (p, Some(r))
        }
        _ => (rest, None),
    };
    if pid.is_empty() || !pid.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    if let Some(t) = tail {
        if t.is_empty() || !t.bytes().all(|b| b.is_ascii_hexdigit()) {
            return None;
        }
    }
    pid.parse().ok()
}

/// Cleans what killed runs on `target` left in `parent` (called with the lock held): an old
/// result moved aside by the rename fallback is put back if `target` is missing, and stale
/// staging and old directories (their process is gone) are removed.
fn recover(parent: &Path, key: &str, target: &Path) -> Result<()> {
    let entries = match fs::read_dir(parent) {
        Ok(e) => e,
        Err(e) => return Err(Error::io(parent, e)),
    };
    let mut stale = Vec::new();
    let mut olds = Vec::new();
    for e in entries.flatten() {
        let name = e.file_name();
        let Some(s) = name.to_str() else { continue };
        if let Some(pid) = hidden_pid(s, key, "staging-") {
            if !alive(pid) {
                stale.push(e.path());
            }
        } else if let Some(pid) = hidden_pid(s, key, "old-") {
            if !alive(pid) {
                olds.push(e.path());
            }
        }
    }
    for old in olds {
        if fs::symlink_metadata(target).is_err() {
            fs::rename(&old, target).map_err(|e| Error::io(&old, e))?;
            sync_dir(parent).map_err(|e| Error::io(parent, e))?;
        } else {
            stale.push(old);
        }
    }
    for dir in stale {
        fs::remove_dir_all(&dir).map_err(|e| Error::io(&dir, e))?;
    }
    Ok(())
}

/// Creates `PARENT/.KEY.staging-<pid>-<random>`.
fn create_staging(parent: &Path, key: &str) -> Result<PathBuf> {
    let pid = std::process::id();
    loop {
        let p = parent.join(format!(
            ".{key}.staging-{pid}-{:08x}",
            rand::random::<u32>()
        ));
        match fs::create_dir(&p) {
            Ok(()) => return Ok(p),
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists => continue,
            Err(e) => return Err(Error::io(&p, e)),
        }
    }
}

/// Copies what of `old` the new result `new` keeps: at the top, the subdirectories `new`
/// does not have and the lock files of nested outputs; inside a subdirectory both have (e.g.
/// `surface --heights OUT/sub/FILE`), every entry `new` does not have. Hard links where
/// possible (the files rebound writes are never modified in place), copies otherwise.
fn carry_nested(old: &Path, new: &Path, top: bool) -> io::Result<()> {
    let entries = match fs::read_dir(old) {
        Ok(e) => e,
        // Not a directory (cannot happen after the checks) or gone: nothing to carry.
        Err(_) => return Ok(()),
    };
    for e in entries {
        let e = e?;
        let name = e.file_name();
        let to = new.join(&name);
        let ft = e.file_type()?;
        if let Ok(md) = fs::symlink_metadata(&to) {
            if ft.is_dir() && md.is_dir() {
                carry_nested(&e.path(), &to, false)?;
            }
            continue;
        }
        let s = name.to_string_lossy();
        let lock = s.starts_with('.') && s.ends_with(".lock");
        if ft.is_dir() && !(top && is_own_hidden(&name)) {
            link_tree(&e.path(), &to)?;
        } else if ft.is_file() && (lock || !top) {
            link_or_copy(&e.path(), &to)?;
        } else if ft.is_symlink() && !top {
            #[cfg(unix)]
            std::os::unix::fs::symlink(fs::read_link(e.path())?, &to)?;
        }
    }
    Ok(())
}

fn link_or_copy(from: &Path, to: &Path) -> io::Result<()> {
    if fs::hard_link(from, to).is_err() {
        fs::copy(from, to)?;
        File::open(to)?.sync_all()?;
    }
    Ok(())
}

fn link_tree(from: &Path, to: &Path) -> io::Result<()> {
    fs::create_dir(to)?;
    for e in fs::read_dir(from)? {
        let e = e?;
        let ft = e.file_type()?;
        let dst = to.join(e.file_name());
        if ft.is_dir() {
            link_tree(&e.path(), &dst)?;
        } else if ft.is_file() {
            link_or_copy(&e.path(), &dst)?;
        } else if ft.is_symlink() {
            #[cfg(unix)]
            std::os::unix::fs::symlink(fs::read_link(e.path())?, &dst)?;
        }
        // FIFOs, sockets and devices are not carried.
    }
    Ok(())
}

/// Syncs a directory's entries to disk.
fn sync_dir(dir: &Path) -> io::Result<()> {
    File::open(dir)?.sync_all()
}

/// Syncs `dir` and every directory below it (the files were synced when written).
fn sync_tree(dir: &Path) -> io::Result<()> {
    for e in fs::read_dir(dir)? {
        let e = e?;
        if e.file_type()?.is_dir() {
            sync_tree(&e.path())?;
        }
    }
    sync_dir(dir)
}

/// Whether `renameat2` failed because the file system (or kernel) lacks `RENAME_EXCHANGE`.
fn exchange_unsupported(code: i32) -> bool {
    #[cfg(unix)]
    {
        code == libc::EINVAL || code == libc::ENOSYS || code == libc::EOPNOTSUPP
    }
    #[cfg(not(unix))]
    {
        let _ = code;
        true
    }
}

/// Atomically exchanges two paths (Linux `renameat2(RENAME_EXCHANGE)`).
#[cfg(target_os = "linux")]
fn exchange(a: &Path, b: &Path) -> io::Result<()> {
    use std::ffi::CString;
    use std::os::unix::ffi::OsStrExt;
    let ca = CString::new(a.as_os_str().as_bytes())?;
    let cb = CString::new(b.as_os_str().as_bytes())?;
    // SAFETY: two valid NUL-terminated paths; AT_FDCWD is ignored for absolute paths.
    let rc = unsafe {
        libc::renameat2(
            libc::AT_FDCWD,
            ca.as_ptr(),
            libc::AT_FDCWD,
            cb.as_ptr(),
            libc::RENAME_EXCHANGE,
        )
    };
    if rc == 0 {
        Ok(())
    } else {
        Err(io::Error::last_os_error())
    }
}

#[cfg(not(target_os = "linux"))]
fn exchange(_a: &Path, _b: &Path) -> io::Result<()> {
    #[cfg(unix)]
    let code = libc::ENOSYS;
    #[cfg(not(unix))]
    let code = 38;
    Err(io::Error::from_raw_os_error(code))
}

/// Where a file given by an option (e.g. `surface --heights FILE`) is written.
#[derive(Clone, Debug, PartialEq)]
pub enum Placement {
    /// Outside the output directory: written on its own (atomically) at this path.
    Outside(PathBuf),
    /// Inside the output directory, at this relative path: written into the staging
    /// directory so that it moves with the swap.
    Inside(PathBuf),
}

impl Placement {
    /// The path to write to, given the run's output directory.
    pub fn path_in(&self, out: &OutputDir) -> PathBuf {
        match self {
            Placement::Outside(p) => p.clone(),
            Placement::Inside(rel) => out.path().join(rel),
        }
    }
}

/// Checks a file the run writes besides its outputs (`option` = `--heights` …): it must be a
/// regular file or not exist, and not clash with the run's own outputs in `out` (the file
/// names `outputs`) nor with the hidden entries beside `out`.
pub fn place_file(file: &Path, option: &str, out: &Path, outputs: &[&str]) -> Result<Placement> {
    let shown = file.display();
    let allowed = "a regular file or a new path, outside `--out` or inside it under a name the run does not write";
    let refuse = |what: &str| {
        Error::Input(format!(
            "invalid `{option}` = {shown}: it is {what}; allowed {allowed}"
        ))
    };
    if file.as_os_str().is_empty() {
        return Err(refuse("empty"));
    }
    match fs::symlink_metadata(file) {
        Ok(md) if md.file_type().is_file() => {}
        Ok(md) => return Err(refuse(kind(&md.file_type()))),
        Err(e) if e.kind() == io::ErrorKind::NotFound => {}
        Err(e) => return Err(refuse(&format!("not usable ({e})"))),
    }
    let rf = resolve(file).map_err(|e| refuse(&format!("not usable ({e})")))?;
    let ro = resolve(out).map_err(|e| Error::io(out, e))?;
    if rf == ro {
        return Err(refuse("the output directory itself"));
    }
    if let (Some(fp), Some(fname), Some(op), Some(oname)) =
        (rf.parent(), rf.file_name(), ro.parent(), ro.file_name())
    {
        if fp == op {
            let key = key_of(oname);
            let n = fname.to_string_lossy();
            if n == format!(".{key}.lock")
                || n.starts_with(&format!(".{key}.staging-"))
                || n.starts_with(&format!(".{key}.old-"))
            {
                return Err(refuse("an entry rebound keeps beside the output directory"));
            }
        }
    }
    match rf.strip_prefix(&ro) {
        Ok(rel) => {
            let first = rel
                .components()
                .next()
                .map(|c| c.as_os_str().to_string_lossy().into_owned())
                .unwrap_or_default();
            if outputs.iter().any(|o| *o == first) {
                return Err(refuse(&format!(
                    "the run's own output `{first}` (the run writes {})",
                    outputs.join(", ")
                )));
            }
            Ok(Placement::Inside(rel.to_path_buf()))
        }
        Err(_) => Ok(Placement::Outside(file.to_path_buf())),
    }
}

/// Checks that the output directory `out` (option `option`) is none of the directories the
/// run reads (`inputs`: option name and path; a file stands for its directory).
pub fn check_distinct(out: &Path, option: &str, inputs: &[(&str, &Path)]) -> Result<()> {
    let ro = resolve(out).map_err(|e| Error::io(out, e))?;
    for (name, p) in inputs {
        let Ok(rp) = resolve(p) else { continue };
        let dir = if rp.is_file() {
            rp.parent().map(Path::to_path_buf).unwrap_or(rp.clone())
        } else {
            rp.clone()
        };
        if dir == ro {
            return Err(Error::Input(format!(
                "invalid `{option}` = {}: it is the directory of `{name}` {}, which the run reads; allowed a directory that holds none of the run's inputs",
                out.display(),
                p.display()
            )));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn manifest(dir: &Path, body: &str) {
        fs::create_dir_all(dir).unwrap();
        fs::write(
            dir.join("run.toml"),
            format!("[run]\ncommand = \"x\"\n{body}"),
        )
        .unwrap();
    }

    fn names(dir: &Path) -> Vec<String> {
        let mut v: Vec<String> = fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        v.sort();
        v
    }

    /// This module's tests one at a time: a process spawned by one test (`dead_pid`) holds a
    /// copy of every open descriptor between its fork and its exec, so another test's run
    /// lock could seem held by "another run" for that moment.
    fn serial() -> std::sync::MutexGuard<'static, ()> {
        static SERIAL: std::sync::Mutex<()> = std::sync::Mutex::new(());
        SERIAL.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// The pid of a process that has exited.
    fn dead_pid() -> u32 {
        let mut c = std::process::Command::new("true").spawn().unwrap();
        let pid = c.id();
        c.wait().unwrap();
        pid
    }

    #[test]
    fn commit_swaps_and_drop_discards() {
        let _serial = serial();
        let tmp = tempfile::tempdir().unwrap();
        let d = tmp.path().join("d");
        let o = OutputDir::begin(&d, "--out").unwrap();
        fs::write(o.path().join("a.csv"), "1").unwrap();
        manifest(o.path(), "");
        o.commit().unwrap();
        assert_eq!(names(&d), ["a.csv", "run.toml"]);
        // A failed run: the old result stays.
        let o = OutputDir::begin(&d, "--out").unwrap();
        fs::write(o.path().join("b.csv"), "2").unwrap();
        drop(o);
        assert_eq!(names(&d), ["a.csv", "run.toml"]);
        // A second result replaces the first as a whole; subdirectories are carried.
        manifest(&d.join("sub"), "");
        let o = OutputDir::begin(&d, "--out").unwrap();
        fs::write(o.path().join("b.csv"), "2").unwrap();
        manifest(o.path(), "y = 1\n");
        o.commit().unwrap();
        assert_eq!(names(&d), ["b.csv", "run.toml", "sub"]);
        assert!(d.join("sub/run.toml").is_file());
        assert_eq!(names(tmp.path()), [".d.lock", "d"]);
    }

    #[test]
    fn the_rename_fallback_swaps_too() {
        let _serial = serial();
        let tmp = tempfile::tempdir().unwrap();
        let d = tmp.path().join("d");
        manifest(&d, "old = 1\n");
        let mut o = OutputDir::begin(&d, "--out").unwrap();
        manifest(o.path(), "new = 1\n");
        o.swap_by_renames().unwrap();
        o.committed = true;
        drop(o);
        assert!(fs::read_to_string(d.join("run.toml"))
            .unwrap()
            .contains("new = 1"));
        assert_eq!(names(tmp.path()), [".d.lock", "d"]);
    }

    #[test]
    fn nested_entries_are_carried() {
        let _serial = serial();
        let tmp = tempfile::tempdir().unwrap();
        let d = tmp.path().join("d");
        manifest(&d, "");
        fs::write(d.join("old.csv"), "x").unwrap();
        fs::create_dir_all(d.join("sub/deep")).unwrap();
        fs::write(d.join("sub/keep.txt"), "k").unwrap();
        fs::write(d.join("sub/h.bin"), "old").unwrap();
        fs::write(d.join("sub/deep/f"), "f").unwrap();
        fs::write(d.join(".nested.lock"), "").unwrap();
        let o = OutputDir::begin(&d, "--out").unwrap();
        manifest(o.path(), "");
        fs::create_dir(o.path().join("sub")).unwrap();
        fs::write(o.path().join("sub/h.bin"), "new").unwrap();
        o.commit().unwrap();
        assert_eq!(names(&d), [".nested.lock", "run.toml", "sub"]);
        assert_eq!(names(&d.join("sub")), ["deep", "h.bin", "keep.txt"]);
        assert_eq!(fs::read_to_string(d.join("sub/h.bin")).unwrap(), "new");
        assert_eq!(fs::read_to_string(d.join("sub/deep/f")).unwrap(), "f");
    }

    #[test]
    fn a_second_run_on_the_same_out_is_refused() {
        let _serial = serial();
        let tmp = tempfile::tempdir().unwrap();
        let d = tmp.path().join("d");
        let o = OutputDir::begin(&d, "--out").unwrap();
        let e = OutputDir::begin(&d, "--out").err().unwrap();
        assert!(
            matches!(&e, Error::Input(m) if m.contains("another rebound run")),
            "{e}"
        );
        drop(o);
        OutputDir::begin(&d, "--out").unwrap();
    }

    #[test]
    fn leftovers_of_killed_runs_are_cleaned_or_put_back() {
        let _serial = serial();
        let tmp = tempfile::tempdir().unwrap();
        let d = tmp.path().join("d");
        let pid = dead_pid();
        // The rename fallback was killed between its renames: the old result is put back.
        manifest(&tmp.path().join(format!(".d.old-{pid}")), "old = 1\n");
        manifest(&tmp.path().join(format!(".d.staging-{pid}-0a1b")), "");
        // A live process's staging directory is left alone.
        let live = tmp.path().join(".d.staging-1-00ff");
        fs::create_dir(&live).unwrap();
        let o = OutputDir::begin(&d, "--out").unwrap();
        assert!(fs::read_to_string(d.join("run.toml"))
            .unwrap()
            .contains("old = 1"));
        drop(o);
        let mut left = names(tmp.path());
        left.retain(|n| n != ".d.lock" && n != "d");
        assert_eq!(left, [".d.staging-1-00ff"]);
    }

    #[test]
    fn foreign_files_and_non_directories_are_refused() {
        let _serial = serial();
        let tmp = tempfile::tempdir().unwrap();
        let f = tmp.path().join("f");
        fs::write(&f, "x").unwrap();
        assert!(matches!(check_out(&f, "--out"), Err(Error::Input(_))));
        let u = tmp.path().join("u");
        fs::create_dir(&u).unwrap();
        check_out(&u, "--out").unwrap();
        fs::write(u.join("notes.txt"), "x").unwrap();
        let e = check_out(&u, "--out").unwrap_err();
        assert!(e.to_string().contains("not a rebound output"), "{e}");
        // A directory of rebound outputs (e.g. shard directories) is one.
        let s = tmp.path().join("s");
        fs::create_dir_all(s.join("shard-1-of-2")).unwrap();
        fs::write(
            s.join("shard-1-of-2/partial.toml"),
            "format = \"rebound partial tally\"\n",
        )
        .unwrap();
        fs::write(s.join(".shard-1-of-2.lock"), "").unwrap();
        check_out(&s, "--out").unwrap();
    }

    #[test]
    fn files_inside_out_must_not_be_outputs() {
        let _serial = serial();
        let tmp = tempfile::tempdir().unwrap();
        let d = tmp.path().join("d");
        let outs = ["run.toml", "a.csv"];
        assert!(place_file(&d.join("run.toml"), "--heights", &d, &outs).is_err());
        assert!(place_file(&d, "--heights", &d, &outs).is_err());
        assert!(place_file(&tmp.path().join(".d.lock"), "--heights", &d, &outs).is_err());
        assert_eq!(
            place_file(&d.join("x/h.rbhf"), "--heights", &d, &outs).unwrap(),
            Placement::Inside(PathBuf::from("x/h.rbhf"))
        );
        let outside = tmp.path().join("h.rbhf");
        assert_eq!(
            place_file(&outside, "--heights", &d, &outs).unwrap(),
            Placement::Outside(outside.clone())
        );
        assert!(place_file(tmp.path(), "--heights", &d, &outs).is_err());
    }

    #[test]
    fn resolve_applies_dots_to_missing_parts() {
        let _serial = serial();
        let tmp = tempfile::tempdir().unwrap();
        let base = fs::canonicalize(tmp.path()).unwrap();
        assert_eq!(
            resolve(&tmp.path().join("a/../b/./c")).unwrap(),
            base.join("b/c")
        );
        assert_eq!(resolve(&tmp.path().join(".")).unwrap(), base);
    }
}
