//! The four-dimensional scenes: the symmetric body of the closed form, the asymmetric
//! reference body of `docs/references.md`, and a double rotation near an unstable
//! relative equilibrium.

use ga_core::f64::g4::{Bivector, Rotor};

use ga_rigid::error::Error;
use ga_rigid::nd::{RigidBody, State, SymmetricBody4, G4};
use ga_rigid::registry::StepKind;

use super::methods::NdMethod;
use crate::report::{Size, SAMPLES};

/// Published values a scene's reference is checked against.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Published {
    /// Where they come from.
    pub source: &'static str,
    /// The time they are given at (a sample time of the scene).
    pub t: f64,
    /// `R(t)`: s, e12, e13, e14, e23, e24, e34, e1234.
    pub rotor: [f64; 8],
    /// `Omega_B(t)` in canonical order.
    pub omega: [f64; 6],
}

/// A four-dimensional test model.
pub struct NdTestScene {
    /// The scene's name in the report.
    pub name: String,
    /// Where it comes from and what it stresses.
    pub source: String,
    /// The free body.
    pub body: RigidBody<G4>,
    /// The state at t = 0.
    pub initial: State<G4>,
    /// The end time.
    pub t_end: f64,
    /// The coarsest number of fixed steps, a multiple of [`SAMPLES`] so that every sample
    /// falls on a step.
    pub coarsest_steps: u64,
    /// Values the reference is checked against, where they are published.
    pub published: Option<Published>,
    /// The two planes (bivector indices) of a steady double rotation the scene starts
    /// near, whose perturbation the page follows.
    pub steady_planes: Option<[usize; 2]>,
}

/// The published 4D reference state of `docs/references.md` (scipy DOP853 at rtol 1e-13).
pub const REFERENCE_BODY_AT_10: Published = Published {
    source: "docs/references.md (scipy DOP853 at rtol 1e-13, 12 decimals)",
    t: 10.0,
    rotor: [
        -0.845752127571,
        -0.001654495749,
        0.054382309786,
        -0.187793734963,
        0.290305428646,
        -0.103803029126,
        -0.384930676753,
        0.057032816706,
    ],
    omega: [
        0.920363924980,
        -0.406450762844,
        0.521437788334,
        -0.488898046121,
        0.219223377642,
        0.776749436333,
    ],
};

impl NdTestScene {
    /// The size of the initial angular velocity, for `h |w|`.
    #[must_use]
    pub fn rate(&self) -> f64 {
        self.initial.omega.norm()
    }

    /// The symmetric body's closed form, where the body has second moments `(a, a, b, b)`.
    #[must_use]
    pub fn closed_form(&self) -> Option<SymmetricBody4> {
        SymmetricBody4::new(&self.body, 1e-12).ok()
    }

    /// The methods that apply: every one, the closed form only on a symmetric body.
    #[must_use]
    pub fn methods(&self) -> Vec<NdMethod> {
        NdMethod::ALL
            .into_iter()
            .filter(|&m| m != NdMethod::ClosedForm || self.closed_form().is_some())
            .collect()
    }

    /// The fixed steps (coarsest first), tolerances, or the sample spacing a method runs at.
    #[must_use]
    pub fn settings(&self, method: NdMethod, size: Size) -> Vec<f64> {
        let quick = size == Size::Quick;
        match method.step_kind() {
            StepKind::AtSamples => vec![self.t_end / SAMPLES as f64],
            StepKind::Fixed => {
                let levels = if quick { 4 } else { 7 };
                (0..levels)
                    .map(|k| self.t_end / (self.coarsest_steps << k) as f64)
                    .collect()
            }
            StepKind::Adaptive => {
                let exponents: &[i32] = if quick {
                    &[4, 6, 8, 10]
                } else {
                    &[3, 4, 5, 6, 7, 8, 9, 10, 11, 12]
                };
                exponents.iter().map(|&e| 10f64.powi(-e)).collect()
            }
        }
    }
}

/// The three scenes, in the order of the page.
pub fn nd_scenes() -> Result<Vec<NdTestScene>, Error> {
    Ok(vec![
        symmetric()?,
        reference_body()?,
        unstable_double_rotation()?,
    ])
}

