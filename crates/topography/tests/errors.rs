//! Broken, hostile and edge-case files: each gives one line naming the file (never a panic,
//! never an allocation the header asks for), and the formats' rarer features (X3P integer
//! data with a validity mask, GSF built byte by byte from its specification) read right.

use md5::{Digest, Md5};
use std::io::Write;
use std::path::{Path, PathBuf};
use topography::{read, read_as, read_matrix, read_xyz, ErrorKind, Format, ReadError};

fn scan(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../tests/data/scans")
        .join(name)
}

fn write(dir: &Path, name: &str, bytes: &[u8]) -> PathBuf {
    let p = dir.join(name);
    std::fs::write(&p, bytes).unwrap();
    p
}

/// The error of reading `path`, checked to be one line starting with the file's name.
fn fails(
    result: Result<topography::Topography, ReadError>,
    path: &Path,
    kind: ErrorKind,
) -> String {
    let e = result.expect_err("the read must fail");
    let line = e.to_string();
    assert!(!line.contains('\n'), "{line}");
    assert!(line.starts_with(&path.display().to_string()), "{line}");
    assert_eq!(e.kind(), kind, "{line}");
    assert_eq!(e.path(), path);
    line
}

fn md5_hex(bytes: &[u8]) -> String {
    Md5::digest(bytes)
        .iter()
        .map(|b| format!("{b:02X}"))
        .collect()
}

/// main.xml of an X3P surface of `nx` × `ny` points of `dtype`; `z` is extra CZ content,
/// `link` extra DataLink content.
fn main_xml(
    nx: i64,
    ny: i64,
    dtype: &str,
    z: &str,
    data: &[u8],
    link: &str,
    cx_type: &str,
) -> String {
    format!(
        r#"<?xml version="1.0" encoding="UTF-8"?>
<p:ISO5436_2 xmlns:p="http://www.opengps.eu/2008/ISO5436_2">
  <Record1><Revision>ISO5436 - 2000</Revision><FeatureType>SUR</FeatureType>
    <Axes>
      <CX><AxisType>{cx_type}</AxisType><DataType>D</DataType><Increment>1.5e-6</Increment><Offset>0</Offset></CX>
      <CY><AxisType>I</AxisType><DataType>D</DataType><Increment>2.5e-6</Increment><Offset>0</Offset></CY>
      <CZ><AxisType>A</AxisType><DataType>{dtype}</DataType>{z}</CZ>
    </Axes></Record1>
  <Record2><Date>2024-01-02T03:04:05</Date><Instrument><Manufacturer>ACME &amp; Sons</Manufacturer><Model>P1</Model><Serial>7</Serial><Version>1</Version></Instrument></Record2>
  <Record3><MatrixDimension><SizeX>{nx}</SizeX><SizeY>{ny}</SizeY><SizeZ>1</SizeZ></MatrixDimension>
    <DataLink><PointDataLink>bindata/data.bin</PointDataLink><MD5ChecksumPointData>{}</MD5ChecksumPointData>{link}</DataLink></Record3>
  <Record4><ChecksumFile>md5checksum.hex</ChecksumFile></Record4>
</p:ISO5436_2>
"#,
        md5_hex(data)
    )
}

/// An X3P archive of `members` (name, bytes); `md5checksum.hex` is added for main.xml unless
/// `sum` gives its content.
fn x3p(dir: &Path, name: &str, xml: &str, members: &[(&str, &[u8])], sum: Option<&str>) -> PathBuf {
    let path = dir.join(name);
    let mut z = zip::ZipWriter::new(std::fs::File::create(&path).unwrap());
    let opt = zip::write::SimpleFileOptions::default()
        .compression_method(zip::CompressionMethod::Deflated);
    z.start_file("main.xml", opt).unwrap();
    z.write_all(xml.as_bytes()).unwrap();
    for (n, b) in members {
        z.start_file(*n, opt).unwrap();
        z.write_all(b).unwrap();
    }
    let sum = sum.map_or_else(
        || format!("{} *main.xml\n", md5_hex(xml.as_bytes())),
        String::from,
    );
    z.start_file("md5checksum.hex", opt).unwrap();
    z.write_all(sum.as_bytes()).unwrap();
    z.finish().unwrap();
    path
}

