//! The layering CONTRIBUTING.md describes, checked on the sources:
//! * the library crate `roughwall` depends on none of the application's crates (no command
//!   line, figures, progress bars, case-file schema or CSV writers, nor the instrument-file
//!   readers of `crates/topography` with their zip and XML crates), so a CFD host and the
//!   Python package link the physics alone;
//! * in each crate, files import each other without cycles: the file-level import graph
//!   (`use` statements and inline `crate::…`, `super::…` paths; re-exports followed to the
//!   file that defines the item; unit tests left out) has no strongly connected component
//!   of more than one file;
//! * in each crate, the top-level modules import each other without circles;
//! * the library's top-level modules import only modules of their own layer or below
//!   (`LIBRARY_LAYERS`): the rough-wall models' dispatch sits above the models it dispatches.

use crate::common::repo_root;
use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

/// Crates the application uses and the library must not.
const APPLICATION_ONLY: [&str; 11] = [
    "clap",
    "plotters",
    "indicatif",
    "toml",
    "serde",
    "csv",
    "sha2",
    "libc",
    "topography",
    "zip",
    "quick-xml",
];

#[test]
fn the_library_depends_on_no_application_crate() {
    let manifest =
        std::fs::read_to_string(repo_root().join("crates/roughwall/Cargo.toml")).unwrap();
    let deps = section(&manifest, "[dependencies]");
    assert!(
        !deps.is_empty(),
        "no [dependencies] in crates/roughwall/Cargo.toml"
    );
    for line in deps {
        let name = line.split(['=', '.', ' ']).next().unwrap_or("").trim();
        assert!(
            !APPLICATION_ONLY.contains(&name),
            "the library depends on `{name}`, an application crate"
        );
    }
    // The library's code names no application module either.
    for file in rust_files(&repo_root().join("crates/roughwall/src")) {
        let text = std::fs::read_to_string(&file).unwrap();
        for name in APPLICATION_ONLY {
            assert!(
                !code(&text).contains(&format!("{name}::")),
                "{} uses `{name}::`",
                file.display()
            );
        }
    }
}

#[test]
fn files_import_each_other_without_cycles() {
    for (krate, dir) in [
        ("roughwall", "crates/roughwall/src"),
        ("topography", "crates/topography/src"),
        ("outputs", "crates/outputs/src"),
        ("reproduce", "crates/reproduce/src"),
        ("rebound", "src"),
    ] {
        let graph = import_graph(&repo_root().join(dir));
        let cycles: Vec<Vec<String>> = strongly_connected(&graph)
            .into_iter()
            .filter(|c| c.len() > 1)
            .collect();
        assert!(
            cycles.is_empty(),
            "{krate}: files importing each other in a loop: {cycles:?}"
        );
        // The graph is not empty by accident: the library's stochastic model imports the
        // collision law, the X3P reader the XML tree, the application's commands the case
        // files.
        let edge = |a: &str, b: &str| graph.get(a).is_some_and(|t| t.contains(b));
        match krate {
            "roughwall" => assert!(edge("models/simulate.rs", "collision.rs")),
            "topography" => assert!(edge("x3p.rs", "xml.rs")),
            "outputs" => assert!(edge("csv.rs", "atomic.rs")),
            "reproduce" => assert!(edge("calibration.rs", "paths.rs")),
            _ => assert!(edge("commands/stochastic.rs", "case/stochastic.rs")),
        }
    }
}

