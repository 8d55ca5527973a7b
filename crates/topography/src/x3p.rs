//! ISO 25178-72 X3P (XML 3D surface profile; ISO 5436-2 file format, openGPS
//! <https://sourceforge.net/p/open-gps/mwiki/X3p/>): a zip archive holding `main.xml`, the
//! point data it names (`Record3/DataLink/PointDataLink`, usually `bindata/data.bin`), an
//! optional validity bit mask (`ValidPointsLink`, usually `bindata/valid.bin`) and
//! `md5checksum.hex`, the MD5 of `main.xml`.
//!
//! Read: a surface (`FeatureType` SUR) on regular X and Y axes (`AxisType` I, with an
//! `Increment` in metres), heights on an absolute Z axis (`AxisType` A) of data type I (i16),
//! L (i32), F (f32) or D (f64), little-endian, x fast (`SizeX` points per row, `SizeY` rows,
//! `SizeZ` 1); a height is `raw × Increment + Offset` of CZ (both optional; an empty element
//! such as `<Offset/>` is absent). `main.xml` sits at the top of the archive, or in one folder
//! whose other paths are then read from it (an `info` entry says so). The validity
//! mask holds one bit per point, least significant bit first, 1 = valid; NaN in F or D data is
//! also missing. The MD5 of `main.xml` (in `md5checksum.hex`), of the point data
//! (`MD5ChecksumPointData`) and of the mask (`MD5ChecksumValidPoints`), where the file gives
//! them, must match — except that a `main.xml` mismatch is only a `warning` entry of `info`
//! when the point data's own MD5 holds; `md5checksum.hex` is read as `md5sum` writes it (`HEX *NAME`) and checks
//! the file it names (SurfaceTopography's writer names the point data there). This is the reading
//! of SurfaceTopography 1.27.1's `IO/X3P.py` (signed I and L, as the openGPS library and
//! Gwyddion's `opengps.c`), with the checksums verified. Explicit axes (`AxisType` A or
//! incremental with a list of coordinates), point lists inline in the XML (`DataList`) and
//! profiles or point clouds are refused.

use crate::error::{quote, ErrorKind, Problem, Result};
use crate::grid::{check_data_len, check_pixel, check_shape};
use crate::xml;
use crate::{Format, Topography};
use md5::{Digest, Md5};
use std::io::{BufReader, Read, Seek};
use std::path::Path;

/// The largest `main.xml` read (real ones are a few kB).
const MAX_XML: u64 = 16 << 20;

