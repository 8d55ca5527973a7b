//! The recipe for a new rough-wall model (CONTRIBUTING.md, "a rough-wall model"), tried with
//! nothing but a model written here: one type implementing `RoughWallModel` and
//! `NamedModel`, run through the same single-hit entry point and the same reproducible run
//! as the registered models, with its parameters checked by the shared checks.
//!
//! The model is a rigid tilt: every virtual wall element is the mean wall turned by a fixed
//! angle towards the particle, in its incident plane (Sommerfeld & Huber 1999's virtual wall
//! with a point-mass `P(γ) = δ(γ − γ₀)`). For the elastic law its rebound is known in closed
//! form: a specular reflection off the tilted element, `α⁺ = −α⁻ + 2γ₀` in the incident plane,
//! so the test asserts that, not just that it runs.

use nalgebra::Vector3;
use roughwall::models::rebound_with;
use roughwall::models::{fill_block, tally_spec, ModelSetup};
use roughwall::models::{refuse_delta_gamma, refuse_escape_table};
use roughwall::stochastic::SeenWall;
use roughwall::stochastic::{Contact, Rebound};
use roughwall::tally::{BlockTally, ConditionTally, Quantity};
use roughwall::CollisionLaw;
use roughwall::Deviations;
use roughwall::Result;
use roughwall::{IncidentCondition, SpeedLaw};
use roughwall::{ModelParams, NamedModel, RoughWallModel};

/// A wall whose every element is tilted by `tilt` (rad) towards the particle.
#[derive(Clone, Copy, Debug, PartialEq)]
struct RigidTilt {
    tilt: f64,
}

impl RoughWallModel for RigidTilt {
    type Incidence = (f64, f64);

    fn name(&self) -> &'static str {
        Self::NAME
    }

    fn anisotropic(&self) -> bool {
        false
    }

    fn incidence(&self, _alpha: f64, beta: f64, _wall: &Deviations) -> (f64, f64) {
        beta.sin_cos()
    }

    fn rebound_drawn<R: rand::Rng + ?Sized>(
        &self,
        sin_cos_beta: &(f64, f64),
        u_in: Vector3<f64>,
        omega_in: Vector3<f64>,
        contact: &Contact,
        _rng: &mut R,
        mut observe: impl FnMut(&Vector3<f64>, &Vector3<f64>, bool),
    ) -> Rebound {
        let seen = SeenWall::of_gammas(self.tilt, 0.0, *sin_cos_beta);
        let (u, w) = contact
            .law
            .collide(u_in, omega_in, seen.normal, contact.diameter_m);
        observe(&u_in, &seen.normal, true);
        Rebound {
            velocity: u,
            spin: w,
            gamma: seen.gamma,
            gamma_star: seen.gamma_star,
            normal: seen.normal,
            tries: 1,
            candidates: 1,
            first: seen,
        }
    }
}

impl NamedModel for RigidTilt {
    const NAME: &'static str = "rigid-tilt";

    fn from_params(params: &ModelParams) -> Result<Self> {
        refuse_delta_gamma(params, Self::NAME)?;
        refuse_escape_table(params, Self::NAME)?;
        Ok(RigidTilt {
            tilt: 3f64.to_radians(),
        })
    }
}

fn wall() -> Deviations {
    Deviations {
        delta_xi: 3.8f64.to_radians(),
        delta_zeta: 7.5f64.to_radians(),
    }
}

