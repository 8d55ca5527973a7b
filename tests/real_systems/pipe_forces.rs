//! The spin and the lifts of the pipe-flow study inside code_saturne (issue 40, parts 1–2),
//! on the coarse study of `run_checks.sh` (`pipe_flow::checks_study`): its run `forces` has
//! 150 µm beads on a smooth wall with the Sec. 4 collision law (friction: rolling and
//! sliding), the spin carried between hits, the Saffman–Mei and the Magnus lift, no
//! dispersion, and particles 0–19 traced at every step; its run `kick` throws the same
//! beads at the wall at 40 m/s, for steep hits (where they roll).
//! * Every hit's rebound, spin included, is the library's for the same hit, bit for bit,
//!   on both Sommerfeld–Huber branches; the spin the particle brings is the one its last
//!   hit gave it, relaxed in the fluid, not 0.
//! * Between hits the particles follow their equation of motion, integrated here
//!   independently (RK4) with the lifts written again from the papers: drag
//!   (Schiller–Naumann), gravity, pressure gradient, Saffman–Mei, Magnus; and the spin
//!   follows the rotational drag of Dennis et al. (1980).

use crate::pipe_flow::{checks_study, hits, num, rows};
use roughwall::collision::{CollisionParams, ShParams};
use roughwall::wall_model::{Hit, WallModel, WallParams};
use std::collections::{BTreeMap, HashMap};
use std::f64::consts::PI;

type V3 = [f64; 3];