pub(crate) fn read(path: &Path) -> Result<Topography> {
    let file = std::fs::File::open(path).map_err(|e| Problem::io(&e))?;
    let mut zip = zip::ZipArchive::new(BufReader::new(file)).map_err(|e| {
        Problem::corrupt(format!(
            "not a readable zip archive ({e}); an X3P file is a zip of main.xml and the point data"
        ))
    })?;
    let mut info = Vec::new();
    // Every other path of the archive is relative to main.xml's folder.
    let folder = main_folder(&zip)?;
    if !folder.is_empty() {
        info.push((
            "main.xml".to_string(),
            format!("in the folder {folder} of the archive; its paths are read from there"),
        ));
    }
    let at = |name: &str| format!("{folder}{name}");
    let main = entry(&mut zip, &at("main.xml"), Size::AtMost(MAX_XML))?
        .ok_or_else(|| Problem::corrupt("the zip archive has no main.xml"))?;
    // `HEX *NAME` as md5sum writes it; ISO 5436-2 names main.xml, SurfaceTopography's writer
    // names the point data: the file it names is the one checked.
    let sum_file = entry(&mut zip, &at("md5checksum.hex"), Size::AtMost(4096))?;
    let sum_file = sum_file.map(|b| String::from_utf8_lossy(&b).into_owned());
    let sum_target = sum_file.as_deref().map(|s| {
        s.split_whitespace()
            .nth(1)
            .map_or("main.xml", |n| n.trim_start_matches('*'))
            .to_string()
    });
    // A main.xml that does not match its checksum is refused, unless the point data's own
    // checksum holds (checked below): then only the XML was edited after it was written.
    let mut main_mismatch = None;
    if let (Some(sum), Some("main.xml")) = (&sum_file, sum_target.as_deref()) {
        match verify(&md5(&main), sum.as_bytes(), "main.xml", "md5checksum.hex") {
            Ok(()) => info.push(("main.xml MD5".to_string(), "verified".to_string())),
            Err(e) => main_mismatch = Some(e),
        }
    }
    let text =
        std::str::from_utf8(&main).map_err(|_| Problem::corrupt("main.xml is not UTF-8 text"))?;
    let root = xml::parse(text, "main.xml")?;
    let need = |path: &[&str]| -> Result<&str> {
        root.text_at(path).ok_or_else(|| {
            Problem::corrupt(format!(
                "main.xml has no {}; an X3P surface states Record1 (axes) and Record3 (grid and data link)",
                path.join("/")
            ))
        })
    };
    let feature = need(&["Record1", "FeatureType"])?;
    if feature != "SUR" {
        return Err(Problem::unsupported(format!(
            "FeatureType is {}; a surface (SUR) is read, not a profile (PRF) or point cloud (PCL)",
            quote(feature)
        )));
    }
    for axis in ["CX", "CY"] {
        let t = need(&["Record1", "Axes", axis, "AxisType"])?;
        if t != "I" {
            return Err(Problem::unsupported(format!(
                "{axis} AxisType is {}; only regular axes (AxisType I, with an Increment) are \
                 read for X and Y, not listed coordinates",
                quote(t)
            )));
        }
    }
    let z_type = need(&["Record1", "Axes", "CZ", "AxisType"])?;
    if z_type != "A" {
        return Err(Problem::unsupported(format!(
            "CZ AxisType is {}; heights on an absolute axis (A) are read",
            quote(z_type)
        )));
    }
    let number = |path: &[&str]| -> Result<Option<f64>> {
        match root.text_at(path) {
            // An empty element (`<Offset/>`) states nothing: the default holds.
            None => Ok(None),
            Some(s) if s.trim().is_empty() => Ok(None),
            Some(s) => s.trim().parse().map(Some).map_err(|_| {
                Problem::corrupt(format!("{} = {} is not a number", path.join("/"), quote(s)))
            }),
        }
    };
    let increment = |axis: &str| -> Result<f64> {
        number(&["Record1", "Axes", axis, "Increment"])?.ok_or_else(|| {
            Problem::no_units(format!(
                "{axis} has no Increment: the pixel size is unknown"
            ))
        })
    };
    let (dx, dy) = (increment("CX")?, increment("CY")?);
    let z_inc = number(&["Record1", "Axes", "CZ", "Increment"])?.unwrap_or(1.0);
    let z_off = number(&["Record1", "Axes", "CZ", "Offset"])?.unwrap_or(0.0);
    let data_type = need(&["Record1", "Axes", "CZ", "DataType"])?;
    let size = match data_type {
        "I" => 2,
        "L" => 4,
        "F" => 4,
        "D" => 8,
        other => {
            return Err(Problem::unsupported(format!(
                "CZ DataType is {}; I (16-bit integer), L (32-bit integer), F (float) and D \
                 (double) are read",
                quote(other)
            )))
        }
    };
    let dim = |name: &str| -> Result<i64> {
        let s = need(&["Record3", "MatrixDimension", name])?;
        s.parse().map_err(|_| {
            Problem::corrupt(format!(
                "MatrixDimension {name} = {} is not a whole number",
                quote(s)
            ))
        })
    };
    let (nx, ny, nz) = (dim("SizeX")?, dim("SizeY")?, dim("SizeZ")?);
    if nz != 1 {
        return Err(Problem::unsupported(format!(
            "SizeZ is {nz}; one layer of heights (SizeZ 1) is read"
        )));
    }
    let points = check_shape(nx, ny)?;
    let link = root.at(&["Record3", "DataLink"]).ok_or_else(|| {
        Problem::unsupported(
            "main.xml has no DataLink: points listed in the XML (DataList) are not read; the \
             points must be a binary file in the archive",
        )
    })?;
    let data_name = link.text_at(&["PointDataLink"]).ok_or_else(|| {
        Problem::corrupt("DataLink has no PointDataLink naming the point data file")
    })?;
    let need_bytes = points as u64 * size as u64;
    let data_sum = link.text_at(&["MD5ChecksumPointData"]);
    let hex_names_data = sum_target.as_deref() == Some(data_name);
    // The point data is converted block by block as it is read (no copy of the member), while
    // a second thread takes its MD5 once for both checksums that may name it.
    let mut heights_m = Vec::with_capacity(points);
    let convert = |bytes: &[u8], out: &mut Vec<f64>| {
        // A height is `raw × Increment + Offset`; a NaN or infinite one is missing.
        let height = |raw: f64| {
            let h = raw * z_inc + z_off;
            if h.is_finite() {
                h
            } else {
                f64::NAN
            }
        };
        match (size, data_type) {
            (2, _) => out.extend(
                bytes
                    .chunks_exact(2)
                    .map(|b| height(i16::from_le_bytes([b[0], b[1]]) as f64)),
            ),
            (8, _) => out.extend(bytes.chunks_exact(8).map(|b| {
                height(f64::from_le_bytes([
                    b[0], b[1], b[2], b[3], b[4], b[5], b[6], b[7],
                ]))
            })),
            (_, "L") => out.extend(
                bytes
                    .chunks_exact(4)
                    .map(|b| height(i32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64)),
            ),
            _ => out.extend(
                bytes
                    .chunks_exact(4)
                    .map(|b| height(f32::from_le_bytes([b[0], b[1], b[2], b[3]]) as f64)),
            ),
        }
    };
    let (read_bytes, digest) = {
        let (mut member, declared) =
            open_entry(&mut zip, &at(data_name), Size::Exactly(need_bytes))?.ok_or_else(|| {
                Problem::corrupt(format!(
                    "the archive has no {} that PointDataLink names",
                    quote(data_name)
                ))
            })?;
        stream(
            &mut member,
            data_name,
            declared,
            size,
            data_sum.is_some() || hex_names_data,
            |bytes| convert(bytes, &mut heights_m),
        )?
    };
    check_data_len(
        points,
        size,
        read_bytes as usize,
        &format!("X3P point data ({data_type})"),
    )?;
    let mut data_verified = false;
    if let (Some(sum), Some(digest)) = (data_sum, &digest) {
        verify(digest, sum.as_bytes(), data_name, "MD5ChecksumPointData")?;
        info.push(("point data MD5".to_string(), "verified".to_string()));
        data_verified = true;
    }
    if let Some(e) = main_mismatch {
        if !data_verified {
            return Err(e);
        }
        info.push((
            "warning".to_string(),
            format!(
                "{} the point data's own MD5 matches, so the heights are read (main.xml was \
                 edited after its checksum was written)",
                e.message
            ),
        ));
    }
    match (&sum_file, sum_target.as_deref(), &digest) {
        (Some(sum), Some(name), Some(digest)) if name == data_name => {
            verify(digest, sum.as_bytes(), data_name, "md5checksum.hex")?;
        }
        (Some(_), Some("main.xml"), _) => {}
        (Some(_), Some(name), _) => info.push((
            "md5checksum.hex".to_string(),
            format!("names {name}, not checked"),
        )),
        _ => info.push(("md5checksum.hex".to_string(), "absent".to_string())),
    }
    let mask_bytes = (points as u64).div_ceil(8);
    let valid_name = link
        .text_at(&["ValidPointsLink"])
        .unwrap_or("bindata/valid.bin");
    let valid = entry(&mut zip, &at(valid_name), Size::Exactly(mask_bytes))?;
    if let (Some(v), Some(sum)) = (&valid, link.text_at(&["MD5ChecksumValidPoints"])) {
        verify(
            &md5(v),
            sum.as_bytes(),
            valid_name,
            "MD5ChecksumValidPoints",
        )?;
    }
    if valid.is_none() && link.child("ValidPointsLink").is_some() {
        return Err(Problem::corrupt(format!(
            "the archive has no {} that ValidPointsLink names",
            quote(valid_name)
        )));
    }
    if let Some(v) = &valid {
        // One bit per point, least significant first; 0 marks a point missing.
        for (k, h) in heights_m.iter_mut().enumerate() {
            if v[k / 8] >> (k % 8) & 1 == 0 {
                *h = f64::NAN;
            }
        }
    }
    for (key, path) in [
        ("date", &["Record2", "Date"][..]),
        ("vendor", &["Record2", "Instrument", "Manufacturer"]),
        ("instrument", &["Record2", "Instrument", "Model"]),
        ("serial", &["Record2", "Instrument", "Serial"]),
        ("version", &["Record2", "Instrument", "Version"]),
        ("calibration date", &["Record2", "CalibrationDate"]),
        ("probing system", &["Record2", "ProbingSystem", "Type"]),
        ("probe", &["Record2", "ProbingSystem", "Identification"]),
        ("comment", &["Record2", "Comment"]),
        ("x offset (m)", &["Record1", "Axes", "CX", "Offset"]),
        ("y offset (m)", &["Record1", "Axes", "CY", "Offset"]),
        ("data type", &["Record1", "Axes", "CZ", "DataType"]),
    ] {
        if let Some(v) = root.text_at(path).filter(|v| !v.is_empty()) {
            info.push((key.to_string(), v.to_string()));
        }
    }
    if valid.is_some() {
        info.push(("validity mask".to_string(), valid_name.to_string()));
    }
    Ok(Topography {
        nx: nx as usize,
        ny: ny as usize,
        dx_m: check_pixel(dx, "x")?,
        dy_m: check_pixel(dy, "y")?,
        heights_m,
        format: Format::X3p,
        info,
    })
}

