//! Finnie's ductile erosion (I. Finnie, *Erosion of surfaces by solid particles*, Wear 3 (1960)
//! 87–103), in the form OpenFOAM's `particleErosion` cloud function implements (Qian et al.
//! 2022 couple the same law; docs/physics.md §8 gives its angle function for K = 2):
//!
//! `V = m|U|²/(p ψ K) · (sin 2α − (6/K) sin²α)` for `tan α < K/6`, and
//! `V = m|U|²/(p ψ K) · K cos²α / 6` otherwise,
//!
//! with `m` the particle mass, `U` its velocity at impact, `α` the impact angle to the wall,
//! `p` the flow stress of the wall material, `ψ` the ratio of the contact depth to the cut
//! depth and `K` the ratio of the vertical to the horizontal force component.

/// Finnie's law with OpenFOAM's parameters.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Finnie {
    /// Flow stress `p` of the wall material (Pa).
    pub flow_stress_pa: f64,
    /// `ψ`: contact depth over cut depth (OpenFOAM's default 2).
    pub psi: f64,
    /// `K`: vertical over horizontal force component (OpenFOAM's default 2).
    pub k: f64,
}

impl Finnie {
    /// The angle function `f(α)` of Finnie (1960): `sin 2α − (6/K) sin²α` below
    /// `tan α = K/6`, `K cos²α / 6` above (continuous at the branch point).
    #[inline]
    pub fn angle_function(&self, alpha: f64) -> f64 {
        let (s, c) = alpha.sin_cos();
        self.angle_function_sc(s, c)
    }

    /// [`Finnie::angle_function`] of `sin α`, `cos α` (`α` in `[0, π/2]`): a run has them
    /// from the impact velocity without trigonometry, and `cos α` is exactly 0 at normal
    /// incidence.
    #[inline]
    pub fn angle_function_sc(&self, s: f64, c: f64) -> f64 {
        if s < self.k / 6.0 * c {
            2.0 * s * c - 6.0 / self.k * s * s
        } else {
            self.k * c * c / 6.0
        }
    }

    /// Volume removed per unit particle mass (m³/kg): `|U|²/(p ψ K) · f(α)`.
    #[inline]
    pub fn volume_per_mass(&self, speed: f64, alpha: f64) -> f64 {
        let (s, c) = alpha.sin_cos();
        self.volume_per_mass_sc(speed, s, c)
    }

    /// [`Finnie::volume_per_mass`] of `sin α`, `cos α`.
    #[inline]
    pub fn volume_per_mass_sc(&self, speed: f64, s: f64, c: f64) -> f64 {
        speed * speed / (self.flow_stress_pa * self.psi * self.k) * self.angle_function_sc(s, c)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const F: Finnie = Finnie {
        flow_stress_pa: 5e8,
        psi: 2.0,
        k: 2.0,
    };

    #[test]
    fn branches_meet_at_tan_alpha_k_over_6() {
        let a0 = (F.k / 6.0).atan();
        let below = 2.0 * a0.sin() * a0.cos() - 6.0 / F.k * a0.sin().powi(2);
        let above = F.k * a0.cos().powi(2) / 6.0;
        assert!((below - above).abs() < 1e-15);
        for eps in [1e-9, 1e-12] {
            let l = F.angle_function(a0 - eps);
            let r = F.angle_function(a0 + eps);
            assert!((l - r).abs() < 1e-8, "{l} {r}");
        }
    }

    #[test]
    fn limits_and_the_physics_md_form() {
        // Grazing: nothing; normal incidence: K cos²α/6 = 0 (no cutting).
        assert_eq!(F.angle_function(0.0), 0.0);
        assert!(F.angle_function(std::f64::consts::FRAC_PI_2).abs() < 1e-16);
        // docs/physics.md §8 writes Finnie's classic f(γ) = sin 2γ − 3 sin²γ (tan γ ≤ 1/3),
        // cos²γ/3 above: the law at K = 2.
        let a = 0.2_f64;
        assert!((F.angle_function(a) - (2.0 * a).sin() + 3.0 * a.sin().powi(2)).abs() < 1e-15);
        let b = 1.0_f64;
        assert!((F.angle_function(b) - b.cos().powi(2) / 3.0).abs() < 1e-15);
        // Volume ∝ U².
        let v1 = F.volume_per_mass(10.0, 0.3);
        assert!((F.volume_per_mass(20.0, 0.3) / v1 - 4.0).abs() < 1e-12);
    }
}