fn i16s(v: &[i16]) -> Vec<u8> {
    v.iter().flat_map(|x| x.to_le_bytes()).collect()
}

#[test]
fn x3p_integer_heights_with_increment_offset_and_validity_mask() {
    let tmp = tempfile::tempdir().unwrap();
    // 3 × 2 points of 16-bit integers; point 4 (ix 1, iy 1) invalid: mask bits 1,1,1,1,0,1.
    let data = i16s(&[-32768, -1, 0, 1, 2, 32767]);
    let valid = [0b0010_1111u8];
    let xml = main_xml(
        3,
        2,
        "I",
        "<Increment>1e-9</Increment><Offset>2e-6</Offset>",
        &data,
        &format!(
            "<ValidPointsLink>bindata/valid.bin</ValidPointsLink><MD5ChecksumValidPoints>{}</MD5ChecksumValidPoints>",
            md5_hex(&valid)
        ),
        "I",
    );
    let p = x3p(
        tmp.path(),
        "int.x3p",
        &xml,
        &[("bindata/data.bin", &data), ("bindata/valid.bin", &valid)],
        None,
    );
    let t = read(&p).unwrap();
    assert_eq!((t.nx, t.ny, t.format), (3, 2, Format::X3p));
    assert_eq!((t.dx_m, t.dy_m), (1.5e-6, 2.5e-6));
    let want = [-32768.0, -1.0, 0.0, 1.0, f64::NAN, 32767.0];
    for (k, (&h, &w)) in t.heights_m.iter().zip(&want).enumerate() {
        if w.is_nan() {
            assert!(h.is_nan() && !t.is_valid(k % 3, k / 3));
        } else {
            assert!((h - (w * 1e-9 + 2e-6)).abs() < 1e-20, "{k}: {h}");
        }
    }
    assert_eq!(t.valid_count(), 5);
    assert_eq!(t.info_value("vendor"), Some("ACME & Sons"));
    assert_eq!(t.info_value("main.xml MD5"), Some("verified"));
    // 32-bit integers and floats.
    let data: Vec<u8> = [-7i32, 0, 7, 1 << 30]
        .iter()
        .flat_map(|x| x.to_le_bytes())
        .collect();
    let xml = main_xml(2, 2, "L", "<Increment>1e-12</Increment>", &data, "", "I");
    let t = read(&x3p(
        tmp.path(),
        "l.x3p",
        &xml,
        &[("bindata/data.bin", &data)],
        None,
    ))
    .unwrap();
    assert_eq!(
        t.heights_m,
        [-7e-12, 0.0, 7e-12, (1u64 << 30) as f64 * 1e-12]
    );
    let data: Vec<u8> = [1.5f32, f32::NAN, -2.0, 4.0]
        .iter()
        .flat_map(|x| x.to_le_bytes())
        .collect();
    let xml = main_xml(2, 2, "F", "", &data, "", "I");
    let t = read(&x3p(
        tmp.path(),
        "f.x3p",
        &xml,
        &[("bindata/data.bin", &data)],
        None,
    ))
    .unwrap();
    assert_eq!(t.valid_count(), 3);
    assert!(t.heights_m[1].is_nan());
    assert_eq!(t.heights_m[3], 4.0);
}

#[test]
fn a_corrupt_zip_is_one_line() {
    let tmp = tempfile::tempdir().unwrap();
    let p = write(
        tmp.path(),
        "bad.x3p",
        b"PK\x03\x04this is not a zip archive at all",
    );
    let m = fails(read(&p), &p, ErrorKind::Corrupt);
    assert!(m.contains("zip"), "{m}");
    // A real X3P cut in half.
    let bytes = std::fs::read(scan("x3p-2.x3p")).unwrap();
    let p = write(tmp.path(), "half.x3p", &bytes[..bytes.len() / 2]);
    fails(read(&p), &p, ErrorKind::Corrupt);
}

