//! rapier3d with its own rigid bodies, stepped two ways: by rapier's own integration, and
//! with each body's rotation advanced by `ga_engine`'s step and handed to rapier as the
//! body's angular velocity (rapier still integrates the pose, so its contacts, joints and
//! queries see a body that moves as the step says).
//!
//! Two scenes: a free T-handle (moments 1 : 2 : 3, spun mostly about the middle axis, no
//! gravity) and a heavy symmetric top whose tip is held at a point of the ground. The
//! measurements (flip period, drifts, cost) are plain functions here so that the binary
//! prints them and the tests check them.
//!
//! The velocity handed to rapier undoes rapier's linearised substep rotation
//! ([`landing_velocity`]; derived in `docs/derivations/rapier-landing.md`).
//!
//! rapier 0.36 does its maths on glam 0.33 (through glamx) and ga-engine on glam 0.32: the
//! two are converted at the boundary, component by component (`to_engine`, `to_rapier`).

use std::time::Instant;

use ga_engine::f32::{step, step_with, Body};
use ga_engine::glam::{DQuat, DVec3, Quat, Vec3};
use rapier3d::prelude as rp;

/// 60 Hz, rapier's default step.
pub const DT: f32 = 1.0 / 60.0;
/// Ten minutes at 60 Hz.
pub const TEN_MINUTES: usize = 36_000;

/// How a body's rotation is advanced.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// rapier alone: its solver's substeps with its gyroscopic term on (rapier's default).
    Rapier,
    /// rapier alone with its gyroscopic term off (`gyroscopic_forces_enabled(false)`):
    /// the world angular velocity is then held between contacts and joints.
    RapierGyroscopicOff,
    /// `ga_engine`'s step advances orientation and angular momentum; rapier is given the
    /// angular velocity that lands its own substeps on that orientation, with its
    /// gyroscopic term off (the step already holds it).
    RapierWithEngineStep,
}

impl Method {
    /// Every method, rapier's default first.
    pub const ALL: [Method; 3] = [
        Method::Rapier,
        Method::RapierGyroscopicOff,
        Method::RapierWithEngineStep,
    ];

    /// The name printed in the tables.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Method::Rapier => "rapier alone",
            Method::RapierGyroscopicOff => "rapier, gyroscopic off",
            Method::RapierWithEngineStep => "rapier + ga-engine step",
        }
    }
}

/// A rapier orientation as ga-engine's glam type.
#[must_use]
pub fn to_engine(q: rp::Rotation) -> Quat {
    Quat::from_xyzw(q.x, q.y, q.z, q.w)
}

/// A ga-engine orientation as rapier's glam type.
#[must_use]
pub fn to_rapier(q: Quat) -> rp::Rotation {
    rp::Rotation::from_xyzw(q.x, q.y, q.z, q.w)
}

fn vec_to_engine(v: rp::Vector) -> Vec3 {
    Vec3::new(v.x, v.y, v.z)
}

fn vec_to_rapier(v: Vec3) -> rp::Vector {
    rp::Vector::new(v.x, v.y, v.z)
}

/// The world angular velocity that turns `from` into `to` in rapier's step of `dt` made of
/// `substeps` substeps.
///
/// rapier's solver moves an orientation by `q <- normalise((1, w h / 2) q)` each substep
/// of length `h = dt / substeps` (rapier 0.36, `integrate_linearized`): a turn about `w` by
/// `2 atan(|w| h / 2)`, not `|w| h`. Turns about one axis add, so the velocity along the
/// axis of `to from^-1` with `2 atan(|w| h / 2) = angle / substeps` lands the substeps on
/// `to` (to rounding). Computed in f64.
#[must_use]
pub fn landing_velocity(from: Quat, to: Quat, dt: f32, substeps: usize) -> Vec3 {
    let d = to.as_dquat() * from.as_dquat().inverse();
    // The shorter way round.
    let d = if d.w < 0.0 { -d } else { d };
    let v = DVec3::new(d.x, d.y, d.z);
    let s = v.length();
    if s == 0.0 {
        return Vec3::ZERO;
    }
    let n = substeps as f64;
    let half_angle = s.atan2(d.w);
    let h = f64::from(dt) / n;
    let speed = (2.0 / h) * (half_angle / n).tan();
    (v * (speed / s)).as_vec3()
}

