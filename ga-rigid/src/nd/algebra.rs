//! The algebra a body turns in: the few operations of G2, G3 or G4 that the dynamics and
//! the integrators ask for, behind one trait, so that each is written once.

use core::fmt::Debug;
use core::ops::{Add, Index, IndexMut, Mul, Neg, Sub};

/// The largest dimension this module treats; vectors are passed padded to this length.
pub const MAX_DIMENSION: usize = 4;

/// A Euclidean geometric algebra of dimension 2, 3 or 4 over `f64`: its bivectors (the
/// angular velocities, momenta and torques) and its rotors (the attitudes).
///
/// Bivector components are in canonical order (G4: e12, e13, e14, e23, e24, e34), listed
/// by [`Algebra::PLANES`]; rotors act by `y = R x ~R`.
pub trait Algebra: Copy + Debug + Default + Send + Sync + 'static {
    /// The dimension `n` of the vector space.
    const DIMENSION: usize;
    /// The planes `(i, j)`, `i < j`, counted from 0, of the bivector components in
    /// canonical order: component `k` is the coefficient of `e_(i+1) e_(j+1)`.
    const PLANES: &'static [(usize, usize)];
    /// The number of rotor components (G2: 2, G3: 4, G4: 8).
    const ROTOR_LEN: usize;
    /// A short name for messages (`"G4"`).
    const NAME: &'static str;

    /// A bivector: an angular velocity, a momentum or a torque.
    type Bivector: Copy
        + Debug
        + PartialEq
        + Default
        + Send
        + Sync
        + Add<Output = Self::Bivector>
        + Sub<Output = Self::Bivector>
        + Neg<Output = Self::Bivector>
        + Mul<f64, Output = Self::Bivector>
        + Index<usize, Output = f64>
        + IndexMut<usize>;
    /// An even element; a unit one is a rotor.
    type Rotor: Copy
        + Debug
        + PartialEq
        + Send
        + Sync
        + Add<Output = Self::Rotor>
        + Sub<Output = Self::Rotor>
        + Mul<f64, Output = Self::Rotor>
        + Mul<Self::Rotor, Output = Self::Rotor>
        + Mul<Self::Bivector, Output = Self::Rotor>
        + Index<usize, Output = f64>;

    /// The identity rotor.
    const ONE: Self::Rotor;

    /// The commutator product `a x b = (ab - ba)/2` (zero in G2, where the one plane
    /// commutes with itself).
    fn commutator(a: Self::Bivector, b: Self::Bivector) -> Self::Bivector;
    /// `exp(b)`, a unit rotor for every finite `b` (in G4 also for non-simple `b`).
    fn exp(b: Self::Bivector) -> Self::Rotor;
    /// The reverse `~r`.
    fn reverse(r: Self::Rotor) -> Self::Rotor;
    /// The sandwich `r b ~r`.
    fn sandwich(r: Self::Rotor, b: Self::Bivector) -> Self::Bivector;
    /// The norm `sqrt(<r ~r>_0)`.
    fn rotor_norm(r: Self::Rotor) -> f64;
    /// The Cayley transform `(1 - b)(1 + b)^-1`: a unit rotor for every finite `b`.
    fn cayley(b: Self::Bivector) -> Self::Rotor;
    /// The geometric product `a b` of two vectors given by their first `n` components.
    fn vector_product(a: [f64; MAX_DIMENSION], b: [f64; MAX_DIMENSION]) -> Self::Rotor;
    /// `r x ~r` for a vector `x` given by its first `n` components (the rest zero).
    fn rotate(r: Self::Rotor, x: [f64; MAX_DIMENSION]) -> [f64; MAX_DIMENSION];
    /// The bivector with components `c` in canonical order (`c.len()` must be the number
    /// of planes).
    fn bivector(c: &[f64]) -> Self::Bivector {
        let mut b = Self::Bivector::default();
        for (k, &x) in c.iter().enumerate().take(Self::PLANES.len()) {
            b[k] = x;
        }
        b
    }
}

