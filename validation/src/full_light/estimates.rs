//! Mitsuba's estimates and the image regions they apply to.

/// One of Mitsuba's three estimates.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Estimate {
    /// Mitsuba's `path` with the delta lights: what a path tracer finds.
    Path,
    /// Mitsuba's light tracer: all the light seen directly on diffuse surfaces.
    Ptracer,
    /// Mitsuba's `path` with area lights of equal power: all the light.
    Area,
    /// Mitsuba's `path` with the delta lights through the pixel centres, as
    /// the tracer samples them (the others average over the pixel).
    PathCentres,
}

impl Estimate {
    /// All three, in the reference's order.
    pub const ALL: [Estimate; 4] = [
        Estimate::Path,
        Estimate::Ptracer,
        Estimate::Area,
        Estimate::PathCentres,
    ];

    /// The reference's key.
    pub fn name(self) -> &'static str {
        self.names()[0]
    }

    /// The reference's key, and the estimate in Hungarian.
    pub fn names(self) -> [&'static str; 2] {
        match self {
            Estimate::Path => ["path", "útkövetés"],
            Estimate::Ptracer => ["ptracer", "fénykövetés"],
            Estimate::Area => ["area", "felületi fények"],
            Estimate::PathCentres => ["path_centres", "path_centres"],
        }
    }
}

/// A region of the image, by what the camera sees first there (at the
/// pixel's centre and its eight neighbours').
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Region {
    /// A diffuse surface: all three estimates apply.
    Diffuse,
    /// Any surface: the light tracer does not apply (it cannot see through
    /// a delta surface).
    Surface,
}

impl Region {
    /// Both.
    pub const ALL: [Region; 2] = [Region::Diffuse, Region::Surface];

    /// The reference's key.
    pub fn name(self) -> &'static str {
        self.names()[0]
    }

    /// The reference's key, and the region in Hungarian.
    pub fn names(self) -> [&'static str; 2] {
        match self {
            Region::Diffuse => ["diffuse", "diffúz"],
            Region::Surface => ["surface", "felület"],
        }
    }

    /// The estimates of all the light that apply here.
    pub fn full_light(self) -> &'static [Estimate] {
        match self {
            Region::Diffuse => &[Estimate::Ptracer, Estimate::Area],
            Region::Surface => &[Estimate::Area],
        }
    }
}
