//! The height-field file written by `rebound surface --heights FILE` and read back by
//! `rebound deterministic --surface FILE`.
//!
//! Format (all little-endian, 40-byte header, then the heights):
//!
//! | offset | type | content |
//! | --- | --- | --- |
//! | 0 | 4 bytes | magic `RBHF` |
//! | 4 | u32 | version = 1 |
//! | 8 | u64 | `nx` (nodes along `x`) |
//! | 16 | u64 | `nz` (nodes along `z`; 1 for a surface constant along `z`) |
//! | 24 | f64 | `dx` grid spacing along `x` (m) |
//! | 32 | f64 | `dz` grid spacing along `z` (m) |
//! | 40 | `nx·nz` × f32 | heights (m), row-major with `x` fastest: `h[iz·nx + ix]` |
//!
//! The field is periodic with periods `nx·dx` and `nz·dz` (see [`HeightField`]). Heights
//! are stored as f32 (relative precision 6·10⁻⁸, far below any roughness scale) to halve
//! the file; reading converts them back to f64 exactly as stored.

use crate::error::{Error, Result};
use crate::surface::HeightField;
use std::io::{Read, Write};
use std::path::Path;

/// File magic.
pub const MAGIC: [u8; 4] = *b"RBHF";
/// Current format version.
pub const VERSION: u32 = 1;

/// Whether `path` starts like a height file of `rebound surface --heights` (its [`MAGIC`]):
/// what tells such a file from a measured scan.
pub fn is_height_file(path: &Path) -> bool {
    let mut magic = [0u8; 4];
    std::fs::File::open(path)
        .and_then(|mut f| f.read_exact(&mut magic))
        .is_ok_and(|_| magic == MAGIC)
}
/// Header length in bytes.
pub const HEADER_LEN: usize = 40;

/// Writes `f` in this format to `w` (the application writes it through a temporary file and
/// a rename, so that nothing half-written is ever left under the final name).
pub fn write_heights(w: &mut impl Write, f: &HeightField) -> std::io::Result<()> {
    w.write_all(&header(f))?;
    let mut buf = Vec::with_capacity(4 * 65536);
    for chunk in f.heights.chunks(65536) {
        buf.clear();
        for &h in chunk {
            buf.extend_from_slice(&(h as f32).to_le_bytes());
        }
        w.write_all(&buf)?;
    }
    Ok(())
}

fn header(f: &HeightField) -> [u8; HEADER_LEN] {
    let mut h = [0u8; HEADER_LEN];
    h[0..4].copy_from_slice(&MAGIC);
    h[4..8].copy_from_slice(&VERSION.to_le_bytes());
    h[8..16].copy_from_slice(&(f.nx as u64).to_le_bytes());
    h[16..24].copy_from_slice(&(f.nz as u64).to_le_bytes());
    h[24..32].copy_from_slice(&f.dx.to_le_bytes());
    h[32..40].copy_from_slice(&f.dz.to_le_bytes());
    h
}

/// Largest grid accepted when reading (nodes in total): 40 000² as for generated
/// surfaces, so that a corrupt header cannot ask for absurd amounts of memory.
pub const MAX_NODES: u64 = 40_000 * 40_000;

/// Grid spacings a height file may have (m).
const MIN_SPACING_M: f64 = 1e-12;
const MAX_SPACING_M: f64 = 1e3;
/// Largest height a height file may hold (m): a rough wall, not a mountain range.
const MAX_HEIGHT_M: f64 = 1.0;

