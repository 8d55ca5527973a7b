//! `rebound pipe-stats` on a small study written by hand (no code_saturne): every statistic
//! against its value computed here, and bad input refused with one line and status 2. The
//! real study is checked in `tests/real_systems/pipe_flow.rs`.

use crate::common::*;
use std::collections::HashMap;
use std::path::Path;

const PARAMS: &str = "phase 2\nnt 100\ndt 0.0005\ndiameter_pipe 0.05\nlength 0.2\nu_bulk 20\n\
wall 1\ndelta_xi_deg 5\ndelta_zeta_deg 5\nmodel 0\nlaw 1\npreset 1\nseed 1\nn_particles 40\n\
d_p 0.0001\nrho_p 2500\ndispersion 1\nt_sample 0.01\nn_bins 2\nlog_hits 1\n";

/// A run of 40 particles, each sampled 10 times, all in the lower slab, at u_x = `ux`
/// (u_r = 0), 1 m travelled and `hits` hits at the bottom with α⁻ = 10°, α⁺ = 10° + `dalpha`,
/// on a facet struck at 10° + `dalpha`/2.
fn write_run(dir: &Path, ux: f64, hits: usize, dalpha: f64) {
    std::fs::create_dir_all(dir).unwrap();
    std::fs::write(dir.join("pipe.params"), PARAMS).unwrap();
    let mut p = String::from(
        "particle_id,n,dist,hits,sum_y,cy_0,cy_1,cz_0,cz_1,ux_0,ux_1,ux2_0,ux2_1,ur_0,ur_1,ur2_0,ur2_1,sy_0,sy_1,sz_0,sz_1\n",
    );
    for id in 0..40 {
        // at y = −R/2: sum_y = 10 × −0.0125 m
        p.push_str(&format!(
            "{id},10,1,{hits},-0.125,10,0,5,5,{},0,{},0,0,0,0,0,4,0,0,0\n",
            10.0 * ux,
            10.0 * ux * ux
        ));
    }
    std::fs::write(dir.join("particles.csv"), p).unwrap();
    let mut h = String::from("particle_id,collision_index,step,y,z,alpha_in_deg,lay_angle_deg,speed_in,speed_out,alpha_out_deg,deflection_deg,status,candidate_walls,alpha_element_deg\n");
    for id in 0..40 {
        for k in 0..hits {
            h.push_str(&format!(
                "{id},{k},50,-0.025,0,10,3,20,18,{},1,0,1,{}\n",
                10.0 + dalpha,
                10.0 + dalpha / 2.0
            ));
        }
    }
    // a hit the library found not approaching the wall (status 1) is logged, not counted
    h.push_str("0,99,50,-0.025,0,10,3,20,20,10,0,1,1,0\n");
    std::fs::write(dir.join("hits_rank0000.csv"), h).unwrap();
}

fn study(root: &Path) {
    std::fs::create_dir_all(root).unwrap();
    std::fs::write(
        root.join("study.tsv"),
        "name\tkind\tdiameter_um\twall\tmodel\tdir\n\
         100um-smooth-paper\tmain\t100\tsmooth\tpaper\truns/a\n\
         100um-iso-paper\tmain\t100\tiso\tpaper\truns/b\n",
    )
    .unwrap();
    write_run(&root.join("runs/a"), 15.0, 1, 0.0);
    write_run(&root.join("runs/b"), 18.0, 3, 2.0);
}

fn rows(path: &Path) -> Vec<HashMap<String, String>> {
    let mut r = csv::Reader::from_path(path).unwrap();
    let header: Vec<String> = r.headers().unwrap().iter().map(String::from).collect();
    r.records()
        .map(|rec| {
            header
                .iter()
                .cloned()
                .zip(rec.unwrap().iter().map(String::from))
                .collect()
        })
        .collect()
}

/// `rebound pipe-stats --study STUDY --out OUT`.
fn pipe_stats(study: &Path, out: &Path) -> Run {
    rebound(&[
        "pipe-stats",
        "--study",
        study.to_str().unwrap(),
        "--out",
        out.to_str().unwrap(),
    ])
}

fn num(r: &HashMap<String, String>, k: &str) -> f64 {
    r[k].parse().unwrap_or_else(|_| panic!("{k} = {:?}", r[k]))
}