/// The plane algebra G2: one plane, rotations that commute.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct G2;

/// Space, G3: three planes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct G3;

/// Four-dimensional space, G4: six planes, and bivectors that need not be simple.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct G4;

impl Algebra for G2 {
    const DIMENSION: usize = 2;
    const PLANES: &'static [(usize, usize)] = &[(0, 1)];
    const ROTOR_LEN: usize = 2;
    const NAME: &'static str = "G2";
    type Bivector = ga_core::f64::g2::Bivector;
    type Rotor = ga_core::f64::g2::Rotor;
    const ONE: Self::Rotor = ga_core::f64::g2::Rotor::ONE;

    fn commutator(_: Self::Bivector, _: Self::Bivector) -> Self::Bivector {
        Self::Bivector::ZERO
    }
    fn exp(b: Self::Bivector) -> Self::Rotor {
        b.exp()
    }
    fn reverse(r: Self::Rotor) -> Self::Rotor {
        r.reverse()
    }
    fn sandwich(r: Self::Rotor, b: Self::Bivector) -> Self::Bivector {
        use ga_core::f64::g2::Sandwich;
        r.sandwich(b)
    }
    fn rotor_norm(r: Self::Rotor) -> f64 {
        r.norm()
    }
    fn cayley(b: Self::Bivector) -> Self::Rotor {
        use ga_core::f64::g2::Rotor;
        // (1 - B)^2 / (1 - B^2) with B^2 = -|B|^2 a scalar.
        let one_minus = Rotor::ONE - Rotor::from(b);
        (one_minus * one_minus) * (1.0 / (1.0 + b.e12 * b.e12))
    }
    fn vector_product(a: [f64; MAX_DIMENSION], b: [f64; MAX_DIMENSION]) -> Self::Rotor {
        use ga_core::f64::g2::Vector;
        Vector::new(a[0], a[1]) * Vector::new(b[0], b[1])
    }
    fn rotate(r: Self::Rotor, x: [f64; MAX_DIMENSION]) -> [f64; MAX_DIMENSION] {
        use ga_core::f64::g2::{Sandwich, Vector};
        let y = r.sandwich(Vector::new(x[0], x[1]));
        [y.e1, y.e2, 0.0, 0.0]
    }
}

impl Algebra for G3 {
    const DIMENSION: usize = 3;
    const PLANES: &'static [(usize, usize)] = &[(0, 1), (0, 2), (1, 2)];
    const ROTOR_LEN: usize = 4;
    const NAME: &'static str = "G3";
    type Bivector = ga_core::f64::g3::Bivector;
    type Rotor = ga_core::f64::g3::Rotor;
    const ONE: Self::Rotor = ga_core::f64::g3::Rotor::ONE;

    fn commutator(a: Self::Bivector, b: Self::Bivector) -> Self::Bivector {
        use ga_core::f64::g3::Commutator;
        a.commutator(b)
    }
    fn exp(b: Self::Bivector) -> Self::Rotor {
        b.exp()
    }
    fn reverse(r: Self::Rotor) -> Self::Rotor {
        r.reverse()
    }
    fn sandwich(r: Self::Rotor, b: Self::Bivector) -> Self::Bivector {
        use ga_core::f64::g3::Sandwich;
        r.sandwich(b)
    }
    fn rotor_norm(r: Self::Rotor) -> f64 {
        r.norm()
    }
    fn cayley(b: Self::Bivector) -> Self::Rotor {
        use ga_core::f64::g3::Rotor;
        // (1 - B)^2 / (1 - B^2) with B^2 = -|B|^2 a scalar.
        let one_minus = Rotor::ONE - Rotor::from(b);
        (one_minus * one_minus) * (1.0 / (1.0 + b.norm_squared()))
    }
    fn vector_product(a: [f64; MAX_DIMENSION], b: [f64; MAX_DIMENSION]) -> Self::Rotor {
        use ga_core::f64::g3::Vector;
        Vector::new(a[0], a[1], a[2]) * Vector::new(b[0], b[1], b[2])
    }
    fn rotate(r: Self::Rotor, x: [f64; MAX_DIMENSION]) -> [f64; MAX_DIMENSION] {
        use ga_core::f64::g3::{Sandwich, Vector};
        let y = r.sandwich(Vector::new(x[0], x[1], x[2]));
        [y.e1, y.e2, y.e3, 0.0]
    }
}