/// One rapier world: everything `PhysicsPipeline::step` takes, with rapier's default
/// integration parameters.
pub struct World {
    /// Gravity, world frame.
    pub gravity: rp::Vector,
    /// rapier's defaults (dt = 1/60, 4 solver iterations, which are also its substeps).
    pub params: rp::IntegrationParameters,
    /// The bodies.
    pub bodies: rp::RigidBodySet,
    /// The joints (the top's ball joint).
    pub joints: rp::ImpulseJointSet,
    pipeline: rp::PhysicsPipeline,
    islands: rp::IslandManager,
    broad_phase: rp::BroadPhaseBvh,
    narrow_phase: rp::NarrowPhase,
    colliders: rp::ColliderSet,
    multibody_joints: rp::MultibodyJointSet,
    soft_bodies: rp::SoftBodySet,
    ccd: rp::CCDSolver,
}

impl World {
    /// An empty world with this gravity.
    #[must_use]
    pub fn new(gravity: Vec3) -> Self {
        World {
            gravity: vec_to_rapier(gravity),
            params: rp::IntegrationParameters::default(),
            bodies: rp::RigidBodySet::new(),
            joints: rp::ImpulseJointSet::new(),
            pipeline: rp::PhysicsPipeline::new(),
            islands: rp::IslandManager::new(),
            broad_phase: rp::BroadPhaseBvh::new(),
            narrow_phase: rp::NarrowPhase::new(),
            colliders: rp::ColliderSet::new(),
            multibody_joints: rp::MultibodyJointSet::new(),
            soft_bodies: rp::SoftBodySet::new(),
            ccd: rp::CCDSolver::new(),
        }
    }

    /// rapier's substeps per step (its solver iterations; no body asks for more).
    #[must_use]
    pub fn substeps(&self) -> usize {
        self.params.num_solver_iterations
    }

    /// One `PhysicsPipeline::step`.
    pub fn step(&mut self) {
        self.pipeline.step(
            self.gravity,
            &self.params,
            &mut self.islands,
            &mut self.broad_phase,
            &mut self.narrow_phase,
            &mut self.bodies,
            &mut self.colliders,
            &mut self.joints,
            &mut self.multibody_joints,
            &mut self.soft_bodies,
            &mut self.ccd,
            &(),
            &(),
        );
    }
}

/// A rigid body's mass, centre of mass on the body origin, principal moments along the
/// body axes.
#[derive(Clone, Copy, Debug)]
pub struct Shape {
    /// Mass.
    pub mass: f32,
    /// Principal moments about the centre of mass, along body x, y, z.
    pub moments: Vec3,
}

/// The free T-handle: moments 1 : 2 : 3, one turn a second about the middle axis with a
/// 1 % wobble about the smallest, no gravity.
pub mod t_handle {
    use super::*;

    /// The body.
    pub const SHAPE: Shape = Shape {
        mass: 1.0,
        moments: Vec3::new(1.0, 2.0, 3.0),
    };

    /// Initial angular momentum (body frame = world frame at the start).
    #[must_use]
    pub fn initial_momentum() -> Vec3 {
        let tau = std::f32::consts::TAU;
        Vec3::new(0.02 * 2.0 * tau, 2.0 * tau, 0.0)
    }

    /// The exact flip period (mean time between flips in the same direction), from the
    /// exact free flow's Jacobi elliptic functions in ga-rigid.
    #[must_use]
    pub fn exact_period() -> f64 {
        let l = initial_momentum().to_array().map(f64::from);
        ga_rigid::exact_flow::free_body_orbit(SHAPE.moments.to_array().map(f64::from), l).period
    }
}