/// The folder of the archive that holds `main.xml` (`""` at the top, else `name/`): the
/// ISO 5436-2 layout puts it at the top; some writers zip a folder instead (x3ptools'
/// `sample-land.x3p`: `sample-land/main.xml`). macOS's `__MACOSX/` copies are no candidates;
/// more than one folder with a `main.xml` is refused, naming them.
fn main_folder<R: Read + Seek>(zip: &zip::ZipArchive<R>) -> Result<String> {
    let names: Vec<String> = zip
        .file_names()
        .filter_map(|n| n.ok().map(|n| n.into_owned()))
        .collect();
    if names.iter().any(|n| n == "main.xml") {
        return Ok(String::new());
    }
    let mut found: Vec<&str> = names
        .iter()
        .filter(|n| !n.starts_with("__MACOSX/"))
        .filter_map(|n| n.strip_suffix("main.xml").filter(|f| f.ends_with('/')))
        .collect();
    found.sort_unstable();
    match found.as_slice() {
        [one] => Ok(one.to_string()),
        [] => Err(Problem::corrupt(
            "the zip archive has no main.xml, at its top or in a folder; an X3P file is a zip of \
             main.xml and the point data",
        )),
        many => Err(Problem::corrupt(format!(
            "the zip archive has no main.xml at its top but one in each of {} folders ({}): \
             which surface to read is not clear; an X3P file holds one",
            many.len(),
            many.iter().map(|f| quote(f)).collect::<Vec<_>>().join(", ")
        ))),
    }
}