/// The paper-reproduction report is not in the shipped binary (issue 41): the application
/// depends on no crate that holds it, and has no module of that name; `rebound report` runs
/// the separate binary `rebound-report`.
#[test]
fn the_report_is_apart_from_the_shipped_binary() {
    let manifest = std::fs::read_to_string(repo_root().join("Cargo.toml")).unwrap();
    let deps = section(&manifest, "[dependencies]");
    assert!(deps.iter().any(|l| l.starts_with("roughwall")));
    for line in deps {
        let name = line.split(['=', '.', ' ']).next().unwrap_or("").trim();
        assert_ne!(
            name, "reproduce",
            "the application depends on the report crate"
        );
    }
    assert!(!repo_root().join("src/report").exists());
    for file in rust_files(&repo_root().join("src")) {
        let text = std::fs::read_to_string(&file).unwrap();
        assert!(
            !code(&text).contains("reproduce::"),
            "{} uses the report's crate",
            file.display()
        );
    }
    // Nor does the report's crate reach into the application.
    let manifest =
        std::fs::read_to_string(repo_root().join("crates/reproduce/Cargo.toml")).unwrap();
    for line in section(&manifest, "[dependencies]") {
        let name = line.split(['=', '.', ' ']).next().unwrap_or("").trim();
        assert_ne!(name, "rebound", "the report depends on the application");
    }
}

/// The library's top-level modules in layers, lowest first: a module imports only modules of
/// its own layer or below, so the physics reads upwards from the foundations to the C library.
/// The rough-wall models sit in `models`, above the paper's model (`stochastic`) and the
/// calibrated one they dispatch to; a module missing here fails the test.
const LIBRARY_LAYERS: [&[&str]; 7] = [
    // Foundations: errors, checks, number formats, memory budgets, random streams, angles.
    &[
        "angles",
        "check",
        "error",
        "format",
        "memory",
        "parameters",
        "rng",
        "warning",
    ],
    // The wall, the collision laws, the carrier flow between hits, incident particles,
    // erosion, force, surfaces, scans, tallies.
    &[
        "carrier",
        "collision",
        "erosion",
        "force",
        "incidence",
        "scan",
        "surface",
        "tally",
        "wall",
    ],
    // The two models of the paper: stochastic (Fig. 13) and deterministic (Secs. 3.1–3.3).
    &["deterministic", "stochastic"],
    // The calibrated model and the measured-wall tables, counted on deterministic runs.
    &["calibrated", "measured_wall"],
    // Every rough-wall model and the dispatch between them; the scan check that sets the
    // paper's model against a scan's in-place reference.
    &["models", "gaussian_cost"],
    // A CFD code's wall.
    &["wall_model"],
    // The C library.
    &["ffi"],
];

/// The top-level modules of a crate (a file's first module segment: `stochastic/simulate.rs`
/// is in `stochastic`, `collision.rs` is `collision`; the crate root is left out) and the
/// modules each imports.
fn module_graph(dir: &str) -> BTreeMap<String, BTreeSet<String>> {
    let files = import_graph(&repo_root().join(dir));
    let top = |file: &str| module_of(file).into_iter().next();
    let mut modules: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for (a, targets) in &files {
        let Some(ma) = top(a) else { continue };
        let out = modules.entry(ma.clone()).or_default();
        for b in targets {
            match top(b) {
                Some(mb) if mb != ma => {
                    out.insert(mb);
                }
                _ => {}
            }
        }
    }
    modules
}

/// In each crate, the top-level modules import each other without circles.
#[test]
fn modules_import_each_other_without_circles() {
    for (krate, dir) in [
        ("roughwall", "crates/roughwall/src"),
        ("topography", "crates/topography/src"),
        ("outputs", "crates/outputs/src"),
        ("reproduce", "crates/reproduce/src"),
        ("rebound", "src"),
    ] {
        let circles: Vec<Vec<String>> = strongly_connected(&module_graph(dir))
            .into_iter()
            .filter(|c| c.len() > 1)
            .collect();
        assert!(
            circles.is_empty(),
            "{krate}: modules importing each other in a loop: {circles:?}"
        );
    }
}