/// The heavy top: a symmetric body whose tip is held at the origin of the ground by a ball
/// joint (rapier alone), or whose rotation about that point is stepped by the engine.
pub mod top {
    use super::*;

    /// Mass 2, moments (0.98, 0.98, 0.4) about the centre of mass, which is 0.1 up the
    /// symmetry axis from the tip: (1, 1, 0.4) about the tip.
    pub const SHAPE: Shape = Shape {
        mass: 2.0,
        moments: Vec3::new(0.98, 0.98, 0.4),
    };
    /// From the tip to the centre of mass, along body z.
    pub const ARM: f32 = 0.1;
    /// Gravity, along -z.
    pub const G: f32 = 9.81;
    /// Spin about the symmetry axis, rad/s.
    pub const SPIN: f32 = 30.0;
    /// Initial tilt about world x, rad.
    pub const TILT: f32 = 0.3;

    /// The moments about the tip (parallel axes).
    #[must_use]
    pub fn moments_about_tip() -> Vec3 {
        let m = SHAPE.moments;
        let d = SHAPE.mass * ARM * ARM;
        Vec3::new(m.x + d, m.y + d, m.z)
    }

    /// Initial orientation.
    #[must_use]
    pub fn initial_orientation() -> Quat {
        Quat::from_rotation_x(TILT)
    }

    /// Initial world angular velocity: the spin about the tilted axis.
    #[must_use]
    pub fn initial_velocity() -> Vec3 {
        initial_orientation() * Vec3::new(0.0, 0.0, SPIN)
    }

    /// Gravity's torque about the tip at orientation `q`.
    #[must_use]
    pub fn torque(q: Quat) -> Vec3 {
        (q * Vec3::new(0.0, 0.0, ARM)).cross(Vec3::new(0.0, 0.0, -SHAPE.mass * G))
    }
}

/// Which scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Scene {
    /// [`t_handle`].
    THandle,
    /// [`top`].
    Top,
    /// The top's body alone, free (no joint, no gravity), spun about its symmetry axis,
    /// its smallest moment, with a 1 % wobble: its spin about that axis is constant in
    /// the exact motion.
    SpinningFree,
}

/// What a scene holds for one body stepped by the engine.
#[derive(Clone, Copy, Debug)]
struct EngineBody {
    handle: rp::RigidBodyHandle,
    /// World angular momentum about the centre of mass (T-handle) or the tip (top).
    momentum: Vec3,
}

/// `n` copies of a scene's body in one rapier world, stepped by one method.
pub struct Run {
    /// The rapier world.
    pub world: World,
    scene: Scene,
    method: Method,
    handles: Vec<rp::RigidBodyHandle>,
    engine: Vec<EngineBody>,
    body: Body,
}

