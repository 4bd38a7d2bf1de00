//! The camera paths' sample numbers: a scrambled Sobol (0,2)-sequence per
//! pair of dimensions, so that a pixel's samples are stratified in every
//! pair they draw, not only in the pixel position.
//!
//! A pixel's sample `k` draws its numbers in order, one *dimension slot*
//! at a time ([`Sample::next_2d`], [`Sample::next_1d`]): the pixel position,
//! then at each vertex of its path the scattering pair and the Russian
//! roulette number. Slot `d` of sample `k` is point `k'` of the first two
//! dimensions of Sobol's sequence (a (0,2)-sequence in base 2: every
//! power-of-two block of `2^m` points aligned on a multiple of `2^m` puts
//! one point in each elementary interval of area `2^-m`), where:
//!
//! - each coordinate is Owen-scrambled: a *nested uniform scramble*, which
//!   flips each bit of the fraction by a random function of the bits
//!   above it, so every point is uniform over the unit square and every
//!   elementary interval of a net goes to another one whole (A. B. Owen,
//!   "Randomly permuted (t,m,s)-nets and (t,s)-sequences", 1995);
//! - the index is shuffled, `k' = scramble(k)`, by a nested uniform
//!   scramble of its own, which keeps the first `2^m` samples an aligned
//!   block of `2^m` Sobol points (still a net) but a different block in
//!   each slot, so that no two slots are correlated through the index;
//! - the scrambles are hash-based (B. Burley, "Practical Hash-based Owen
//!   Scrambling", JCGT 9(4), 2020): reversing the bits turns "depends on
//!   the bits above" into "depends on the bits below", which the carries
//!   of an addition and of a multiplication provide, each seeded by a hash
//!   of `(seed, pixel, slot)`.
//!
//! So the image depends on the seed alone, never on the threads; each
//! number is uniform, so every estimate stays unbiased; and over a pixel's
//! samples, a smooth integrand's error falls faster than `1/√N`. The photon
//! map's photons keep their plain PCG32 streams (`crate::rng`): each photon
//! is one sample of its own.

use crate::rng::splitmix64;

/// Keeps the samplers' keys apart from the PCG streams' ("SAMPLER" in ASCII).
const SAMPLER_SALT: u64 = 0x0053_414D_504C_4552;

/// The samples of one pixel of one render.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Sampler {
    key: u64,
    /// Slot 0's seeds, the same for every sample of the pixel: worked out
    /// once here, not once per sample (the box filter's pair is drawn from
    /// slot 0 by every sample of every pixel).
    first: [u32; 3],
}

/// One sample of a pixel: its numbers, drawn one dimension slot at a time.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Sample {
    key: u64,
    index: u32,
    slot: u32,
    first: [u32; 3],
}

impl Sampler {
    /// The samples of pixel `pixel` (or any other index of a camera ray,
    /// such as a cube map's texel) of a render with seed `seed`.
    pub fn for_pixel(seed: u64, pixel: u64) -> Self {
        let key = splitmix64(seed ^ splitmix64(pixel ^ SAMPLER_SALT));
        Sampler {
            key,
            first: slot_seeds(key, 0),
        }
    }

    /// Sample `index` (0-based) of this pixel, before its first number.
    pub fn sample(&self, index: u32) -> Sample {
        Sample {
            key: self.key,
            index,
            slot: 0,
            first: self.first,
        }
    }
}

impl Sample {
    /// The next slot's pair, each number uniform in `[0, 1)`; over the
    /// pixel's samples `0..2^m` the pairs of one slot are a (0, m, 2)-net.
    #[inline]
    pub fn next_2d(&mut self) -> [f32; 2] {
        let seeds = self.next_seeds();
        let i = shuffled(self.index, seeds[0]);
        // `owen_scramble(sobol_0(i), s)` and `owen_scramble(sobol_1(i), s)`,
        // their bits, with the scramble entered in its mirrored form: the
        // van der Corput point mirrored is `i` itself, and Sobol's second
        // dimension mirrored is the superset sum of `i`'s bits.
        [
            unit(scramble_mirrored(i, seeds[1])),
            unit(scramble_mirrored(sobol_1_mirrored(i), seeds[2])),
        ]
    }

    /// The next slot's number, uniform in `[0, 1)`: the first coordinate of
    /// the slot's pair, so a pixel's first `2^m` samples of one slot put one
    /// number in each interval of length `2^-m`.
    pub fn next_1d(&mut self) -> f32 {
        self.take_1d().value()
    }

    /// The next slot, counted now, its number worked out only if asked
    /// ([`Slot1d::value`], the bits of [`Sample::next_1d`]): a path takes
    /// its slots in the same order whatever it meets, but uses some of
    /// their numbers only on some surfaces (a lobe choice at glass, not
    /// at a conductor; the roulette number where the roulette is played).
    pub fn take_1d(&mut self) -> Slot1d {
        let slot = Slot1d {
            key: self.key,
            index: self.index,
            slot: self.slot,
        };
        self.slot += 1;
        slot
    }

    /// How many slots this sample has drawn.
    pub fn slots_drawn(&self) -> u32 {
        self.slot
    }