/// No library module imports one of a higher layer ([`LIBRARY_LAYERS`]).
#[test]
fn library_imports_point_down_its_layers() {
    let layer_of = |m: &str| LIBRARY_LAYERS.iter().position(|l| l.contains(&m));
    let graph = module_graph("crates/roughwall/src");
    assert!(graph.len() > 10, "{graph:?}");
    for (a, targets) in &graph {
        let la =
            layer_of(a).unwrap_or_else(|| panic!("module `{a}` is in no layer of LIBRARY_LAYERS"));
        for b in targets {
            let lb = layer_of(b)
                .unwrap_or_else(|| panic!("module `{b}` is in no layer of LIBRARY_LAYERS"));
            assert!(
                lb <= la,
                "`{a}` (layer {la}) imports `{b}` (layer {lb}), a higher layer"
            );
        }
    }
    // The test can fail: the models import the paper's model, one layer down.
    assert!(graph["models"].contains("stochastic"));
}

#[test]
fn a_loop_is_found() {
    let tmp = tempfile::tempdir().unwrap();
    let src = tmp.path();
    std::fs::create_dir_all(src.join("a")).unwrap();
    std::fs::write(src.join("lib.rs"), "mod a;\nmod b;\n").unwrap();
    std::fs::write(src.join("a/mod.rs"), "mod c;\npub use c::Thing;\n").unwrap();
    std::fs::write(
        src.join("a/c.rs"),
        "use crate::b::other;\npub struct Thing;\n",
    )
    .unwrap();
    std::fs::write(
        src.join("b.rs"),
        "use crate::a::Thing;\npub fn other() {}\n",
    )
    .unwrap();
    let cycles: Vec<_> = strongly_connected(&import_graph(src))
        .into_iter()
        .filter(|c| c.len() > 1)
        .collect();
    assert_eq!(cycles, [vec!["a/c.rs".to_string(), "b.rs".to_string()]]);
}

/// The lines of a TOML section, up to the next section.
fn section<'a>(text: &'a str, name: &str) -> Vec<&'a str> {
    text.lines()
        .skip_while(|l| l.trim() != name)
        .skip(1)
        .take_while(|l| !l.trim_start().starts_with('['))
        .filter(|l| !l.trim().is_empty() && !l.trim_start().starts_with('#'))
        .collect()
}

fn rust_files(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    for e in std::fs::read_dir(dir).unwrap() {
        let p = e.unwrap().path();
        if p.is_dir() {
            out.extend(rust_files(&p));
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push(p);
        }
    }
    out.sort();
    out
}