impl Run {
    /// `n` identical bodies of `scene` (apart from one another: no colliders), stepped by
    /// `method`.
    ///
    /// # Panics
    /// Never for the scenes here (their moments are valid).
    #[must_use]
    pub fn new(scene: Scene, method: Method, n: usize) -> Self {
        let engine_steps = method == Method::RapierWithEngineStep;
        let (shape, gravity, q0, w0, com0, body) = match scene {
            Scene::THandle => {
                let s = t_handle::SHAPE;
                let w0 = t_handle::initial_momentum() / s.moments;
                let body = Body::from_principal(s.moments, Quat::IDENTITY).expect("valid");
                (s, Vec3::ZERO, Quat::IDENTITY, w0, Vec3::ZERO, body)
            }
            Scene::Top => {
                let q0 = top::initial_orientation();
                let body =
                    Body::from_principal(top::moments_about_tip(), Quat::IDENTITY).expect("valid");
                let g = Vec3::new(0.0, 0.0, -top::G);
                let com0 = q0 * Vec3::new(0.0, 0.0, top::ARM);
                (top::SHAPE, g, q0, top::initial_velocity(), com0, body)
            }
            Scene::SpinningFree => {
                let s = top::SHAPE;
                let q0 = top::initial_orientation();
                let w0 = q0 * Vec3::new(0.01 * top::SPIN, 0.0, top::SPIN);
                let body = Body::from_principal(s.moments, Quat::IDENTITY).expect("valid");
                (s, Vec3::ZERO, q0, w0, Vec3::ZERO, body)
            }
        };
        let mut world = World::new(gravity);
        let ground = world.bodies.insert(rp::RigidBodyBuilder::fixed());
        let mut handles = Vec::with_capacity(n);
        let mut engine = Vec::new();
        for _ in 0..n {
            let builder = rp::RigidBodyBuilder::dynamic()
                .pose(rp::Pose::from_parts(vec_to_rapier(com0), to_rapier(q0)))
                .additional_mass_properties(rp::MassProperties::new(
                    rp::Vector::ZERO,
                    shape.mass,
                    vec_to_rapier(shape.moments),
                ))
                .angvel(vec_to_rapier(w0))
                // A point of the top moves as w x r about the tip.
                .linvel(vec_to_rapier(w0.cross(com0)))
                // Not an integration parameter: a body without colliders could otherwise
                // be put to sleep by a slow stretch of its motion.
                .can_sleep(false)
                // The engine's step holds the gyroscopic term; gravity on the top is in
                // the engine's torque about the tip.
                .gyroscopic_forces_enabled(method == Method::Rapier)
                .gravity_scale(if engine_steps { 0.0 } else { 1.0 });
            let handle = world.bodies.insert(builder);
            if scene == Scene::Top && !engine_steps {
                // The tip, body (0, 0, -ARM), held at the ground's origin.
                let joint = rp::SphericalJointBuilder::new()
                    .local_anchor1(rp::Vector::ZERO)
                    .local_anchor2(rp::Vector::new(0.0, 0.0, -top::ARM));
                world.joints.insert(ground, handle, joint, true);
            }
            if engine_steps {
                engine.push(EngineBody {
                    handle,
                    momentum: body.angular_momentum(q0, w0),
                });
            }
            handles.push(handle);
        }
        Run {
            world,
            scene,
            method,
            handles,
            engine,
            body,
        }
    }

    /// One rapier step; with the engine, each body's orientation and momentum are first
    /// advanced by the engine's step and rapier is given the velocities that land its pose
    /// there.
    pub fn step(&mut self) {
        if self.method == Method::RapierWithEngineStep {
            let substeps = self.world.substeps();
            for e in &mut self.engine {
                let rb = &mut self.world.bodies[e.handle];
                let q = to_engine(*rb.rotation());
                let (q1, l1) = match self.scene {
                    Scene::THandle | Scene::SpinningFree => {
                        step(&self.body, q, e.momentum, Vec3::ZERO, DT)
                    }
                    Scene::Top => step_with(&self.body, q, e.momentum, top::torque, DT),
                };
                e.momentum = l1;
                rb.set_angvel(vec_to_rapier(landing_velocity(q, q1, DT, substeps)), true);
                if self.scene == Scene::Top {
                    // The centre of mass to where the new orientation puts it above the
                    // tip (rapier moves it in a straight line over the step).
                    let com1 = q1 * Vec3::new(0.0, 0.0, top::ARM);
                    let com = vec_to_engine(rb.translation());
                    rb.set_linvel(vec_to_rapier((com1 - com) / DT), true);
                }
            }
        }
        self.world.step();
    }

