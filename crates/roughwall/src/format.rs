//! Numbers as text, the same on every machine: the cells of every CSV output and the
//! values quoted in one-line error messages.

/// A number for a CSV cell in scientific notation, 7 significant digits (`1.817077e-8`):
/// for quantities whose scale is far from 1, such as erosion in m³/kg. Empty for
/// non-finite values, like [`fmt_num`].
pub fn fmt_sci(x: f64) -> String {
    if !x.is_finite() {
        return String::new();
    }
    if x == 0.0 {
        return "0".into();
    }
    let s = format!("{x:.6e}");
    match s.split_once('e') {
        Some((m, e)) if m.contains('.') => {
            let m = m.trim_end_matches('0').trim_end_matches('.');
            format!("{m}e{e}")
        }
        _ => s,
    }
}

/// A number for a CSV cell: 7 significant digits, shortest form, the same on every machine.
/// Non-finite values are a bug upstream; they are written as an empty cell rather than `NaN`.
pub fn fmt_num(x: f64) -> String {
    if !x.is_finite() {
        return String::new();
    }
    if x == 0.0 {
        return "0".into();
    }
    let rounded: f64 = format!("{x:.6e}").parse().unwrap_or(x);
    format!("{rounded}")
}

/// An optional number: empty cell for `None`.
pub fn fmt_opt(x: Option<f64>) -> String {
    x.map(fmt_num).unwrap_or_default()
}