#[test]
fn bad_xml_is_one_line() {
    let tmp = tempfile::tempdir().unwrap();
    let data = i16s(&[1, 2, 3, 4]);
    for (i, xml) in [
        "<p:ISO5436_2><Record1><FeatureType>SUR</FeatureType>".to_string(),
        "<a><b></a>".to_string(),
        "not xml at all".to_string(),
        "<a>&unknown;</a>".to_string(),
        format!("{}{}", "<a>".repeat(100), "</a>".repeat(100)),
    ]
    .iter()
    .enumerate()
    {
        let p = x3p(
            tmp.path(),
            &format!("bad{i}.x3p"),
            xml,
            &[("bindata/data.bin", &data)],
            None,
        );
        let m = fails(read(&p), &p, ErrorKind::Corrupt);
        assert!(m.contains("main.xml"), "{m}");
    }
}

#[test]
fn x3p_checksum_mismatches_are_refused_unless_the_point_data_vouches() {
    let tmp = tempfile::tempdir().unwrap();
    let data = i16s(&[1, 2, 3, 4]);
    let xml = main_xml(2, 2, "I", "", &data, "", "I");
    let p = x3p(
        tmp.path(),
        "main.x3p",
        &xml,
        &[("bindata/data.bin", &data)],
        Some("00112233445566778899aabbccddeeff *main.xml\n"),
    );
    // Only main.xml fails its checksum, and the point data's own MD5 holds: the heights are
    // intact, read with a warning (issue 39).
    let t = read(&p).unwrap();
    assert_eq!(t.heights_m, [1.0, 2.0, 3.0, 4.0]);
    let w = t.info_value("warning").expect("a warning");
    assert!(w.contains("main.xml") && w.contains("point data"), "{w}");
    // Without a point-data checksum to vouch for the heights, the mismatch is refused.
    let bare = xml.replace(
        &format!(
            "<MD5ChecksumPointData>{}</MD5ChecksumPointData>",
            md5_hex(&data)
        ),
        "",
    );
    assert_ne!(bare, xml);
    let p = x3p(
        tmp.path(),
        "bare.x3p",
        &bare,
        &[("bindata/data.bin", &data)],
        Some("00112233445566778899aabbccddeeff *main.xml\n"),
    );
    let m = fails(read(&p), &p, ErrorKind::Checksum);
    assert!(m.contains("main.xml"), "{m}");
    let other = i16s(&[1, 2, 3, 5]);
    let p = x3p(
        tmp.path(),
        "data.x3p",
        &xml,
        &[("bindata/data.bin", &other)],
        None,
    );
    let m = fails(read(&p), &p, ErrorKind::Checksum);
    assert!(m.contains("bindata/data.bin"), "{m}");
}

#[test]
fn x3p_explicit_axes_and_other_features_are_refused_by_name() {
    let tmp = tempfile::tempdir().unwrap();
    let data = i16s(&[1, 2, 3, 4]);
    let xml = main_xml(2, 2, "I", "", &data, "", "A");
    let p = x3p(
        tmp.path(),
        "axis.x3p",
        &xml,
        &[("bindata/data.bin", &data)],
        None,
    );
    let m = fails(read(&p), &p, ErrorKind::Unsupported);
    assert!(
        m.contains("CX AxisType") && m.contains("regular axes"),
        "{m}"
    );
    let xml = main_xml(2, 2, "Q", "", &data, "", "I");
    let p = x3p(
        tmp.path(),
        "type.x3p",
        &xml,
        &[("bindata/data.bin", &data)],
        None,
    );
    let m = fails(read(&p), &p, ErrorKind::Unsupported);
    assert!(m.contains("DataType"), "{m}");
}

