//! One hour of game time at 60 Hz in f32 (216,000 steps) of a T-handle (Dzhanibekov
//! body, moments 1 : 2 : 3, spun about the intermediate axis) and of a heavy spinning
//! top, by `ga_engine`'s steps against the engines' gyroscopic Euler steps.
//!
//! Prints, per method: the relative drift of |L| and of the energy at the end and their
//! largest excursion, and for the T-handle the flip period (mean time between successive
//! flips in the same direction, from the sign changes of the momentum along the
//! intermediate axis) against the exact flow's (`free_body_orbit`, elliptic functions in
//! f64). Run: `cargo run --release -p ga-engine --example t_handle`.

use ga_engine::f32::{
    explicit_gyroscopic_euler, implicit_gyroscopic_euler, step, step_order4, step_with, Body,
};
use ga_engine::glam::{Quat, Vec3};
use ga_rigid::exact_flow::free_body_orbit;

/// 60 Hz.
const DT: f32 = 1.0 / 60.0;
/// One hour.
const STEPS: usize = 216_000;

/// The steps compared.
#[derive(Clone, Copy, Debug)]
enum Method {
    Splitting,
    SplittingOrder4,
    ExplicitEuler,
    ImplicitEuler,
}

impl Method {
    fn name(self) -> &'static str {
        match self {
            Method::Splitting => "engine::step (order 2)",
            Method::SplittingOrder4 => "engine::step_order4",
            Method::ExplicitEuler => "explicit gyroscopic Euler",
            Method::ImplicitEuler => "implicit gyroscopic Euler",
        }
    }

    /// One step from `(q, L)` with world torque `t`; the Euler steps carry the angular
    /// velocity internally, converted here so that every method reports L.
    fn step(self, body: &Body, q: Quat, l: Vec3, w: &mut Vec3, t: Vec3) -> (Quat, Vec3) {
        match self {
            Method::Splitting => step(body, q, l, t, DT),
            Method::SplittingOrder4 => step_order4(body, q, l, t, DT),
            Method::ExplicitEuler | Method::ImplicitEuler => {
                let (q, w2) = if matches!(self, Method::ExplicitEuler) {
                    explicit_gyroscopic_euler(body, q, *w, t, DT)
                } else {
                    implicit_gyroscopic_euler(body, q, *w, t, DT)
                };
                *w = w2;
                (q, body.angular_momentum(q, w2))
            }
        }
    }
}

const METHODS: [Method; 4] = [
    Method::Splitting,
    Method::SplittingOrder4,
    Method::ExplicitEuler,
    Method::ImplicitEuler,
];

/// Drift and excursion of a quantity relative to its start.
#[derive(Default)]
struct Drift {
    start: f64,
    last: f64,
    worst: f64,
}

impl Drift {
    fn new(start: f64) -> Self {
        Drift {
            start,
            last: start,
            worst: 0.0,
        }
    }
    fn push(&mut self, x: f64) {
        self.last = x;
        self.worst = self.worst.max((x / self.start - 1.0).abs());
    }
    fn end(&self) -> f64 {
        self.last / self.start - 1.0
    }
}

