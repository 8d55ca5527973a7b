//! Reads a measured scan of a surface — stylus profilometer, confocal or white-light
//! microscope, interferometer, AFM — into one height field in metres, so that a user can start
//! from a scan of their own wall (issue 29).
//!
//! ```no_run
//! let t = topography::read(std::path::Path::new("wall.x3p"))?;
//! println!("{} × {} points, {} m × {} m pixels, {} valid", t.nx, t.ny, t.dx_m, t.dy_m, t.valid_count());
//! # Ok::<(), topography::ReadError>(())
//! ```
//!
//! Formats ([`Format`]), one file each:
//! * ISO 25178-72 X3P (`x3p`), Digital Surf SUR (`sur`), Gwyddion Simple Field (`gsf`);
//! * Gwyddion's text export and the phase-map text export with a `pixel size =` header
//!   (`gwyddion_text`, `phase_text`); a plain matrix of numbers ([`read_matrix`]: it states no
//!   units) and x-y-z columns on a regular grid (`xyz`, [`read_xyz`]);
//! * Zygo MetroPro `.dat`, Wyko `.opd`, Sensofar `.plu` (`metropro`, `opd`, `plu`).
//!
//! The layouts follow the formats' specifications where they are public (X3P, GSF) and
//! otherwise the readers of SurfaceTopography 1.27.1 (`SurfaceTopography/IO/*.py`, MIT) and
//! Gwyddion (`modules/file/*.c`), cited in each file; the code is our own.
//! `tests/real_systems/surfacetopography.rs` of the workspace compares every value read from
//! the real instrument files of `tests/data/scans/` with SurfaceTopography's.
//!
//! Conventions. `heights_m[iy * nx + ix]`: x is the fast axis (a row of a text file, a row of
//! the binary raster), y the slow one, as the file stores them. Lengths are converted to metres
//! with the units the file states; a file that states none is refused unless the caller gives
//! them ([`read_matrix`], [`read_xyz`]). A point the file marks as missing (NaN, a validity
//! mask, a no-data code) is NaN, never zero. Sizes are checked before any allocation: a header
//! that claims more than [`MAX_POINTS`] points, or more data than the file holds, is refused.
//! Every failure is a [`ReadError`] whose `Display` is one line: the file, what is wrong, what
//! is allowed. Only regular files are opened (a FIFO would block, a device never end), and
//! no read goes past the size limit whatever size the file reports.

#![deny(missing_docs)]

mod bytes;
mod detect;
mod error;
mod grid;
mod gsf;
mod gwyddion_text;
mod matrix;
mod metropro;
mod opd;
mod phase_text;
mod plu;
mod sur;
mod text;
mod units;
mod x3p;
mod xml;
mod xyz;

use std::path::Path;

pub use error::{ErrorKind, ReadError};
pub use grid::MAX_POINTS;

/// A height field read from an instrument file.
#[derive(Debug, Clone, PartialEq)]
pub struct Topography {
    /// Points along x, the fast axis.
    pub nx: usize,
    /// Points along y.
    pub ny: usize,
    /// Pixel size along x in metres, from the file (or the caller for plain text).
    pub dx_m: f64,
    /// Pixel size along y in metres.
    pub dy_m: f64,
    /// Heights in metres, row-major: `heights_m[iy * nx + ix]`; NaN marks a missing or invalid
    /// point.
    pub heights_m: Vec<f64>,
    /// The format the file was read as.
    pub format: Format,
    /// What the file states beside the heights (instrument, date, channel, original units…),
    /// as (key, value) pairs in the order read.
    pub info: Vec<(String, String)>,
}

impl Topography {
    /// The number of valid (not NaN) points.
    pub fn valid_count(&self) -> usize {
        self.heights_m.iter().filter(|h| !h.is_nan()).count()
    }

    /// Whether the point (`ix`, `iy`) is measured; false outside the grid.
    pub fn is_valid(&self, ix: usize, iy: usize) -> bool {
        ix < self.nx && iy < self.ny && !self.heights_m[iy * self.nx + ix].is_nan()
    }

    /// The value of `key` in [`Topography::info`], if the file stated it.
    pub fn info_value(&self, key: &str) -> Option<&str> {
        self.info
            .iter()
            .find(|(k, _)| k == key)
            .map(|(_, v)| v.as_str())
    }
}

/// The file formats this crate reads.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Format {
    /// ISO 25178-72 XML 3D surface profile (`.x3p`): a zip of `main.xml` and binary points.
    X3p,
    /// Digital Surf `.sur` (MountainsMap), single surface object.
    Sur,
    /// Gwyddion Simple Field `.gsf`.
    Gsf,
    /// Gwyddion's plain-text export: `# Channel:`, `# Width:`, `# Height:`, `# Value units:`
    /// header lines, then a matrix.
    GwyddionText,
    /// Text export with `h=`, `w=`, `pixel size=` and `height conversion factor (-> m)=` header
    /// lines (a phase map in radians converted to heights), then a matrix.
    PhaseText,
    /// A plain matrix of numbers with no header: no units ([`read_matrix`]).
    Matrix,
    /// x, y, z columns on a regular grid ([`read_xyz`], or [`read`] when a header states units).
    Xyz,
    /// Zygo MetroPro `.dat`.
    MetroPro,
    /// Wyko (Bruker Vision) `.opd`.
    Opd,
    /// Sensofar `.plu` / `.apx`.
    Plu,
}

