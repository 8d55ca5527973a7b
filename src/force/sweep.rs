//! Expanding a force sweep (models × λ × β × U_N) into rows.
use super::{Impact, Model, Particle};
use crate::error::{Error, Result};
use rayon::prelude::*;

/// A resolved sweep: every list non-empty, β in degrees, U_N in m/s.
#[derive(Debug, Clone, PartialEq)]
pub struct Sweep {
    /// Models, in output order.
    pub models: Vec<Model>,
    /// Aspect ratios λ ≥ 1.
    pub lambdas: Vec<f64>,
    /// Orientations β (degrees, [0, 90]).
    pub betas_deg: Vec<f64>,
    /// Normal impact speeds U_N ≥ 0 (m/s).
    pub u_ns: Vec<f64>,
}

/// One evaluated point of the sweep.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Row {
    /// Model.
    pub model: Model,
    /// λ.
    pub lambda: f64,
    /// β (degrees).
    pub beta_deg: f64,
    /// U_N (m/s).
    pub u_n: f64,
    /// Model output.
    pub result: super::ForceResult,
}

impl Sweep {
    /// The default sweep: Hu et al. 2021, Fig. 6 (λ = 1.5, 2, 3; β = 0…90° by 1°; U_N = 0.0457 m/s).
    pub fn fig6() -> Self {
        Sweep {
            models: vec![Model::Hu2021, Model::HertzRigid, Model::HertzDynamic],
            lambdas: vec![1.5, 2.0, 3.0],
            betas_deg: (0..=90).map(f64::from).collect(),
            u_ns: vec![0.0457],
        }
    }

    /// Checks every value and that every model covers every λ, before any work is done.
    pub fn validate(&self) -> Result<()> {
        for (key, empty) in [
            ("models", self.models.is_empty()),
            ("lambda", self.lambdas.is_empty()),
            ("beta_deg", self.betas_deg.is_empty()),
            ("u_n_m_s", self.u_ns.is_empty()),
        ] {
            if empty {
                return Err(Error::invalid(key, "[]", "a non-empty list"));
            }
        }
        for &l in &self.lambdas {
            for m in &self.models {
                m.check_lambda(l)?;
            }
        }
        for &b in &self.betas_deg {
            Impact::from_deg(self.lambdas[0], b, 0.0)?;
        }
        for &u in &self.u_ns {
            Impact::from_deg(self.lambdas[0], 0.0, u)?;
        }
        Ok(())
    }

    /// Number of rows.
    pub fn len(&self) -> usize {
        self.models.len() * self.lambdas.len() * self.betas_deg.len() * self.u_ns.len()
    }

    /// True if the sweep has no rows.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Evaluates every point (in parallel on the current rayon pool); rows are ordered by
    /// model, λ, β, U_N whatever the thread count.
    pub fn rows(&self, p: &Particle) -> Result<Vec<Row>> {
        p.validate()?;
        self.validate()?;
        let (nl, nb, nu) = (self.lambdas.len(), self.betas_deg.len(), self.u_ns.len());
        (0..self.len())
            .into_par_iter()
            .map(|i| {
                let model = self.models[i / (nl * nb * nu)];
                let lambda = self.lambdas[(i / (nb * nu)) % nl];
                let beta_deg = self.betas_deg[(i / nu) % nb];
                let u_n = self.u_ns[i % nu];
                let result = model.evaluate(p, &Impact::from_deg(lambda, beta_deg, u_n)?)?;
                Ok(Row {
                    model,
                    lambda,
                    beta_deg,
                    u_n,
                    result,
                })
            })
            .collect()
    }
}

/// Inclusive arithmetic range `start, start + step, …, ≤ stop` (stop included within 1e-9 step).
pub fn range_step(key: &str, start: f64, stop: f64, step: f64) -> Result<Vec<f64>> {
    if !(start.is_finite() && stop.is_finite() && step.is_finite() && step > 0.0 && stop >= start) {
        return Err(Error::invalid(
            key,
            format!("{{start = {start}, stop = {stop}, step = {step}}}"),
            "finite start ≤ stop, step > 0",
        ));
    }
    let n = ((stop - start) / step + 1e-9).floor() as usize;
    if n > 10_000_000 {
        return Err(Error::invalid(
            key,
            format!("{} points", n + 1),
            "at most 10^7 points",
        ));
    }
    Ok((0..=n)
        .map(|i| {
            if i == n && ((stop - start) / step - n as f64).abs() < 1e-9 {
                stop
            } else {
                start + step * i as f64
            }
        })
        .collect())
}

/// `points` values evenly spaced in log10 between `10^log_start` and `10^log_stop`, inclusive.
pub fn range_log(key: &str, log_start: f64, log_stop: f64, points: usize) -> Result<Vec<f64>> {
    if !(log_start.is_finite() && log_stop.is_finite() && (1..=10_000_000).contains(&points)) {
        return Err(Error::invalid(
            key,
            format!("{{log_start = {log_start}, log_stop = {log_stop}, points = {points}}}"),
            "finite log10 bounds, 1 ≤ points ≤ 10^7",
        ));
    }
    if points == 1 {
        return Ok(vec![10f64.powf(log_start)]);
    }
    Ok((0..points)
        .map(|i| 10f64.powf(log_start + (log_stop - log_start) * i as f64 / (points - 1) as f64))
        .collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges() {
        let r = range_step("beta_deg", 0.0, 90.0, 1.0).unwrap();
        assert_eq!(r.len(), 91);
        assert_eq!(r[90], 90.0);
        let r = range_step("beta_deg", 0.0, 1.0, 0.1).unwrap();
        assert_eq!(r.len(), 11);
        assert_eq!(*r.last().unwrap(), 1.0);
        let r = range_log("u_n_m_s", -2.0, 1.0, 4).unwrap();
        assert!((r[0] - 0.01).abs() < 1e-15 && (r[3] - 10.0).abs() < 1e-12);
        assert!(range_step("beta_deg", 0.0, 1.0, 0.0).is_err());
    }

    #[test]
    fn rows_are_ordered_and_complete() {
        let p = Particle {
            density: 2500.0,
            youngs: 64e9,
            poisson: 0.24,
            diameter: 2.45e-6,
        };
        let s = Sweep {
            models: vec![Model::Hu2021, Model::HertzRigid],
            lambdas: vec![1.5, 2.0],
            betas_deg: vec![0.0, 45.0, 90.0],
            u_ns: vec![0.0, 1.0],
        };
        let rows = s.rows(&p).unwrap();
        assert_eq!(rows.len(), 24);
        assert_eq!(rows[0].model, Model::Hu2021);
        assert_eq!(
            (rows[1].lambda, rows[1].beta_deg, rows[1].u_n),
            (1.5, 0.0, 1.0)
        );
        assert_eq!(
            (rows[23].model, rows[23].lambda, rows[23].beta_deg),
            (Model::HertzRigid, 2.0, 90.0)
        );
        assert!(rows
            .iter()
            .all(|r| r.result.f_max.is_finite() && r.result.xi.is_finite()));
    }
}