fn t_handle() {
    let moments = [1.0_f32, 2.0, 3.0];
    let body = Body::from_principal(Vec3::from(moments), Quat::IDENTITY).expect("positive");
    // About one turn per second about the intermediate axis, a 1% wobble.
    let l0 = Vec3::new(
        0.02 * 2.0 * std::f32::consts::TAU,
        2.0 * std::f32::consts::TAU,
        0.0,
    );
    let exact_period = free_body_orbit(moments.map(f64::from), l0.to_array().map(f64::from)).period;
    println!("T-handle, moments (1, 2, 3), L0 = {l0}, dt = 1/60 s, {STEPS} steps (1 hour)");
    println!("  exact flow: flip period {exact_period:.6} s (a flip every half period)");
    for method in METHODS {
        let (mut q, mut l) = (Quat::IDENTITY, l0);
        let mut w = body.angular_velocity(q, l);
        let mut momentum = Drift::new(f64::from(l.length()));
        let mut energy = Drift::new(f64::from(body.kinetic_energy(q, l)));
        // Flips: sign changes of the body momentum along the intermediate axis.
        let mut last_sign = 1.0_f32;
        let mut rising = Vec::new();
        let mut prev_b = (q.inverse() * l).y;
        for n in 0..STEPS {
            (q, l) = method.step(&body, q, l, &mut w, Vec3::ZERO);
            let b = (q.inverse() * l).y;
            if b.signum() != last_sign && b != 0.0 {
                // Linear interpolation of the crossing time.
                let t = (n as f64 + f64::from(prev_b / (prev_b - b))) * f64::from(DT);
                if b > 0.0 {
                    rising.push(t);
                }
                last_sign = b.signum();
            }
            prev_b = b;
            momentum.push(f64::from(l.length()));
            energy.push(f64::from(body.kinetic_energy(q, l)));
        }
        let period = if rising.len() >= 2 {
            (rising[rising.len() - 1] - rising[0]) / (rising.len() - 1) as f64
        } else {
            f64::NAN
        };
        println!(
            "  {:<27} |L| drift {:+.2e} (max {:.2e})  energy drift {:+.2e} (max {:.2e})  flip period {:.6} s ({:+.3}% of exact, {} flips)",
            method.name(),
            momentum.end(),
            momentum.worst,
            energy.end(),
            energy.worst,
            period,
            100.0 * (period / exact_period - 1.0),
            rising.len(),
        );
    }
}

fn top() {
    // A symmetric top on a fixed pivot: moments about the pivot (1, 1, 0.4), centre of
    // mass 0.1 up the symmetry axis, mass 2, g = 9.81; spun at 30 rad/s, tilted 0.3 rad.
    let body = Body::from_principal(Vec3::new(1.0, 1.0, 0.4), Quat::IDENTITY).expect("positive");
    let (mass, g, arm) = (2.0_f32, 9.81_f32, 0.1_f32);
    let torque = |q: Quat| (q * Vec3::Z * arm).cross(Vec3::new(0.0, 0.0, -mass * g));
    let potential = |q: Quat| f64::from(mass * g * arm * (q * Vec3::Z).z);
    let q0 = Quat::from_rotation_x(0.3);
    let l0 = body.angular_momentum(q0, q0 * Vec3::new(0.0, 0.0, 30.0));
    println!("heavy top, moments (1, 1, 0.4) about the pivot, spin 30 rad/s, tilt 0.3 rad; gravity torque from the orientation at each step's start (held over the step), or at both ends (step_with)");
    for method in [None].into_iter().chain(METHODS.map(Some)) {
        let (mut q, mut l) = (q0, l0);
        let mut w = body.angular_velocity(q, l);
        // |L| is not conserved under gravity; L_z (vertical) and L . e3 (spin) are.
        let mut vertical = Drift::new(f64::from(l.z));
        let mut spin = Drift::new(f64::from(l.dot(q * Vec3::Z)));
        let mut energy = Drift::new(f64::from(body.kinetic_energy(q, l)) + potential(q));
        for _ in 0..STEPS {
            (q, l) = match method {
                Some(m) => m.step(&body, q, l, &mut w, torque(q)),
                None => step_with(&body, q, l, torque, DT),
            };
            vertical.push(f64::from(l.z));
            spin.push(f64::from(l.dot(q * Vec3::Z)));
            energy.push(f64::from(body.kinetic_energy(q, l)) + potential(q));
        }
        println!(
            "  {:<27} L_z drift {:+.2e} (max {:.2e})  spin L.e3 drift {:+.2e} (max {:.2e})  energy drift {:+.2e} (max {:.2e})",
            method.map_or("engine::step_with (the call for it)", Method::name),
            vertical.end(),
            vertical.worst,
            spin.end(),
            spin.worst,
            energy.end(),
            energy.worst
        );
    }
}

fn main() {
    t_handle();
    top();
}