/// The size an archive member must have.
enum Size {
    AtMost(u64),
    Exactly(u64),
}

/// The member `name` and its declared size, `None` when the archive has none; the declared
/// size is checked before anything is read.
fn open_entry<'a, R: Read + Seek>(
    zip: &'a mut zip::ZipArchive<R>,
    name: &str,
    size: Size,
) -> Result<Option<(zip::read::ZipFile<'a, R>, u64)>> {
    let f = match zip.by_name(name) {
        Ok(f) => f,
        Err(zip::result::ZipError::FileNotFound) => return Ok(None),
        Err(e) => {
            return Err(Problem::corrupt(format!(
                "the zip member {} cannot be read: {e}",
                quote(name)
            )))
        }
    };
    let declared = f.size();
    match size {
        Size::AtMost(max) if declared > max => Err(Problem::new(
            ErrorKind::TooLarge,
            format!(
                "{} is {declared} bytes; at most {max} are read",
                quote(name)
            ),
        )),
        Size::Exactly(n) if declared != n => {
            let kind = if declared < n {
                ErrorKind::Truncated
            } else {
                ErrorKind::Corrupt
            };
            Err(Problem::new(
                kind,
                format!(
                    "{} holds {declared} bytes but main.xml's grid and data type need {n}",
                    quote(name)
                ),
            ))
        }
        Size::AtMost(_) | Size::Exactly(_) => Ok(Some((f, declared))),
    }
}

/// The bytes of the member `name`, `None` when the archive has none; its declared size is
/// checked before reading, and its content must match it.
fn entry<R: Read + Seek>(
    zip: &mut zip::ZipArchive<R>,
    name: &str,
    size: Size,
) -> Result<Option<Vec<u8>>> {
    let Some((mut f, declared)) = open_entry(zip, name, size)? else {
        return Ok(None);
    };
    let mut out = Vec::with_capacity(declared as usize);
    (&mut f)
        .take(declared + 1)
        .read_to_end(&mut out)
        .map_err(|e| damaged(name, &e))?;
    held(name, declared, out.len() as u64)?;
    Ok(Some(out))
}

