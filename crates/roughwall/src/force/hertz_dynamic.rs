//! `hertz-dynamic`: the contact of `hertz-rigid` integrated in time (docs/physics.md §7).
//!
//! A rigid prolate spheroid, free to translate and to rotate in the β plane, meets the rigid wall
//! with normal speed U_N and no spin. The contact is frictionless, so the horizontal velocity is
//! constant and drops out. State `(δ, φ, v, ω)`: approach δ of the lowest point, rotation φ of the
//! major axis (θ = β + φ), vertical velocity v of the centre (up positive) and spin ω = dθ/dt:
//!
//! ```text
//! δ' = d(θ) ω − v          (the lowest point moves as the body turns: d = dh/dθ)
//! φ' = ω
//! v' = F/m                 F = k(θ) δ^{3/2}   (Johnson 1985 §4.2, instantaneous radii R'(θ), R''(θ))
//! ω' = −d(θ) F / I         (normal force through the lowest point, lever arm d(θ))
//! ```
//!
//! For a sphere (d ≡ 0, k constant) this is Hu et al. 2021, Eq. (1) with Newton's law.
//! The force acts through the current lowest point; the O(δ/R) variation of k(θ) during the
//! contact makes the system non-conservative at that order only.
//!
//! Integration: classical RK4 with a fixed step `t_c / N`, where `t_c` is the closed-form contact
//! time of `hertz-rigid` at the initial orientation, so the step scales with the contact itself
//! (nanoseconds for micrometre glass, microseconds for millimetre steel) and the same N gives
//! the same relative accuracy at every scale. The first step, from δ = 0 where F ∝ δ^{3/2} is
//! too rough for RK4, is the contact's series expansion instead. The peak is located inside its
//! step by a root find of dF/dt on the RK4 step from the step's start (dense, same order), and
//! separation (δ = 0) likewise, which gives the contact time.
use super::spheroid::Spheroid;
use super::{hertz_impact, hertz_rigid, ForceResult, Impact, Particle};

/// Step control of the integration.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Options {
    /// RK4 steps per (estimated) contact duration.
    pub steps_per_contact: usize,
}

impl Default for Options {
    /// 64 steps per contact: peak within 1e-7 of the converged value (sphere: of Eq. 3) and
    /// contact time within 2e-7 (see tests and the speed-versus-error table of `force_sweep`).
    fn default() -> Self {
        Options {
            steps_per_contact: 64,
        }
    }
}

/// Full result of one integrated impact.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Outcome {
    /// Peak force (N).
    pub f_max: f64,
    /// Contact duration (s); `None` if no contact (U_N = 0) or no separation within the step cap.
    pub contact_time: Option<f64>,
    /// RK4 steps taken.
    pub steps: usize,
    /// Rotation of the major axis during the contact (rad).
    pub rotation: f64,
    /// Kinetic energy (translation + rotation) at separation over the incident one; 1 for an
    /// elastic contact up to the O(δ/R) non-conservation of k(θ) (and 0 without separation).
    pub energy_ratio: f64,
}

type State = [f64; 4];

struct Body {
    shape: Spheroid,
    e_star: f64,
    mass: f64,
    inertia: f64,
    beta: f64,
}

impl Body {
    /// Lever arm d(θ) and stiffness k(θ) at θ = β + φ.
    #[inline]
    fn geometry(&self, phi: f64) -> (f64, f64) {
        let lp = self.shape.lowest_point(self.beta + phi);
        (
            lp.lever_arm,
            hertz_rigid::stiffness(self.e_star, lp.r_in_plane, lp.r_out_of_plane),
        )
    }

    #[inline]
    fn force(&self, s: &State) -> f64 {
        let delta = s[0].max(0.0);
        self.geometry(s[1]).1 * delta * delta.sqrt()
    }

    #[inline]
    fn rhs(&self, s: &State) -> State {
        self.rhs_force(s).0
    }

    /// dF/dt = k'(θ) ω δ^{3/2} + (3/2) k δ^{1/2} δ'.
    fn force_rate(&self, s: &State) -> f64 {
        let delta = s[0].max(0.0);
        let (d, k) = self.geometry(s[1]);
        let eps = 1e-6;
        let dk = (self.geometry(s[1] + eps).1 - self.geometry(s[1] - eps).1) / (2.0 * eps);
        let rate = d * s[3] - s[2];
        dk * s[3] * delta * delta.sqrt() + 1.5 * k * delta.sqrt() * rate
    }

    /// Right-hand side and force at `s` (one geometry evaluation).
    #[inline]
    fn rhs_force(&self, s: &State) -> (State, f64) {
        let (d, k) = self.geometry(s[1]);
        let delta = s[0].max(0.0);
        let f = k * delta * delta.sqrt();
        (
            [d * s[3] - s[2], s[3], f / self.mass, -d * f / self.inertia],
            f,
        )
    }

