//! Seeded batches of random inputs, as f64 arrays in canonical blade order.
//!
//! Canonical order is grade first, then lexicographic on the indices: a G3 rotor is
//! `[s, e12, e13, e23]`, a G4 bivector `[e12, e13, e14, e23, e24, e34]`, a G4 rotor
//! `[s, e12, e13, e14, e23, e24, e34, e1234]`. Every bench converts the same arrays into
//! each library's types, outside the timed loop.

use crate::table::{Scalar, G4};
use ga_test_rng::Rng;

/// Items per batch in the throughput benches (and steps in the latency chains).
pub const BATCH: usize = 4096;

/// Converts an f64 array to the bench's scalar type.
#[must_use]
pub fn cast<S: Scalar, const K: usize>(x: &[f64; K]) -> [S; K] {
    x.map(S::from_f64)
}

/// Converts a batch of f64 arrays to the bench's scalar type.
#[must_use]
pub fn cast_all<S: Scalar, const K: usize>(xs: &[[f64; K]]) -> Vec<[S; K]> {
    xs.iter().map(cast).collect()
}

/// `count` unit G3 rotors `[s, e12, e13, e23]` (uniform directions in 4D).
#[must_use]
pub fn g3_rotors(count: usize, seed: u64) -> Vec<[f64; 4]> {
    let mut rng = Rng::new(seed);
    (0..count).map(|_| rng.unit_array()).collect()
}

/// `count` unit G3 vectors `[e1, e2, e3]`.
#[must_use]
pub fn g3_vectors(count: usize, seed: u64) -> Vec<[f64; 3]> {
    let mut rng = Rng::new(seed);
    (0..count).map(|_| rng.unit_array()).collect()
}

/// `count` G3 bivectors `[e12, e13, e23]` with coefficients uniform in `[-1, 1)`.
#[must_use]
pub fn g3_bivectors(count: usize, seed: u64) -> Vec<[f64; 3]> {
    let mut rng = Rng::new(seed);
    (0..count).map(|_| rng.uniform_array(-1.0, 1.0)).collect()
}

/// `count` full G3 multivectors with coefficients uniform in `[-amplitude, amplitude)`.
#[must_use]
pub fn g3_multivectors(count: usize, amplitude: f64, seed: u64) -> Vec<[f64; 8]> {
    let mut rng = Rng::new(seed);
    (0..count)
        .map(|_| rng.uniform_array(-amplitude, amplitude))
        .collect()
}

/// `count` unit G4 vectors `[e1, e2, e3, e4]`.
#[must_use]
pub fn g4_vectors(count: usize, seed: u64) -> Vec<[f64; 4]> {
    let mut rng = Rng::new(seed);
    (0..count).map(|_| rng.unit_array()).collect()
}

/// `count` G4 bivectors with coefficients uniform in `[-1, 1)` (generally not simple).
#[must_use]
pub fn g4_bivectors(count: usize, seed: u64) -> Vec<[f64; 6]> {
    let mut rng = Rng::new(seed);
    (0..count).map(|_| rng.uniform_array(-1.0, 1.0)).collect()
}

/// `count` unit G4 rotors, each the product of four random unit vectors, in canonical
/// order `[s, e12, e13, e14, e23, e24, e34, e1234]`.
#[must_use]
pub fn g4_rotors(count: usize, seed: u64) -> Vec<[f64; 8]> {
    let algebra = G4::euclidean();
    let vector_blades = algebra.blades_of_grades(&[1]);
    let even_blades = algebra.blades_of_grades(&[0, 2, 4]);
    let mut rng = Rng::new(seed);
    (0..count)
        .map(|_| {
            let mut rotor = algebra.embed(&[0], &[1.0]);
            for _ in 0..4 {
                let v: [f64; 4] = rng.unit_array();
                rotor = algebra.geometric(&rotor, &algebra.embed(&vector_blades, &v));
            }
            let even = algebra.extract(&even_blades, &rotor);
            std::array::from_fn(|i| even[i])
        })
        .collect()
}

/// `count` full G4 multivectors with coefficients uniform in `[-amplitude, amplitude)`.
#[must_use]
pub fn g4_multivectors(count: usize, amplitude: f64, seed: u64) -> Vec<[f64; 16]> {
    let mut rng = Rng::new(seed);
    (0..count)
        .map(|_| rng.uniform_array(-amplitude, amplitude))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::table::norm_squared;

    #[test]
    fn g4_rotors_are_unit_and_even() {
        let algebra = G4::euclidean();
        let even_blades = algebra.blades_of_grades(&[0, 2, 4]);
        for r in g4_rotors(100, 5) {
            let mv = algebra.embed(&even_blades, &r);
            let unit = algebra.geometric(&mv, &algebra.reverse(&mv));
            assert!((unit[0] - 1.0).abs() < 1e-12);
            assert!(norm_squared(&unit) - 1.0 < 1e-12);
        }
    }

    #[test]
    fn same_seed_gives_same_batch() {
        assert_eq!(g3_rotors(10, 42), g3_rotors(10, 42));
        assert_ne!(g3_rotors(10, 42), g3_rotors(10, 43));
    }
}
