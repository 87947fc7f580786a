//! Closed-form motions: the planar body, and the symmetric body of G4 with second moments
//! `(a, a, b, b)` (derived in `docs/derivations/symmetric-body-4d.md`, in the lecture's
//! style for the 3D top).

use ga_core::f64::g4;

use super::algebra::{Algebra, G2, G4};
use super::body::RigidBody;
use super::state::State;
use crate::error::{self, Error};

/// The planar body's motion: in G2 the one plane commutes with itself, so `Omega` is
/// constant and `R(t) = R(0) exp(-Omega t/2)` (no torque).
#[must_use]
pub fn planar(state: State<G2>, t: f64) -> State<G2> {
    State {
        rotor: state.rotor * G2::exp(state.omega * (-0.5 * t)),
        omega: state.omega,
    }
}

/// The free symmetric body of G4, second moments `(a, a, b, b)`:
///
/// ```text
/// R(t) = exp(-L t / (2 (a + b))) R(0) exp(nu D t / 2),
/// Omega(t) = U Omega(0) ~U,   U = exp(-nu D t / 2),
/// ```
///
/// with `L = R(0) I(Omega(0)) ~R(0)` the space momentum, `D = w12 e12 - w34 e34` the
/// constant part of `Omega` in the two planes that commute with `J = diag(a, a, b, b)`,
/// and `nu = (a - b)/(a + b)`: a turn in the space momentum's planes times a constant
/// internal turn in the body.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SymmetricBody4 {
    a: f64,
    b: f64,
}

impl SymmetricBody4 {
    /// The closed form for `body`, whose second moments must be `(a, a, b, b)`: `l_1` and
    /// `l_2` equal within `relative_tolerance`, and `l_3` and `l_4`.
    pub fn new(body: &RigidBody<G4>, relative_tolerance: f64) -> Result<Self, Error> {
        if body.has_torque() {
            return Err(Error::invalid(
                "body",
                "the symmetric body's closed form is for a free body; this one has a torque",
            ));
        }
        let l = body.second_moments();
        let close = |x: f64, y: f64| (x - y).abs() <= relative_tolerance * x.max(y);
        if !(close(l[0], l[1]) && close(l[2], l[3])) {
            return Err(Error::invalid(
                "second_moments",
                format!(
                    "the closed form needs second moments (a, a, b, b), got ({}, {}, {}, {})",
                    error::num(l[0]),
                    error::num(l[1]),
                    error::num(l[2]),
                    error::num(l[3])
                ),
            ));
        }
        Ok(SymmetricBody4 {
            a: 0.5 * (l[0] + l[1]),
            b: 0.5 * (l[2] + l[3]),
        })
    }

    /// The state at time `t` from `state` at time 0.
    #[must_use]
    pub fn at(&self, state: State<G4>, t: f64) -> State<G4> {
        let (a, b) = (self.a, self.b);
        let w = state.omega;
        let inertia = g4::Bivector::new(2.0 * a, a + b, a + b, a + b, a + b, 2.0 * b);
        let mut momentum = w;
        for k in 0..6 {
            momentum[k] *= inertia[k];
        }
        let space = G4::sandwich(state.rotor, momentum);
        let nu = (a - b) / (a + b);
        let d = g4::Bivector::new(w.e12, 0.0, 0.0, 0.0, 0.0, -w.e34);
        let internal = G4::exp(d * (0.5 * nu * t));
        let rotor = G4::exp(space * (-0.5 * t / (a + b))) * state.rotor * internal;
        State {
            rotor,
            omega: G4::sandwich(G4::reverse(internal), w),
        }
    }
}
