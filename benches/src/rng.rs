//! A seeded xorshift64* generator: enough randomness for bench inputs, no dependency.

/// Marsaglia's xorshift64* generator (Vigna's multiplier), seeded explicitly.
#[derive(Clone, Debug)]
pub struct XorShift64 {
    state: u64,
}

impl XorShift64 {
    /// A generator started from `seed`; a zero seed is replaced, since zero is a fixed point.
    #[must_use]
    pub fn new(seed: u64) -> Self {
        let state = if seed == 0 {
            0x9E37_79B9_7F4A_7C15
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

    /// A uniform number in `[0, 1)` with 53 random bits.
    pub fn next_f64(&mut self) -> f64 {
        // The top 53 bits, scaled by 2^-53.
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    /// A uniform number in `[lo, hi)`.
    pub fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next_f64()
    }

    /// `N` uniform numbers in `[lo, hi)`.
    pub fn uniform_array<const N: usize>(&mut self, lo: f64, hi: f64) -> [f64; N] {
        std::array::from_fn(|_| self.uniform(lo, hi))
    }

    /// A point on the unit sphere in `N` dimensions (rejection from the cube, then scaled).
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

    #[test]
    fn same_seed_gives_same_sequence() {
        let mut a = XorShift64::new(7);
        let mut b = XorShift64::new(7);
        for _ in 0..100 {
            assert_eq!(a.next_u64(), b.next_u64());
        }
    }

    #[test]
    fn uniform_stays_in_range_and_covers_it() {
        let mut rng = XorShift64::new(1);
        let xs: Vec<f64> = (0..10_000).map(|_| rng.uniform(-2.0, 3.0)).collect();
        assert!(xs.iter().all(|x| (-2.0..3.0).contains(x)));
        let mean = xs.iter().sum::<f64>() / xs.len() as f64;
        assert!((mean - 0.5).abs() < 0.05, "mean {mean}");
    }

    #[test]
    fn unit_array_has_unit_norm() {
        let mut rng = XorShift64::new(3);
        for _ in 0..1000 {
            let v: [f64; 4] = rng.unit_array();
            let n: f64 = v.iter().map(|c| c * c).sum();
            assert!((n - 1.0).abs() < 1e-12);
        }
    }
}
