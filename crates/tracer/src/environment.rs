//! The environment: the radiance that rays leaving the scene receive, as a
//! function of their direction alone (`001`, "Környezet leképezés"). Where
//! a scene has one, it replaces the constant `background` for every ray
//! that misses everything, so a mirror reflects it as the camera sees it.
//!
//! Directions are mapped to texels by `techniques::envmap` and nowhere else
//! ([`LatLong`], [`CubeTexel`]): the slides' maps, in the scene's own
//! (world) frame, `−z` the lat-long map's pole `v = 0`.
//!
//! | kind | what | |
//! |---|---|---|
//! | [`Environment::DirectionColour`] | `scale · (d + 1) / 2` along unit `d` | procedural, exact: for tests |
//! | [`Environment::LatLong`] | a `2h × h` image, `u` across, `v` down | the slides' latitude–longitude map |
//! | [`Environment::Cube`] | six square faces of one side, OpenGL's order, from six images or one cross ([`CROSS`]) | the slides' cube map; also what `capture::capture_cube` makes |
//!
//! **Texels.** Row 0 of an image is `v = 0` and column 0 is `u = 0` (the
//! first row of a texture upload is `t = 0` in OpenGL). Texel `(i, j)` of
//! a `w × h` image covers `u ∈ [i/w, (i+1)/w]`, `v ∈ [j/h, (j+1)/h]` and
//! holds the radiance of its centre. A lookup filters bilinearly between
//! the four nearest centres, as `GL_LINEAR` does: across the lat-long
//! map's seam `u = 0 ≡ 1` it wraps, at its poles and at a cube face's
//! edges it clamps to the edge texel.
//!
//! **Assumption**, the slides': what is stored is infinitely far away, so
//! only a ray's direction matters, never where it starts. How wrong that
//! is for surroundings at a finite distance is measured in
//! `docs/techniques.md` ("Environment mapping against ray tracing").

use std::fmt;

use glam::Vec3;
use techniques::envmap::cube::{CubeTexel, Face};
use techniques::envmap::lat_long::LatLong;
use techniques::envmap::Direction;

/// An image of linear radiance, W/(sr·m²) per channel, rows top (`v = 0`)
/// to bottom.
#[derive(Clone, PartialEq)]
pub struct Texels {
    width: u32,
    height: u32,
    texels: Vec<Vec3>,
}

impl fmt::Debug for Texels {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Texels({} × {})", self.width, self.height)
    }
}

impl Texels {
    /// `width × height` texels, rows top to bottom; `None` unless there
    /// are exactly that many and each side is at least 1.
    pub fn new(width: u32, height: u32, texels: Vec<Vec3>) -> Option<Self> {
        let count = u64::from(width) * u64::from(height);
        (width > 0 && height > 0 && texels.len() as u64 == count).then_some(Texels {
            width,
            height,
            texels,
        })
    }

    /// Width, texels.
    pub fn width(&self) -> u32 {
        self.width
    }

    /// Height, texels.
    pub fn height(&self) -> u32 {
        self.height
    }

    /// The texel at column `i`, row `j`.
    pub fn get(&self, i: u32, j: u32) -> Vec3 {
        self.texels[(j as usize) * (self.width as usize) + i as usize]
    }

    /// The bilinear mean of the four texel centres around `(u, v)`;
    /// columns wrap when `wrap_u` (the lat-long seam), else clamp.
    fn bilinear(&self, u: f64, v: f64, wrap_u: bool) -> Vec3 {
        bilinear(&self.texels, self.width, self.height, u, v, wrap_u)
    }
}