/// Reads a height field written by [`write_heights`]. Every problem — missing file,
/// foreign file, unknown version, impossible sizes or spacings, truncated or
/// over-long data, non-finite heights — is an `Error::Input` naming the file.
pub fn read_heights(path: &Path) -> Result<HeightField> {
    let bad = |what: String| Error::Input(format!("{}: {what}", path.display()));
    let mut file =
        std::fs::File::open(path).map_err(|e| bad(format!("cannot open the height file: {e}")))?;
    let len = file
        .metadata()
        .map_err(|e| bad(format!("cannot read the height file: {e}")))?
        .len();
    let mut h = [0u8; HEADER_LEN];
    if len < HEADER_LEN as u64 {
        return Err(bad(format!(
            "not a rebound height file (only {len} bytes; the header alone has {HEADER_LEN})"
        )));
    }
    file.read_exact(&mut h)
        .map_err(|e| bad(format!("cannot read the header: {e}")))?;
    if h[0..4] != MAGIC {
        return Err(bad(
            "not a rebound height file (magic is not `RBHF`; write one with `rebound surface --heights FILE`)"
                .into(),
        ));
    }
    let u64_at = |o: usize| u64::from_le_bytes(h[o..o + 8].try_into().unwrap_or([0; 8]));
    let f64_at = |o: usize| f64::from_le_bytes(h[o..o + 8].try_into().unwrap_or([0; 8]));
    let version = u32::from_le_bytes([h[4], h[5], h[6], h[7]]);
    if version != VERSION {
        return Err(bad(format!(
            "height file version {version} is not supported (this rebound reads version {VERSION})"
        )));
    }
    let (nx, nz, dx, dz) = (u64_at(8), u64_at(16), f64_at(24), f64_at(32));
    if nx == 0 || nz == 0 || nx.saturating_mul(nz) > MAX_NODES {
        return Err(bad(format!(
            "invalid grid {nx} × {nz}: allowed 1 to {MAX_NODES} nodes in total"
        )));
    }
    // A rough wall's grid: spacings from a picometre to a kilometre.
    for (name, d) in [("dx", dx), ("dz", dz)] {
        if !(d.is_finite() && (MIN_SPACING_M..=MAX_SPACING_M).contains(&d)) {
            return Err(bad(format!(
                "invalid spacing {name} = {d}: allowed {MIN_SPACING_M} to {MAX_SPACING_M} metres"
            )));
        }
    }
    let count = nx * nz;
    // Heights in f64, and the tracker's tile map beside them.
    let need = count.saturating_mul(9);
    if let Some(avail) = crate::memory::available_bytes().filter(|&a| need > a) {
        return Err(bad(format!(
            "a {nx} × {nz} height field needs {}, the process may use {} (the least of the address-space limit, the cgroup limit and the free memory)",
            crate::memory::human(need),
            crate::memory::human(avail)
        )));
    }
    let expected = HEADER_LEN as u64 + 4 * count;
    if len != expected {
        let what = if len < expected {
            "truncated"
        } else {
            "has trailing bytes"
        };
        return Err(bad(format!(
            "{what}: {len} bytes, but a {nx} × {nz} grid needs {expected}"
        )));
    }
    let count = count as usize;
    let mut heights = Vec::with_capacity(count);
    let mut buf = vec![0u8; 4 * 65536];
    let mut left = count;
    while left > 0 {
        let take = left.min(65536);
        let bytes = &mut buf[..4 * take];
        file.read_exact(bytes)
            .map_err(|e| bad(format!("cannot read the heights: {e}")))?;
        for b in bytes.chunks_exact(4) {
            let v = f32::from_le_bytes([b[0], b[1], b[2], b[3]]);
            if !(v.is_finite() && (v as f64).abs() <= MAX_HEIGHT_M) {
                let i = heights.len();
                return Err(bad(format!(
                    "height at node (ix = {}, iz = {}), byte offset {}, is {v}: allowed finite heights within ±{MAX_HEIGHT_M} m",
                    i % nx as usize,
                    i / nx as usize,
                    HEADER_LEN + 4 * i
                )));
            }
            heights.push(v as f64);
        }
        left -= take;
    }
    Ok(HeightField {
        nx: nx as usize,
        nz: nz as usize,
        dx,
        dz,
        heights,
        triangulation: Default::default(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sample() -> HeightField {
        HeightField {
            nx: 5,
            nz: 3,
            dx: 1e-6,
            dz: 2e-6,
            heights: (0..15).map(|i| (i as f64 - 7.0) * 1.25e-7).collect(),
            triangulation: Default::default(),
        }
    }

    fn bytes_of(f: &HeightField) -> Vec<u8> {
        let mut v = Vec::new();
        write_heights(&mut v, f).unwrap();
        v
    }

    #[test]
    fn round_trip_is_exact_for_f32_heights() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("h.rbhf");
        let f = sample();
        std::fs::write(&p, bytes_of(&f)).unwrap();
        assert_eq!(std::fs::metadata(&p).unwrap().len(), 40 + 15 * 4);
        let g = read_heights(&p).unwrap();
        assert_eq!((g.nx, g.nz, g.dx, g.dz), (5, 3, 1e-6, 2e-6));
        for (a, b) in f.heights.iter().zip(&g.heights) {
            assert_eq!(*b, *a as f32 as f64);
        }
        // The header layout is the documented one.
        let bytes = std::fs::read(&p).unwrap();
        assert_eq!(&bytes[0..4], b"RBHF");
        assert_eq!(u32::from_le_bytes(bytes[4..8].try_into().unwrap()), 1);
        assert_eq!(u64::from_le_bytes(bytes[8..16].try_into().unwrap()), 5);
        assert_eq!(u64::from_le_bytes(bytes[16..24].try_into().unwrap()), 3);
        assert_eq!(f64::from_le_bytes(bytes[32..40].try_into().unwrap()), 2e-6);
        let h0 = f32::from_le_bytes(bytes[40..44].try_into().unwrap());
        assert_eq!(h0, (-7.0 * 1.25e-7) as f32);
    }

    #[test]
    fn bad_files_are_input_errors_naming_the_file() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("h.rbhf");
        std::fs::write(&p, bytes_of(&sample())).unwrap();
        let good = std::fs::read(&p).unwrap();
        let check = |bytes: &[u8], needle: &str| {
            let q = dir.path().join("bad.rbhf");
            std::fs::write(&q, bytes).unwrap();
            match read_heights(&q) {
                Err(Error::Input(m)) => {
                    assert!(m.contains("bad.rbhf") && m.contains(needle), "{m}")
                }
                other => panic!("expected an input error, got {other:?}"),
            }
        };
        check(&good[..good.len() - 1], "truncated");
        check(&good[..20], "not a rebound height file");
        let mut longer = good.clone();
        longer.push(0);
        check(&longer, "trailing");
        let mut foreign = good.clone();
        foreign[0..4].copy_from_slice(b"\x89PNG");
        check(&foreign, "magic");
        let mut v2 = good.clone();
        v2[4] = 2;
        check(&v2, "version 2");
        let mut zero = good.clone();
        zero[8..16].copy_from_slice(&0u64.to_le_bytes());
        check(&zero, "invalid grid");
        let mut huge = good.clone();
        huge[8..16].copy_from_slice(&u64::MAX.to_le_bytes());
        check(&huge, "invalid grid");
        let mut dx = good.clone();
        dx[24..32].copy_from_slice(&(-1.0f64).to_le_bytes());
        check(&dx, "dx");
        let mut nan = good.clone();
        nan[44..48].copy_from_slice(&f32::NAN.to_le_bytes());
        check(&nan, "ix = 1, iz = 0");
        match read_heights(&dir.path().join("missing.rbhf")) {
            Err(Error::Input(m)) => assert!(m.contains("missing.rbhf")),
            other => panic!("{other:?}"),
        }
    }
}