#[test]
fn pipe_stats_gives_each_statistic_and_its_error() {
    let d = Dir::new();
    let s = d.path().join("study");
    study(&s);
    let out = d.path().join("out");
    pipe_stats(&s, &out).ok();
    let summary = rows(&out.join("summary.csv"));
    assert_eq!(summary.len(), 2);
    let iso = summary
        .iter()
        .find(|r| r["run"] == "100um-iso-paper")
        .unwrap();
    // every particle the same: the values exactly, no spread between batches
    assert_eq!(num(iso, "collisions_per_m"), 3.0);
    assert_eq!(num(iso, "collisions_per_m_se"), 0.0);
    assert_eq!(num(iso, "mean_ux_m_s"), 18.0);
    assert_eq!(num(iso, "rms_ux_m_s"), 0.0);
    assert_eq!(num(iso, "bottom_half_fraction"), 1.0);
    assert_eq!(num(iso, "mean_height_over_r"), -0.5);
    assert_eq!(num(iso, "mean_alpha_in_deg"), 10.0);
    assert!((num(iso, "mean_alpha_change_deg") - 2.0).abs() < 1e-6);
    assert_eq!(num(iso, "mean_alpha_element_deg"), 11.0);
    // Finnie, p = 1 GPa, ψ = K = 2: 20²/(4e9) (sin 2α − 3 sin² α) m³/kg per hit; 3 hits
    // per metre; over the wall 2πR per metre of pipe; in µm per tonne (×1e9); on the mean
    // wall α = 10°, on the facet struck 11°
    let per_t = |v: f64| 3.0 * v / (2.0 * std::f64::consts::PI * 0.025) * 1e9;
    let finnie = |deg: f64| {
        let a = f64::to_radians(deg);
        400.0 / 4e9 * ((2.0 * a).sin() - 3.0 * a.sin().powi(2))
    };
    for (column, expect) in [
        ("erosion_finnie_mean_wall_um_per_t", per_t(finnie(10.0))),
        ("erosion_finnie_um_per_t", per_t(finnie(11.0))),
    ] {
        let got = num(iso, column);
        assert!(
            (got - expect).abs() < 1e-6 * expect,
            "{column}: {got} vs {expect}"
        );
    }
    // Oka (Hv 1.8 GPa, SiO₂ constants) and DNV (carbon steel), from their library laws at
    // the same angles: 100 µm beads at 20 m/s.
    use roughwall::erosion::{AngleDependency, Dnv, ErosionModel, OkaInput};
    let oka = ErosionModel::Oka(
        OkaInput {
            hardness_gpa: 1.8,
            ..Default::default()
        }
        .resolve(),
    );
    let dnv = ErosionModel::Dnv(Dnv {
        k: 2e-9,
        n: 2.6,
        target_density_kg_m3: 7800.0,
        angle_dependency: AngleDependency::Ductile,
    });
    for (law, name) in [(oka, "oka"), (dnv, "dnv")] {
        for (column, deg) in [
            (format!("erosion_{name}_um_per_t"), 11.0),
            (format!("erosion_{name}_mean_wall_um_per_t"), 10.0),
        ] {
            let expect = per_t(law.volume_per_mass(20.0, f64::to_radians(deg), 1e-4));
            let got = num(iso, &column);
            assert!(
                (got - expect).abs() < 1e-6 * expect,
                "{column}: {got} vs {expect}"
            );
        }
    }
    // concentration: all samples in the lower half, whose share of the area is 1/2
    let prof = rows(&out.join("profiles.csv"));
    let slab = |at: &str| {
        prof.iter()
            .find(|r| {
                r["run"] == "100um-iso-paper"
                    && r["profile"] == "vertical"
                    && r["position_over_r"] == at
            })
            .unwrap()
    };
    let c0 = slab("-0.5");
    assert!((num(c0, "concentration") - 2.0).abs() < 1e-6);
    // along the vertical diameter: 4 of 10 samples in the strip |z| < R/5 of the lower half:
    // a 0.4 R wide rectangle down to y = −√0.96 R, then the circle's cap below it
    let d0 = prof
        .iter()
        .find(|r| {
            r["run"] == "100um-iso-paper"
                && r["profile"] == "vertical_diameter"
                && r["position_over_r"] == "-0.5"
        })
        .unwrap();
    let g = |y: f64| y * (1.0 - y * y).sqrt() + y.asin();
    let yw = 0.96f64.sqrt();
    let area = 0.4 * yw + (g(-yw) - g(-1.0));
    let expect = 0.4 / (area / std::f64::consts::PI);
    let got = num(d0, "concentration");
    assert!((got - expect).abs() < 1e-5 * expect, "{got} vs {expect}");
    // the upper slab has no sample: its velocities are empty, never 0 or NaN
    let c1 = slab("0.5");
    assert_eq!(num(c1, "concentration"), 0.0);
    assert_eq!(c1["ux_mean_m_s"], "");
    assert_eq!(c1["ux_rms_m_s"], "");
    // the paired difference iso − smooth
    let cmp = rows(&out.join("comparisons.csv"));
    let d = cmp
        .iter()
        .find(|r| {
            r["a"] == "100um-iso-paper"
                && r["b"] == "100um-smooth-paper"
                && r["quantity"] == "collisions_per_m"
        })
        .unwrap();
    assert_eq!(num(d, "difference"), 2.0);
    for name in [
        "concentration_100um.svg",
        "velocity_100um.svg",
        "wall_hits_100um.svg",
        "run.toml",
    ] {
        assert!(out.join(name).is_file(), "{name}");
    }
    let text = std::fs::read_to_string(out.join("summary.csv")).unwrap();
    assert!(!text.to_lowercase().contains("nan"));
}

