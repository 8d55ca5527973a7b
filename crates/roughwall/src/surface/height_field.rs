//! The periodic height field and its triangulation, shared by the surface
//! statistics (Radenkovic & Simonin 2021, Sec. 2.2, Table 1) and the deterministic
//! particle-centre tracker (Sec. 3.1), so both see the very same triangles.

/// A periodic height field on an `nx × nz` grid of spacings `dx`, `dz` (metres).
///
/// Heights are in metres, row-major with `x` fastest: `heights[iz * nx + ix]`.
/// Node `(ix, iz)` sits at `(ix·dx, iz·dz)`; the field repeats with periods
/// `nx·dx` and `nz·dz`. 2-D roughness (constant along `z`) may use `nz = 1`.
#[derive(Clone, Debug, PartialEq)]
pub struct HeightField {
    /// Nodes along `x`.
    pub nx: usize,
    /// Nodes along `z` (1 for a 2-D surface constant along `z`).
    pub nz: usize,
    /// Grid spacing along `x` (m).
    pub dx: f64,
    /// Grid spacing along `z` (m).
    pub dz: f64,
    /// Heights `y` of the nodes (m), row-major with `x` fastest: `heights[iz * nx + ix]`;
    /// `nx · nz` of them.
    pub heights: Vec<f64>,
    /// Which diagonal splits each cell into its two triangles.
    pub triangulation: Triangulation,
}

/// How every grid cell is split into two triangles (docs/physics.md §5: "two triangles a
/// cell"; the notes and the papers do not say along which diagonal).
///
/// `Alternating` (the default) splits the cells with `ix + iz` even along the diagonal from
/// node `(ix, iz)` to `(ix+1, iz+1)` and the others along the diagonal from `(ix+1, iz)` to
/// `(ix, iz+1)` (a checkerboard): mirroring the grid in `x` or `z` maps it onto itself,
/// shifted by one cell, when the node counts are even, so the wall keeps the mirror symmetry
/// `β⁻ → −β⁻` of the statistics it was generated with. `Uniform` splits every cell along the
/// first diagonal (the earlier default; CHANGELOG): that pairs each facet's two slopes
/// the same way everywhere and gives an isotropic wall a systematic asymmetry (mean α⁺
/// 0.08–0.15° higher at β⁻ = +30°…+60° than at −30°…−60° on the (5°, 5°) wall, 2–4 standard
/// errors over 8 surfaces; docs/models.md, "The triangulation and mirror symmetry").
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Triangulation {
    /// The diagonal alternates between neighbouring cells (checkerboard; the default).
    #[default]
    Alternating,
    /// Every cell split along the diagonal `(ix, iz)`–`(ix+1, iz+1)`.
    Uniform,
}

impl Triangulation {
    /// The case-file spellings, in the order the error messages list them.
    pub const NAMES: [&'static str; 2] = ["alternating", "uniform"];

    /// The case-file spelling.
    pub fn name(self) -> &'static str {
        match self {
            Triangulation::Uniform => "uniform",
            Triangulation::Alternating => "alternating",
        }
    }

    /// Parses a case-file spelling.
    pub fn from_name(s: &str) -> Option<Self> {
        match s {
            "uniform" => Some(Triangulation::Uniform),
            "alternating" => Some(Triangulation::Alternating),
            _ => None,
        }
    }
}

impl HeightField {
    /// Height at node `(ix, iz)`, indices taken modulo the grid (periodic wall).
    #[inline]
    pub fn at(&self, ix: usize, iz: usize) -> f64 {
        self.heights[(iz % self.nz) * self.nx + (ix % self.nx)]
    }

    /// Period along `x` (m).
    pub fn length_x(&self) -> f64 {
        self.nx as f64 * self.dx
    }

    /// Period along `z` (m).
    pub fn length_z(&self) -> f64 {
        self.nz as f64 * self.dz
    }

    /// Highest node (m): above it no triangle can be hit.
    pub fn max_height(&self) -> f64 {
        self.heights
            .iter()
            .copied()
            .fold(f64::NEG_INFINITY, f64::max)
    }

    /// Whether cell `(ix, iz)` (indices modulo the grid) is split along the other
    /// diagonal, from node `(ix+1, iz)` to `(ix, iz+1)` ([`Triangulation`]).
    #[inline]
    pub fn flipped(&self, ix: usize, iz: usize) -> bool {
        self.triangulation == Triangulation::Alternating
            && ((ix % self.nx) + (iz % self.nz)) % 2 == 1
    }

