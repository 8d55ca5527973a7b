//! Expanding a force sweep (models × λ × β × U_N) into rows.
use super::{Impact, Model, Particle};
use crate::error::{Error, Result};
use rayon::prelude::*;

/// Most points a sweep may have in all (models × D × λ × β × U_N).
pub const MAX_ROWS: usize = 1_000_000;

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
    /// Volume-equivalent diameters D (m); the particle's own diameter is replaced by each.
    pub diameters: Vec<f64>,
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
    /// The particle (with this row's diameter).
    pub particle: Particle,
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
            diameters: vec![2.45e-6],
        }
    }

    /// Checks every value and that every model covers every λ, before any work is done.
    pub fn validate(&self) -> Result<()> {
        for (key, empty) in [
            ("models", self.models.is_empty()),
            ("lambda", self.lambdas.is_empty()),
            ("beta_deg", self.betas_deg.is_empty()),
            ("u_n_m_s", self.u_ns.is_empty()),
            ("diameter_um", self.diameters.is_empty()),
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
        // Each axis is bounded; so is their product (rows, the CSV and its memory).
        let rows = [
            self.models.len(),
            self.diameters.len(),
            self.lambdas.len(),
            self.betas_deg.len(),
            self.u_ns.len(),
        ]
        .iter()
        .fold(1u128, |a, &n| a * n as u128);
        if rows > MAX_ROWS as u128 {
            return Err(Error::invalid(
                "sweep",
                format!(
                    "{} models × {} diameters × {} λ × {} β × {} U_N = {rows} points",
                    self.models.len(),
                    self.diameters.len(),
                    self.lambdas.len(),
                    self.betas_deg.len(),
                    self.u_ns.len()
                ),
                &format!("at most {MAX_ROWS} points in all"),
            ));
        }
        crate::memory::require(
            "sweep",
            format!("{rows} points"),
            rows as u64 * std::mem::size_of::<Row>() as u64 * 3,
            "the sweep's rows and their CSV",
        )
    }

    /// Number of rows.
    pub fn len(&self) -> usize {
        self.models.len()
            * self.diameters.len()
            * self.lambdas.len()
            * self.betas_deg.len()
            * self.u_ns.len()
    }

    /// True if the sweep has no rows.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Evaluates every point (in parallel on the current rayon pool); rows are ordered by
    /// model, D, λ, β, U_N whatever the thread count. `material` gives ρ, E, σ.
    pub fn rows(&self, material: &Particle) -> Result<Vec<Row>> {
        self.validate()?;
        for &d in &self.diameters {
            Particle {
                diameter: d,
                ..*material
            }
            .validate()?;
        }
        let (nd, nl, nb, nu) = (
            self.diameters.len(),
            self.lambdas.len(),
            self.betas_deg.len(),
            self.u_ns.len(),
        );
        (0..self.len())
            .into_par_iter()
            .map(|i| {
                let model = self.models[i / (nd * nl * nb * nu)];
                let diameter = self.diameters[(i / (nl * nb * nu)) % nd];
                let lambda = self.lambdas[(i / (nb * nu)) % nl];
                let beta_deg = self.betas_deg[(i / nu) % nb];
                let u_n = self.u_ns[i % nu];
                let particle = Particle {
                    diameter,
                    ..*material
                };
                let result =
                    model.evaluate(&particle, &Impact::from_deg(lambda, beta_deg, u_n)?)?;
                Ok(Row {
                    model,
                    lambda,
                    beta_deg,
                    u_n,
                    particle,
                    result,
                })
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

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
            diameters: vec![2.45e-6],
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
