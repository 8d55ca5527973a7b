//! Erosion of the wall by the impacts a rebound model produces: the volume of wall material
//! one impact removes, from the particle's mass, its speed and its impact angle to the *local*
//! wall element (the facet hit, or the virtual wall sampled), by one of three laws:
//!
//! * [`finnie`]: Finnie (1960), ductile micro-cutting, in OpenFOAM's form;
//! * [`dnv`]: DNV RP-O501, as implemented in Equinor's `pysand`;
//! * [`oka`]: Oka, Okamura & Yoshida (2005).
//!
//! "Model only what a scene needs": a case without `[erosion]` computes none of it.

pub mod dnv;
pub mod finnie;
pub mod oka;

/// An erosion law with its parameters (SI units).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ErosionModel {
    Finnie(finnie::Finnie),
    Dnv(dnv::Dnv),
    Oka(oka::Oka),
}

impl ErosionModel {
    /// Wall volume (m³) removed per kilogram of particles striking at `speed` (m/s) and
    /// impact angle `alpha` (rad, between the velocity and the local wall plane, in
    /// `[0, π/2]`), for particles of diameter `diameter_m`. Zero for a zero speed; never NaN.
    #[inline]
    pub fn volume_per_mass(&self, speed: f64, alpha: f64, diameter_m: f64) -> f64 {
        if !(speed > 0.0 && speed.is_finite() && alpha.is_finite()) {
            return 0.0;
        }
        let alpha = alpha.clamp(0.0, std::f64::consts::FRAC_PI_2);
        let v = match self {
            ErosionModel::Finnie(m) => m.volume_per_mass(speed, alpha),
            ErosionModel::Dnv(m) => m.volume_per_mass(speed, alpha),
            ErosionModel::Oka(m) => m.volume_per_mass(speed, alpha, diameter_m),
        };
        if v.is_finite() {
            v.max(0.0)
        } else {
            0.0
        }
    }

    /// The model's name in case files.
    pub fn name(&self) -> &'static str {
        match self {
            ErosionModel::Finnie(_) => "finnie",
            ErosionModel::Dnv(_) => "dnv",
            ErosionModel::Oka(_) => "oka",
        }
    }
}

/// What a run needs to tally erosion: the law and the particle mass (for the volume per
/// particle).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ErosionSetup {
    pub model: ErosionModel,
    pub particle_mass_kg: f64,
    /// Particle diameter (m), for laws with a size effect (Oka).
    pub diameter_m: f64,
}

impl ErosionSetup {
    /// The local impact angle (rad, to the element of unit normal `n`) of velocity `u`
    /// and the wall volume per unit particle mass (m³/kg) that impact removes.
    #[inline]
    pub fn impact(&self, u: &nalgebra::Vector3<f64>, n: &nalgebra::Vector3<f64>) -> (f64, f64) {
        let (alpha, speed) = impact(u, n);
        (
            alpha,
            self.model.volume_per_mass(speed, alpha, self.diameter_m),
        )
    }
}

impl ErosionSetup {
    /// The resolved law for `run.toml`: the model, every parameter (defaults filled in, SI
    /// units) and the particle mass.
    pub fn manifest(&self) -> toml::Value {
        let mut t = toml::Table::new();
        let mut put = |k: &str, v: f64| {
            t.insert(k.into(), toml::Value::Float(v));
        };
        match &self.model {
            ErosionModel::Finnie(f) => {
                put("flow_stress_pa", f.flow_stress_pa);
                put("psi", f.psi);
                put("k", f.k);
            }
            ErosionModel::Dnv(d) => {
                put("k", d.k);
                put("n", d.n);
                put("target_density_kg_m3", d.target_density_kg_m3);
            }
            ErosionModel::Oka(o) => {
                put("hardness_gpa", o.hardness_gpa);
                put("k", o.k);
                put("k1", o.k1);
                put("k2", o.k2);
                put("k3", o.k3);
                put("n1", o.n1);
                put("n2", o.n2);
                put("reference_speed_m_s", o.reference_speed_m_s);
                put("reference_diameter_m", o.reference_diameter_m);
            }
        }
        put("particle_mass_kg", self.particle_mass_kg);
        if let ErosionModel::Dnv(d) = &self.model {
            let a = match d.angle_dependency {
                dnv::AngleDependency::Ductile => "ductile",
                dnv::AngleDependency::Brittle => "brittle",
            };
            t.insert("angle_dependency".into(), toml::Value::String(a.into()));
        }
        t.insert(
            "model".into(),
            toml::Value::String(self.model.name().into()),
        );
        toml::Value::Table(t)
    }
}

/// The impact angle (rad, to the local wall plane, in `[0, π/2]`) and speed of a velocity
/// `u` arriving on a wall element of unit normal `n` (pointing into the flow).
#[inline]
pub fn impact(u: &nalgebra::Vector3<f64>, n: &nalgebra::Vector3<f64>) -> (f64, f64) {
    let speed = u.norm();
    if speed.is_nan() || speed <= 0.0 {
        return (0.0, 0.0);
    }
    ((-u.dot(n) / speed).clamp(0.0, 1.0).asin(), speed)
}

#[cfg(test)]
mod tests {
    use super::*;
    use nalgebra::Vector3;

    #[test]
    fn impact_angle_is_to_the_local_plane() {
        let n = Vector3::new(0.0, 1.0, 0.0);
        let (a, s) = impact(&Vector3::new(1.0, -1.0, 0.0), &n);
        assert!((a - std::f64::consts::FRAC_PI_4).abs() < 1e-15 && (s - 2f64.sqrt()).abs() < 1e-15);
        assert_eq!(
            impact(&Vector3::new(0.0, -3.0, 0.0), &n).0,
            std::f64::consts::FRAC_PI_2
        );
        assert_eq!(impact(&Vector3::zeros(), &n), (0.0, 0.0));
        // Leaving the element: no impact angle below zero.
        assert_eq!(impact(&Vector3::new(1.0, 1.0, 0.0), &n).0, 0.0);
    }
}
