//! The state-transition matrix of a heavy top's attitude and spin, from six dual-number
//! runs of `lie-rk4`: each column is the derivative of `(R(T), Omega(T))` along one initial
//! parameter: a component of `B` in `R(0) = exp(B)` at `B = 0`, or a component of `w(0)`.
//! (The `d/dB12` column has no spin part: a turn about the vertical, the field's axis, is
//! a symmetry of the heavy top.)
//!
//! Run: `cargo run -p ga-rigid --example heavy_top_stm --features dual --release`.
//! The columns are checked against central differences in `ga-rigid/tests/gradients.rs`.

use ga_core::dual64::g3::{Bivector, Vector};
use ga_core::num_dual::Dual64;
use ga_rigid::gradients::dual64::{FreeBody, State};

fn main() {
    let c = |x: f64| Dual64::new(x, 0.0);
    let body = FreeBody::new([c(1.0), c(1.2), c(0.4)])
        .expect("positive moments")
        .with_gravity(
            c(1.0),
            Vector::new(c(0.0), c(0.0), c(-9.81)),
            Vector::new(c(0.0), c(0.0), c(0.1)),
        );
    let w0 = [1.0, 0.5, 8.0];
    let (step, t) = (0.01, 5.0);
    let names = ["R.s", "R.e12", "R.e13", "R.e23", "O.e12", "O.e13", "O.e23"];
    let mut columns = Vec::new();
    for p in 0..6 {
        let seed = |k: usize, x: f64| Dual64::new(x, if k == p { 1.0 } else { 0.0 });
        let rotor = Bivector::new(seed(0, 0.0), seed(1, 0.0), seed(2, 0.0)).exp();
        let w = [0, 1, 2].map(|k| seed(k + 3, w0[k]));
        let end = body
            .lie_rk4(State::new(rotor, w), step, t)
            .expect("valid step");
        let (r, o) = (end.rotor, end.omega);
        columns.push([r.s, r.e12, r.e13, r.e23, o.e12, o.e13, o.e23]);
    }
    println!("heavy top, moments (1, 1.2, 0.4), w(0) = {w0:?}, lie-rk4 h = {step}, T = {t}");
    println!(
        "{:>7} {:>10} | {:>10} {:>10} {:>10} {:>10} {:>10} {:>10}",
        "", "value", "d/dB12", "d/dB13", "d/dB23", "d/dw1", "d/dw2", "d/dw3"
    );
    for (row, name) in names.iter().enumerate() {
        print!("{name:>7} {:>10.6} |", columns[0][row].re);
        for column in &columns {
            print!(" {:>10.5}", column[row].eps);
        }
        println!();
    }
}