fn v3(r: &HashMap<String, String>, names: [&str; 3]) -> V3 {
    names.map(|k| num(r, k))
}
fn dot(a: V3, b: V3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn norm(a: V3) -> f64 {
    dot(a, a).sqrt()
}
fn cross(a: V3, b: V3) -> V3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
fn add(a: V3, b: V3, k: f64) -> V3 {
    [a[0] + k * b[0], a[1] + k * b[1], a[2] + k * b[2]]
}
fn scale(a: V3, k: f64) -> V3 {
    a.map(|x| k * x)
}

#[test]
fn spin_rebounds_in_code_saturne_are_the_librarys_bit_for_bit() {
    let runs = checks_study().join("runs");
    let (wall, _) = WallModel::new(&WallParams {
        collision: CollisionParams {
            model: Some("sommerfeld-huber".into()),
            preset: Some("glass-steel".into()),
            ..Default::default()
        },
        seed: 2021,
        ..Default::default()
    })
    .unwrap();
    let sh = ShParams::glass_steel();
    let mut all = hits(&runs.join("150um-smooth-paper-forces"));
    let kicked = hits(&runs.join("150um-smooth-paper-kick"));
    all.extend(
        kicked
            .into_iter()
            .map(|((p, c), h)| ((p + 1_000_000, c), h)),
    );
    let (mut rolling, mut sliding, mut spun, mut spin_mattered) = (0, 0, 0, 0);
    let mut n = 0;
    for (&(pid, cidx), h) in &all {
        if num(h, "status") != 0.0 {
            continue;
        }
        n += 1;
        let u_in = v3(h, ["ux_in", "uy_in", "uz_in"]);
        let w_in = v3(h, ["wx_in", "wy_in", "wz_in"]);
        let normal = v3(h, ["nx", "ny", "nz"]);
        let hit = Hit {
            velocity: u_in,
            spin: w_in,
            normal,
            lay: [1.0, 0.0, 0.0],
            wall_velocity: [0.0; 3],
            diameter_m: num(h, "diameter"),
            particle_id: pid % 1_000_000,
            collision_index: cidx,
        };
        let out = wall.rebound(&hit);
        let logged_u = v3(h, ["ux_out", "uy_out", "uz_out"]);
        let logged_w = v3(h, ["wx_out", "wy_out", "wz_out"]);
        assert_eq!(out.velocity, logged_u, "{pid}/{cidx}: velocity");
        assert_eq!(out.spin, logged_w, "{pid}/{cidx}: spin");
        spun += usize::from(norm(w_in) > 0.0);
        // a particle starts at rest; from its second hit on it brings a spin
        assert!(cidx == 0 || norm(w_in) > 0.0, "{pid}/{cidx}: no spin");
        let without = wall.rebound(&Hit {
            spin: [0.0; 3],
            ..hit
        });
        spin_mattered += usize::from(without.velocity != out.velocity);
        // Which branch (Radenkovic & Simonin 2021, Eq. 38), in the normal on the fluid's side.
        let nf = scale(normal, -dot(u_in, normal).signum() / norm(normal));
        let un = dot(u_in, nf);
        let alpha = (-un / norm(u_in)).asin();
        let (e, mu) = (sh.restitution(alpha), sh.friction(alpha));
        let r = 0.5 * hit.diameter_m;
        let slip = add(add(u_in, nf, -un), cross(w_in, nf), -r);
        if norm(slip) < 3.5 * mu * (1.0 + e) * (-un) {
            rolling += 1;
            // the contact point leaves the wall without slipping
            let uo_t = add(logged_u, nf, -dot(logged_u, nf));
            let after = add(uo_t, cross(logged_w, nf), -r);
            assert!(
                norm(after) < 1e-9 * norm(u_in),
                "{pid}/{cidx}: rolling rebound slips {after:?}"
            );
        } else {
            sliding += 1;
        }
    }
    eprintln!(
        "{n} rebounds: {rolling} rolling, {sliding} sliding; {spun} with spin, {spin_mattered} changed by it"
    );
    assert!(n > 200, "only {n} rebounds");
    assert!(
        rolling >= 10 && sliding >= 10,
        "{rolling} rolling, {sliding} sliding"
    );
    // The spin is carried: the particles bring the fluid's or their last hit's spin (a
    // first hit within the run's first step brings none).
    assert!(100 * spun >= 99 * n, "{spun} of {n} hits with spin");
    assert!(
        2 * spin_mattered > n,
        "the spin changed {spin_mattered} of {n} rebounds"
    );
    // Without `spin` the hits get 0 and keep it.
    for h in hits(&runs.join("150um-smooth-paper")).values() {
        for k in ["wx_in", "wy_in", "wz_in", "wx_out", "wy_out", "wz_out"] {
            assert_eq!(num(h, k), 0.0, "{k}");
        }
    }
}

/// The traced state of one particle at the start of one step.
struct State {
    step: i64,
    cidx: u64,
    x: V3,
    v: V3,
    us: V3,
    taup: f64,
    grad_p: V3,
    vorticity: V3,
    spin: V3,
    a_saffman: V3,
    a_magnus: V3,
    rho_f: f64,
    mu_f: f64,
    rho_p: f64,
    d: f64,
}

fn state(r: &HashMap<String, String>) -> State {
    State {
        step: num(r, "step") as i64,
        cidx: num(r, "collision_index") as u64,
        x: v3(r, ["x", "y", "z"]),
        v: v3(r, ["vx", "vy", "vz"]),
        us: v3(r, ["usx", "usy", "usz"]),
        taup: num(r, "taup"),
        grad_p: v3(r, ["gpx", "gpy", "gpz"]),
        vorticity: v3(r, ["wfx", "wfy", "wfz"]),
        spin: v3(r, ["wpx", "wpy", "wpz"]),
        a_saffman: v3(r, ["asx", "asy", "asz"]),
        a_magnus: v3(r, ["amx", "amy", "amz"]),
        rho_f: num(r, "rho_f"),
        mu_f: num(r, "mu_f"),
        rho_p: num(r, "rho_p"),
        d: num(r, "d_p"),
    }
}

impl State {
    fn mass(&self) -> f64 {
        self.rho_p * PI * self.d.powi(3) / 6.0
    }
    /// Schiller–Naumann: τ_p = ρ_p d² / (18 μ (1 + 0.15 Re^0.687)).
    fn taup(&self, slip: V3) -> f64 {
        let re = self.rho_f * self.d * norm(slip) / self.mu_f;
        self.rho_p * self.d * self.d / (18.0 * self.mu_f * (1.0 + 0.15 * re.powf(0.687)))
    }
    /// Saffman (1965) `F = 1.615 d² (ρ μ)^½ |ω|^−½ (u − v) × ω` times Mei's (1992) factor.
    fn saffman(&self, slip: V3) -> V3 {
        let w = norm(self.vorticity);
        let re_p = self.rho_f * self.d * norm(slip) / self.mu_f;
        let re_s = self.rho_f * self.d * self.d * w / self.mu_f;
        let beta = re_s / (2.0 * re_p);
        let f = if re_p <= 40.0 {
            (1.0 - 0.3314 * beta.sqrt()) * (-re_p / 10.0).exp() + 0.3314 * beta.sqrt()
        } else {
            0.0524 * (beta * re_p).sqrt()
        };
        let k = 1.615 * self.d * self.d * (self.rho_f * self.mu_f / w).sqrt() * f;
        scale(cross(slip, self.vorticity), k / self.mass())
    }
    /// Magnus: `F = ρ/2 π/4 d² C_LR |u − v| Ω × (u − v)/|Ω|`, Oesterlé & Bui Dinh's C_LR.
    fn magnus(&self, slip: V3, spin: V3) -> V3 {
        let rot = add(scale(self.vorticity, 0.5), spin, -1.0);
        let re_p = self.rho_f * self.d * norm(slip) / self.mu_f;
        let re_r = self.rho_f * self.d * self.d * norm(rot) / self.mu_f;
        let c = 0.45 + (re_r / re_p - 0.45) * (-0.05684 * re_r.powf(0.4) * re_p.powf(0.3)).exp();
        let k = self.rho_f / 2.0 * PI / 4.0 * self.d * self.d * c * norm(slip) / norm(rot);
        scale(cross(rot, slip), k / self.mass())
    }
    /// dω/dt = T/I: T = ρ/2 (d/2)⁵ C_R |Ω| Ω (Dennis et al. 1980), I = π ρ_p d⁵/60.
    fn spin_rate(&self, vorticity: V3, spin: V3) -> V3 {
        let rot = add(scale(vorticity, 0.5), spin, -1.0);
        let re_r = self.rho_f * self.d * self.d * norm(rot) / self.mu_f;
        if re_r == 0.0 {
            return [0.0; 3];
        }
        let c_r = if re_r <= 32.0 {
            64.0 * PI / re_r
        } else {
            12.9 / re_r.sqrt() + 128.4 / re_r
        };
        let torque = self.rho_f / 2.0 * (self.d / 2.0).powi(5) * c_r * norm(rot);
        scale(rot, torque / (PI * self.rho_p * self.d.powi(5) / 60.0))
    }
}

/// RK4 of `dy/dt = f(y)` over `dt` in `n` steps.
fn rk4<const N: usize>(
    mut y: [f64; N],
    dt: f64,
    n: usize,
    f: impl Fn(&[f64; N]) -> [f64; N],
) -> [f64; N] {
    let h = dt / n as f64;
    let at = |y: &[f64; N], k: &[f64; N], c: f64| std::array::from_fn(|i| y[i] + c * k[i]);
    for _ in 0..n {
        let k1 = f(&y);
        let k2 = f(&at(&y, &k1, h / 2.0));
        let k3 = f(&at(&y, &k2, h / 2.0));
        let k4 = f(&at(&y, &k3, h));
        y = std::array::from_fn(|i| y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]));
    }
    y
}

