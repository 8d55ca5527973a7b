//! Finding, reading and parsing a case file, with one-line errors that name the key.

use super::schema::Case;
use roughwall::{Error, Result};
use std::path::{Path, PathBuf};

/// Largest case file read (bytes): far above any real case, far below what would strain the
/// parser (a 50 MB list of angles is a mistake, not a case).
pub const MAX_CASE_BYTES: u64 = 4 << 20;

/// Seed used when neither the case nor `--seed` gives one.
pub const DEFAULT_SEED: u64 = 2021;

/// Where a case path points: as given, else under `configs/` (of the working directory,
/// then of this source tree, so tests and installed binaries find the shipped cases).
pub fn resolve_path(path: &Path) -> Result<PathBuf> {
    if path.is_file() {
        return Ok(path.to_path_buf());
    }
    if let Some(kind) = roughwall::check::not_a_regular_file(path) {
        return Err(Error::Input(format!(
            "case file `{}` is {kind}, not a file",
            path.display()
        )));
    }
    let candidates = [
        Path::new("configs").join(path),
        Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("configs")
            .join(path),
    ];
    for c in candidates {
        if c.is_file() {
            return Ok(c);
        }
    }
    Err(Error::Input(format!(
        "case file `{}` not found (looked as given and under configs/)",
        path.display()
    )))
}

/// The text of the case at `path` (or `default_toml`) and where it came from.
pub fn load_text(path: Option<&Path>, default_toml: &str) -> Result<(String, String)> {
    match path {
        Some(p) => {
            let resolved = resolve_path(p)?;
            let size = std::fs::metadata(&resolved).map_or(0, |m| m.len());
            if size > MAX_CASE_BYTES {
                return Err(Error::invalid(
                    "--case",
                    format!("`{}` ({size} bytes)", resolved.display()),
                    &format!("a case file of at most {MAX_CASE_BYTES} bytes"),
                ));
            }
            let text = std::fs::read_to_string(&resolved)
                .map_err(|e| Error::Input(format!("case file `{}`: {e}", resolved.display())))?;
            Ok((text, resolved.display().to_string()))
        }
        None => Ok((default_toml.to_string(), BUILT_IN.to_string())),
    }
}

/// How the built-in case of a command is named in messages.
pub const BUILT_IN: &str = "<built-in case>";

/// Parses case text; `origin` names it in errors.
pub fn parse(text: &str, origin: &str) -> Result<Case> {
    // First as a plain TOML tree, to reject NaN/inf anywhere with the key's path.
    let tree: toml::Table = toml::from_str(text).map_err(|e| one_line(origin, text, &e))?;
    check_finite(&toml::Value::Table(tree))?;
    let case: Case = toml::from_str(text).map_err(|e| one_line(origin, text, &e))?;
    if case.name.trim().is_empty() {
        return Err(Error::invalid("name", "\"\"", "a non-empty name"));
    }
    if case.surface.is_some() && case.wall.is_some() {
        return Err(Error::Input(format!(
            "{origin}: give either [surface] or [wall], not both"
        )));
    }
    Ok(case)
}

/// The one check for NaN and ±inf, shared by case files (on their TOML tree, before the
/// schema) and the C library's wall parameters (on the [`Case`] that `rw_wall_new` builds,
/// see [`Case::check_finite`]), so that both give the same one-line message for the same
/// value: `invalid `KEY` = VALUE: allowed a finite number`, for the first non-finite number
/// by key path.
pub fn check_finite(tree: &toml::Value) -> Result<()> {
    reject_non_finite(tree, "").map_err(|(key, v)| Error::invalid(&key, v, "a finite number"))
}

fn reject_non_finite(v: &toml::Value, path: &str) -> std::result::Result<(), (String, f64)> {
    match v {
        toml::Value::Float(f) if !f.is_finite() => Err((path.to_string(), *f)),
        toml::Value::Table(t) => {
            for (k, v) in t {
                let p = if path.is_empty() {
                    k.clone()
                } else {
                    format!("{path}.{k}")
                };
                reject_non_finite(v, &p)?;
            }
            Ok(())
        }
        toml::Value::Array(a) => {
            for (i, v) in a.iter().enumerate() {
                reject_non_finite(v, &format!("{path}[{i}]"))?;
            }
            Ok(())
        }
        _ => Ok(()),
    }
}

