//! The accuracy report of issue 5: physical models against Hu et al. 2021's fit, and the
//! speed-versus-error table of `hertz-dynamic`.
use super::hertz_dynamic::{simulate, Options};
use super::sweep::Row;
use super::{Impact, Model, Particle};
use std::collections::BTreeMap;

/// Deviation of one model from `hu2021` over the β values of one (D, λ, U_N) of a sweep.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Accuracy {
    /// The model compared with `hu2021`.
    pub model: Model,
    /// λ.
    pub lambda: f64,
    /// D (m).
    pub diameter: f64,
    /// U_N (m/s).
    pub u_n: f64,
    /// Number of β values compared.
    pub points: usize,
    /// Smallest and largest β compared (degrees).
    pub beta_range_deg: (f64, f64),
    /// Mean of |F_model / F_hu2021 − 1| over β.
    pub mean_rel_dev: f64,
    /// Maximum of |F_model / F_hu2021 − 1| over β.
    pub max_rel_dev: f64,
    /// β of the maximum deviation (degrees).
    pub beta_at_max_deg: f64,
}

/// (D, λ, U_N) as bit patterns: exact grouping keys.
type PointKey = (u64, u64, u64);

/// Compares every non-`hu2021` model with `hu2021` at equal (D, λ, β, U_N). The deviation is
/// taken on ξ, which equals the force ratio for U_N > 0 and stays defined at U_N = 0.
/// Empty if `hu2021` or another model is missing.
pub fn accuracy(rows: &[Row]) -> Vec<Accuracy> {
    let key = |r: &Row| {
        (
            r.particle.diameter.to_bits(),
            r.lambda.to_bits(),
            r.u_n.to_bits(),
        )
    };
    let mut hu: BTreeMap<(u64, u64, u64, u64), f64> = BTreeMap::new();
    for r in rows.iter().filter(|r| r.model == Model::Hu2021) {
        let k = key(r);
        hu.insert((k.0, k.1, k.2, r.beta_deg.to_bits()), r.result.xi);
    }
    // Groups in first-seen order (indexed: a sweep may have 10⁵ points).
    let mut order: Vec<(Model, PointKey)> = Vec::new();
    let mut index: std::collections::HashMap<(Model, PointKey), usize> = Default::default();
    let mut groups: BTreeMap<(usize, PointKey), Vec<(f64, f64)>> = BTreeMap::new();
    for r in rows.iter().filter(|r| r.model != Model::Hu2021) {
        let k = key(r);
        let Some(&xi_hu) = hu.get(&(k.0, k.1, k.2, r.beta_deg.to_bits())) else {
            continue;
        };
        if xi_hu <= 0.0 {
            continue;
        }
        let gi = *index.entry((r.model, k)).or_insert_with(|| {
            order.push((r.model, k));
            order.len() - 1
        });
        groups
            .entry((gi, k))
            .or_default()
            .push((r.beta_deg, (r.result.xi / xi_hu - 1.0).abs()));
    }
    groups
        .into_iter()
        .map(|((gi, k), devs)| {
            let n = devs.len();
            let mean = devs.iter().map(|d| d.1).sum::<f64>() / n as f64;
            let (beta_at_max, max) =
                devs.iter()
                    .copied()
                    .fold((devs[0].0, 0.0), |a, d| if d.1 > a.1 { d } else { a });
            let lo = devs.iter().map(|d| d.0).fold(f64::INFINITY, f64::min);
            let hi = devs.iter().map(|d| d.0).fold(f64::NEG_INFINITY, f64::max);
            Accuracy {
                model: order[gi].0,
                lambda: f64::from_bits(k.1),
                diameter: f64::from_bits(k.0),
                u_n: f64::from_bits(k.2),
                points: n,
                beta_range_deg: (lo, hi),
                mean_rel_dev: mean,
                max_rel_dev: max,
                beta_at_max_deg: beta_at_max,
            }
        })
        .collect()
}