    /// A warning when the alternating split cannot close over the periodic seam: with an
    /// odd node count along an axis, the last and the first cells of a row share a
    /// diagonal, so the wall is mirror symmetric only up to that one line of cells
    /// ([`Triangulation`]). The automatic grid always has an even count (8 × 5-smooth).
    pub fn triangulation_seam(&self) -> Option<crate::warning::Warning> {
        if self.triangulation != Triangulation::Alternating {
            return None;
        }
        let odd: Vec<String> = [("nx", self.nx), ("nz", self.nz)]
            .into_iter()
            .filter(|&(_, n)| n > 1 && n % 2 == 1)
            .map(|(k, n)| format!("{k} = {n}"))
            .collect();
        (!odd.is_empty()).then(|| {
            crate::warning::Warning(format!(
                "the surface has an odd node count ({}): the alternating triangulation repeats a diagonal at the periodic seam, so the wall is mirror symmetric only up to that one line of cells; an even count closes it",
                odd.join(", ")
            ))
        })
    }

    /// Unnormalised upward normals of the two triangles of cell `(ix, iz)`.
    ///
    /// Along the diagonal from node `(ix, iz)` to `(ix+1, iz+1)`: triangle 0 is
    /// `(00, 10, 11)` (below the diagonal, where the local coordinate `s_x ≥ s_z`),
    /// triangle 1 is `(00, 11, 01)` (`s_z > s_x`). In a [`flipped`](Self::flipped) cell the
    /// cell is seen mirrored in `x` (`u = 1 − s_x`), so the diagonal from `(ix+1, iz)` to
    /// `(ix, iz+1)` is `u = s_z`: triangle 0 is `(10, 00, 01)` (`u ≥ s_z`), triangle 1
    /// `(10, 01, 11)`. The `x`-slopes of the two triangles are the same edges either way;
    /// the `z`-slopes trade places. For `y = f(x, z)` the normal is `(−∂f/∂x, 1, −∂f/∂z)`
    /// (docs/physics.md §1).
    #[inline]
    pub fn cell_normals(&self, ix: usize, iz: usize) -> [[f64; 3]; 2] {
        let h00 = self.at(ix, iz);
        let h10 = self.at(ix + 1, iz);
        let h01 = self.at(ix, iz + 1);
        let h11 = self.at(ix + 1, iz + 1);
        // Triangle 0: slopes from the edges 00→10 (x) and 10→11 (z); flipped: 00→01 (z).
        // Triangle 1: slopes from the edges 01→11 (x) and 00→01 (z); flipped: 10→11 (z).
        let (gz0, gz1) = if self.flipped(ix, iz) {
            (h01 - h00, h11 - h10)
        } else {
            (h11 - h10, h01 - h00)
        };
        let t0 = [-(h10 - h00) / self.dx, 1.0, -gz0 / self.dz];
        let t1 = [-(h11 - h01) / self.dx, 1.0, -gz1 / self.dz];
        [t0, t1]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn plane_has_the_plane_normal_in_both_triangles() {
        // f = 0.1 x − 0.2 z on a periodic grid is not periodic, so test one interior cell.
        let (nx, nz, dx, dz) = (4, 4, 0.5, 0.25);
        let mut heights = vec![0.0; nx * nz];
        for iz in 0..nz {
            for ix in 0..nx {
                heights[iz * nx + ix] = 0.1 * ix as f64 * dx - 0.2 * iz as f64 * dz;
            }
        }
        let f = HeightField {
            nx,
            nz,
            dx,
            dz,
            heights,
            triangulation: Default::default(),
        };
        for triangulation in [Triangulation::Alternating, Triangulation::Uniform] {
            let f = HeightField {
                triangulation,
                ..f.clone()
            };
            for (ix, iz) in [(1, 1), (1, 2), (2, 1)] {
                assert_eq!(
                    f.flipped(ix, iz),
                    triangulation == Triangulation::Alternating && ix + iz == 3
                );
                for t in f.cell_normals(ix, iz) {
                    assert!((t[0] + 0.1).abs() < 1e-12 && (t[2] - 0.2).abs() < 1e-12);
                }
            }
        }
    }

    #[test]
    fn an_odd_node_count_warns_only_for_the_alternating_split() {
        let f = |nx: usize, nz: usize, triangulation| HeightField {
            nx,
            nz,
            dx: 1.0,
            dz: 1.0,
            heights: vec![0.0; nx * nz],
            triangulation,
        };
        assert!(f(8, 6, Triangulation::Alternating)
            .triangulation_seam()
            .is_none());
        assert!(f(8, 1, Triangulation::Alternating)
            .triangulation_seam()
            .is_none());
        assert!(f(7, 5, Triangulation::Uniform)
            .triangulation_seam()
            .is_none());
        let w = f(8, 5, Triangulation::Alternating)
            .triangulation_seam()
            .unwrap();
        assert!(w.0.contains("nz = 5") && !w.0.contains("nx"), "{}", w.0);
    }
}
