//! A bad wall parameter gives the same one-line message from the C library's `rw_wall_new`
//! as from a case file (issue 9: "validated with the same ranges and one-line messages as
//! case files"): for each bad value, the message of `rw_wall_new` is compared with what
//! `rebound stochastic --case` prints for the case file holding that value (`error: ` and
//! the message, one line, exit 2), for every numeric parameter the library declares.

use crate::common;
use common::*;
use roughwall::ffi::*;
use std::ffi::{c_char, CStr};

/// A parameter of both interfaces: how to set it in `rw_wall_params` and in a case file.
#[derive(Clone, Copy)]
enum Param {
    DeltaXi,
    DeltaZeta,
    Psi,
    EH,
    AlphaE,
    Mu0,
    MuH,
    AlphaMu,
    /// Δγ with an isotropic model (`RW_MODEL_GAUSSIAN_ANGLE`, `gaussian-angle`).
    DeltaGammaIsotropic,
    /// Δγ with the paper's model, which takes it from the wall.
    DeltaGammaPapers,
}

/// The Sec. 4 glass–steel scene (`configs/cases/glass-steel.toml`) with `p` = `x`.
fn case_text(p: Param, x: f64) -> String {
    let v = common::toml_number(x);
    let base = &read_shipped_case("cases/glass-steel.toml");
    let sh = "preset = \"glass-steel\"";
    let edit = |from: &str, to: String| {
        assert!(base.contains(from), "{from}");
        base.replacen(from, &to, 1)
    };
    match p {
        Param::DeltaXi => edit("delta_xi_deg = 3.8", format!("delta_xi_deg = {v}")),
        Param::DeltaZeta => edit("delta_zeta_deg = 7.5", format!("delta_zeta_deg = {v}")),
        Param::Psi => edit("psi = 2.0", format!("psi = {v}")),
        Param::EH => edit(sh, format!("{sh}\ne_h = {v}")),
        Param::AlphaE => edit(sh, format!("{sh}\nalpha_e_deg = {v}")),
        Param::Mu0 => edit(sh, format!("{sh}\nmu_0 = {v}")),
        Param::MuH => edit(sh, format!("{sh}\nmu_h = {v}")),
        Param::AlphaMu => edit(sh, format!("{sh}\nalpha_mu_deg = {v}")),
        Param::DeltaGammaIsotropic => edit(
            "psi = 2.0",
            format!("psi = 2.0\nmodel = \"gaussian-angle\"\ndelta_gamma_deg = {v}"),
        ),
        Param::DeltaGammaPapers => edit("psi = 2.0", format!("psi = 2.0\ndelta_gamma_deg = {v}")),
    }
}

/// The same wall as `rw_wall_params`, with `p` = `x`.
fn c_params(p: Param, x: f64) -> rw_wall_params {
    let mut c = std::mem::MaybeUninit::<rw_wall_params>::uninit();
    assert_eq!(unsafe { rw_wall_params_default(c.as_mut_ptr()) }, RW_OK);
    let mut c = unsafe { c.assume_init() };
    c.delta_xi_deg = 3.8;
    c.delta_zeta_deg = 7.5;
    c.law = RW_LAW_SOMMERFELD_HUBER;
    c.preset = RW_PRESET_GLASS_STEEL;
    c.psi = 2.0;
    match p {
        Param::DeltaXi => c.delta_xi_deg = x,
        Param::DeltaZeta => c.delta_zeta_deg = x,
        Param::Psi => c.psi = x,
        Param::EH => c.e_h = x,
        Param::AlphaE => c.alpha_e_deg = x,
        Param::Mu0 => c.mu_0 = x,
        Param::MuH => c.mu_h = x,
        Param::AlphaMu => c.alpha_mu_deg = x,
        Param::DeltaGammaIsotropic => {
            c.model = RW_MODEL_GAUSSIAN_ANGLE;
            c.delta_gamma_deg = x;
        }
        Param::DeltaGammaPapers => c.delta_gamma_deg = x,
    }
    c
}

