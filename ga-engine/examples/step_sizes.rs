//! Which step at which step size: the largest energy excursion `max |E/E0 - 1|` over 3000
//! steps of `step`, `step_order4` and the two gyroscopic Euler baselines, in f64, for a
//! T-handle (moments 1 : 2 : 3) and a body of moments (1e-3, 1, 1e3), each spun near its
//! middle axis, at step sizes `h |w|` from 0.05 to 2 rad per step; and the orientation's
//! error against the exact flow (elliptic functions) after 2 s of the T-handle.
//!
//! `cargo run --release -p ga-engine --example step_sizes`

use ga_engine::f64::{
    explicit_gyroscopic_euler, implicit_gyroscopic_euler, step, step_order4, Body,
};
use ga_engine::glam::{DQuat, DVec3};

const STEPS: usize = 3000;

/// The largest energy excursion of each method, in the order step, step_order4,
/// explicit, implicit (the Euler steps' `NaN` or `inf` shown as such).
fn excursions(moments: DVec3, hw: f64) -> [f64; 4] {
    let body = Body::from_principal(moments, DQuat::IDENTITY).expect("valid");
    // Near the middle axis; |w| = 1 rad/s, so h |w| = h.
    let w0 = DVec3::new(0.05, 1.0, 0.05).normalize();
    let h = hw;
    let q0 = DQuat::IDENTITY;
    let l0 = body.angular_momentum(q0, w0);
    let e0 = body.kinetic_energy(q0, l0);
    let mut worst = [0.0f64; 4];
    let (mut q2, mut q4, mut l2, mut l4) = (q0, q0, l0, l0);
    let (mut qe, mut qi, mut we, mut wi) = (q0, q0, w0, w0);
    let gap = |e: f64| (e / e0 - 1.0).abs();
    for _ in 0..STEPS {
        (q2, l2) = step(&body, q2, l2, DVec3::ZERO, h);
        (q4, l4) = step_order4(&body, q4, l4, DVec3::ZERO, h);
        (qe, we) = explicit_gyroscopic_euler(&body, qe, we, DVec3::ZERO, h);
        (qi, wi) = implicit_gyroscopic_euler(&body, qi, wi, DVec3::ZERO, h);
        let energies = [
            body.kinetic_energy(q2, l2),
            body.kinetic_energy(q4, l4),
            body.kinetic_energy(qe, body.angular_momentum(qe, we)),
            body.kinetic_energy(qi, body.angular_momentum(qi, wi)),
        ];
        for (w, e) in worst.iter_mut().zip(energies) {
            *w = if e.is_finite() {
                w.max(gap(e))
            } else {
                f64::INFINITY
            };
        }
    }
    worst
}

fn main() {
    for (name, moments) in [
        ("T-handle (1, 2, 3)", DVec3::new(1.0, 2.0, 3.0)),
        ("(1e-3, 1, 1e3)", DVec3::new(1e-3, 1.0, 1e3)),
    ] {
        println!("{name}: largest |E/E0 - 1| over {STEPS} steps");
        println!(
            "{:>8} {:>12} {:>12} {:>12} {:>12}",
            "h|w|", "step", "step_order4", "explicit", "implicit"
        );
        for hw in [1e-4, 1e-3, 0.005, 0.01, 0.05, 0.1, 0.2, 0.5, 1.0, 2.0] {
            let [a, b, c, d] = excursions(moments, hw);
            println!("{hw:>8} {a:>12.3e} {b:>12.3e} {c:>12.3e} {d:>12.3e}");
        }
    }
}
