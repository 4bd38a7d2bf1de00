//! Why an environment's image file cannot be its map, in English.

use std::fmt;

/// Why an environment's image file cannot be its map.
#[derive(Debug)]
pub enum ImageProblem {
    /// The file could not be read: the operating system's reason.
    Read(std::io::Error),
    /// Not a PNG the decoder reads: its description (a bad signature or
    /// checksum, data cut short, a header past the decoder's limits).
    Decode(String),
    /// A PNG whose pixels are not 8-bit RGB or RGBA: the colour type.
    Pixels(String),
    /// A size its map cannot have.
    Size {
        /// Width, pixels.
        width: u32,
        /// Height, pixels.
        height: u32,
        /// What the map needs.
        expected: SizeRule,
    },
}

/// What size an environment image must have.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SizeRule {
    /// A latitude–longitude map: width twice the height (360° by 180°).
    TwiceAsWideAsHigh,
    /// A cube face: square.
    Square,
    /// A cube cross: four faces wide and three high, the faces square.
    FourByThreeFaces,
    /// A cube face after the first: the first face's side, pixels.
    SideOfFirstFace(u32),
    /// Any image: each side at most this many pixels.
    AtMost(u32),
}

impl fmt::Display for ImageProblem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ImageProblem::Read(source) => write!(f, "cannot be read: {source}"),
            ImageProblem::Decode(message) => {
                write!(f, "is not a PNG that can be decoded: {message}")
            }
            ImageProblem::Pixels(format) => {
                write!(
                    f,
                    "has {format} pixels; an environment is 8-bit RGB or RGBA"
                )
            }
            ImageProblem::Size {
                width,
                height,
                expected,
            } => {
                write!(f, "is {width} × {height} pixels; ")?;
                match expected {
                    SizeRule::TwiceAsWideAsHigh => {
                        f.write_str("a lat-long map is twice as wide as high")
                    }
                    SizeRule::Square => f.write_str("a cube face is square"),
                    SizeRule::FourByThreeFaces => {
                        f.write_str("a cube cross is four square faces wide and three high")
                    }
                    SizeRule::SideOfFirstFace(side) => write!(
                        f,
                        "every cube face has the first face's side, {side} pixels"
                    ),
                    SizeRule::AtMost(side) => write!(f, "each side is at most {side} pixels"),
                }
            }
        }
    }
}
