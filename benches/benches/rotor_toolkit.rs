//! The G3 rotor toolkit against glam's `Quat` in f64: slerp, the matrix both ways and
//! the rotation arc, per item over a batch.

mod common;

use common::{batch1, batch2, config, conv, group, BATCH};
use criterion::{criterion_group, criterion_main, Criterion};
use ga_benches::inputs::{g3_rotors, g3_vectors};
use ga_core::f64::g3::{Rotor, Vector};
use glam::{DMat3, DQuat, DVec3};

fn rotors(seed: u64) -> Vec<Rotor> {
    conv(&g3_rotors(BATCH, seed), Rotor::from_array)
}

fn slerp(c: &mut Criterion) {
    let (a, b) = (rotors(1), rotors(2));
    let mut g = group(c, "g3/toolkit/slerp/f64/batch");
    batch2(&mut g, "ga-core", &a, &b, |x, y| x.slerp(y, 0.3));
    batch2(
        &mut g,
        "glam",
        &conv(&a, DQuat::from),
        &conv(&b, DQuat::from),
        |x, y| x.slerp(y, 0.3),
    );
    g.finish();
}

fn matrices(c: &mut Criterion) {
    let r = rotors(3);
    let mut g = group(c, "g3/toolkit/to_matrix/f64/batch");
    batch1(&mut g, "ga-core", &r, Rotor::to_matrix);
    batch1(&mut g, "glam", &conv(&r, DQuat::from), DMat3::from_quat);
    g.finish();
    let m = conv(&r, Rotor::to_matrix);
    let mut g = group(c, "g3/toolkit/from_matrix/f64/batch");
    batch1(&mut g, "ga-core", &m, Rotor::from_mat3);
    batch1(
        &mut g,
        "glam",
        &conv(&m, |m| DMat3::from_cols_array_2d(&m)),
        |m| DQuat::from_mat3(&m),
    );
    g.finish();
}

fn rotation_arc(c: &mut Criterion) {
    let a = conv(&g3_vectors(BATCH, 4), Vector::from_array);
    let b = conv(&g3_vectors(BATCH, 5), Vector::from_array);
    let mut g = group(c, "g3/toolkit/from_rotation_arc/f64/batch");
    batch2(&mut g, "ga-core", &a, &b, Rotor::from_rotation_arc);
    batch2(
        &mut g,
        "glam",
        &conv(&a, DVec3::from),
        &conv(&b, DVec3::from),
        DQuat::from_rotation_arc,
    );
    g.finish();
}

criterion_group! {
    name = benches;
    config = config();
    targets = slerp, matrices, rotation_arc
}
criterion_main!(benches);