#[test]
fn x3p_sizes_are_checked_before_reading() {
    let tmp = tempfile::tempdir().unwrap();
    let data = i16s(&[1, 2, 3, 4]);
    let xml = main_xml(1_000_000, 1_000_000, "D", "", &data, "", "I");
    let p = x3p(
        tmp.path(),
        "huge.x3p",
        &xml,
        &[("bindata/data.bin", &data)],
        None,
    );
    let m = fails(read(&p), &p, ErrorKind::TooLarge);
    assert!(m.contains("1000000 × 1000000"), "{m}");
    // More points than the data file holds.
    let xml = main_xml(30, 20, "I", "", &data, "", "I");
    let p = x3p(
        tmp.path(),
        "short.x3p",
        &xml,
        &[("bindata/data.bin", &data)],
        None,
    );
    let m = fails(read(&p), &p, ErrorKind::Truncated);
    assert!(m.contains("8 bytes") && m.contains("1200"), "{m}");
    // A 1 × 1 scan.
    let one = i16s(&[1]);
    let xml = main_xml(1, 1, "I", "", &one, "", "I");
    let p = x3p(
        tmp.path(),
        "one.x3p",
        &xml,
        &[("bindata/data.bin", &one)],
        None,
    );
    fails(read(&p), &p, ErrorKind::NoData);
    // Every point invalid.
    let xml = main_xml(
        2,
        2,
        "I",
        "",
        &data,
        "<ValidPointsLink>bindata/valid.bin</ValidPointsLink>",
        "I",
    );
    let p = x3p(
        tmp.path(),
        "none.x3p",
        &xml,
        &[("bindata/data.bin", &data), ("bindata/valid.bin", &[0])],
        None,
    );
    let m = fails(read(&p), &p, ErrorKind::NoData);
    assert!(m.contains("all 2 × 2 points"), "{m}");
}

/// A Digital Surf file: `sur-2.sur` with header fields replaced.
fn sur_with(fields: &[(usize, &[u8])], len: Option<usize>) -> Vec<u8> {
    let mut b = std::fs::read(scan("sur-2.sur")).unwrap();
    for (at, v) in fields {
        b[*at..*at + v.len()].copy_from_slice(v);
    }
    if let Some(n) = len {
        b.truncate(n);
    }
    b
}

#[test]
fn sur_sizes_are_checked_before_reading() {
    let tmp = tempfile::tempdir().unwrap();
    let p = write(tmp.path(), "cut.sur", &sur_with(&[], Some(100_000)));
    let m = fails(read(&p), &p, ErrorKind::Truncated);
    assert!(m.contains("272492 points"), "{m}");
    let p = write(tmp.path(), "header.sur", &sur_with(&[], Some(300)));
    fails(read(&p), &p, ErrorKind::Truncated);
    let million = 1_000_000i32.to_le_bytes();
    let p = write(
        tmp.path(),
        "huge.sur",
        &sur_with(
            &[(108, &million), (112, &million), (116, &0u32.to_le_bytes())],
            None,
        ),
    );
    fails(read(&p), &p, ErrorKind::TooLarge);
    let p = write(
        tmp.path(),
        "more.sur",
        &sur_with(
            &[
                (108, &1000i32.to_le_bytes()),
                (112, &1000i32.to_le_bytes()),
                (116, &1_000_000u32.to_le_bytes()),
            ],
            None,
        ),
    );
    fails(read(&p), &p, ErrorKind::Truncated);
    let one = 1i32.to_le_bytes();
    let p = write(
        tmp.path(),
        "one.sur",
        &sur_with(
            &[(108, &one), (112, &one), (116, &1u32.to_le_bytes())],
            None,
        ),
    );
    fails(read(&p), &p, ErrorKind::NoData);
    let p = write(
        tmp.path(),
        "neg.sur",
        &sur_with(&[(108, &(-5i32).to_le_bytes())], None),
    );
    fails(read(&p), &p, ErrorKind::Corrupt);
    let p = write(
        tmp.path(),
        "bits.sur",
        &sur_with(&[(98, &8u16.to_le_bytes())], None),
    );
    fails(read(&p), &p, ErrorKind::Unsupported);
    let p = write(tmp.path(), "unit.sur", &sur_with(&[(212, b"V  ")], None));
    let m = fails(read(&p), &p, ErrorKind::NoUnits);
    assert!(m.contains("z step unit"), "{m}");
}

