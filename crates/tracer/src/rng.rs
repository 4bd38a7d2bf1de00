//! The path tracer's random numbers: PCG32 (M. E. O'Neill, "PCG: A Family of
//! Simple Fast Space-Efficient Statistically Good Algorithms for Random
//! Number Generation", 2014, `pcg32_random_r` of the reference C code),
//! seeded through SplitMix64 (Steele, Lea and Flood, OOPSLA 2014).
//!
//! Each pixel gets its own stream from `(seed, pixel index)`, and each
//! photon of the photon map its own from `(seed, pass, photon index)`, so
//! an image depends on the seed only, never on how pixels or photons are
//! shared among threads.

/// A PCG32 generator: 64-bit LCG state, XSH-RR output.
#[derive(Clone, Debug)]
pub struct Pcg32 {
    state: u64,
    increment: u64,
}

const MULTIPLIER: u64 = 6364136223846793005;

/// Keeps the photons' streams apart from the pixels' ("PHOTONS" in ASCII).
const PHOTON_SALT: u64 = 0x0050_484F_544F_4E53;

/// SplitMix64's step: a bijective 64-bit mixer.
pub fn splitmix64(x: u64) -> u64 {
    let mut z = x.wrapping_add(0x9E37_79B9_7F4A_7C15);
    z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
    z ^ (z >> 31)
}

impl Pcg32 {
    /// The reference `pcg32_srandom_r(initstate, initseq)`.
    pub fn new(init_state: u64, init_seq: u64) -> Self {
        let mut rng = Pcg32 {
            state: 0,
            increment: (init_seq << 1) | 1,
        };
        rng.next_u32();
        rng.state = rng.state.wrapping_add(init_state);
        rng.next_u32();
        rng
    }

    /// The stream of one pixel of one render.
    pub fn for_pixel(seed: u64, pixel: u64) -> Self {
        Pcg32::new(splitmix64(seed ^ splitmix64(pixel)), splitmix64(pixel))
    }

    /// The stream of photon `index` of pass `pass` of one render, apart
    /// from every pixel's (the key is salted before it is mixed).
    pub fn for_photon(seed: u64, pass: u32, index: u32) -> Self {
        let key = splitmix64(((pass as u64) << 32 | index as u64) ^ PHOTON_SALT);
        Pcg32::new(splitmix64(seed ^ key), key)
    }

    /// The next 32 random bits.
    pub fn next_u32(&mut self) -> u32 {
        let old = self.state;
        self.state = old.wrapping_mul(MULTIPLIER).wrapping_add(self.increment);
        let xorshifted = (((old >> 18) ^ old) >> 27) as u32;
        let rot = (old >> 59) as u32;
        xorshifted.rotate_right(rot)
    }

    /// Uniform in `[0, 1)`: the top 24 bits, so every value is exact in `f32`.
    pub fn next_f32(&mut self) -> f32 {
        (self.next_u32() >> 8) as f32 * (1.0 / 16_777_216.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The first outputs of the reference implementation's demo
    /// (`pcg32-demo.c`, seeded with `pcg32_srandom_r(&rng, 42u, 54u)`),
    /// as printed in the PCG distribution's expected output.
    #[test]
    fn pcg32_matches_the_reference_sequence() {
        let mut rng = Pcg32::new(42, 54);
        let expected = [
            0xa15c02b7, 0x7b47f409, 0xba1d3330, 0x83d2f293, 0xbfa4784b, 0xcbed606e,
        ];
        for want in expected {
            assert_eq!(rng.next_u32(), want);
        }
    }

    #[test]
    fn uniform_floats_lie_in_the_unit_interval_with_the_right_mean() {
        let mut rng = Pcg32::for_pixel(7, 123);
        let n = 100_000;
        let mut sum = 0.0_f64;
        for _ in 0..n {
            let u = rng.next_f32();
            assert!((0.0..1.0).contains(&u));
            sum += u as f64;
        }
        // The mean of n uniforms has standard deviation 1/√(12 n) ≈ 0.00091;
        // 5 standard deviations.
        assert!((sum / n as f64 - 0.5).abs() < 5.0 * 0.000_913);
    }

    #[test]
    fn pixel_streams_differ_and_repeat() {
        let a: Vec<u32> = (0..4)
            .map({
                let mut r = Pcg32::for_pixel(1, 0);
                move |_| r.next_u32()
            })
            .collect();
        let b: Vec<u32> = (0..4)
            .map({
                let mut r = Pcg32::for_pixel(1, 1);
                move |_| r.next_u32()
            })
            .collect();
        let a2: Vec<u32> = (0..4)
            .map({
                let mut r = Pcg32::for_pixel(1, 0);
                move |_| r.next_u32()
            })
            .collect();
        assert_ne!(a, b);
        assert_eq!(a, a2);
    }
}