#[test]
fn a_model_written_outside_the_library_rebounds_through_its_entry_point() {
    let model = RigidTilt::from_params(&ModelParams::default()).unwrap();
    let law = CollisionLaw::Elastic;
    let contact = Contact {
        wall: &wall(),
        law: &law,
        psi: 2.0,
        diameter_m: 500e-6,
    };
    let mut rng = roughwall::rng::stream(1, &[0]);
    for (a_deg, b_deg) in [(-10.0, 0.0f64), (-25.0, 40.0), (-60.0, -120.0)] {
        let a = f64::to_radians(a_deg);
        let u = roughwall::angles::velocity_from_angles(4.0, a, b_deg.to_radians());
        let out = rebound_with(&model, u, Vector3::zeros(), &contact, &mut rng);
        // A specular reflection off the element it reports, which keeps the speed.
        let n = out.normal;
        let mirror = u - n * (2.0 * u.dot(&n));
        assert!((out.velocity - mirror).norm() < 1e-12, "{a_deg}");
        assert!(
            (out.velocity.norm() - 4.0).abs() < 1e-12,
            "elastic: the speed is kept"
        );
        // The element leans towards the particle by γ₀ (Eq. 23 composes γ from the wall's
        // angles to first order, so off β = 0 the lean is γ₀ to O(γ₀³)).
        let (a_out, _) = roughwall::angles::incident_angles(&out.velocity);
        let tol = if b_deg == 0.0 { 1e-12 } else { 1e-4 };
        assert!(
            (a_out - (-a + 2.0 * model.tilt)).abs() < tol,
            "{a_deg}: {a_out}"
        );
    }
    // The cases every model shares: a smooth wall is the mean wall, whatever the model.
    let smooth = Deviations {
        delta_xi: 0.0,
        delta_zeta: 0.0,
    };
    let u = roughwall::angles::velocity_from_angles(4.0, -0.3, 0.2);
    let flat = Contact {
        wall: &smooth,
        ..contact
    };
    let out = rebound_with(&model, u, Vector3::zeros(), &flat, &mut rng);
    assert_eq!(out.velocity, Vector3::new(u.x, -u.y, u.z));
}

#[test]
fn a_model_written_outside_the_library_runs_reproducibly_and_checks_its_keys() {
    let model = RigidTilt::from_params(&ModelParams::default()).unwrap();
    let setup = ModelSetup {
        wall: wall(),
        law: CollisionLaw::Elastic,
        psi: 2.0,
        diameter_m: 500e-6,
        speed: SpeedLaw::horizontal(1.0, 0.0),
        erosion: None,
        model,
        spin: Default::default(),
    };
    let cond = IncidentCondition::from_degrees(-12.5, 30.0);
    let spec = tally_spec(&setup.wall, cond, 1.0, None);
    // Particles 0..2000 in one block, then in two: a run's split.
    let tally = |ranges: &[(u64, u64)]| {
        let mut t = ConditionTally::new(spec);
        for (k, &range) in ranges.iter().enumerate() {
            let mut b = BlockTally::new(&spec, k as u64);
            fill_block(&setup, &cond, 0, 7, range, &mut b);
            t.absorb(b);
        }
        t.result()
    };
    let whole = tally(&[(0, 2000)]);
    // Every rebound leaves at α⁺ = 12.5° + 2 × 3°: the α⁺ histogram is one bin.
    let alpha_out = whole.pdf(Quantity::AlphaOut).expect("α⁺ is tallied");
    let peak = alpha_out
        .iter()
        .max_by(|x, y| x.value.total_cmp(&y.value))
        .unwrap();
    assert!(peak.lo <= 18.5 && 18.5 < peak.hi, "{peak:?}");
    assert!((peak.value * (peak.hi - peak.lo) - 1.0).abs() < 1e-12);
    let split = tally(&[(0, 700), (700, 2000)]);
    let values = |r: &roughwall::tally::ConditionResult| -> Vec<u64> {
        r.pdf(Quantity::AlphaOut)
            .unwrap()
            .iter()
            .map(|b| b.value.to_bits())
            .collect()
    };
    assert_eq!(values(&split), values(&whole));
    // Its parameters are checked by the shared checks, with the library's messages.
    let given = ModelParams {
        delta_gamma_deg: Some(2.0),
        ..Default::default()
    };
    let err = RigidTilt::from_params(&given).unwrap_err().to_string();
    assert!(
        err.contains("`stochastic.delta_gamma_deg`") && err.contains("\"rigid-tilt\""),
        "{err}"
    );
}
