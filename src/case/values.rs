//! A list of values, a linear range or a logarithmic range (`[sweep]`), expanded and checked.

use super::schema::*;
use roughwall::check::check_length;
use roughwall::{Error, Result};

impl Values {
    /// The values, checked finite; `key` names them in errors. Ranges hold at most 1e6 points.
    pub fn expand(&self, key: &str) -> Result<Vec<f64>> {
        let v = match self {
            Values::List(v) => v.clone(),
            Values::One(x) => vec![*x],
            Values::Linear(r) => {
                if r.step <= 0.0 || r.stop < r.start {
                    return Err(Error::invalid(
                        key,
                        format!(
                            "{{start = {}, stop = {}, step = {}}}",
                            r.start, r.stop, r.step
                        ),
                        "start ≤ stop and step > 0",
                    ));
                }
                // Count in floating point first: a tiny step must not overflow the count.
                let n = ((r.stop - r.start) / r.step + 1e-9).floor() + 1.0;
                if n.is_nan() || n > 1e6 {
                    return Err(Error::invalid(
                        key,
                        format!(
                            "{{start = {}, stop = {}, step = {}}} ({n:e} points)",
                            r.start, r.stop, r.step
                        ),
                        "at most 1000000 points",
                    ));
                }
                (0..n as usize)
                    .map(|i| r.start + i as f64 * r.step)
                    .collect()
            }
            Values::Log(r) => {
                if !(1..=1_000_000).contains(&r.points) {
                    return Err(Error::invalid(
                        &format!("{key}.points"),
                        r.points,
                        "an integer from 1 to 1000000",
                    ));
                }
                let n = r.points as usize;
                (0..n)
                    .map(|i| {
                        let t = if n == 1 {
                            0.0
                        } else {
                            i as f64 / (n - 1) as f64
                        };
                        10f64.powf(r.log_start + t * (r.log_stop - r.log_start))
                    })
                    .collect()
            }
        };
        if v.is_empty() {
            return Err(Error::invalid(key, "[]", "at least one value"));
        }
        check_length(key, v.len(), 1_000_000, "values", "at most 1000000 values")?;
        if let Some(bad) = v.iter().find(|x| !x.is_finite()) {
            return Err(Error::invalid(key, bad, "finite values"));
        }
        Ok(v)
    }
}