    /// The three seeds of the next slot, and the slot counted.
    fn next_seeds(&mut self) -> [u32; 3] {
        let seeds = match self.slot {
            0 => self.first,
            slot => slot_seeds(self.key, slot),
        };
        self.slot += 1;
        seeds
    }
}

/// A slot of one sample, taken in order by [`Sample::take_1d`], its
/// number not yet worked out.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Slot1d {
    key: u64,
    index: u32,
    slot: u32,
}

impl Slot1d {
    /// The slot's number, uniform in `[0, 1)`: what [`Sample::next_1d`]
    /// would have drawn there.
    pub fn value(&self) -> f32 {
        let seeds = slot_seeds(self.key, self.slot);
        // `owen_scramble(sobol_0(i), s)`, as in [`Sample::next_2d`].
        unit(scramble_mirrored(shuffled(self.index, seeds[0]), seeds[1]))
    }
}

/// The three 32-bit seeds of slot `slot` of a pixel's samples (the
/// index's shuffle and the two coordinates' scrambles).
fn slot_seeds(key: u64, slot: u32) -> [u32; 3] {
    let h = splitmix64(key ^ slot as u64);
    let g = splitmix64(h);
    [h as u32, (h >> 32) as u32, g as u32]
}

/// The sample index seen by one slot: a nested uniform scramble of `index`
/// (bits above a power-of-two prefix's are flipped alike, so the prefix
/// stays an aligned block of Sobol points).
fn shuffled(index: u32, seed: u32) -> u32 {
    owen_scramble(index, seed)
}

/// Dimension 0 of Sobol's sequence, the base-2 van der Corput sequence:
/// the index's bits mirrored about the binary point, as a 32-bit fraction.
#[cfg(test)]
fn sobol_0(index: u32) -> u32 {
    index.reverse_bits()
}

/// Dimension 1 of Sobol's sequence: its generator matrix is Pascal's
/// triangle mod 2, column `j` `v_j = v_{j-1} ^ (v_{j-1} >> 1)` from
/// `v_0 = 1/2` (I. M. Sobol', 1967; primitive polynomial `x + 1`); the
/// point is the xor of the columns of the index's set bits
/// ([`sobol_1_mirrored`], mirrored back).
#[cfg(test)]
fn sobol_1(index: u32) -> u32 {
    sobol_1_mirrored(index).reverse_bits()
}

/// [`sobol_1`]'s point mirrored (its bit `i` from the binary point is bit
/// `i` here). Pascal's triangle mod 2 has `C(j, i)` odd exactly where the
/// bits of `i` are a subset of those of `j` (Lucas' theorem), so bit `i`
/// of the point is the xor of the index's bits `j ⊇ i`: the superset sum
/// over the five bits of a bit's position, one xor-shift per bit, each
/// adding to bit `i` (where that bit of `i` is clear) bit `i + 2^b`.
fn sobol_1_mirrored(index: u32) -> u32 {
    let mut x = index;
    x ^= (x >> 1) & 0x5555_5555;
    x ^= (x >> 2) & 0x3333_3333;
    x ^= (x >> 4) & 0x0f0f_0f0f;
    x ^= (x >> 8) & 0x00ff_00ff;
    x ^= (x >> 16) & 0x0000_ffff;
    x
}

/// The generator's columns `v_0 … v_31`.
#[cfg(test)]
const SOBOL_1_COLUMNS: [u32; 32] = {
    let mut v = [0; 32];
    v[0] = 1 << 31;
    let mut j = 1;
    while j < 32 {
        v[j] = v[j - 1] ^ (v[j - 1] >> 1);
        j += 1;
    }
    v
};

/// A nested uniform scramble of the 32-bit fraction `x`: bit `b` (from
/// the top) flipped by a function of `seed` and the bits above it only.
/// Mirrored, those are the bits *below*, and an operation whose output bit
/// `b` is input bit `b` xor a function of the lower bits is a bijection
/// of that kind; composing several keeps the kind. The steps: adding the
/// seed (its carries), multiplying by an odd number drawn from the seed,
/// and three `x ^= x · c` with even constants `c` (bit `b` of `x · c`
/// depends on bits below `b` only), which spread each bit's influence to
/// the bits above it. The even constants are those of the paper's
/// hash (any even numbers keep the kind; these mix well).
fn owen_scramble(x: u32, seed: u32) -> u32 {
    scramble_mirrored(x.reverse_bits(), seed)
}

/// [`owen_scramble`] of the fraction whose mirror image is `y`: the
/// scramble's steps on the mirrored bits, and the result mirrored back.
fn scramble_mirrored(mut y: u32, seed: u32) -> u32 {
    y = y.wrapping_add(seed);
    y ^= y.wrapping_mul(0x6c50_b47c);
    y = y.wrapping_mul(seed.rotate_right(16) | 1);
    y ^= y.wrapping_mul(0xb82f_1e52);
    y ^= y.wrapping_mul(0xc7af_e638);
    y.reverse_bits()
}

/// The top 24 bits of a 32-bit fraction, exact in `f32`, in `[0, 1)`.
fn unit(x: u32) -> f32 {
    (x >> 8) as f32 * (1.0 / 16_777_216.0)
}

#[cfg(test)]
mod tests;
