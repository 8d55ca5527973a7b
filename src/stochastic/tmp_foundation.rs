//! TEMPORARY private copies of the lead's foundation interfaces (`crate::angles`,
//! `crate::wall`, `crate::collision`) until "skeleton v1" lands; removed after the merge.
#![allow(dead_code)]
use nalgebra::Vector3;

pub mod angles {
    use nalgebra::Vector3;
    pub fn incident_angles(u: Vector3<f64>) -> (f64, f64) {
        let s = u.norm();
        let alpha = (u.y / s).clamp(-1.0, 1.0).asin();
        let beta = if u.x == 0.0 && u.z == 0.0 {
            0.0
        } else {
            (-u.z).atan2(u.x)
        };
        (alpha, beta)
    }
    pub fn velocity_from_angles(speed: f64, alpha: f64, beta: f64) -> Vector3<f64> {
        let h = speed * alpha.cos();
        Vector3::new(h * beta.cos(), speed * alpha.sin(), -h * beta.sin())
    }
    pub fn wrap_pi(x: f64) -> f64 {
        let mut y = x % (2.0 * std::f64::consts::PI);
        if y <= -std::f64::consts::PI {
            y += 2.0 * std::f64::consts::PI;
        } else if y > std::f64::consts::PI {
            y -= 2.0 * std::f64::consts::PI;
        }
        y
    }
    pub fn normal_from_gamma(gamma: f64, gamma_star: f64, beta_in: f64) -> Vector3<f64> {
        let (sb, cb) = beta_in.sin_cos();
        let xi = cb * gamma + sb * gamma_star;
        let zeta = -sb * gamma + cb * gamma_star;
        let nx = -xi.sin();
        let nz = -zeta.sin();
        let ny2 = 1.0 - nx * nx - nz * nz;
        let n = Vector3::new(nx, ny2.max(0.0).sqrt(), nz);
        n / n.norm()
    }
    pub fn gamma_from_normal(n: Vector3<f64>, beta_in: f64) -> (f64, f64) {
        let xi = n.x.clamp(-1.0, 1.0).acos() - std::f64::consts::FRAC_PI_2;
        let zeta = n.z.clamp(-1.0, 1.0).acos() - std::f64::consts::FRAC_PI_2;
        let (sb, cb) = beta_in.sin_cos();
        (cb * xi - sb * zeta, sb * xi + cb * zeta)
    }
}

pub mod wall {
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct Deviations {
        pub delta_xi: f64,
        pub delta_zeta: f64,
    }
    #[derive(Clone, Copy, Debug)]
    pub struct Moments {
        pub var_a: f64,
        pub var_b: f64,
        pub cov: f64,
    }
    pub fn deviation_from_surface(h: f64, c_l: f64) -> f64 {
        std::f64::consts::SQRT_2 * h / c_l
    }
    pub fn rotated_moments(dev: &Deviations, beta: f64) -> Moments {
        let (s, c) = beta.sin_cos();
        let (x2, z2) = (dev.delta_xi.powi(2), dev.delta_zeta.powi(2));
        Moments {
            var_a: c * c * x2 + s * s * z2,
            var_b: s * s * x2 + c * c * z2,
            cov: s * c * (x2 - z2),
        }
    }
    pub fn conditional_gamma_star(m: &Moments, gamma: f64) -> (f64, f64) {
        if m.var_a > 0.0 {
            (
                m.cov / m.var_a * gamma,
                (m.var_b - m.cov * m.cov / m.var_a).max(0.0),
            )
        } else {
            (0.0, m.var_b.max(0.0))
        }
    }
    pub fn delta_gamma(dev: &Deviations, beta: f64) -> f64 {
        rotated_moments(dev, beta).var_a.max(0.0).sqrt()
    }
}

pub mod collision {
    use nalgebra::Vector3;
    #[derive(Clone, Copy, Debug)]
    pub struct ShParams {
        pub e_h: f64,
        pub alpha_e: f64,
        pub mu_0: f64,
        pub mu_h: f64,
        pub alpha_mu: f64,
    }
    impl ShParams {
        pub fn glass_steel() -> Self {
            Self {
                e_h: 0.72,
                alpha_e: 20.6_f64.to_radians(),
                mu_0: 0.5,
                mu_h: 0.115,
                alpha_mu: 22_f64.to_radians(),
            }
        }
    }
    #[derive(Clone, Copy, Debug)]
    pub enum CollisionLaw {
        Elastic,
        SommerfeldHuber(ShParams),
    }
    impl CollisionLaw {
        pub fn collide(
            &self,
            u: Vector3<f64>,
            omega: Vector3<f64>,
            n: Vector3<f64>,
            d: f64,
        ) -> (Vector3<f64>, Vector3<f64>) {
            let vn = u.dot(&n);
            match self {
                CollisionLaw::Elastic => (u - 2.0 * vn * n, omega),
                CollisionLaw::SommerfeldHuber(p) => {
                    let theta = (-vn / u.norm()).clamp(-1.0, 1.0).asin();
                    let e = if theta <= p.alpha_e {
                        1.0 + (p.e_h - 1.0) / p.alpha_e * theta
                    } else {
                        p.e_h
                    };
                    let mu = if theta <= p.alpha_mu {
                        p.mu_0 + (p.mu_h - p.mu_0) / p.alpha_mu * theta
                    } else {
                        p.mu_h
                    };
                    let ut = u - vn * n;
                    let wxn = omega.cross(&n);
                    let slip = ut - 0.5 * d * wxn;
                    let s = slip.norm();
                    let vn_out = -e * vn;
                    if -vn * 3.5 * mu * (1.0 + e) > s {
                        let ut_out = 5.0 / 7.0 * (ut + d / 5.0 * wxn);
                        let w_out = omega.dot(&n) * n + 2.0 / d * n.cross(&ut_out);
                        (ut_out + vn_out * n, w_out)
                    } else {
                        let eps = slip / s;
                        let ut_out = ut + mu * (1.0 + e) * vn * eps;
                        let w_out = omega - 5.0 * mu * (1.0 + e) * vn / d * n.cross(&eps);
                        (ut_out + vn_out * n, w_out)
                    }
                }
            }
        }
    }
    pub fn _unused(_: Vector3<f64>) {}
}
pub fn _unused(_: Vector3<f64>) {}