/// The bilinear mean of the four centres around `(u, v)` of the
/// `width × height` texels `texels`, rows top to bottom; columns wrap when
/// `wrap_u`, else clamp, and rows clamp. Indexes `texels` by the sides it
/// is given: a caller that gives sides larger than the image panics.
fn bilinear(texels: &[Vec3], width: u32, height: u32, u: f64, v: f64, wrap_u: bool) -> Vec3 {
    let (w, h) = (i64::from(width), i64::from(height));
    let x = u * w as f64 - 0.5;
    let y = v * h as f64 - 0.5;
    let (x0, y0) = (x.floor(), y.floor());
    let (fx, fy) = ((x - x0) as f32, (y - y0) as f32);
    let column = |i: i64| {
        if wrap_u {
            i.rem_euclid(w)
        } else {
            i.clamp(0, w - 1)
        }
    };
    let (x0, y0) = (x0 as i64, y0 as i64);
    let at = |i: i64, j: i64| texels[(j.clamp(0, h - 1) * w + column(i)) as usize];
    let top = at(x0, y0) * (1.0 - fx) + at(x0 + 1, y0) * fx;
    let bottom = at(x0, y0 + 1) * (1.0 - fx) + at(x0 + 1, y0 + 1) * fx;
    top * (1.0 - fy) + bottom * fy
}

/// Six square faces of one side, in [`Face::ALL`]'s order (`+X, −X, +Y,
/// −Y, +Z, −Z`), oriented as `techniques::envmap::cube` (OpenGL's
/// Table 8.19). A cube map has one side: every face is read by it.
#[derive(Clone, Debug, PartialEq)]
pub struct CubeMap {
    side: u32,
    faces: Vec<Texels>,
}

impl CubeMap {
    /// The cube map of `faces`, in [`Face::ALL`]'s order, each
    /// `side × side`: checked once, where the faces enter (the scene
    /// reader, for files; `capture::capture_cube`, which makes them so), and
    /// trusted by every lookup.
    pub(crate) fn of_side(side: u32, faces: Vec<Texels>) -> Self {
        CubeMap { side, faces }
    }

    /// The side of every face, texels.
    pub fn side(&self) -> u32 {
        self.side
    }

    /// The face `face`.
    pub fn face(&self, face: Face) -> &Texels {
        &self.faces[face_index(face)]
    }

    /// The filtered radiance at `(u, v)` of `face`, clamped at its edges.
    fn bilinear(&self, face: Face, u: f64, v: f64) -> Vec3 {
        let texels = &self.faces[face_index(face)].texels;
        bilinear(texels, self.side, self.side, u, v, false)
    }
}

/// The horizontal cross: where each face of [`Face::ALL`] lies in a
/// cube map given as one image four faces wide and three high, as
/// `(column, row)` in faces, each face as is (its `u` across, its `v`
/// down, as in its own file). The middle row is `−X, +Z, +X, −Z`, with `+Y`
/// above `+Z` and `−Y` below it: with Table 8.19's orientations this is
/// the one such cross that runs on across every edge where two faces
/// touch (`tests::the_cross_runs_on_across_its_inner_edges`).
pub const CROSS: [(u32, u32); 6] = [(2, 1), (0, 1), (1, 0), (1, 2), (1, 1), (3, 1)];

/// The six faces cut from a cross image of faces of `side` texels, in
/// [`Face::ALL`]'s order. The caller has checked that `cross` is
/// `4 side × 3 side`.
pub(crate) fn cut_cross(cross: &Texels, side: u32) -> Vec<Texels> {
    CROSS
        .iter()
        .map(|&(column, row)| {
            let texels = (0..side * side)
                .map(|k| cross.get(column * side + k % side, row * side + k / side))
                .collect();
            Texels {
                width: side,
                height: side,
                texels,
            }
        })
        .collect()
}

/// The place of `face` in [`Face::ALL`].
fn face_index(face: Face) -> usize {
    match face {
        Face::PositiveX => 0,
        Face::NegativeX => 1,
        Face::PositiveY => 2,
        Face::NegativeY => 3,
        Face::PositiveZ => 4,
        Face::NegativeZ => 5,
    }
}

/// What rays that leave the scene receive, by direction.
#[derive(Clone, Debug, PartialEq)]
pub enum Environment {
    /// `scale · (d + 1) / 2` along the unit direction `d`: the normal-colour
    /// sky, smooth and exact, for tests.
    DirectionColour {
        /// Radiance of `(1, 1, 1)`'s channel at full colour, W/(sr·m²).
        scale: f32,
    },
    /// A latitude–longitude image, `2h × h`, times `scale`.
    LatLong {
        /// The image's linear values.
        texels: Texels,
        /// Multiplies every texel.
        scale: f32,
    },
    /// A cube map, times `scale`.
    Cube {
        /// The faces' linear values.
        map: CubeMap,
        /// Multiplies every texel.
        scale: f32,
    },
}

