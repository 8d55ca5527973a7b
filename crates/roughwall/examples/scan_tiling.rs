//! What mirrored tiling costs (issue 29, part 4): a measured scan is not periodic, and the
//! deterministic model bounces on it mirror-tiled (`surface::scan::periodic`). On generated
//! Sec. 3 walls ((Δξ, Δζ) = (2.5°, 7.5°), the automatic 100-c_L grid) this compares, surface
//! by surface, particles on the periodic wall itself with particles on a window of it taken
//! as a scan and mirror-tiled: the whole wall (100 c_L) and its first quarter (a 50-c_L
//! window). The difference of the means, averaged over the surfaces, is the tiling's bias;
//! its standard error is the spread between surfaces over √N.
//!
//! `cargo run --release -p roughwall --example scan_tiling -- SURFACES HISTORIES OUT.csv`
//! (scripts/scan-tiling.sh).

use roughwall::deterministic::{choose_surface, generate_surface, SceneOptions, SurfacePlan};
use roughwall::deterministic::{run_condition, ModelSetup};
use roughwall::scan::mirrored_wall;
use roughwall::tally::{Moments, ShiftedSums};
use roughwall::CollisionLaw;
use roughwall::Deviations;
use roughwall::ScanField;
use roughwall::Tracker;
use roughwall::{HeightField, Triangulation};
use roughwall::{IncidentCondition, SpeedLaw};

/// Mean `α⁺` and mean `β⁺ − β⁻` (degrees) of `count` histories on `field`.
fn means(
    field: &HeightField,
    setup: &ModelSetup,
    cond: IncidentCondition,
    count: usize,
) -> [f64; 2] {
    let tracker = Tracker::new(field, 1000).expect("tracker");
    let run = run_condition(&tracker, setup, cond, 0, count, 2021);
    let n = run.outcomes.len() as f64;
    let a = run
        .outcomes
        .iter()
        .map(|o| o.alpha_out.to_degrees())
        .sum::<f64>()
        / n;
    let b = run
        .outcomes
        .iter()
        .map(|o| o.dbeta.to_degrees())
        .sum::<f64>()
        / n;
    [a, b]
}

/// The first `nx × nz` nodes of `f` as a (non-periodic) scan.
fn window(f: &HeightField, nx: usize, nz: usize) -> ScanField {
    let heights = (0..nz)
        .flat_map(|iz| f.heights[iz * f.nx..iz * f.nx + nx].iter().copied())
        .collect();
    ScanField::new(nx, nz, f.dx, f.dz, heights).expect("window")
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let surfaces: u64 = args.get(1).and_then(|s| s.parse().ok()).unwrap_or(16);
    let count: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(50_000);
    let out = args
        .get(3)
        .cloned()
        .unwrap_or_else(|| "scan_tiling.csv".into());
    let (xi, zeta) = (2.5f64.to_radians(), 7.5f64.to_radians());
    let spec = choose_surface(xi, zeta, &SceneOptions::default()).expect("surface");
    let plan = SurfacePlan::Auto(spec);
    let setup = ModelSetup {
        law: CollisionLaw::Elastic,
        diameter_m: 100e-6,
        speed: SpeedLaw::horizontal(1.0, 0.0),
        wall: Deviations {
            delta_xi: xi,
            delta_zeta: zeta,
        },
        psi: 2.0,
        erosion: None,
        spin: Default::default(),
    };
    let conditions: Vec<IncidentCondition> =
        [(-2.5, 0.0), (-2.5, 90.0), (-12.5, 0.0), (-12.5, 90.0)]
            .iter()
            .map(|&(a, b)| IncidentCondition::from_degrees(a, b))
            .collect();
    let windows = [("100 c_L", 1usize), ("50 c_L", 2usize)];
    // Per window and condition: the differences tiled − periodic of mean α⁺ and mean
    // β⁺ − β⁻, one per surface.
    let mut diffs = vec![[ShiftedSums::default(); 2]; windows.len() * conditions.len()];
    for r in 0..surfaces {
        let wall = generate_surface(&plan, 1000 + r, Triangulation::Alternating).expect("generate");
        let periodic: Vec<[f64; 2]> = conditions
            .iter()
            .map(|&c| means(&wall, &setup, c, count))
            .collect();
        for (w, &(_, div)) in windows.iter().enumerate() {
            let scan = window(&wall, wall.nx / div, wall.nz / div);
            let (tiled, _) = mirrored_wall(&scan, 0.0).unwrap_or_else(|e| panic!("{e}"));
            for (k, &c) in conditions.iter().enumerate() {
                let m = means(&tiled, &setup, c, count);
                for q in 0..2 {
                    diffs[w * conditions.len() + k][q].push(m[q] - periodic[k][q]);
                }
            }
        }
        eprintln!("scan_tiling: surface {} of {surfaces}", r + 1);
    }
    let mut csv = String::from(
        "window,alpha_in_deg,beta_in_deg,surfaces,histories,bias_mean_alpha_out_deg,se_bias_mean_alpha_out_deg,bias_mean_dbeta_deg,se_bias_mean_dbeta_deg\n",
    );
    for (w, &(name, _)) in windows.iter().enumerate() {
        for (k, c) in conditions.iter().enumerate() {
            let [a, b]: [Moments; 2] = diffs[w * conditions.len() + k].map(|s| s.moments());
            csv.push_str(&format!(
                "{name},{},{},{surfaces},{count},{:.4},{:.4},{:.4},{:.4}\n",
                c.alpha_in_deg(),
                c.beta_in_deg(),
                a.mean,
                a.se().unwrap_or(f64::NAN),
                b.mean,
                b.se().unwrap_or(f64::NAN),
            ));
        }
    }
    std::fs::write(&out, csv).expect("write");
}
