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
    pub nx: usize,
    pub nz: usize,
    pub dx: f64,
    pub dz: f64,
    pub heights: Vec<f64>,
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

    /// Unnormalised upward normals of the two triangles of cell `(ix, iz)`.
    ///
    /// Triangulation convention: the diagonal runs from node `(ix, iz)` to node
    /// `(ix+1, iz+1)`. Triangle 0 is `(00, 10, 11)` (below the diagonal, where the
    /// local coordinate `s_x ≥ s_z`), triangle 1 is `(00, 11, 01)` (`s_z > s_x`).
    /// For `y = f(x, z)` the normal is `(−∂f/∂x, 1, −∂f/∂z)` (physics notes §1).
    #[inline]
    pub fn cell_normals(&self, ix: usize, iz: usize) -> [[f64; 3]; 2] {
        let h00 = self.at(ix, iz);
        let h10 = self.at(ix + 1, iz);
        let h01 = self.at(ix, iz + 1);
        let h11 = self.at(ix + 1, iz + 1);
        // Triangle 0: slopes from the edges 00→10 (x) and 10→11 (z).
        let t0 = [-(h10 - h00) / self.dx, 1.0, -(h11 - h10) / self.dz];
        // Triangle 1: slopes from the edges 01→11 (x) and 00→01 (z).
        let t1 = [-(h11 - h01) / self.dx, 1.0, -(h01 - h00) / self.dz];
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
        };
        for t in f.cell_normals(1, 1) {
            assert!((t[0] + 0.1).abs() < 1e-12 && (t[2] - 0.2).abs() < 1e-12);
        }
    }
}