/// The symmetric body `(a, a, b, b)` with a non-simple `Omega_B(0)` (its `Omega ^ Omega`
/// is not zero) and a turned `R(0)`: the initial state of the closed form's test in
/// `ga-rigid/tests/nd.rs`, which checks it against a matrix form of Euler's equations.
fn symmetric() -> Result<NdTestScene, Error> {
    Ok(NdTestScene {
        name: "4D symmetric body".into(),
        source: "second moments (0.6, 0.6, 1.7, 1.7), R(0) = exp(0.2, -0.5, 0.3, 0.7, -0.1, \
                 0.4), Omega_B(0) = (0.9, -0.7, 0.5, 0.3, 1.1, -0.6), non-simple; against the \
                 closed form of docs/derivations/symmetric-body-4d.md"
            .into(),
        body: RigidBody::new(&[0.6, 0.6, 1.7, 1.7])?,
        initial: State::new(
            Bivector::new(0.2, -0.5, 0.3, 0.7, -0.1, 0.4).exp(),
            Bivector::new(0.9, -0.7, 0.5, 0.3, 1.1, -0.6),
        ),
        t_end: 10.0,
        coarsest_steps: 100,
        published: None,
        steady_planes: None,
    })
}

/// The asymmetric reference body of `docs/references.md`.
fn reference_body() -> Result<NdTestScene, Error> {
    Ok(NdTestScene {
        name: "4D asymmetric reference body".into(),
        source: "docs/references.md: second moments (0.5, 0.9, 1.4, 2.0), R(0) = 1, \
                 Omega_B(0) = (1.0, 0, 0.4, -0.6, 0.2, 0.8)"
            .into(),
        body: RigidBody::new(&[0.5, 0.9, 1.4, 2.0])?,
        initial: State::new(Rotor::ONE, Bivector::new(1.0, 0.0, 0.4, -0.6, 0.2, 0.8)),
        t_end: 10.0,
        coarsest_steps: 100,
        published: Some(REFERENCE_BODY_AT_10),
        steady_planes: None,
    })
}

/// The perturbation of the unstable double rotation in each of the four other planes.
pub const PERTURBATION: f64 = 1e-3;

/// The 4D cousin of the Dzhanibekov flip: a steady double rotation in the two
/// complementary planes whose moments are the middle ones, slightly perturbed.
///
/// With second moments `l = (0.5, 2.0, 0.9, 1.4)` the plane moments `l_i + l_j` are 1.4
/// (e13), 1.9 (e14), 2.5 (e12), 2.3 (e34), 2.9 (e23), 3.4 (e24): e12 and e34 hold the
/// middle two. Every `Omega = w e12 + z e34` is a relative equilibrium (`I(Omega)`
/// commutes with it). Linearised, the other four components obey
/// `(l_i + l_j) dW_ij/dt = (l_i - l_j) sum_k W_ik W_kj`, two coupled pairs, and for
/// `(w, z) = (2, 1)` the 4x4 matrix has eigenvalues `+-0.533 +- 0.037i`: the steady
/// double rotation is unstable, a perturbation growing like `exp(0.53 t)`. (Not every
/// double rotation of this body is: at `w = z` the eigenvalues are imaginary.) The
/// report follows the perturbation on the reference run and prints its growth; a test
/// checks it.
fn unstable_double_rotation() -> Result<NdTestScene, Error> {
    let p = PERTURBATION;
    Ok(NdTestScene {
        name: "4D unstable double rotation".into(),
        source: format!(
            "second moments (0.5, 2.0, 0.9, 1.4), R(0) = 1, Omega_B(0) = 2 e12 + e34 (the \
             middle plane moments, an unstable relative equilibrium) plus {p:e} in each of \
             e13, e14, e23, e24"
        ),
        body: RigidBody::new(&[0.5, 2.0, 0.9, 1.4])?,
        initial: State::new(Rotor::ONE, Bivector::new(2.0, p, p, p, p, 1.0)),
        t_end: 20.0,
        // Coarser, the splitting loses the solution (error above 0.1) on the flip.
        coarsest_steps: 400,
        published: None,
        steady_planes: Some([0, 5]),
    })
}