#[test]
fn an_all_invalid_sur_is_one_line() {
    let tmp = tempfile::tempdir().unwrap();
    // 2 × 2 points, all at zmin − 2 with special points flagged.
    let mut b = sur_with(&[], Some(512));
    let two = 2i32.to_le_bytes();
    for (at, v) in [
        (86, &1u16.to_le_bytes()[..]),
        (100, &10i32.to_le_bytes()),
        (108, &two),
        (112, &two),
        (116, &4u32.to_le_bytes()),
    ] {
        b[at..at + v.len()].copy_from_slice(v);
    }
    for _ in 0..4 {
        b.extend(8i32.to_le_bytes());
    }
    let p = write(tmp.path(), "none.sur", &b);
    fails(read(&p), &p, ErrorKind::NoData);
    // One measured point is enough.
    b[512..516].copy_from_slice(&9i32.to_le_bytes());
    let p = write(tmp.path(), "one.sur", &b);
    assert_eq!(read(&p).unwrap().valid_count(), 1);
}

/// A GSF file, byte by byte as its specification describes it: the magic line, `name = value`
/// lines, NUL padding to a multiple of 4 (at least one NUL), little-endian f32 data.
fn gsf(header: &str, values: &[f32]) -> Vec<u8> {
    let mut b = b"Gwyddion Simple Field 1.0\n".to_vec();
    b.extend_from_slice(header.as_bytes());
    let pad = 4 - b.len() % 4;
    b.extend(std::iter::repeat_n(0u8, pad));
    assert!((1..=4).contains(&pad) && b.len().is_multiple_of(4));
    for v in values {
        b.extend(v.to_le_bytes());
    }
    b
}

#[test]
fn gsf_built_from_its_specification() {
    let tmp = tempfile::tempdir().unwrap();
    let header = "XRes = 3\nYRes = 2\nXReal = 6e-6\nYReal = 5e-6\nXOffset = 0\nYOffset = 0\n\
                  XYUnits = m\nZUnits = m\nTitle = Topography\n";
    let values = [1e-7, 2e-7, f32::NAN, -1e-7, 0.0, 3e-7];
    let p = write(tmp.path(), "field.gsf", &gsf(header, &values));
    let t = read(&p).unwrap();
    assert_eq!((t.format, t.nx, t.ny), (Format::Gsf, 3, 2));
    assert!((t.dx_m - 2e-6).abs() < 1e-20 && (t.dy_m - 2.5e-6).abs() < 1e-20);
    assert_eq!(t.valid_count(), 5);
    assert!(!t.is_valid(2, 0) && t.is_valid(0, 1));
    assert_eq!(t.heights_m[5], 3e-7f32 as f64);
    assert_eq!(t.info_value("Title"), Some("Topography"));
    // Units with a prefix, header lengths needing each padding 1..4.
    for extra in ["", "A", "AB", "ABC"] {
        let h = format!(
            "XRes = 2\nYRes = 2\nXReal = 4\nYReal = 2\nXYUnits = µm\nZUnits = nm\nX{extra} = 1\n"
        );
        let p = write(tmp.path(), "um.gsf", &gsf(&h, &[1.0, 2.0, 3.0, 4.0]));
        let t = read(&p).unwrap();
        assert!((t.dx_m - 2e-6).abs() < 1e-20 && (t.dy_m - 1e-6).abs() < 1e-20);
        assert!((t.heights_m[3] - 4e-9).abs() < 1e-22);
    }
}

#[test]
fn gsf_errors_are_one_line() {
    let tmp = tempfile::tempdir().unwrap();
    let ok = "XRes = 2\nYRes = 2\nXReal = 1\nYReal = 1\nXYUnits = m\nZUnits = m\n";
    let full = gsf(ok, &[1.0; 4]);
    let p = write(tmp.path(), "cut.gsf", &full[..full.len() - 3]);
    fails(read(&p), &p, ErrorKind::Truncated);
    let p = write(tmp.path(), "nonul.gsf", &full[..40]);
    fails(read(&p), &p, ErrorKind::Truncated);
    let p = write(
        tmp.path(),
        "huge.gsf",
        &gsf(
            "XRes = 1000000\nYRes = 1000000\nXReal = 1\nYReal = 1\nXYUnits = m\nZUnits = m\n",
            &[1.0; 4],
        ),
    );
    fails(read(&p), &p, ErrorKind::TooLarge);
    let p = write(
        tmp.path(),
        "units.gsf",
        &gsf("XRes = 2\nYRes = 2\nXReal = 1\nYReal = 1\n", &[1.0; 4]),
    );
    let m = fails(read(&p), &p, ErrorKind::NoUnits);
    assert!(m.contains("XYUnits"), "{m}");
    let p = write(
        tmp.path(),
        "volts.gsf",
        &gsf(
            "XRes = 2\nYRes = 2\nXReal = 1\nYReal = 1\nXYUnits = m\nZUnits = V\n",
            &[1.0; 4],
        ),
    );
    fails(read(&p), &p, ErrorKind::NoUnits);
    let p = write(
        tmp.path(),
        "one.gsf",
        &gsf(
            "XRes = 1\nYRes = 1\nXReal = 1\nYReal = 1\nXYUnits = m\nZUnits = m\n",
            &[1.0],
        ),
    );
    fails(read(&p), &p, ErrorKind::NoData);
    let p = write(tmp.path(), "nan.gsf", &gsf(ok, &[f32::NAN; 4]));
    fails(read(&p), &p, ErrorKind::NoData);
}