/// `rw_wall_new`'s status and message.
fn c_message(p: &rw_wall_params) -> (i32, String) {
    let mut w = std::ptr::null_mut();
    let mut buf = [0 as c_char; 1024];
    let s = unsafe { rw_wall_new(p, &mut w, buf.as_mut_ptr(), buf.len()) };
    unsafe { rw_wall_free(w) };
    let msg = unsafe { CStr::from_ptr(buf.as_ptr()) };
    (s, msg.to_str().unwrap().to_string())
}

/// What `rebound stochastic` prints for the case `text` when it refuses it (exit status 2,
/// one line, without its `error: `), `None` when it runs it (a few particles).
fn case_message(text: &str, dir: &std::path::Path, k: usize) -> Option<String> {
    let case = write_case(dir, &format!("case{k}.toml"), text);
    let out = dir.join(format!("out{k}"));
    let run = rebound_case("stochastic", &case, &out, &["--particles", "1000"]);
    if run.code == 0 {
        return None;
    }
    assert_eq!(run.code, 2, "{}", run.stderr);
    assert!(!out.exists(), "a refused run wrote {}", out.display());
    let line = run.stderr.trim();
    assert_eq!(line.lines().count(), 1, "{line}");
    Some(line.strip_prefix("error: ").expect("error: …").to_string())
}

const NAN: f64 = f64::NAN;
const INF: f64 = f64::INFINITY;

/// The bad values: negative, zero where it must be positive, too large, NaN, ±inf. (In
/// `rw_wall_params` a NaN Sommerfeld–Huber parameter or Δγ means "the preset's value" or
/// "from the wall", not a bad value, so NaN is checked for Δξ, Δζ and ψ only.)
fn bad_values() -> Vec<(Param, f64)> {
    use Param::*;
    let mut v = Vec::new();
    for p in [DeltaXi, DeltaZeta] {
        v.extend([-1.0, -1e-9, 20.5, 25.0, 1e300, NAN, INF, -INF].map(|x| (p, x)));
    }
    v.extend([0.0, -1.0, 0.005, 100.5, 1e9, NAN, INF, -INF].map(|x| (Psi, x)));
    v.extend([0.0, -0.5, 1.5, INF, -INF].map(|x| (EH, x)));
    v.extend([0.0, -10.0, 90.5, INF].map(|x| (AlphaE, x)));
    v.extend([-0.1, 2.5, INF, -INF].map(|x| (Mu0, x)));
    v.extend([-1.0, 3.0, INF].map(|x| (MuH, x)));
    v.extend([0.0, 100.0, -INF].map(|x| (AlphaMu, x)));
    v.extend([-1.0, 25.0, INF].map(|x| (DeltaGammaIsotropic, x)));
    v.extend([3.0].map(|x| (DeltaGammaPapers, x)));
    v
}

#[test]
fn rw_wall_new_gives_the_case_files_message_for_every_bad_value() {
    let tmp = Dir::new();
    // The base wall is valid on both sides (the Δζ = 7.5° warning aside).
    let (s, _) = c_message(&c_params(Param::Psi, 2.0));
    assert_eq!(s, RW_OK);
    assert_eq!(
        case_message(&case_text(Param::Psi, 2.0), tmp.path(), 0),
        None
    );
    let mut keys = std::collections::BTreeSet::new();
    for (k, (p, x)) in bad_values().into_iter().enumerate() {
        let text = case_text(p, x);
        let (status, from_c) = c_message(&c_params(p, x));
        assert_eq!(status, RW_INVALID_PARAMETER, "{x}: {from_c}\n{text}");
        let from_case = case_message(&text, tmp.path(), k + 1)
            .unwrap_or_else(|| panic!("case accepted: {x}\n{text}"));
        assert_eq!(from_c, from_case, "{x}\n{text}");
        assert!(from_c.contains('`') && !from_c.contains('\n'), "{from_c}");
        keys.insert(from_c.split('`').nth(1).unwrap().to_string());
    }
    // Every numeric parameter the library declares (`roughwall::parameters`) was reached,
    // its own key in the message: a new one fails here until the case file and the C
    // library both read it.
    let want: std::collections::BTreeSet<String> = roughwall::parameters::WALL_PARAMETERS
        .iter()
        .filter(|q| q.kind == roughwall::parameters::ParameterKind::Number)
        .map(|q| q.case_key.to_string())
        .collect();
    assert_eq!(keys, want);
}
