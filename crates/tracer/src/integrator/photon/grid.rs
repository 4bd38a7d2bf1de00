//! A uniform hash grid over the photons of one pass (Teschner et al.,
//! "Optimized Spatial Hashing for Collision Detection of Deformable
//! Objects", VMV 2003, for the hash): cells as wide as the gather radius,
//! so a query visits the 27 cells around its point, each found in O(1).
//! The photons are sorted into buckets stably, in the order they were
//! emitted, so the map does not depend on the thread count.

use glam::{IVec3, Vec3};

use super::landed::Photon;

/// The photons of one pass, bucketed by cell.
#[derive(Clone, Debug)]
pub struct Grid {
    /// 1 / the cell's side, 1/m.
    inverse_cell: f32,
    /// Buckets − 1 (a power of two minus one).
    mask: usize,
    /// `photons[starts[b]..starts[b + 1]]` is bucket `b`.
    starts: Vec<u32>,
    photons: Vec<Photon>,
}

impl Grid {
    /// The grid of `photons` with cells of side `cell` (the gather radius).
    pub fn new(photons: Vec<Photon>, cell: f32) -> Grid {
        let inverse_cell = 1.0 / cell;
        let buckets = (2 * photons.len()).max(1).next_power_of_two();
        let mask = buckets - 1;
        let bucket_of = |p: &Photon| bucket(cell_of(p.point, inverse_cell), mask);
        let mut starts = vec![0u32; buckets + 1];
        for p in &photons {
            starts[bucket_of(p) + 1] += 1;
        }
        for b in 0..buckets {
            starts[b + 1] += starts[b];
        }
        let mut next = starts.clone();
        let mut sorted = photons.clone();
        for p in photons {
            let b = bucket_of(&p);
            sorted[next[b] as usize] = p;
            next[b] += 1;
        }
        Grid {
            inverse_cell,
            mask,
            starts,
            photons: sorted,
        }
    }

    /// The photons held.
    pub fn len(&self) -> usize {
        self.photons.len()
    }

    /// The photons held, bucket by bucket.
    pub fn photons(&self) -> &[Photon] {
        &self.photons
    }

    /// Whether no photon is held.
    pub fn is_empty(&self) -> bool {
        self.photons.is_empty()
    }

    /// Calls `f` once for each photon within `radius` (at most the cell's
    /// side) of `x`, in a fixed order.
    pub fn within(&self, x: Vec3, radius: f32, mut f: impl FnMut(&Photon)) {
        if self.photons.is_empty() {
            return;
        }
        let centre = cell_of(x, self.inverse_cell);
        // Neighbouring cells can share a bucket: each bucket once.
        let mut buckets = [0usize; 27];
        let mut i = 0;
        for dz in -1..=1 {
            for dy in -1..=1 {
                for dx in -1..=1 {
                    let cell = centre.wrapping_add(IVec3::new(dx, dy, dz));
                    buckets[i] = bucket(cell, self.mask);
                    i += 1;
                }
            }
        }
        buckets.sort_unstable();
        let r2 = radius * radius;
        let mut last = usize::MAX;
        for b in buckets {
            if b == last {
                continue;
            }
            last = b;
            let (start, end) = (self.starts[b] as usize, self.starts[b + 1] as usize);
            for p in &self.photons[start..end] {
                if (p.point - x).length_squared() <= r2 {
                    f(p);
                }
            }
        }
    }
}

/// The cell holding `x` (float-to-integer casts saturate, so a point far
/// outside `i32` cells lands in an edge cell; its neighbours wrap, and
/// the distance test keeps only the photons within the radius).
fn cell_of(x: Vec3, inverse_cell: f32) -> IVec3 {
    (x * inverse_cell).floor().as_ivec3()
}

fn bucket(cell: IVec3, mask: usize) -> usize {
    let h = (cell.x as u32).wrapping_mul(73_856_093)
        ^ (cell.y as u32).wrapping_mul(19_349_663)
        ^ (cell.z as u32).wrapping_mul(83_492_791);
    h as usize & mask
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::Pcg32;

    fn photon(point: Vec3) -> Photon {
        Photon {
            point,
            towards_source: Vec3::Y,
            flux: Vec3::ONE,
            object: 0,
            bounces: 1,
        }
    }

    /// The grid finds exactly the photons a brute-force search finds,
    /// each once, for points anywhere around and between the photons.
    #[test]
    fn a_query_finds_each_photon_within_the_radius_once_as_brute_force_does() {
        let mut rng = Pcg32::new(3, 5);
        let mut u = || rng.next_f32() * 2.0 - 1.0;
        let points: Vec<Vec3> = (0..2000).map(|_| Vec3::new(u(), u(), u())).collect();
        let radius = 0.1;
        let grid = Grid::new(points.iter().copied().map(photon).collect(), radius);
        for _ in 0..300 {
            let x = Vec3::new(u(), u(), u()) * 1.2;
            let mut found = Vec::new();
            grid.within(x, radius, |p| found.push(p.point.to_array()));
            let mut brute: Vec<[f32; 3]> = points
                .iter()
                .filter(|p| (**p - x).length_squared() <= radius * radius)
                .map(|p| p.to_array())
                .collect();
            found.sort_by(|a, b| a.partial_cmp(b).unwrap());
            brute.sort_by(|a, b| a.partial_cmp(b).unwrap());
            assert_eq!(found, brute);
        }
    }
}