#[test]
fn truncated_and_oversized_instrument_files_are_one_line() {
    let tmp = tempfile::tempdir().unwrap();
    for (name, cut) in [
        ("metropro-1.dat", 1_000_000),
        ("opd-1.opd", 1_000_000),
        ("plu-1.plu", 1_000_000),
    ] {
        let b = std::fs::read(scan(name)).unwrap();
        let p = write(tmp.path(), name, &b[..cut]);
        fails(read(&p), &p, ErrorKind::Truncated);
        let p = write(tmp.path(), &format!("head-{name}"), &b[..200]);
        fails(read(&p), &p, ErrorKind::Truncated);
    }
    // MetroPro: 65535 × 65535 points (its widest), more than MAX_POINTS.
    let mut b = std::fs::read(scan("metropro-1.dat")).unwrap();
    b[68..72].copy_from_slice(&[0xff; 4]);
    let p = write(tmp.path(), "huge.dat", &b);
    fails(read(&p), &p, ErrorKind::TooLarge);
    // PLU: 10⁶ × 10⁶ points.
    let mut b = std::fs::read(scan("plu-1.plu")).unwrap();
    for at in [388, 392, 500, 504] {
        b[at..at + 4].copy_from_slice(&1_000_000u32.to_le_bytes());
    }
    let p = write(tmp.path(), "huge.plu", &b);
    fails(read(&p), &p, ErrorKind::TooLarge);
    // OPD: an array of 65535 × 65535 points in a short file.
    let mut b = std::fs::read(scan("opd-1.opd")).unwrap();
    let start = opd_raster_offset(&b);
    b[start..start + 4].copy_from_slice(&[0xff; 4]);
    let p = write(tmp.path(), "huge.opd", &b);
    fails(read(&p), &p, ErrorKind::TooLarge);
}

/// Where the `Raw` array's content starts in an OPD file: after the directory, the blocks
/// before it.
fn opd_raster_offset(b: &[u8]) -> usize {
    let dir = i32::from_le_bytes(b[20..24].try_into().unwrap()) as usize;
    let mut pos = 2 + dir;
    for i in 1..dir / 24 {
        let e = 2 + 24 * i;
        let name = String::from_utf8_lossy(&b[e..e + 16])
            .trim_end_matches('\0')
            .to_string();
        let len = i32::from_le_bytes(b[e + 18..e + 22].try_into().unwrap());
        if name == "Raw" {
            return pos;
        }
        if len > 0 {
            pos += len as usize;
        }
    }
    panic!("no Raw block");
}

