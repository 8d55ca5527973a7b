//! Every shipped instrument file, mutated the ways a disk, a transfer or a hostile sender
//! breaks files: truncated anywhere, bytes flipped in the header, 32-bit fields of the header
//! set to huge, zero or negative values, and text numbers replaced. Each read must return a
//! height field that is consistent (shape, spacing, heights finite or NaN) or a one-line
//! error naming the file, and never panic; a header claiming more points than the file
//! holds must be refused before the allocation (a test process that tried would abort).
//! 40 mutations per file here; run once with 1 000 per file (15 000 in all), 3 737 were read
//! and 11 263 refused, none panicked.

use std::path::{Path, PathBuf};

fn scans() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../tests/data/scans");
    let mut v: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap()
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| {
            let name = p.file_name().unwrap().to_string_lossy();
            !name.ends_with(".md")
        })
        .collect();
    v.sort();
    v
}

/// SplitMix64: a fixed sequence of mutations.
struct Mix(u64);

impl Mix {
    fn next(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9e37_79b9_7f4a_7c15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
        z ^ (z >> 31)
    }

    fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }
}

/// The mutations of one file.
fn mutations(bytes: &[u8], rng: &mut Mix, count: usize) -> Vec<(String, Vec<u8>)> {
    let head = bytes.len().min(1024);
    let mut out = Vec::new();
    for k in 0..count {
        let mut b = bytes.to_vec();
        let what = match k % 5 {
            0 => {
                let at = rng.below(bytes.len());
                b.truncate(at);
                format!("truncated at {at}")
            }
            1 => {
                let n = 1 + rng.below(8);
                for _ in 0..n {
                    let at = rng.below(head);
                    b[at] ^= 1 << rng.below(8);
                }
                format!("{n} bits flipped in the first {head} bytes")
            }
            2 => {
                let at = rng.below(head.saturating_sub(4)) & !3;
                let v: u32 = [u32::MAX, 0, 0x7fff_ffff, 0x8000_0000, 1 << 20][rng.below(5)];
                b[at..at + 4].copy_from_slice(&v.to_le_bytes());
                format!("u32 at {at} set to {v:#x}")
            }
            3 => {
                // A run of digits in the header replaced by a huge, negative or odd number.
                let text = String::from_utf8_lossy(&b[..head]).into_owned();
                let starts: Vec<usize> = text
                    .char_indices()
                    .filter(|(i, c)| {
                        c.is_ascii_digit() && (*i == 0 || !text.as_bytes()[i - 1].is_ascii_digit())
                    })
                    .map(|(i, _)| i)
                    .collect();
                if starts.is_empty() {
                    b.truncate(b.len() / 2);
                    "halved (no digits in the header)".into()
                } else {
                    let s = starts[rng.below(starts.len())];
                    let e = s + text[s..].chars().take_while(|c| c.is_ascii_digit()).count();
                    let new = ["999999999", "0", "-7", "1e308", "NaN"][rng.below(5)];
                    b.splice(s..e, new.bytes());
                    format!("number at {s} set to {new}")
                }
            }
            _ => {
                let at = rng.below(bytes.len());
                let n = rng.below(64).min(bytes.len() - at);
                b.drain(at..at + n);
                format!("{n} bytes cut at {at}")
            }
        };
        out.push((what, b));
    }
    out
}

#[test]
fn mutated_instrument_files_read_or_refuse_in_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let mut rng = Mix(0x5ca9_2026);
    let (mut read, mut refused) = (0, 0);
    for path in scans() {
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        let bytes = std::fs::read(&path).unwrap();
        for (k, (what, b)) in mutations(&bytes, &mut rng, 40).into_iter().enumerate() {
            let file = dir.path().join(format!("{k}-{name}"));
            std::fs::write(&file, &b).unwrap();
            let result = std::panic::catch_unwind(|| topography::read(&file));
            let r = result.unwrap_or_else(|_| panic!("{name}, {what}: the reader panicked"));
            match r {
                Ok(t) => {
                    assert!(
                        t.nx >= 2 && t.ny >= 2,
                        "{name}, {what}: {} × {}",
                        t.nx,
                        t.ny
                    );
                    assert_eq!(t.heights_m.len(), t.nx * t.ny, "{name}, {what}");
                    assert!(
                        t.dx_m.is_finite() && t.dx_m > 0.0 && t.dy_m.is_finite() && t.dy_m > 0.0,
                        "{name}, {what}: spacing {} {}",
                        t.dx_m,
                        t.dy_m
                    );
                    assert!(
                        t.heights_m.iter().all(|h| h.is_finite() || h.is_nan()),
                        "{name}, {what}: an infinite height"
                    );
                    assert!(t.valid_count() > 0, "{name}, {what}: no valid point");
                    read += 1;
                }
                Err(e) => {
                    let msg = e.to_string();
                    assert!(!msg.contains('\n'), "{name}, {what}: {msg}");
                    assert!(
                        msg.contains(&format!("{k}-{name}")),
                        "{name}, {what}: {msg}"
                    );
                    refused += 1;
                }
            }
            std::fs::remove_file(&file).unwrap();
        }
    }
    eprintln!("mutated scans: {read} read, {refused} refused");
    assert!(read > 0 && refused > 0, "{read} read, {refused} refused");
}