    /// The first body's state in f64: orientation, the world angular momentum about the
    /// centre of mass (T-handle) or about the tip (top), and the energy (kinetic, plus
    /// the potential for the top).
    ///
    /// rapier alone: from rapier's velocities and pose (the top's momentum about the tip
    /// and its kinetic energy include the centre of mass's motion). With the engine: from
    /// rapier's orientation and the engine's momentum.
    #[must_use]
    pub fn state(&self) -> (DQuat, DVec3, f64) {
        let rb = &self.world.bodies[self.handles[0]];
        let q = to_engine(*rb.rotation()).as_dquat().normalize();
        match self.method {
            Method::Rapier | Method::RapierGyroscopicOff => {
                let shape = match self.scene {
                    Scene::THandle => t_handle::SHAPE,
                    Scene::Top | Scene::SpinningFree => top::SHAPE,
                };
                let w = q.inverse() * vec_to_engine(rb.angvel()).as_dvec3();
                let l_body = shape.moments.as_dvec3() * w;
                let mut l = q * l_body;
                let mut e = 0.5 * w.dot(l_body);
                if self.scene == Scene::Top {
                    let m = f64::from(shape.mass);
                    let v = vec_to_engine(rb.linvel()).as_dvec3();
                    let r = vec_to_engine(rb.translation()).as_dvec3();
                    l += r.cross(v) * m;
                    e += 0.5 * m * v.length_squared() + m * f64::from(top::G) * r.z;
                }
                (q, l, e)
            }
            Method::RapierWithEngineStep => {
                let l = self.engine[0].momentum.as_dvec3();
                let moments = self.body.principal_moments().as_dvec3();
                let l_body = q.inverse() * l;
                let mut e = 0.5 * (l_body * l_body / moments).element_sum();
                if self.scene == Scene::Top {
                    let m = f64::from(top::SHAPE.mass);
                    let up = (q * DVec3::Z).z * f64::from(top::ARM);
                    e += m * f64::from(top::G) * up;
                }
                (q, l, e)
            }
        }
    }
}

/// The relative drift of a quantity: at the end, and the largest on the way.
#[derive(Clone, Copy, Debug)]
pub struct Drift {
    start: f64,
    /// Relative change at the end.
    pub end: f64,
    /// Largest relative change.
    pub worst: f64,
}

impl Drift {
    fn new(start: f64) -> Self {
        Drift {
            start,
            end: 0.0,
            worst: 0.0,
        }
    }

    fn push(&mut self, x: f64) {
        self.end = x / self.start - 1.0;
        self.worst = self.worst.max(self.end.abs());
    }
}

/// What a run of the T-handle measured.
#[derive(Clone, Debug)]
pub struct FreeReport {
    /// Mean time between flips in the same direction (NaN with fewer than two).
    pub period: f64,
    /// The flips counted (in one direction).
    pub flips: usize,
    /// Kinetic energy.
    pub energy: Drift,
    /// |L|.
    pub momentum: Drift,
    /// The largest angle between rapier's orientation after a step and the one the
    /// engine's step asked for (zero for rapier alone).
    pub landing: f64,
}

/// `steps` steps of one T-handle by `method`.
#[must_use]
pub fn run_t_handle(method: Method, steps: usize) -> FreeReport {
    let mut run = Run::new(Scene::THandle, method, 1);
    let (q, l, e) = run.state();
    let mut energy = Drift::new(e);
    let mut momentum = Drift::new(l.length());
    // Flips: the body momentum along the middle axis changes sign.
    let mut prev = (q.inverse() * l).y;
    let mut rising = Vec::new();
    let mut landing: f64 = 0.0;
    for n in 0..steps {
        let asked = if method == Method::RapierWithEngineStep {
            let e0 = run.engine[0];
            let q0 = to_engine(*run.world.bodies[e0.handle].rotation());
            Some(step(&run.body, q0, e0.momentum, Vec3::ZERO, DT).0)
        } else {
            None
        };
        run.step();
        let (q, l, e) = run.state();
        if let Some(a) = asked {
            // The angle of a^-1 q from its vector part (acos of a dot product near 1
            // would lose half the digits).
            let d = a.as_dquat().normalize().inverse() * q;
            let angle = 2.0 * DVec3::new(d.x, d.y, d.z).length().atan2(d.w.abs());
            landing = landing.max(angle);
        }
        energy.push(e);
        momentum.push(l.length());
        let b = (q.inverse() * l).y;
        if prev < 0.0 && b >= 0.0 {
            // Linear interpolation of the crossing time.
            rising.push((n as f64 + prev / (prev - b)) * f64::from(DT));
        }
        prev = b;
    }
    let period = if rising.len() >= 2 {
        (rising[rising.len() - 1] - rising[0]) / (rising.len() - 1) as f64
    } else {
        f64::NAN
    };
    FreeReport {
        period,
        flips: rising.len(),
        energy,
        momentum,
        landing,
    }
}