#[test]
fn text_errors_are_one_line() {
    let tmp = tempfile::tempdir().unwrap();
    let gwy = "# Channel: Z\n# Width: 2 µm\n# Height: 2 µm\n# Value units: m\n";
    let p = write(
        tmp.path(),
        "ragged.txt",
        format!("{gwy}1 2\n3 4 5\n").as_bytes(),
    );
    let m = fails(read(&p), &p, ErrorKind::Corrupt);
    assert!(m.contains("line 6"), "{m}");
    let p = write(
        tmp.path(),
        "nounit.txt",
        b"# Channel: Z\n# Width: 2 um\n# Height: 2 um\n1 2\n3 4\n",
    );
    fails(read(&p), &p, ErrorKind::NoUnits);
    let p = write(
        tmp.path(),
        "volts.txt",
        b"# Width: 2 um\n# Height: 2 um\n# Value units: V\n1 2\n3 4\n",
    );
    fails(read(&p), &p, ErrorKind::NoUnits);
    let p = write(tmp.path(), "one.txt", format!("{gwy}1\n").as_bytes());
    fails(read(&p), &p, ErrorKind::NoData);
    let p = write(
        tmp.path(),
        "nan.txt",
        format!("{gwy}NaN nan\nbad NaN\n").as_bytes(),
    );
    fails(read(&p), &p, ErrorKind::NoData);
    let p = write(
        tmp.path(),
        "two.txt",
        format!("{gwy}1 2\n3 4\n{gwy}1 2\n").as_bytes(),
    );
    fails(read(&p), &p, ErrorKind::Unsupported);
    let p = write(
        tmp.path(),
        "words.txt",
        format!("{gwy}1 2\nthree four\n").as_bytes(),
    );
    fails(read(&p), &p, ErrorKind::Corrupt);
    let p = write(
        tmp.path(),
        "phase.txt",
        b"h=3 w=2\npixel size=1e-6 m\nheight conversion factor (-> m)=1e-8\n1 2\n3 4\n",
    );
    let m = fails(read(&p), &p, ErrorKind::Corrupt);
    assert!(m.contains("h (rows) = 3"), "{m}");
    let p = write(tmp.path(), "m.txt", b"1 2\n3 4\n");
    for (dx, dy, u) in [(0.0, 1.0, 1.0), (1.0, f64::NAN, 1.0), (1.0, 1.0, -1.0)] {
        fails(read_matrix(&p, dx, dy, u), &p, ErrorKind::BadArgument);
    }
    fails(read_as(&p, Format::Matrix), &p, ErrorKind::NoUnits);
}

#[test]
fn a_scattered_xyz_is_refused_with_a_message() {
    let tmp = tempfile::tempdir().unwrap();
    let p = write(
        tmp.path(),
        "scattered.xyz",
        b"0 0 1\n1 0 1\n2.5 0 1\n0 1 1\n1 1 1\n2.5 1 1\n",
    );
    let m = fails(read_xyz(&p, 1.0, 1.0), &p, ErrorKind::Corrupt);
    assert!(
        m.contains("not a regular grid") && m.contains("not equally spaced"),
        "{m}"
    );
    let p = write(tmp.path(), "hole.xyz", b"0 0 1\n1 0 1\n0 1 1\n");
    let m = fails(read_xyz(&p, 1.0, 1.0), &p, ErrorKind::Corrupt);
    assert!(m.contains("not a regular grid"), "{m}");
    let p = write(tmp.path(), "twice.xyz", b"0 0 1\n1 0 1\n0 1 1\n0 1 2\n");
    let m = fails(read_xyz(&p, 1.0, 1.0), &p, ErrorKind::Corrupt);
    assert!(m.contains("appears twice"), "{m}");
    let p = write(tmp.path(), "line.xyz", b"0 0 1\n1 0 1\n2 0 1\n");
    fails(read_xyz(&p, 1.0, 1.0), &p, ErrorKind::NoData);
    // Units from a Gwyddion xyzexport header.
    let p = write(
        tmp.path(),
        "units.xyz",
        b"# Channel: Z\n# Lateral units: um\n# Value units: nm\n0 0 1\n2 0 1\n0 3 1\n2 3 4\n",
    );
    let t = read(&p).unwrap();
    assert_eq!((t.format, t.nx, t.ny), (Format::Xyz, 2, 2));
    assert!((t.dx_m - 2e-6).abs() < 1e-20 && (t.dy_m - 3e-6).abs() < 1e-20);
    assert!((t.heights_m[3] - 4e-9).abs() < 1e-22);
}

