//! The wall's parameters are declared once (`roughwall::parameters::WALL_PARAMETERS`), and
//! every interface is held to that declaration: the C header's `rw_wall_params` and the
//! Fortran type (the same fields, in the same order), Python's `Wall(...)` with its stub and
//! the PyO3 constructor (the same keywords, in the same order), the case-file reference
//! `docs/cases.md` (a row for every key), and the laws' own range checks (a bad value's
//! message names the key and says what the declaration allows). The case file's reading of
//! each key is held to it by the application's `tests/wall_messages.rs`.

use crate::common::repo_root;
use roughwall::parameters::{ParameterKind, WALL_PARAMETERS};
use roughwall::{CollisionParams, WallModel, WallParams};

fn read(path: &str) -> String {
    std::fs::read_to_string(repo_root().join(path)).unwrap_or_else(|e| panic!("{path}: {e}"))
}

/// The names declared in a block of `text` between the line holding `start` and the next one
/// holding `end`, as `field` yields them from each line.
fn fields_between(
    text: &str,
    start: &str,
    end: &str,
    field: impl Fn(&str) -> Vec<String>,
) -> Vec<String> {
    let from = text.find(start).unwrap_or_else(|| panic!("no `{start}`"));
    let block = &text[from..];
    let block = &block[block.find('\n').unwrap_or(0)..];
    let block = &block[..block.find(end).unwrap_or_else(|| panic!("no `{end}`"))];
    block.lines().flat_map(field).collect()
}

fn c_names() -> Vec<String> {
    WALL_PARAMETERS
        .iter()
        .map(|p| p.c_name.to_string())
        .collect()
}

fn python_names() -> Vec<String> {
    WALL_PARAMETERS
        .iter()
        .map(|p| p.python_name.to_string())
        .collect()
}

#[test]
fn the_c_header_and_the_fortran_type_have_every_parameter_in_order() {
    let header = read("include/roughwall.h");
    let end = header
        .find("} rw_wall_params;")
        .expect("rw_wall_params in the header");
    let start = header[..end].rfind("typedef struct").expect("its typedef");
    let mut in_comment = false;
    let mut c = Vec::new();
    for l in header[start..end].lines().skip(1) {
        let l = l.trim();
        if l.starts_with("/*") {
            in_comment = !l.ends_with("*/");
            continue;
        }
        if in_comment {
            in_comment = !l.ends_with("*/");
            continue;
        }
        if let Some(decl) = l.strip_suffix(';') {
            c.extend(decl.rsplit([' ', '*']).next().map(str::to_string));
        }
    }
    assert_eq!(c, c_names(), "include/roughwall.h: rw_wall_params");
    let fortran = read("examples/fortran/roughwall.f90");
    let f = fields_between(
        &fortran,
        "type, bind(c), public :: rw_wall_params",
        "end type",
        |l| {
            let decl = l.split('!').next().unwrap_or("");
            match decl.split_once("::") {
                Some((_, names)) => names
                    .split(',')
                    .map(|n| n.trim().to_string())
                    .filter(|n| !n.is_empty())
                    .collect(),
                None => vec![],
            }
        },
    );
    assert_eq!(
        f,
        c_names(),
        "examples/fortran/roughwall.f90: rw_wall_params"
    );
}

#[test]
fn python_has_every_parameter_in_order() {
    let keywords = |path: &str, start: &str, end: &str| {
        fields_between(&read(path), start, end, |l| {
            let l = l.trim();
            match l.split_once(':') {
                Some((name, _)) if !name.contains(' ') && name != "self" && !name.is_empty() => {
                    vec![name.to_string()]
                }
                _ => vec![],
            }
        })
    };
    let py = "crates/roughwall-py/python/roughwall/";
    // Keyword-only arguments: their order is not part of Python's API.
    let sorted = |mut v: Vec<String>| {
        v.sort();
        v
    };
    for path in [format!("{py}_wall.py"), format!("{py}__init__.pyi")] {
        let got: Vec<String> = keywords(&path, "def __init__(", ")")
            .into_iter()
            .filter(|k| k != "*")
            .collect();
        assert_eq!(sorted(got), sorted(python_names()), "{path}: Wall.__init__");
    }
    let rust = read("crates/roughwall-py/src/wall.rs");
    let signature = rust
        .lines()
        .find(|l| l.contains("#[pyo3(signature = (delta_xi_deg"))
        .expect("the PyO3 constructor's signature");
    let inner = &signature[signature.find("= (").unwrap() + 3..signature.rfind("))").unwrap()];
    let got: Vec<String> = inner.split(',').map(|s| s.trim().to_string()).collect();
    assert_eq!(got, python_names(), "crates/roughwall-py/src/wall.rs");
}