/// The code of a file: comments dropped, the unit-test module (from `#[cfg(test)] mod …` on,
/// by convention the file's last item) left out. A `#[cfg(test)]` on any other item (a
/// test-only constant or branch) does not cut the file there.
fn code(text: &str) -> String {
    let cut = text
        .match_indices("#[cfg(test)]")
        .find(|(i, m)| text[i + m.len()..].trim_start().starts_with("mod "))
        .map_or(text.len(), |(i, _)| i);
    text[..cut]
        .lines()
        .map(|l| match l.find("//") {
            Some(i) => &l[..i],
            None => l,
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// The module path of a file relative to the crate's `src/` (`lib.rs`, `main.rs` → root).
fn module_of(rel: &str) -> Vec<String> {
    let rel = rel.trim_end_matches(".rs");
    let mut parts: Vec<String> = rel.split('/').map(String::from).collect();
    if matches!(
        parts.last().map(String::as_str),
        Some("mod" | "lib" | "main")
    ) {
        parts.pop();
    }
    parts
}

/// The paths a `use` tree names, braces expanded (`a::{b, c::d}` → `a::b`, `a::c::d`).
fn expand(tree: &str) -> Vec<String> {
    let tree = tree.trim();
    let Some(open) = tree.find('{') else {
        let path = tree.split(" as ").next().unwrap_or("").trim();
        return vec![path.to_string()];
    };
    let prefix = &tree[..open];
    let inner = &tree[open + 1..tree.rfind('}').unwrap_or(tree.len())];
    let (mut depth, mut start, mut parts) = (0, 0, Vec::new());
    for (i, ch) in inner.char_indices() {
        match ch {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                parts.push(&inner[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    parts.push(&inner[start..]);
    parts
        .into_iter()
        .filter(|p| !p.trim().is_empty())
        .flat_map(expand)
        .map(|p| match p.as_str() {
            "self" => prefix.trim_end_matches("::").to_string(),
            _ => format!("{prefix}{p}"),
        })
        .collect()
}

/// Every path a file's code names through `crate::`, `super::`, `self::` or a child module,
/// absolute (as segments from the crate root), with whether it is a `pub use` (a re-export).
/// `is_module` tells the modules that exist (a path starting with a child's name is relative).
fn paths_of(
    code: &str,
    module: &[String],
    is_module: &dyn Fn(&[String]) -> bool,
) -> Vec<(Vec<String>, bool)> {
    let mut out = Vec::new();
    let absolute = |path: &str| -> Option<Vec<String>> {
        let segs: Vec<&str> = path.split("::").map(str::trim).collect();
        let mut at: Vec<String> = module.to_vec();
        let mut rest = &segs[..];
        match segs.first().copied() {
            Some("crate") => {
                at.clear();
                rest = &segs[1..];
            }
            Some("self") => rest = &segs[1..],
            Some("super") => {
                while rest.first() == Some(&"super") {
                    at.pop();
                    rest = &rest[1..];
                }
            }
            Some(first) => {
                let mut child = module.to_vec();
                child.push(first.to_string());
                if !is_module(&child) {
                    return None; // another crate, or a name in scope
                }
            }
            None => return None,
        }
        at.extend(rest.iter().map(|s| s.to_string()));
        Some(at)
    };
    // `use` statements, possibly over several lines; the other lines are scanned for
    // inline paths below.
    let mut statement: Option<(String, bool)> = None;
    let mut rest = String::new();
    for line in code.lines() {
        let t = line.trim();
        if statement.is_none() {
            let public = t.starts_with("pub");
            let body = t
                .strip_prefix("use ")
                .or_else(|| t.strip_prefix("pub use "))
                .or_else(|| t.strip_prefix("pub(crate) use "))
                .or_else(|| t.strip_prefix("pub(super) use "));
            match body {
                Some(b) => statement = Some((b.to_string(), public)),
                None => {
                    rest.push_str(line);
                    rest.push('\n');
                    continue;
                }
            }
        } else if let Some((s, _)) = statement.as_mut() {
            s.push(' ');
            s.push_str(t);
        }
        if let Some((s, public)) = statement.take() {
            match s.find(';') {
                Some(end) => {
                    for p in expand(&s[..end]) {
                        if let Some(a) = absolute(&p) {
                            out.push((a, public));
                        }
                    }
                }
                None => statement = Some((s, public)),
            }
        }
    }
    // Inline paths: `crate::a::b`, `super::a::b`, `self::a` anywhere.
    let code = rest.as_str();
    let starts = ["crate::", "super::", "self::"]
        .into_iter()
        .flat_map(|p| code.match_indices(p));
    for (i, _) in starts {
        if code[..i].ends_with(|c: char| c.is_alphanumeric() || c == '_') {
            continue;
        }
        let path: String = code[i..]
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_' || *c == ':')
            .collect();
        if let Some(a) = absolute(path.trim_end_matches(':')) {
            out.push((a, false));
        }
    }
    out
}

/// File → files it imports, by paths relative to `src` (`stochastic/simulate.rs`).
fn import_graph(src: &Path) -> BTreeMap<String, BTreeSet<String>> {
    let files: BTreeMap<Vec<String>, String> = rust_files(src)
        .iter()
        .map(|p| {
            let rel = p
                .strip_prefix(src)
                .unwrap()
                .to_string_lossy()
                .replace('\\', "/");
            (module_of(&rel), rel)
        })
        .collect();
    let codes: BTreeMap<String, String> = files
        .values()
        .map(|rel| {
            (
                rel.clone(),
                code(&std::fs::read_to_string(src.join(rel)).unwrap()),
            )
        })
        .collect();
    let is_module = |m: &[String]| files.contains_key(m);
    // Re-exports: (module, name) → the path it re-exports.
    let mut reexports: BTreeMap<(Vec<String>, String), Vec<String>> = BTreeMap::new();
    for (module, rel) in &files {
        for (path, public) in paths_of(&codes[rel], module, &is_module) {
            if public {
                if let Some(name) = path.last() {
                    reexports.insert((module.clone(), name.clone()), path.clone());
                }
            }
        }
    }
    // The file of the longest module prefix of `path`, through re-exports.
    let file_of = |path: &[String]| -> Option<String> {
        let mut path = path.to_vec();
        for _ in 0..8 {
            let k = (0..=path.len())
                .rev()
                .find(|&k| files.contains_key(&path[..k]))?;
            let module = path[..k].to_vec();
            match path
                .get(k)
                .and_then(|n| reexports.get(&(module.clone(), n.clone())))
            {
                Some(target) if *target != path => {
                    let mut next = target.clone();
                    next.extend(path[k + 1..].iter().cloned());
                    path = next;
                }
                _ => return files.get(&module).cloned(),
            }
        }
        None
    };
    let mut graph: BTreeMap<String, BTreeSet<String>> = BTreeMap::new();
    for (module, rel) in &files {
        let targets = graph.entry(rel.clone()).or_default();
        for (path, public) in paths_of(&codes[rel], module, &is_module) {
            if public {
                continue; // a re-export is plumbing: a user of the item depends on its file
            }
            if let Some(t) = file_of(&path) {
                if t != *rel {
                    targets.insert(t);
                }
            }
        }
    }
    graph
}

/// Tarjan's strongly connected components, each sorted, in a stable order.
fn strongly_connected(graph: &BTreeMap<String, BTreeSet<String>>) -> Vec<Vec<String>> {
    struct State<'a> {
        graph: &'a BTreeMap<String, BTreeSet<String>>,
        index: BTreeMap<&'a str, usize>,
        low: BTreeMap<&'a str, usize>,
        stack: Vec<&'a str>,
        on_stack: BTreeSet<&'a str>,
        out: Vec<Vec<String>>,
    }
    fn visit<'a>(s: &mut State<'a>, v: &'a str) {
        let i = s.index.len();
        s.index.insert(v, i);
        s.low.insert(v, i);
        s.stack.push(v);
        s.on_stack.insert(v);
        let graph = s.graph;
        for w in graph.get(v).into_iter().flatten() {
            let w = w.as_str();
            if !s.index.contains_key(w) {
                visit(s, w);
                let lw = s.low[w];
                let lv = s.low.get_mut(v).unwrap();
                *lv = (*lv).min(lw);
            } else if s.on_stack.contains(w) {
                let iw = s.index[w];
                let lv = s.low.get_mut(v).unwrap();
                *lv = (*lv).min(iw);
            }
        }
        if s.low[v] == s.index[v] {
            let mut comp = Vec::new();
            while let Some(w) = s.stack.pop() {
                s.on_stack.remove(w);
                comp.push(w.to_string());
                if w == v {
                    break;
                }
            }
            comp.sort();
            s.out.push(comp);
        }
    }
    let mut s = State {
        graph,
        index: BTreeMap::new(),
        low: BTreeMap::new(),
        stack: Vec::new(),
        on_stack: BTreeSet::new(),
        out: Vec::new(),
    };
    for v in graph.keys() {
        if !s.index.contains_key(v.as_str()) {
            visit(&mut s, v);
        }
    }
    s.out.sort();
    s.out
}

#[test]
fn only_the_test_module_is_left_out_of_a_files_code() {
    let text = "use a::b;\n#[cfg(test)]\nconst K: u8 = 1; // x\nuse c::d;\n#[cfg(test)]\nmod tests {\n    use e::f;\n}\n";
    assert_eq!(
        code(text),
        "use a::b;\n#[cfg(test)]\nconst K: u8 = 1; \nuse c::d;"
    );
    // The library's C ABI sits after a test-only constant: its imports are scanned.
    let ffi =
        std::fs::read_to_string(crate::common::repo_root().join("crates/roughwall/src/ffi.rs"))
            .unwrap();
    assert!(code(&ffi).contains("pub unsafe extern \"C\" fn rw_rebound("));
}