#[test]
fn unknown_and_missing_files_are_one_line() {
    let tmp = tempfile::tempdir().unwrap();
    let p = write(tmp.path(), "picture.png", b"\x89PNG\r\n\x1a\n\0\0\0");
    let m = fails(read(&p), &p, ErrorKind::UnknownFormat);
    assert!(m.contains("X3P") && m.contains(".png"), "{m}");
    let p = tmp.path().join("absent.x3p");
    fails(read(&p), &p, ErrorKind::Io);
    let p = tmp.path().join("absent.sur");
    fails(read_as(&p, Format::Sur), &p, ErrorKind::Io);
    // A file name with a line break still gives one line.
    let p = write(tmp.path(), "two\nlines.sur", b"DIGITAL SURF");
    let e = read(&p).unwrap_err();
    assert!(!e.to_string().contains('\n'), "{e}");
}

/// An empty `<Offset/>` is no offset (x3ptools writes one), and `main.xml` in one folder of
/// the archive is read from there with a note; in two folders it is refused naming both
/// (issue 39).
#[test]
fn x3p_empty_offset_and_a_folder_layout_are_read() {
    let tmp = tempfile::tempdir().unwrap();
    let data = i16s(&[1, 2, 3, 4]);
    let xml = main_xml(
        2,
        2,
        "I",
        "<Increment>1e-9</Increment><Offset/>",
        &data,
        "",
        "I",
    );
    let p = x3p(
        tmp.path(),
        "offset.x3p",
        &xml,
        &[("bindata/data.bin", &data)],
        None,
    );
    let raw_times_increment = [1.0, 2.0, 3.0, 4.0].map(|r| r * 1e-9);
    assert_eq!(read(&p).unwrap().heights_m, raw_times_increment);
    let zipped = |name: &str, folders: &[&str]| {
        let path = tmp.path().join(name);
        let mut z = zip::ZipWriter::new(std::fs::File::create(&path).unwrap());
        let opt = zip::write::SimpleFileOptions::default();
        // macOS's resource copies are no candidates.
        z.start_file("__MACOSX/land/main.xml", opt).unwrap();
        z.write_all(b"not xml").unwrap();
        for f in folders {
            for (n, b) in [
                ("main.xml", xml.as_bytes()),
                ("bindata/data.bin", &data[..]),
                (
                    "md5checksum.hex",
                    format!("{} *main.xml\n", md5_hex(xml.as_bytes())).as_bytes(),
                ),
            ] {
                z.start_file(format!("{f}/{n}"), opt).unwrap();
                z.write_all(b).unwrap();
            }
        }
        z.finish().unwrap();
        path
    };
    let p = zipped("folder.x3p", &["land"]);
    let t = read(&p).unwrap();
    assert_eq!(t.heights_m, raw_times_increment);
    assert_eq!(t.info_value("main.xml MD5"), Some("verified"));
    assert!(
        t.info_value("main.xml").unwrap().contains("land/"),
        "{:?}",
        t.info
    );
    let p = zipped("two.x3p", &["a", "b"]);
    let m = fails(read(&p), &p, ErrorKind::Corrupt);
    assert!(m.contains("`a/`") && m.contains("`b/`"), "{m}");
}

/// Two columns whose first rises in equal steps are an x, z line profile: named so and
/// refused, whether detected or read as a matrix on the user's word, so that no advice leads
/// to reading the positions as heights (issue 39).
#[test]
fn a_two_column_profile_is_named_and_refused() {
    let tmp = tempfile::tempdir().unwrap();
    let text: String = (0..200)
        .map(|i| {
            format!(
                "{:.6e} {:.6e}\n",
                i as f64 * 0.5e-6,
                1e-7 * (i as f64 * 0.7).sin()
            )
        })
        .collect();
    let p = write(tmp.path(), "profile.txt", text.as_bytes());
    let m = fails(read(&p), &p, ErrorKind::Unsupported);
    assert!(m.contains("line profile"), "{m}");
    let m = fails(read_matrix(&p, 1e-6, 1e-6, 1.0), &p, ErrorKind::Unsupported);
    assert!(m.contains("line profile"), "{m}");
    // Two columns of heights are a (narrow) surface.
    let text: String = (0..50)
        .map(|i| format!("{} {}\n", (i as f64 * 1.3).sin(), (i as f64 * 0.4).cos()))
        .collect();
    let p = write(tmp.path(), "narrow.txt", text.as_bytes());
    assert_eq!(read_matrix(&p, 1e-6, 1e-6, 1e-6).unwrap().nx, 2);
}
