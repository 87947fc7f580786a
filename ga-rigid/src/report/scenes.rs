use ga_core::f64::g3::{Rotor, Vector};

use crate::dynamics::{omega_from_vector, Gravity, RigidBody, State};
use crate::error::Error;
use crate::integrators::Method;

/// A test model: a body, a start and an end time, and the step sizes that make sense for it.
pub struct TestScene {
    /// The scene's name in the report.
    pub name: &'static str,
    /// Where it comes from.
    pub source: &'static str,
    /// The body (with its torque, if any).
    pub body: RigidBody,
    /// The state at t = 0.
    pub initial: State,
    /// The end time.
    pub t_end: f64,
    /// The coarsest number of steps of the fixed-step methods.
    pub coarsest_steps: u32,
}

impl TestScene {
    fn free(
        name: &'static str,
        source: &'static str,
        moments: [f64; 3],
        momentum: [f64; 3],
        t_end: f64,
        coarsest_steps: u32,
    ) -> Result<TestScene, Error> {
        let body = RigidBody::new_unphysical(moments)?;
        let w = [0, 1, 2].map(|k| momentum[k] / moments[k]);
        Ok(TestScene {
            name,
            source,
            body,
            initial: State {
                rotor: Rotor::ONE,
                omega: omega_from_vector(w),
            },
            t_end,
            coarsest_steps,
        })
    }

    /// The methods that apply to this scene, and the ones left out with the reason.
    pub fn methods(&self) -> (Vec<Method>, Vec<(Method, &'static str)>) {
        let mut run = Vec::new();
        let mut left_out = Vec::new();
        for method in Method::ALL {
            match method {
                Method::ClosedForm if self.body.has_torque() => {
                    left_out.push((method, "a torque acts"))
                }
                Method::ClosedForm if self.body.symmetry_axis(1e-12).is_none() => {
                    left_out.push((method, "the body is not symmetric"))
                }
                Method::Exact if self.body.has_torque() => left_out.push((method, "a torque acts")),
                _ => run.push(method),
            }
        }
        (run, left_out)
    }
}

/// The work-precision scenes.
pub fn reference_scenes() -> Result<Vec<TestScene>, Error> {
    let hlw = 1.1f64;
    Ok(vec![
        TestScene::free(
            "Hairer-Lubich-Wanner body",
            "Geometric Numerical Integration; moments (2, 1, 2/3), m(0) = (cos 1.1, 0, sin 1.1)",
            [2.0, 1.0, 2.0 / 3.0],
            [hlw.cos(), 0.0, hlw.sin()],
            10.0,
            25,
        )?,
        TestScene::free(
            "Hairer-Vilmart driver",
            "moments (0.6, 0.8, 1.0), m(0) = (1.8, 0.4, -0.9)",
            [0.6, 0.8, 1.0],
            [1.8, 0.4, -0.9],
            10.0,
            100,
        )?,
        TestScene::free(
            "Dzhanibekov (near the separatrix)",
            "Principia; moments (3, 5, 9), m(0) = (0, 2, 0.01), 1 - m = 4.2e-5",
            [3.0, 5.0, 9.0],
            [0.0, 2.0, 0.01],
            100.0,
            200,
        )?,
        TestScene::free(
            "symmetric short fat top",
            "Principia; moments (3, 3, 9), m(0) = (0, 5, 7)",
            [3.0, 3.0, 9.0],
            [0.0, 5.0, 7.0],
            10.0,
            25,
        )?,
        heavy_top()?,
    ])
}

fn heavy_top() -> Result<TestScene, Error> {
    let body = RigidBody::new([1.0, 1.0, 0.5])?.with_torque(Gravity {
        mass: 1.0,
        g: Vector::new(0.0, 0.0, -9.81),
        com_offset: Vector::new(0.0, 0.0, 0.5),
    });
    let tilt = (ga_core::f64::g3::Bivector::E23 * -0.15).exp();
    Ok(TestScene {
        name: "heavy top",
        source: "moments (1, 1, 0.5) about the pivot, centre of mass 0.5 up the axis, tilted 0.3 rad, spin 20 rad/s",
        body,
        initial: State { rotor: tilt, omega: omega_from_vector([0.0, 0.0, 20.0]) },
        t_end: 4.0,
        coarsest_steps: 100,
    })
}

/// The stiff and extreme cases.
pub fn stability_scenes() -> Result<Vec<TestScene>, Error> {
    Ok(vec![
        TestScene::free(
            "needle",
            "moments (1, 1, 1e-3), w(0) = (0.01, 0, 1000), h = 1/60: 16.7 rad a step",
            [1.0, 1.0, 1e-3],
            [0.01, 0.0, 1.0],
            10.0,
            600,
        )?,
        TestScene::free(
            "fast tumbling",
            "Hairer-Vilmart body at 100 times the rate, h = 0.01: 3.2 rad a step",
            [0.6, 0.8, 1.0],
            [180.0, 40.0, -90.0],
            2.0,
            200,
        )?,
        TestScene::free(
            "long run near the separatrix",
            "Dzhanibekov body for 2000 s (34 flips), h = 0.05",
            [3.0, 5.0, 9.0],
            [0.0, 2.0, 0.01],
            2000.0,
            40_000,
        )?,
        TestScene::free(
            "near-symmetric body",
            "moments (1, 1 + 1e-9, 2), m(0) = (0.6, 0.8, 1), h = 0.01",
            [1.0, 1.0 + 1e-9, 2.0],
            [0.6, 0.8, 1.0],
            50.0,
            5000,
        )?,
    ])
}
