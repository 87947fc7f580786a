//! The one seeded random generator of the workspace's tests, benches and examples.
//!
//! Every test draws its random inputs from [`Rng`] with a fixed seed, so that a failure
//! reproduces and its tolerance was checked on exactly the inputs it will see again.
//! The generator is Marsaglia's xorshift64* (Vigna's multiplier, "An experimental
//! exploration of Marsaglia's xorshift generators, scrambled", 2016): 64 bits of state,
//! period 2^64 - 1, and output that passes BigCrush apart from the lowest bits, which no
//! helper here uses. It is not for cryptography.
//!
//! `no_std` without the default feature `std`, which only [`Rng::unit_array`] needs.

#![cfg_attr(not(feature = "std"), no_std)]

/// A seeded xorshift64* generator.
#[derive(Clone, Debug)]
pub struct Rng {
    state: u64,
}

/// The state a zero seed is replaced by: zero is xorshift's one fixed point.
const ZERO_SEED_REPLACEMENT: u64 = 0x9E37_79B9_7F4A_7C15;

impl Rng {
    /// A generator started from `seed`; a zero seed is replaced, since zero would give
    /// zeros for ever.
    #[must_use]
    pub const fn new(seed: u64) -> Self {
        let state = if seed == 0 {
            ZERO_SEED_REPLACEMENT
        } else {
            seed
        };
        Self { state }
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        let mut x = self.state;
        x ^= x >> 12;
        x ^= x << 25;
        x ^= x >> 27;
        self.state = x;
        x.wrapping_mul(0x2545_F491_4F6C_DD1D)
    }

    /// A uniform number in `[0, 1)` from the top 53 bits (every value a multiple of 2^-53).
    pub fn next_f64(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    /// A uniform number in `[0, 1)` from the top 24 bits (every value a multiple of 2^-24).
    pub fn next_f32(&mut self) -> f32 {
        (self.next_u64() >> 40) as f32 * (1.0 / (1u64 << 24) as f32)
    }

    /// A uniform number in `[lo, hi)`: `lo + (hi - lo) u` for `u` from [`Rng::next_f64`].
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next_f64()
    }

    /// A uniform number in `[-1, 1)`: [`Rng::uniform`]`(-1.0, 1.0)`, the range most tests
    /// draw components from.
    pub fn signed(&mut self) -> f64 {
        self.uniform(-1.0, 1.0)
    }

    /// A uniform `f32` in `[lo, hi)`: `lo + (hi - lo) u` for `u` from [`Rng::next_f32`].
    pub fn uniform_f32(&mut self, lo: f32, hi: f32) -> f32 {
        lo + (hi - lo) * self.next_f32()
    }

    /// `N` uniform numbers in `[lo, hi)`, drawn in order.
    pub fn uniform_array<const N: usize>(&mut self, lo: f64, hi: f64) -> [f64; N] {
        core::array::from_fn(|_| self.uniform(lo, hi))
    }

    /// `N` uniform `f32`s in `[lo, hi)` from 53-bit draws (each [`Rng::uniform`] rounded
    /// to `f32`), for `f32` tests that share their inputs with an `f64` twin.
    pub fn uniform_array_f32<const N: usize>(&mut self, lo: f64, hi: f64) -> [f32; N] {
        core::array::from_fn(|_| self.uniform(lo, hi) as f32)
    }

    /// A point on the unit sphere in `N` dimensions: a point of the cube `[-1, 1)^N`
    /// whose squared norm lies in `[1e-4, 1]` (rejection keeps the direction uniform and
    /// away from zero), scaled to unit length.
    #[cfg(feature = "std")]
    pub fn unit_array<const N: usize>(&mut self) -> [f64; N] {
        loop {
            let x: [f64; N] = self.uniform_array(-1.0, 1.0);
            let norm_squared: f64 = x.iter().map(|c| c * c).sum();
            if (1e-4..=1.0).contains(&norm_squared) {
                let inv = 1.0 / norm_squared.sqrt();
                return x.map(|c| c * inv);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The first outputs from seed 1, computed outside Rust from the recurrence's
    /// definition (shifts 12, 25, 27, then the multiplier, mod 2^64) in Python's integers:
    /// `x ^= x >> 12; x ^= (x << 25) & M; x ^= x >> 27; (x * 0x2545F4914F6CDD1D) & M`.
    #[test]
    fn first_outputs_match_an_independent_computation() {
        let mut rng = Rng::new(1);
        let expected = [
            0x47e4_ce4b_896c_dd1d_u64,
            0xabcf_a6a8_e079_651d,
            0xb9d1_0d8f_eb73_1f57,
        ];
        for e in expected {
            assert_eq!(rng.next_u64(), e);
        }
    }

    #[test]
    fn same_seed_gives_same_sequence_and_zero_seed_is_not_stuck() {
        let (mut a, mut b) = (Rng::new(7), Rng::new(7));
        for _ in 0..100 {
            assert_eq!(a.next_u64(), b.next_u64());
        }
        let mut zero = Rng::new(0);
        assert_ne!(zero.next_u64(), zero.next_u64());
    }

    #[test]
    fn uniform_stays_in_range_and_has_the_right_mean() {
        let mut rng = Rng::new(1);
        let n = 10_000;
        let mut sum = 0.0;
        for _ in 0..n {
            let x = rng.uniform(-2.0, 3.0);
            assert!((-2.0..3.0).contains(&x));
            sum += x;
        }
        // The mean of 10^4 uniform draws on an interval of width 5 has standard error
        // 5 / sqrt(12 * 10^4) = 0.014; 0.05 is over three of them.
        assert!(
            (sum / n as f64 - 0.5).abs() < 0.05,
            "mean {}",
            sum / n as f64
        );
        let mut lowest = 1.0_f32;
        let mut highest = -1.0_f32;
        for _ in 0..n {
            let x = rng.uniform_f32(-1.0, 1.0);
            assert!((-1.0..1.0).contains(&x));
            lowest = lowest.min(x);
            highest = highest.max(x);
        }
        assert!(lowest < -0.99 && highest > 0.99, "{lowest} {highest}");
    }

    #[cfg(feature = "std")]
    #[test]
    fn unit_array_has_unit_norm() {
        let mut rng = Rng::new(3);
        for _ in 0..1000 {
            let v: [f64; 4] = rng.unit_array();
            let n: f64 = v.iter().map(|c| c * c).sum();
            assert!((n - 1.0).abs() < 1e-12);
        }
    }
}