/// One row of the speed-versus-error table of `hertz-dynamic`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Convergence {
    /// Requested RK4 steps per estimated contact.
    pub steps_per_contact: usize,
    /// Steps actually taken (to separation).
    pub steps: usize,
    /// |F_max / F_max,ref − 1| against `reference` steps per contact.
    pub rel_err_f_max: f64,
    /// |t_c / t_c,ref − 1|.
    pub rel_err_contact_time: f64,
    /// Wall time per impact (s), single thread, mean over repeated runs.
    pub time_per_impact_s: f64,
}

/// Steps per contact tabulated by [`convergence`].
pub const CONVERGENCE_STEPS: [usize; 9] = [8, 16, 32, 64, 128, 200, 256, 512, 1024];
/// Reference resolution for [`convergence`].
pub const REFERENCE_STEPS: usize = 20_000;

/// Speed versus error of `hertz-dynamic` for one impact: each resolution of `steps` against
/// `reference` steps per contact; each timing repeats the impact for at least `min_time_s`.
pub fn convergence(
    p: &Particle,
    imp: &Impact,
    steps: &[usize],
    reference: usize,
    min_time_s: f64,
) -> Vec<Convergence> {
    let fine = simulate(
        p,
        imp,
        &Options {
            steps_per_contact: reference,
        },
    );
    steps
        .iter()
        .map(|&n| {
            let opts = Options {
                steps_per_contact: n,
            };
            let out = simulate(p, imp, &opts);
            let start = std::time::Instant::now();
            let mut reps = 0u64;
            while reps == 0 || start.elapsed().as_secs_f64() < min_time_s {
                std::hint::black_box(simulate(std::hint::black_box(p), imp, &opts));
                reps += 1;
            }
            let rel = |a: Option<f64>, b: Option<f64>| match (a, b) {
                (Some(a), Some(b)) if b > 0.0 => (a / b - 1.0).abs(),
                _ => 0.0,
            };
            Convergence {
                steps_per_contact: n,
                steps: out.steps,
                rel_err_f_max: if fine.f_max > 0.0 {
                    (out.f_max / fine.f_max - 1.0).abs()
                } else {
                    0.0
                },
                rel_err_contact_time: rel(out.contact_time, fine.contact_time),
                time_per_impact_s: start.elapsed().as_secs_f64() / reps as f64,
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::force::sweep::Sweep;

    #[test]
    fn accuracy_groups_and_matches() {
        let p = Particle {
            density: 2500.0,
            youngs: 64e9,
            poisson: 0.24,
            diameter: 2.45e-6,
        };
        let s = Sweep {
            models: vec![Model::Hu2021, Model::HertzRigid],
            lambdas: vec![2.0, 3.0],
            betas_deg: vec![0.0, 45.0, 90.0],
            u_ns: vec![0.0457],
            diameters: vec![2.45e-6],
        };
        let acc = accuracy(&s.rows(&p).unwrap());
        assert_eq!(acc.len(), 2);
        assert_eq!(
            (acc[0].model, acc[0].lambda, acc[0].points),
            (Model::HertzRigid, 2.0, 3)
        );
        // λ = 2, β = 0: ξ_rigid / ξ_hu − 1 by hand from the two closed forms.
        let d0 = crate::force::hertz_rigid::xi(2.0, 0.0) / 0.82837 - 1.0;
        assert!(acc[0].max_rel_dev >= d0.abs() && acc[0].mean_rel_dev <= acc[0].max_rel_dev);
        assert_eq!(acc[0].beta_range_deg, (0.0, 90.0));
    }

    #[test]
    fn convergence_errors_shrink() {
        let p = Particle {
            density: 2500.0,
            youngs: 64e9,
            poisson: 0.24,
            diameter: 2.45e-6,
        };
        let imp = Impact::from_deg(2.0, 45.0, 0.0457).unwrap();
        let c = convergence(&p, &imp, &[8, 64], 2000, 0.0);
        assert!(c[1].rel_err_f_max < c[0].rel_err_f_max && c[1].rel_err_f_max < 1e-5);
        assert!(c.iter().all(|r| r.time_per_impact_s > 0.0));
    }
}
