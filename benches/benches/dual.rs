//! The price of derivatives: the G3 rotor product over `num_dual::Dual64`
//! (`ga_core::dual64::g3`, the macro's generic-scalar path) against the same product in
//! `f64` (`ga_core::f64::g3`), per item over a batch and per step of a dependent chain.
//! A dual number carries two `f64`s and its product three multiplications, so about 2x to
//! 3x is the expected range; the target is at most 2.5x.

mod common;

use common::{batch2, chain, config, conv, group};
use criterion::{criterion_group, criterion_main, Criterion};
use ga_benches::inputs::g3_rotors;
use ga_core::num_dual::Dual64;

fn rotor_mul(c: &mut Criterion) {
    let (p, q) = (g3_rotors(common::BATCH, 1), g3_rotors(common::BATCH, 2));
    let real = |x: [f64; 4]| ga_core::f64::g3::Even::from_array(x);
    // Derivative parts that are not zero, so that no work can be skipped.
    let dual =
        |x: [f64; 4]| ga_core::dual64::g3::Even::from_array(x.map(|v| Dual64::new(v, 0.5 - v)));

    let mut g = group(c, "g3/rotor_mul/dual/batch");
    batch2(&mut g, "f64", &conv(&p, real), &conv(&q, real), |a, b| {
        a * b
    });
    batch2(
        &mut g,
        "Dual64",
        &conv(&p, dual),
        &conv(&q, dual),
        |a, b| a * b,
    );
    g.finish();

    // A chain of products, renormalised now and then by the inputs being unit rotors.
    let mut g = group(c, "g3/rotor_mul/dual/chain");
    chain(
        &mut g,
        "f64",
        real([1.0, 0.0, 0.0, 0.0]),
        &conv(&q, real),
        |x, a| x * a,
    );
    chain(
        &mut g,
        "Dual64",
        dual([1.0, 0.0, 0.0, 0.0]),
        &conv(&q, dual),
        |x, a| x * a,
    );
    g.finish();
}

criterion_group! {
    name = benches;
    config = config();
    targets = rotor_mul
}
criterion_main!(benches);