#[test]
fn lifts_and_spin_follow_their_equations_of_motion_in_code_saturne() {
    let run = checks_study().join("runs/150um-smooth-paper-forces");
    let params = std::fs::read_to_string(run.join("pipe.params")).unwrap();
    let param = |k: &str| -> f64 {
        params
            .lines()
            .find_map(|l| l.strip_prefix(&format!("{k} ")))
            .unwrap_or_else(|| panic!("{k} in pipe.params"))
            .trim()
            .parse()
            .unwrap()
    };
    let (dt, length) = (param("dt"), param("length"));
    let gravity = [0.0, -9.81, 0.0];
    let mut by_particle: BTreeMap<u64, Vec<State>> = BTreeMap::new();
    for r in rows(&run.join("trace_rank0000.csv")) {
        by_particle
            .entry(num(&r, "particle_id") as u64)
            .or_default()
            .push(state(&r));
    }
    assert_eq!(by_particle.len(), 20, "traced particles");
    let (mut steps, mut spins) = (0usize, 0usize);
    let (mut worst_v, mut worst_x, mut worst_w): (f64, f64, f64) = (0.0, 0.0, 0.0);
    let (mut missed_saffman, mut missed_magnus, mut resolved) = (0usize, 0usize, 0usize);
    for trace in by_particle.values() {
        for pair in trace.windows(2) {
            let (a, b) = (&pair[0], &pair[1]);
            if b.step != a.step + 1 || b.cidx != a.cidx {
                continue; // a wall hit in between
            }
            steps += 1;
            // The lifts the hook applied are the papers' (written again here).
            let slip = add(a.us, a.v, -1.0);
            let (s, m) = (a.saffman(slip), a.magnus(slip, a.spin));
            // (Crowe et al.'s 4.1126 is Saffman's 1.615 × 8/π to 5 digits: 9e-6 apart)
            for (got, want, what, tol) in [
                (a.a_saffman, s, "Saffman-Mei", 1e-5),
                (a.a_magnus, m, "Magnus", 1e-9),
            ] {
                assert!(
                    norm(add(got, want, -1.0)) <= tol * norm(want) + 1e-12,
                    "step {}: {what} {got:?} vs {want:?}",
                    a.step
                );
            }
            assert!((a.taup(slip) - a.taup).abs() <= 1e-9 * a.taup, "τ_p");
            // One step of the particle's equation of motion, integrated by RK4: drag towards
            // the fluid of its cell (the velocity seen at the step's end: no dispersion),
            // gravity, pressure gradient and the lifts, held over the step as code_saturne
            // holds every force but drag (cs_lagr_sde.c, 6.0.2).
            let push = |with_s: bool, with_m: bool| -> [f64; 6] {
                let mut acc = add(gravity, a.grad_p, -1.0 / a.rho_p);
                if with_s {
                    acc = add(acc, s, 1.0);
                }
                if with_m {
                    acc = add(acc, m, 1.0);
                }
                let y0 = [a.x[0], a.x[1], a.x[2], a.v[0], a.v[1], a.v[2]];
                rk4(y0, dt, 50, |y| {
                    let v = [y[3], y[4], y[5]];
                    let drag = scale(add(b.us, v, -1.0), 1.0 / a.taup);
                    [
                        v[0],
                        v[1],
                        v[2],
                        drag[0] + acc[0],
                        drag[1] + acc[1],
                        drag[2] + acc[2],
                    ]
                })
            };
            let y = push(true, true);
            let lift_dv = norm(add(s, m, 1.0)) * dt;
            let dv = norm(add([y[3], y[4], y[5]], b.v, -1.0));
            let mut dx = add([y[0], y[1], y[2]], b.x, -1.0);
            dx[0] -= length * (dx[0] / length).round(); // the periodic section
            worst_v = worst_v.max(dv / lift_dv.max(1e-30));
            worst_x = worst_x.max(norm(dx) / (lift_dv * dt).max(1e-30));
            // (code_saturne stands for a zero Lagrangian time scale without dispersion with
            // T_L = 1e-12 s, which leaves terms of |u| T_L/τ_p ≈ 1e-11 |u| in the step.)
            let floor = 1e-10 * norm(a.v);
            assert!(
                dv <= 1e-6 * lift_dv + floor,
                "step {}: velocity off by {dv}",
                a.step
            );
            assert!(
                norm(dx) <= (1e-6 * lift_dv + floor) * dt,
                "step {}: position off by {dx:?}",
                a.step
            );
            // Each lift is resolved: leaving it out misses the step by more than the
            // integration's error.
            if norm(s) * dt > 1e3 * (dv + floor) && norm(m) * dt > 1e3 * (dv + floor) {
                resolved += 1;
                let miss = |y: [f64; 6]| norm(add([y[3], y[4], y[5]], b.v, -1.0));
                missed_saffman += usize::from(miss(push(false, true)) > 0.5 * norm(s) * dt);
                missed_magnus += usize::from(miss(push(true, false)) > 0.5 * norm(m) * dt);
            }
            // The spin relaxes by the rotational drag over the step, in the fluid of the cell
            // the particle ends it in (the hook relaxes it at the end of the step).
            let w = rk4(a.spin, dt, 50, |w| a.spin_rate(b.vorticity, *w));
            let change = norm(add(b.spin, a.spin, -1.0));
            let off = norm(add(w, b.spin, -1.0));
            if change > 0.0 {
                spins += 1;
                worst_w = worst_w.max(off / change);
            }
            assert!(
                off <= 1e-3 * change + 1e-9,
                "step {}: spin off by {off} of {change}",
                a.step
            );
        }
    }
    eprintln!(
        "{steps} steps between hits: velocity within {worst_v:.1e} and position within \
         {worst_x:.1e} of the lifts' contribution; spin within {worst_w:.1e} of its change \
         ({spins} steps); {resolved} steps resolve both lifts"
    );
    assert!(steps > 1000, "only {steps} steps traced between hits");
    assert!(spins > 1000, "the spin changed on {spins} steps");
    assert!(
        resolved > 100,
        "both lifts resolved on {resolved} steps only"
    );
    assert_eq!(
        missed_saffman, resolved,
        "steps that need the Saffman-Mei lift"
    );
    assert_eq!(missed_magnus, resolved, "steps that need the Magnus lift");
}