/// Turns a (multi-line) TOML/serde error into one line with the file, line and key.
fn one_line(origin: &str, text: &str, e: &toml::de::Error) -> Error {
    let mut msg = e.message().replace('\n', " ");
    // serde's words for a sweep key of the wrong shape; say what is allowed instead.
    if msg.contains("untagged enum Values") {
        msg = "allowed a number, a list of numbers, { start, stop, step } or { log_start, log_stop, points }".into();
    }
    let Some(span) = e.span() else {
        return Error::Input(format!("{origin}: {msg}"));
    };
    let start = span.start.min(text.len());
    let line_no = text[..start].matches('\n').count() + 1;
    let line = text.lines().nth(line_no - 1).unwrap_or("").trim();
    let key = line.split('=').next().unwrap_or("").trim();
    // serde calls an array of tables and a TOML datetime "map": say what they are.
    if let Some(name) = line.strip_prefix("[[").and_then(|l| l.split("]]").next()) {
        let name = name.trim();
        return Error::Input(format!(
            "{origin}:{line_no}: section `[[{name}]]` is an array of tables: allowed one table `[{name}]`"
        ));
    }
    if msg.contains("invalid type: map") && line.contains('=') {
        let value = line.split_once('=').map_or("", |(_, v)| v).trim();
        let date = value.len() >= 8
            && (value.as_bytes().get(4) == Some(&b'-') || value.as_bytes().get(2) == Some(&b':'));
        if date && value.bytes().take(2).all(|b| b.is_ascii_digit()) {
            msg = msg.replace("invalid type: map", "invalid type: a datetime");
        }
    }
    if line.contains('=') && !key.is_empty() {
        Error::Input(format!("{origin}:{line_no}: key `{key}`: {msg}"))
    } else {
        Error::Input(format!("{origin}:{line_no}: {msg}"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn err(text: &str) -> String {
        match parse(text, "t.toml") {
            Err(e) => {
                let s = e.to_string();
                assert!(!s.contains('\n'), "multi-line: {s}");
                assert_eq!(e.exit_code(), 2);
                s
            }
            Ok(_) => panic!("accepted: {text}"),
        }
    }

    #[test]
    fn unknown_key_wrong_type_missing_and_nan_are_one_line_errors() {
        assert!(err("name='a'\n[surface]\nlenght_um = 5.0\n").contains("lenght_um"));
        assert!(err("name='a'\n[surface]\nnodes = 'many'\n").contains("nodes"));
        assert!(err("seed = 1\n").contains("name"));
        assert!(err("name='a'\n[surface]\nrms_height_um = nan\n").contains("surface.rms_height_um"));
        assert!(err("name='a'\n[surface]\n[wall]\n").contains("not both"));
    }

    #[test]
    fn a_non_finite_number_is_the_same_message_from_a_file_and_from_the_wall_model() {
        use roughwall::{WallModel, WallParams};
        for (text, value) in [
            ("nan", f64::NAN),
            ("inf", f64::INFINITY),
            ("-inf", f64::NEG_INFINITY),
        ] {
            let want = format!("invalid `wall.delta_zeta_deg` = {value}: allowed a finite number");
            let from_file = err(&format!(
                "name='a'\n[wall]\ndelta_xi_deg = 1.0\ndelta_zeta_deg = {text}\n"
            ));
            assert_eq!(from_file, want);
            let built = WallModel::new(&WallParams {
                delta_xi_deg: 1.0,
                delta_zeta_deg: value,
                ..Default::default()
            });
            assert_eq!(built.unwrap_err().to_string(), want);
        }
        let fine = parse(
            "name='a'\n[wall]\ndelta_xi_deg = 1.0\ndelta_zeta_deg = 2.0\n",
            "t.toml",
        );
        assert!(fine.is_ok());
    }

    #[test]
    fn shipped_paths_resolve_under_configs() {
        assert!(resolve_path(Path::new("definitely/not/here.toml")).is_err());
    }
}
