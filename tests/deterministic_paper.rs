//! Paper-scale runs (ignored in CI): `cargo test --release --test integration
//! deterministic_paper -- --ignored --nocapture` prints the Sec. 3 statistics of both walls on the surfaces
//! `deterministic` chooses, at 10⁵ particles per condition.

use crate::common::deterministic::*;
use roughwall::collision::CollisionLaw;
use roughwall::deterministic::Tracker;
use roughwall::tally::Quantity;

/// Paper-scale numbers (run with `--release -- --ignored --nocapture`): both walls of
/// Sec. 3 on the surfaces `deterministic` chooses, 10⁵ particles per condition.
#[test]
#[ignore]
fn paper_scale_sec3() {
    use roughwall::deterministic::scene::{choose_surface, SceneOptions};
    for (dxi, dze) in [(2.5f64, 7.5f64), (7.5, 2.5)] {
        let c =
            choose_surface(dxi.to_radians(), dze.to_radians(), &SceneOptions::default()).unwrap();
        let f = gaussian_surface(
            c.nodes,
            c.spacing_m(),
            c.rms_height_m,
            c.corr_length_x_m,
            c.corr_length_z_m,
            2021,
        );
        let t = Tracker::new(&f, 1000).unwrap();
        let dv = dev(dxi, dze);
        let mut k = 0;
        for a in [-2.5, -12.5, -32.5] {
            for b in [0.0, 30.0, 60.0, 90.0] {
                let t0 = std::time::Instant::now();
                let r = run(&t, &CollisionLaw::Elastic, &dv, a, b, k, 100_000, UNIT);
                let el = t0.elapsed().as_secs_f64();
                k += 1;
                let tal = r.tally(1.0);
                let g = |q: Quantity| *tal.estimate(q).unwrap();
                eprintln!(
                    "({dxi},{dze}) a {a:6} b {b:4}: α⁺ {:.2}±{:.2} dβ {:+.3} (sd {:.2}) dβ1 {:+.3} (sd {:.2}) sdξ {:.2} sdζ {:.2} p1 {} lost {} {:.0}/s",
                    g(Quantity::AlphaOut).mean, g(Quantity::AlphaOut).std, g(Quantity::Dbeta).mean, g(Quantity::Dbeta).std,
                    g(Quantity::DbetaFirst).mean, g(Quantity::DbetaFirst).std, g(Quantity::XiFirst).std, g(Quantity::ZetaFirst).std,
                    tal.summary.p_single.unwrap().value, r.lost.total(), 1e5 / el
                );
            }
        }
    }
}