impl Environment {
    /// The radiance arriving along a ray that travels in `direction` and
    /// meets nothing (any non-zero length; the map normalises it once, by
    /// `techniques::envmap::Direction::new`). A direction that is no
    /// direction (zero or not finite, which no traced ray has) sees black.
    pub fn radiance(&self, direction: Vec3) -> Vec3 {
        let Ok(d) = Direction::new(direction.as_dvec3()) else {
            return Vec3::ZERO;
        };
        match self {
            Environment::DirectionColour { scale } => {
                (d.get().as_vec3() + Vec3::ONE) * 0.5 * *scale
            }
            Environment::LatLong { texels, scale } => {
                let t = LatLong::from_direction(d);
                texels.bilinear(t.u(), t.v(), true) * *scale
            }
            Environment::Cube { map, scale } => {
                let t = CubeTexel::from_direction(d);
                map.bilinear(t.face(), t.u(), t.v()) * *scale
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn ramp(width: u32, height: u32) -> Texels {
        let texels = (0..width * height)
            .map(|k| Vec3::new((k % width) as f32, (k / width) as f32, 1.0))
            .collect();
        Texels::new(width, height, texels).unwrap()
    }

    /// At a texel's centre the filter returns that texel exactly; half way
    /// between two centres, their mean (exact in binary: 0.5).
    #[test]
    fn bilinear_filtering_meets_the_texel_centres() {
        let t = ramp(4, 2);
        assert_eq!(
            t.bilinear(2.5 / 4.0, 0.5 / 2.0, false),
            Vec3::new(2.0, 0.0, 1.0)
        );
        assert_eq!(
            t.bilinear(2.0 / 4.0, 0.5 / 2.0, false),
            Vec3::new(1.5, 0.0, 1.0)
        );
        // Across the seam the last column meets the first.
        assert_eq!(t.bilinear(0.0, 0.5 / 2.0, true), Vec3::new(1.5, 0.0, 1.0));
        // Clamped at the edge instead.
        assert_eq!(t.bilinear(0.0, 0.5 / 2.0, false), Vec3::new(0.0, 0.0, 1.0));
    }

    /// Where two faces of the cross touch, the directions on either side
    /// of the edge are one (to 1e-15): the cross is the cube unfolded.
    #[test]
    fn the_cross_runs_on_across_its_inner_edges() {
        let at = |column: u32, row: u32| {
            let k = CROSS.iter().position(|&p| p == (column, row))?;
            Some(Face::ALL[k])
        };
        let mut edges = 0;
        for (k, &(column, row)) in CROSS.iter().enumerate() {
            let face = Face::ALL[k];
            for (right, below) in [(1, 0), (0, 1)] {
                let Some(next) = at(column + right, row + below) else {
                    continue;
                };
                edges += 1;
                for t in [0.1, 0.5, 0.9] {
                    let ((u0, v0), (u1, v1)) = if right == 1 {
                        ((1.0, t), (0.0, t))
                    } else {
                        ((t, 1.0), (t, 0.0))
                    };
                    let a = CubeTexel::from_uv(face, u0, v0).unwrap().direction().get();
                    let b = CubeTexel::from_uv(next, u1, v1).unwrap().direction().get();
                    assert!((a - b).length() < 1e-15, "{face:?} | {next:?} at {t}");
                }
            }
        }
        // −X|+Z, +Z|+X, +X|−Z across; +Y over +Z, +Z over −Y.
        assert_eq!(edges, 5);
    }

    #[test]
    fn texels_refuse_a_count_that_is_not_their_size() {
        assert!(Texels::new(2, 2, vec![Vec3::ZERO; 3]).is_none());
        assert!(Texels::new(0, 2, Vec::new()).is_none());
        assert!(Texels::new(2, 1, vec![Vec3::ZERO; 2]).is_some());
    }
}