/// What a run of the top (or of its body spinning free) measured.
#[derive(Clone, Debug)]
pub struct TopReport {
    /// Energy, kinetic plus potential.
    pub energy: Drift,
    /// The vertical angular momentum about the tip, or about the centre of mass for the
    /// free body (conserved: gravity's torque about the tip is horizontal).
    pub vertical: Drift,
    /// The momentum about the tip along the symmetry axis (conserved for a symmetric top).
    pub spin: Drift,
    /// The largest distance of the tip from its point on the ground (zero for the free
    /// body).
    pub tip: f64,
}

/// `steps` steps of one top, or of its body spinning free ([`Scene::SpinningFree`]), by
/// `method`.
#[must_use]
pub fn run_top(scene: Scene, method: Method, steps: usize) -> TopReport {
    let mut run = Run::new(scene, method, 1);
    let (q, l, e) = run.state();
    let mut energy = Drift::new(e);
    let mut vertical = Drift::new(l.z);
    let mut spin = Drift::new(l.dot(q * DVec3::Z));
    let mut tip: f64 = 0.0;
    for _ in 0..steps {
        run.step();
        let (q, l, e) = run.state();
        energy.push(e);
        vertical.push(l.z);
        spin.push(l.dot(q * DVec3::Z));
        if scene != Scene::Top {
            continue;
        }
        let rb = &run.world.bodies[run.handles[0]];
        let tip_at = vec_to_engine(rb.translation()).as_dvec3()
            - q * DVec3::new(0.0, 0.0, f64::from(top::ARM));
        tip = tip.max(tip_at.length());
    }
    TopReport {
        energy,
        vertical,
        spin,
        tip,
    }
}

/// The median time of one body-step, in nanoseconds: `n` bodies in one world, `samples`
/// timings of `steps` steps each after a warm-up.
#[must_use]
pub fn cost_per_body_step(
    scene: Scene,
    method: Method,
    n: usize,
    steps: usize,
    samples: usize,
) -> f64 {
    let mut run = Run::new(scene, method, n);
    for _ in 0..steps {
        run.step();
    }
    let mut times: Vec<f64> = (0..samples)
        .map(|_| {
            let start = Instant::now();
            for _ in 0..steps {
                run.step();
            }
            start.elapsed().as_secs_f64() * 1e9 / (steps * n) as f64
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}

/// The median time of the engine's step alone (no rapier) per body, in nanoseconds, on
/// `n` T-handles, timed as [`cost_per_body_step`].
#[must_use]
pub fn engine_step_cost(n: usize, steps: usize, samples: usize) -> f64 {
    let s = t_handle::SHAPE;
    let body = Body::from_principal(s.moments, Quat::IDENTITY).expect("valid");
    let mut states = vec![(Quat::IDENTITY, t_handle::initial_momentum()); n];
    let advance = |states: &mut Vec<(Quat, Vec3)>| {
        for (q, l) in states.iter_mut() {
            (*q, *l) = step(&body, *q, *l, Vec3::ZERO, DT);
        }
    };
    advance(&mut states);
    let mut times: Vec<f64> = (0..samples)
        .map(|_| {
            let start = Instant::now();
            for _ in 0..steps {
                advance(std::hint::black_box(&mut states));
            }
            start.elapsed().as_secs_f64() * 1e9 / (steps * n) as f64
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}