impl Algebra for G4 {
    const DIMENSION: usize = 4;
    const PLANES: &'static [(usize, usize)] = &[(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)];
    const ROTOR_LEN: usize = 8;
    const NAME: &'static str = "G4";
    type Bivector = ga_core::f64::g4::Bivector;
    type Rotor = ga_core::f64::g4::Rotor;
    const ONE: Self::Rotor = ga_core::f64::g4::Rotor::ONE;

    fn commutator(a: Self::Bivector, b: Self::Bivector) -> Self::Bivector {
        use ga_core::f64::g4::Commutator;
        a.commutator(b)
    }
    fn exp(b: Self::Bivector) -> Self::Rotor {
        b.exp()
    }
    fn reverse(r: Self::Rotor) -> Self::Rotor {
        r.reverse()
    }
    fn sandwich(r: Self::Rotor, b: Self::Bivector) -> Self::Bivector {
        use ga_core::f64::g4::Sandwich;
        r.sandwich(b)
    }
    fn rotor_norm(r: Self::Rotor) -> f64 {
        r.norm()
    }
    fn cayley(b: Self::Bivector) -> Self::Rotor {
        use ga_core::f64::g4::Rotor;
        // (1 + B)^-1 = (1 - B)(1 - B^2)^-1, and 1 - B^2 = alpha + beta I commutes with every
        // even element; as I I = 1 its inverse is (alpha - beta I)/(alpha^2 - beta^2), and
        // alpha - |beta| = 1 + (|a| - |b|)^2 > 0 for B = a P + b Q in orthogonal planes.
        let square = b * b;
        let (alpha, beta) = (1.0 - square.s, -square.e1234);
        let inverse = Rotor::new(alpha, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -beta)
            * (1.0 / (alpha * alpha - beta * beta));
        let one_minus = Rotor::ONE - Rotor::from(b);
        one_minus * one_minus * inverse
    }
    fn vector_product(a: [f64; MAX_DIMENSION], b: [f64; MAX_DIMENSION]) -> Self::Rotor {
        use ga_core::f64::g4::Vector;
        Vector::from_array(a) * Vector::from_array(b)
    }
    fn rotate(r: Self::Rotor, x: [f64; MAX_DIMENSION]) -> [f64; MAX_DIMENSION] {
        use ga_core::f64::g4::{Sandwich, Vector};
        r.sandwich(Vector::from_array(x)).to_array()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The plane list matches the bivector basis constants of each algebra.
    #[test]
    fn planes_follow_the_canonical_blade_order() {
        use ga_core::f64::g4::{Bivector, Vector};
        let basis = [Vector::E1, Vector::E2, Vector::E3, Vector::E4];
        for (k, &(i, j)) in G4::PLANES.iter().enumerate() {
            let blade = (basis[i] * basis[j]).grade2();
            let mut expected = Bivector::ZERO;
            expected[k] = 1.0;
            assert_eq!(blade, expected, "plane {k}");
        }
    }

    /// The Cayley transform is the unit rotor `(1 - B)(1 + B)^-1`, checked by multiplying
    /// back with `1 + B`.
    #[test]
    fn cayley_is_unit_and_inverts_one_plus_b() {
        use ga_core::f64::g4::Rotor;
        let b = G4::bivector(&[0.3, -0.2, 0.7, 0.1, 0.5, -0.4]);
        let c = G4::cayley(b);
        assert!((G4::rotor_norm(c) - 1.0).abs() < 1e-15);
        let back = c * (Rotor::ONE + Rotor::from(b)) - (Rotor::ONE - Rotor::from(b));
        assert!(back.norm() < 1e-15, "{back:?}");
    }
}