#[test]
fn pipe_stats_refuses_what_is_not_a_study() {
    let d = Dir::new();
    let out = d.path().join("out");
    let missing = d.path().join("nothing");
    pipe_stats(&missing, &out).refused("study.tsv");
    let s = d.path().join("bad");
    std::fs::create_dir_all(&s).unwrap();
    std::fs::write(s.join("study.tsv"), "run,dir\n").unwrap();
    pipe_stats(&s, &out).refused("wrong header");
    // a run whose particles.csv lacks a column
    let s = d.path().join("study");
    study(&s);
    std::fs::write(s.join("runs/b/particles.csv"), "particle_id,n\n0,1\n").unwrap();
    pipe_stats(&s, &out).refused("particles.csv");
    // a run whose hit log is missing: its tallies count rebounds the logs do not hold
    let s = d.path().join("study2");
    study(&s);
    std::fs::remove_file(s.join("runs/a/hits_rank0000.csv")).unwrap();
    pipe_stats(&s, &out).refused("missing or truncated");
    assert!(!out.exists(), "a refused run wrote --out");
}

/// `sensitivity.csv`: a physics switch run on both lays changes the lay ratio
/// (circumferential over axial) by what the runs give, paired: collisions 4/2 in the study,
/// 3/2 with the switch; a study without switches writes the header only.
#[test]
fn pipe_stats_gives_each_switchs_change_of_the_lay_ratio() {
    let d = Dir::new();
    let s = d.path().join("study");
    std::fs::create_dir_all(&s).unwrap();
    std::fs::write(
        s.join("study.tsv"),
        "name\tkind\tdiameter_um\twall\tmodel\tdir\n\
         100um-axial-paper\tmain\t100\taxial\tpaper\truns/a\n\
         100um-circ-paper\tmain\t100\tcirc\tpaper\truns/b\n\
         100um-axial-paper-no-lift\tno-lift\t100\taxial\tpaper\truns/c\n\
         100um-circ-paper-no-lift\tno-lift\t100\tcirc\tpaper\truns/d\n",
    )
    .unwrap();
    write_run(&s.join("runs/a"), 18.0, 2, 1.0);
    write_run(&s.join("runs/b"), 17.0, 4, 2.0);
    write_run(&s.join("runs/c"), 18.0, 2, 1.0);
    write_run(&s.join("runs/d"), 17.0, 3, 2.0);
    let out = d.path().join("out");
    pipe_stats(&s, &out).ok();
    let table = rows(&out.join("sensitivity.csv"));
    let r = table
        .iter()
        .find(|r| r["switch"] == "no-lift" && r["quantity"] == "collisions_per_m")
        .unwrap();
    assert_eq!(num(r, "ratio_study"), 2.0);
    assert_eq!(num(r, "ratio_switch"), 1.5);
    assert_eq!(num(r, "change"), -0.5);
    assert_eq!(num(r, "change_se"), 0.0);
    // The erosion ratios too, one row per law.
    for law in ["finnie", "oka", "dnv"] {
        let q = format!("erosion_{law}_um_per_t");
        assert!(table.iter().any(|r| r["quantity"] == q), "{q}");
    }
    // No switch: the header only.
    let plain = d.path().join("plain");
    study(&plain);
    let out2 = d.path().join("out2");
    pipe_stats(&plain, &out2).ok();
    assert!(rows(&out2.join("sensitivity.csv")).is_empty());
}

/// `costs.csv`: a run's `forces_cost.csv` per particle step (10⁴ particle steps: 3 ms of lift
/// is 300 ns, 1 + 0.5 ms of spin 150 ns, 0.1 s of steps 10 µs, a share of 4.5 %); runs
/// without one are left out, and a study without any writes no `costs.csv`.
#[test]
fn pipe_stats_gives_what_the_forces_cost_per_particle_step() {
    let d = Dir::new();
    let s = d.path().join("study");
    study(&s);
    std::fs::write(
        s.join("runs/b/forces_cost.csv"),
        "particle_steps,lift_s,spin_relax_s,spin_exchange_s,step_s\n10000,0.003,0.001,0.0005,0.1\n",
    )
    .unwrap();
    let out = d.path().join("out");
    pipe_stats(&s, &out).ok();
    let table = rows(&out.join("costs.csv"));
    assert_eq!(table.len(), 1);
    let r = &table[0];
    let close = |k: &str, v: f64| assert!((num(r, k) - v).abs() < 1e-9 * v, "{k}: {}", r[k]);
    close("lift_ns_per_particle_step", 300.0);
    close("spin_ns_per_particle_step", 150.0);
    close("step_ns_per_particle_step", 10000.0);
    close("forces_share", 0.045);
    // A broken file is an error naming it, not a silent row.
    std::fs::write(
        s.join("runs/b/forces_cost.csv"),
        "particle_steps,lift_s,spin_relax_s,spin_exchange_s,step_s\n0,0,0,0,0\n",
    )
    .unwrap();
    pipe_stats(&s, &d.path().join("out2")).refused("forces_cost.csv");
    let plain = d.path().join("plain");
    study(&plain);
    pipe_stats(&plain, &d.path().join("out3")).ok();
    assert!(!d.path().join("out3/costs.csv").exists());
}