impl Format {
    /// Every format, in the order of the documentation.
    pub const ALL: [Format; 10] = [
        Format::X3p,
        Format::Sur,
        Format::Gsf,
        Format::GwyddionText,
        Format::PhaseText,
        Format::Matrix,
        Format::Xyz,
        Format::MetroPro,
        Format::Opd,
        Format::Plu,
    ];

    /// A short name (`x3p`, `sur`, `gsf`, `gwyddion_text`, `phase_text`, `matrix`, `xyz`,
    /// `metropro`, `opd`, `plu`).
    pub fn name(self) -> &'static str {
        match self {
            Format::X3p => "x3p",
            Format::Sur => "sur",
            Format::Gsf => "gsf",
            Format::GwyddionText => "gwyddion_text",
            Format::PhaseText => "phase_text",
            Format::Matrix => "matrix",
            Format::Xyz => "xyz",
            Format::MetroPro => "metropro",
            Format::Opd => "opd",
            Format::Plu => "plu",
        }
    }

    /// The format of a [`Format::name`].
    pub fn from_name(name: &str) -> Option<Format> {
        Format::ALL.into_iter().find(|f| f.name() == name)
    }
}

impl std::fmt::Display for Format {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// Reads `path`, detecting its format by its first bytes, then by its extension (`.plu` has
/// no magic bytes; text is told apart by its header lines).
pub fn read(path: &Path) -> Result<Topography, ReadError> {
    bytes::check_regular_file(path).map_err(|p| ReadError::new(path, p))?;
    let format = detect::detect(path).map_err(|p| ReadError::new(path, p))?;
    read_as(path, format)
}

/// Reads `path` as `format`. [`Format::Matrix`] is refused (a matrix states no units: use
/// [`read_matrix`]), and so is [`Format::Xyz`] when the file's header states no units (use
/// [`read_xyz`]).
pub fn read_as(path: &Path, format: Format) -> Result<Topography, ReadError> {
    bytes::check_regular_file(path).map_err(|p| ReadError::new(path, p))?;
    let result = match format {
        Format::X3p => x3p::read(path),
        Format::Sur => bytes::read_file(path).and_then(|b| sur::parse(&b)),
        Format::Gsf => bytes::read_file(path).and_then(|b| gsf::parse(&b)),
        Format::GwyddionText => gwyddion_text::read(path),
        Format::PhaseText => phase_text::read(path),
        Format::Matrix => Err(error::Problem::new(
            ErrorKind::NoUnits,
            "a plain matrix of numbers states no pixel size and no unit: read it with \
             read_matrix(path, dx_m, dy_m, unit_m), or add a Gwyddion header \
             (# Width: 10 µm, # Height: 10 µm, # Value units: m)",
        )),
        Format::Xyz => xyz::read(path, None),
        Format::MetroPro => bytes::read_file(path).and_then(|b| metropro::parse(&b)),
        Format::Opd => bytes::read_file(path).and_then(|b| opd::parse(&b)),
        Format::Plu => bytes::read_file(path).and_then(|b| plu::parse(&b)),
    };
    result
        .and_then(grid::finish)
        .map_err(|p| ReadError::new(path, p))
}

/// Reads a plain matrix of numbers: one row of the file per y, one column per x, separated by
/// whitespace, commas or semicolons; lines starting with `#` are skipped; `NaN`, `nan`, `bad`
/// and infinities mark missing points. The file states no units: `dx_m`, `dy_m` are the pixel
/// sizes in metres and `unit_m` is the length of one height unit in metres (1e-6 for heights
/// in µm).
pub fn read_matrix(
    path: &Path,
    dx_m: f64,
    dy_m: f64,
    unit_m: f64,
) -> Result<Topography, ReadError> {
    bytes::check_regular_file(path)
        .and_then(|()| matrix::read(path, dx_m, dy_m, unit_m))
        .and_then(grid::finish)
        .map_err(|p| ReadError::new(path, p))
}

/// Reads x, y, z columns (whitespace, comma or semicolon separated, any order of the points)
/// that lie on a regular grid; a scattered or incomplete grid is refused. Positions are in units
/// of `xy_unit_m` metres and heights in units of `z_unit_m` metres; a header the file has
/// (`# Lateral units:`, `# Value units:`) is ignored in favour of these.
pub fn read_xyz(path: &Path, xy_unit_m: f64, z_unit_m: f64) -> Result<Topography, ReadError> {
    bytes::check_regular_file(path)
        .and_then(|()| xyz::read(path, Some((xy_unit_m, z_unit_m))))
        .and_then(grid::finish)
        .map_err(|p| ReadError::new(path, p))
}