    fn rk4(&self, s: &State, h: f64) -> State {
        self.rk4_with(s, &self.rhs(s), h)
    }

    /// One classical RK4 step of size `h` from `s`, whose derivative `k1` is known.
    #[inline]
    fn rk4_with(&self, s: &State, k1: &State, h: f64) -> State {
        let add = |a: &State, b: &State, c: f64| {
            [
                a[0] + c * b[0],
                a[1] + c * b[1],
                a[2] + c * b[2],
                a[3] + c * b[3],
            ]
        };
        let k2 = self.rhs(&add(s, k1, 0.5 * h));
        let k3 = self.rhs(&add(s, &k2, 0.5 * h));
        let k4 = self.rhs(&add(s, &k3, h));
        let mut out = *s;
        for i in 0..4 {
            out[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
        }
        out
    }

    /// Root of `g(rk4(s, τ))` for τ in (0, h) given g(s) and g(rk4(s, h)) of opposite signs
    /// (Illinois false position). A root located to 1e-7 h moves a smooth maximum by O(1e-14).
    fn root_in_step(&self, s: &State, h: f64, g: impl Fn(&State) -> f64) -> f64 {
        let (mut a, mut b) = (0.0, h);
        let (mut ga, mut gb) = (g(s), g(&self.rk4(s, h)));
        let mut side = 0;
        for _ in 0..40 {
            let c = if ga != gb {
                (a * gb - b * ga) / (gb - ga)
            } else {
                0.5 * (a + b)
            };
            let c = if c > a && c < b { c } else { 0.5 * (a + b) };
            let gc = g(&self.rk4(s, c));
            if gc == 0.0 || (b - a) <= 1e-7 * h {
                return c;
            }
            if (gc > 0.0) == (ga > 0.0) {
                a = c;
                ga = gc;
                if side == -1 {
                    gb *= 0.5;
                }
                side = -1;
            } else {
                b = c;
                gb = gc;
                if side == 1 {
                    ga *= 0.5;
                }
                side = 1;
            }
        }
        0.5 * (a + b)
    }
}

/// Integrates one impact (Hu et al. 2021, Eq. 1 for spheres; docs/physics.md §7 for spheroids).
/// `p` and `imp` must be valid (see [`Particle::validate`], [`Impact::validate`]).
pub fn simulate(p: &Particle, imp: &Impact, opts: &Options) -> Outcome {
    if imp.u_n <= 0.0 {
        return Outcome {
            f_max: 0.0,
            contact_time: None,
            steps: 0,
            rotation: 0.0,
            energy_ratio: 0.0,
        };
    }
    let shape = Spheroid::from_volume_diameter(p.diameter, imp.lambda);
    let body = Body {
        shape,
        e_star: p.e_star(),
        mass: p.mass(),
        inertia: p.mass() * shape.inertia_per_mass(),
        beta: imp.beta,
    };
    let (k0, m_eff0) = hertz_rigid::contact_parameters(p, imp.lambda, imp.beta);
    let t_est = hertz_impact(k0, m_eff0, imp.u_n).1.unwrap_or(0.0);
    let n = opts.steps_per_contact.max(4);
    let h = t_est / n as f64;
    let max_steps = 50 * n;

    // The first step from δ = 0 by the contact's series expansion (F ∝ δ^{3/2} is not smooth
    // enough at δ = 0 for RK4): with c = k U^{3/2}, to leading order
    // v = −U + (2/5)(c/m) t^{5/2}, ω = −(2/5)(d c/I) t^{5/2}, φ = −(4/35)(d c/I) t^{7/2},
    // δ = U t − (4/35) c (1/m + d²/I) t^{7/2}; the neglected terms are O(t^6).
    let (d0, k0) = body.geometry(0.0);
    let c = k0 * imp.u_n * imp.u_n.sqrt();
    let t25 = h * h * h.sqrt();
    let t35 = t25 * h;
    let mut s: State = [
        imp.u_n * h - 4.0 / 35.0 * c * (1.0 / body.mass + d0 * d0 / body.inertia) * t35,
        -4.0 / 35.0 * d0 * c / body.inertia * t35,
        -imp.u_n + 0.4 * c / body.mass * t25,
        -0.4 * d0 * c / body.inertia * t25,
    ];
    let (mut ds, mut f) = body.rhs_force(&s);
    let mut prev = s; // state one step back (for the peak bracket)
    let mut t = h;
    let mut f_max: f64 = 0.0;
    let mut peak_done = false;
    for step in 1..=max_steps {
        let next = body.rk4_with(&s, &ds, h);
        if next[0] <= 0.0 {
            // Separation inside this step: δ(t + τ) = 0.
            let tau = body.root_in_step(&s, h, |x| x[0]);
            let end = body.rk4(&s, tau);
            let ke = body.mass * end[2] * end[2] + body.inertia * end[3] * end[3];
            return Outcome {
                f_max,
                contact_time: Some(t + tau),
                steps: step,
                rotation: end[1],
                energy_ratio: ke / (body.mass * imp.u_n * imp.u_n),
            };
        }
        let (dn, fn_) = body.rhs_force(&next);
        if !peak_done && fn_ < f {
            // F rose up to the sample at t and falls after it: the peak lies in [t − h, t + h].
            // Locate dF/dt = 0 on the RK4 step from the bracketing sample.
            peak_done = true;
            let start = if body.force_rate(&s) > 0.0 || step == 1 {
                s
            } else {
                prev
            };
            let tau = body.root_in_step(&start, h, |x| body.force_rate(x));
            f_max = f_max.max(body.force(&body.rk4(&start, tau)));
        }
        f_max = f_max.max(fn_);
        prev = s;
        s = next;
        ds = dn;
        f = fn_;
        t += h;
    }
    Outcome {
        f_max,
        contact_time: None,
        steps: max_steps,
        rotation: s[1],
        energy_ratio: 0.0,
    }
}

/// `hertz-dynamic` for one impact with the given step control: the elliptical Hertz contact of
/// docs/physics.md §7 integrated in time with the spheroid free to translate and rotate; for a
/// sphere this is Hu et al. Eq. (1).
pub fn evaluate(p: &Particle, imp: &Impact, opts: &Options) -> ForceResult {
    let out = simulate(p, imp, opts);
    let scale = p.force_scale(imp.u_n);
    let xi = if imp.u_n > 0.0 && scale > 0.0 && out.f_max > 0.0 {
        out.f_max / scale
    } else {
        // U_N → 0 (or a speed so small that the force underflows): no rotation during the
        // contact, the rigid model's ξ.
        hertz_rigid::xi(imp.lambda, imp.beta)
    };
    ForceResult {
        f_max: out.f_max,
        xi,
        contact_time: out.contact_time,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::force::{hertz_sphere, Model};
    use std::f64::consts::FRAC_PI_2;

    fn glass() -> Particle {
        Particle {
            density: 2500.0,
            youngs: 64e9,
            poisson: 0.24,
            diameter: 2.45e-6,
        }
    }

    /// Hu et al. 2021, Eq. (1) integrated in time equals Eq. (3) to 1e-6 (the analogue of Fig. 4),
    /// for micrometre glass (ns contacts) and 5 mm steel (µs contacts) alike.
    #[test]
    fn sphere_matches_eq3() {
        let steel = Particle {
            density: 7850.0,
            youngs: 210e9,
            poisson: 0.3,
            diameter: 5e-3,
        };
        for p in [glass(), steel] {
            for u in [0.0457, 1.0, 20.0] {
                let imp = Impact {
                    lambda: 1.0,
                    beta: 0.7,
                    u_n: u,
                };
                let dynm = evaluate(&p, &imp, &Options::default());
                let eq3 = hertz_sphere::evaluate(&p, u);
                assert!(
                    (dynm.f_max / eq3.f_max - 1.0).abs() < 1e-6,
                    "{} vs {}",
                    dynm.f_max,
                    eq3.f_max
                );
                let tc = eq3.contact_time.unwrap();
                assert!((dynm.contact_time.unwrap() / tc - 1.0).abs() < 1e-6);
            }
        }
    }

    /// The contact is elastic: the kinetic energy comes back (translation + rotation), up to the
    /// O(δ/a) work of the varying stiffness; a wrong torque sign or lever arm would break this.
    /// The body turns towards lying flat (θ decreases): the force acts at the lowest point.
    #[test]
    fn energy_comes_back_and_spin_sign() {
        for (lambda, beta) in [(1.0, 0.3), (2.0, 0.785), (3.0, 0.2), (3.0, 1.3)] {
            let imp = Impact {
                lambda,
                beta,
                u_n: 0.0457,
            };
            let out = simulate(&glass(), &imp, &Options::default());
            assert!(
                (out.energy_ratio - 1.0).abs() < 1e-4,
                "λ={lambda}: {}",
                out.energy_ratio
            );
            if lambda > 1.0 {
                assert!(out.rotation < 0.0, "λ={lambda} β={beta}: {}", out.rotation);
            }
        }
    }

    #[test]
    fn end_orientations_equal_rigid() {
        for lambda in [1.5, 2.0, 3.0] {
            for beta in [0.0, FRAC_PI_2] {
                let imp = Impact {
                    lambda,
                    beta,
                    u_n: 0.0457,
                };
                let d = Model::HertzDynamic.evaluate(&glass(), &imp).unwrap();
                let r = Model::HertzRigid.evaluate(&glass(), &imp).unwrap();
                assert!(
                    (d.f_max / r.f_max - 1.0).abs() < 1e-6,
                    "λ={lambda} β={beta}: {} {}",
                    d.f_max,
                    r.f_max
                );
            }
        }
    }
}