/// Bytes per block of [`stream`]: a multiple of every value size.
const BLOCK: usize = 1 << 20;

/// Reads the member `f` (`declared` bytes) in blocks of whole values of `size` bytes, each
/// passed to `convert` in order, and, when `md5` is asked for, takes the MD5 of its bytes on
/// another thread meanwhile. Returns the bytes read (the declared count, or an error) and
/// the MD5.
fn stream(
    f: &mut impl Read,
    name: &str,
    declared: u64,
    size: usize,
    md5: bool,
    mut convert: impl FnMut(&[u8]),
) -> Result<(u64, Option<[u8; 16]>)> {
    use std::sync::mpsc::{channel, sync_channel};
    let mut f = f.take(declared + 1);
    // Fills `buf` up to its length or the member's end; the bytes read.
    let mut fill = |buf: &mut [u8]| -> Result<usize> {
        let mut n = 0;
        while n < buf.len() {
            match f.read(&mut buf[n..]) {
                Ok(0) => break,
                Ok(k) => n += k,
                Err(e) if e.kind() == std::io::ErrorKind::Interrupted => {}
                Err(e) => return Err(damaged(name, &e)),
            }
        }
        Ok(n)
    };
    let block = BLOCK.min(declared as usize + 1);
    let mut total = 0u64;
    if !md5 {
        let mut buf = vec![0u8; block];
        loop {
            let n = fill(&mut buf)?;
            total += n as u64;
            convert(&buf[..n - n % size]);
            if n < block {
                break;
            }
        }
        held(name, declared, total)?;
        return Ok((total, None));
    }
    std::thread::scope(|s| {
        // Full blocks go to the hashing thread and come back to be filled again.
        let (to_hash, blocks) = sync_channel::<(Vec<u8>, usize)>(2);
        let (give_back, returned) = channel::<Vec<u8>>();
        let hasher = s.spawn(move || {
            let mut h = Md5::new();
            for (buf, n) in blocks {
                h.update(&buf[..n]);
                // The reader may have stopped: the block is then not needed.
                let _ = give_back.send(buf);
            }
            <[u8; 16]>::from(h.finalize())
        });
        loop {
            let mut buf = returned.try_recv().unwrap_or_else(|_| vec![0u8; block]);
            let n = fill(&mut buf)?;
            total += n as u64;
            convert(&buf[..n - n % size]);
            // The hashing thread ends only when this sender is dropped: it cannot be gone.
            let _ = to_hash.send((buf, n));
            if n < block {
                break;
            }
        }
        drop(to_hash);
        held(name, declared, total)?;
        let digest = hasher
            .join()
            .map_err(|_| Problem::corrupt(format!("the MD5 of {} failed", quote(name))))?;
        Ok((total, Some(digest)))
    })
}

/// The read of the member `name` failed.
fn damaged(name: &str, e: &std::io::Error) -> Problem {
    Problem::corrupt(format!("the zip member {} is damaged: {e}", quote(name)))
}

/// Checks that the member `name` held the `declared` bytes (`got`, at most one more read).
fn held(name: &str, declared: u64, got: u64) -> Result<()> {
    if got != declared {
        return Err(Problem::truncated(format!(
            "the zip member {} declares {declared} bytes but holds {got}",
            quote(name)
        )));
    }
    Ok(())
}

/// The MD5 of `data`.
fn md5(data: &[u8]) -> [u8; 16] {
    Md5::digest(data).into()
}

/// Checks that the MD5 `digest` (of the member `name`) is the 32 hex digits at the start of
/// `stored`.
fn verify(digest: &[u8; 16], stored: &[u8], name: &str, source: &str) -> Result<()> {
    let stored = String::from_utf8_lossy(stored);
    let want = stored
        .split_whitespace()
        .next()
        .unwrap_or("")
        .to_ascii_lowercase();
    let got: String = digest.iter().map(|b| format!("{b:02x}")).collect();
    if want.len() != 32 || !want.bytes().all(|b| b.is_ascii_hexdigit()) {
        return Err(Problem::corrupt(format!(
            "{source} holds {}, not an MD5 checksum (32 hexadecimal digits)",
            quote(&stored)
        )));
    }
    if want != got {
        return Err(Problem::new(
            ErrorKind::Checksum,
            format!(
                "the MD5 checksum of {} is {got} but {source} says {want}: the file is damaged",
                quote(name)
            ),
        ));
    }
    Ok(())
}