#[test]
fn the_case_file_reference_documents_every_key() {
    let docs = read("docs/cases.md");
    let mut documented = std::collections::BTreeSet::new();
    // A table's rows name a section in their first cell (`[collision]`, blank for the one
    // above), or give keys of the sections the heading names (none: top-level keys).
    let (mut heading, mut section) = (Vec::<String>::new(), String::new());
    let bracketed = |text: &str| -> Vec<String> {
        text.split("`[")
            .skip(1)
            .filter_map(|s| s.split(']').next())
            .map(str::to_string)
            .collect()
    };
    let keys = |cell: &str| -> Vec<String> {
        cell.split([',', '/'])
            .map(|k| k.trim().trim_matches('`').to_string())
            .filter(|k| !k.is_empty())
            .collect()
    };
    for line in docs.lines() {
        if line.starts_with('#') {
            heading = bracketed(line);
            section.clear();
            continue;
        }
        if !line.starts_with('|') {
            continue;
        }
        let cells: Vec<&str> = line.split('|').map(str::trim).collect();
        let (first, second) = (
            cells.get(1).copied().unwrap_or(""),
            cells.get(2).copied().unwrap_or(""),
        );
        if first.starts_with("`[") {
            section = bracketed(first).into_iter().next().unwrap_or_default();
        } else if first.starts_with('`') {
            for key in keys(first) {
                if heading.is_empty() {
                    documented.insert(key.clone());
                }
                for h in &heading {
                    documented.insert(format!("{h}.{key}"));
                }
            }
            continue;
        } else if !first.is_empty() {
            section.clear();
        }
        if !section.is_empty() {
            for key in keys(second) {
                documented.insert(format!("{section}.{key}"));
            }
        }
    }
    for p in WALL_PARAMETERS {
        assert!(
            documented.contains(p.case_key),
            "docs/cases.md has no row for `{}`",
            p.case_key
        );
    }
}

/// A value outside what each numeric parameter allows gives the one-line message that names
/// its key and says what the declaration allows.
#[test]
fn each_range_check_says_what_the_declaration_allows() {
    let sh = |f: &dyn Fn(&mut CollisionParams)| {
        let mut c = CollisionParams {
            model: Some("sommerfeld-huber".into()),
            preset: Some("glass-steel".into()),
            ..Default::default()
        };
        f(&mut c);
        c
    };
    let mut checked = Vec::new();
    for q in WALL_PARAMETERS.iter() {
        let mut p = WallParams::default();
        match q.case_key {
            "wall.delta_xi_deg" => p.delta_xi_deg = 25.0,
            "wall.delta_zeta_deg" => p.delta_zeta_deg = -1.0,
            "collision.model" => p.collision.model = Some("plastic".into()),
            "collision.preset" => p.collision = sh(&|c| c.preset = Some("wood".into())),
            "collision.e_h" => p.collision = sh(&|c| c.e_h = Some(1.5)),
            "collision.alpha_e_deg" => p.collision = sh(&|c| c.alpha_e_deg = Some(95.0)),
            "collision.mu_0" => p.collision = sh(&|c| c.mu_0 = Some(3.0)),
            "collision.mu_h" => p.collision = sh(&|c| c.mu_h = Some(-1.0)),
            "collision.alpha_mu_deg" => p.collision = sh(&|c| c.alpha_mu_deg = Some(0.0)),
            "stochastic.psi" => p.psi = Some(1000.0),
            "stochastic.delta_gamma_deg" => {
                p.model = Some("gaussian-angle".into());
                p.delta_gamma_deg = Some(30.0)
            }
            // Any u64 is a seed; the model's name and the table are checked by the registry
            // and the table's reader (tests/stochastic_variants.rs, tests/calibrated_model.rs).
            "seed" | "stochastic.model" | "stochastic.escape_table" | "stochastic.wall_table" => {
                continue
            }
            other => panic!("`{other}` is declared but not checked here"),
        }
        let err = WallModel::new(&p).map(|_| ()).unwrap_err().to_string();
        assert!(
            err.contains(&format!("`{}`", q.case_key)) && err.contains(q.allowed),
            "{}: {err} (declared: {})",
            q.case_key,
            q.allowed
        );
        checked.push(q.case_key);
    }
    let numbers = WALL_PARAMETERS
        .iter()
        .filter(|q| q.kind == ParameterKind::Number)
        .count();
    assert!(checked.len() > numbers, "{checked:?}");
}
