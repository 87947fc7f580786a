//! `ga_engine` against the step engines use today (issue 19), f32, 60 Hz:
//!
//! - `engine/f32/one_body`: 1024 different bodies, each stepped once by a one-body call
//!   (`step`, `step_order4`, `step_with` with the torque held, the module's own baselines) against the explicit gyroscopic
//!   Euler step written here directly on glam, the way an engine writes it
//!   (`glam_explicit_euler`). Targets: `step` at most 1.5x `glam_explicit_euler` (issue
//!   19), then at most 1.0x (issue 36).
//!   `step_framed`: the same bodies with their moments given in another order, which
//!   the step reaches through a frame (two quaternion products more). `step_tensor`: the
//!   same bodies built from their inertia tensors turned by a seeded rotation (a body from a
//!   mesh or a rotated collider: a general frame), against the same Euler step on glam with
//!   the body-frame tensor and its inverse as `Mat3` (`glam_explicit_euler_tensor`), and
//!   with the principal moments and frame as rapier keeps such a body, one quaternion
//!   product a step (`glam_explicit_euler_principal`).
//! - `engine/f32/slice`: the same 1024 bodies by `step_slice` (eight lanes with AVX, else
//!   four) on `BodyState`s, and by `BodyColumns::step` (the column store: each component of
//!   eight bodies side by side, as the lanes take them). Targets (issue 36): at most
//!   0.4x `glam_explicit_euler` per body.
//! - `engine/f64/slice`: the same 1024 bodies in f64, one at a time (`step`), by
//!   `step_slice` (four lanes, in one AVX register where the CPU has AVX) and by
//!   `BodyColumns::step`, against the explicit gyroscopic Euler step on glam's `DQuat` and
//!   `DVec3` (`glam_explicit_euler`), the peer of an engine that runs in f64.
//! - `engine/f32/rayon`: 2^20 bodies by `par_step_slice` and `BodyColumns::par_step` on 1
//!   and on all threads.
//!
//! Times are per body (criterion's throughput is bodies per second).

mod common;

use common::config;
use criterion::{black_box, criterion_group, criterion_main, Criterion, Throughput};
use ga_engine::f32::{
    explicit_gyroscopic_euler, implicit_gyroscopic_euler, par_step_slice, step, step_order4,
    step_slice, step_with, Body, BodyColumns, BodyState,
};
use ga_engine::glam::{DQuat, DVec3, Mat3, Quat, Vec3};

/// Bodies per batch.
const BODIES: usize = 1024;
/// 60 Hz.
const DT: f32 = 1.0 / 60.0;

/// Seeded, varied T-handle-like bodies: diagonal inertia (the common case in engines,
/// and the glam step below assumes it), turning at a few rad/s, small torques.
fn crowd(n: usize) -> Vec<BodyState> {
    crowd_in_order(n, [0, 1, 2])
}

/// [`crowd`] with each body's moments given in `order` (the smallest moment first for
/// `[0, 1, 2]`): the step orders the axes itself, through a frame where they come in
/// another order, so `[1, 2, 0]` measures a body that needs one.
fn crowd_in_order(n: usize, order: [usize; 3]) -> Vec<BodyState> {
    let mut rng = ga_test_rng::Rng::new(0x9e37_79b9_7f4a_7c15);
    let mut next = move || rng.next_f32();
    (0..n)
        .map(|_| {
            let sorted = [1.0 + next(), 2.0 + next(), 3.0 + next()];
            let moments = Vec3::from(order.map(|k| sorted[k]));
            let body = Body::from_principal(moments, Quat::IDENTITY).expect("positive");
            let q = Quat::from_xyzw(next() - 0.5, next() - 0.5, next() - 0.5, 1.0).normalize();
            let l = Vec3::new(next() - 0.5, 4.0 * next(), next() - 0.5) * 4.0;
            let mut s = BodyState::new(body, q, l);
            s.torque = Vec3::new(next() - 0.5, next() - 0.5, next() - 0.5) * 0.1;
            s
        })
        .collect()
}

/// [`crowd`]'s bodies, each built from its inertia tensor turned by a seeded rotation
/// (`R diag(I) R^T`), so that its principal frame is a general rotation; with the tensor.
fn crowd_of_tensors(n: usize) -> Vec<(BodyState, Mat3)> {
    let mut rng = ga_test_rng::Rng::new(0x2545_f491_4f6c_dd1d);
    let mut next = move || rng.next_f32() - 0.5;
    crowd(n)
        .into_iter()
        .map(|mut s| {
            let turn = Quat::from_xyzw(next(), next(), next(), next()).normalize();
            let r = Mat3::from_quat(turn);
            let tensor = r * Mat3::from_diagonal(s.body.principal_moments()) * r.transpose();
            s.body = Body::from_tensor(tensor).expect("positive");
            (s, tensor)
        })
        .collect()
}

/// Stamps the explicit gyroscopic Euler step on glam in one precision (the same lines for
/// `Quat` and `DQuat`).
macro_rules! glam_explicit_euler_in {
    ($name:ident, $quat:ty, $vec3:ty, $t:ty) => {
        /// Explicit gyroscopic Euler on glam: body-frame Euler equations, then the
        /// orientation by the new world angular velocity, normalised. `i` principal
        /// moments (diagonal inertia).
        #[inline]
        fn $name(i: $vec3, inv_i: $vec3, q: $quat, w: $vec3, t: $vec3, h: $t) -> ($quat, $vec3) {
            let q_inv = q.conjugate();
            let wb = q_inv * w;
            let tb = q_inv * t;
            let wb = wb + h * (tb - wb.cross(i * wb)) * inv_i;
            let w = q * wb;
            let q = (q + <$quat>::from_vec4((0.5 * h * w).extend(0.0)) * q).normalize();
            (q, w)
        }
    };
}
glam_explicit_euler_in!(glam_explicit_euler, Quat, Vec3, f32);
glam_explicit_euler_in!(glam_explicit_euler_f64, DQuat, DVec3, f64);

/// [`glam_explicit_euler`] for a body whose tensor `i` (and its inverse) is a full matrix
/// in the body frame, as an engine writes it for a body that is not in its principal axes.
#[inline]
fn glam_explicit_euler_tensor(
    i: &Mat3,
    inv_i: &Mat3,
    q: Quat,
    w: Vec3,
    t: Vec3,
    h: f32,
) -> (Quat, Vec3) {
    let q_inv = q.conjugate();
    let wb = q_inv * w;
    let tb = q_inv * t;
    let wb = wb + h * (*inv_i * (tb - wb.cross(*i * wb)));
    let w = q * wb;
    let q = (q + Quat::from_vec4((0.5 * h * w).extend(0.0)) * q).normalize();
    (q, w)
}

/// [`glam_explicit_euler`] for a body kept as its principal moments `i` and principal frame
/// `p` (principal axes to body frame), as rapier keeps a body that is not in its principal
/// axes: the orientation of the principal axes `q p` each step (one quaternion product),
/// the diagonal Euler equations in them, and the orientation by the world velocity.
#[inline]
fn glam_explicit_euler_principal(
    p: Quat,
    i: Vec3,
    inv_i: Vec3,
    q: Quat,
    w: Vec3,
    t: Vec3,
    h: f32,
) -> (Quat, Vec3) {
    let q_p = q * p;
    let q_inv = q_p.conjugate();
    let wb = q_inv * w;
    let tb = q_inv * t;
    let wb = wb + h * (tb - wb.cross(i * wb)) * inv_i;
    let w = q_p * wb;
    let q = (q + Quat::from_vec4((0.5 * h * w).extend(0.0)) * q).normalize();
    (q, w)
}

fn engine(c: &mut Criterion) {
    let states = crowd(BODIES);
    let velocities: Vec<Vec3> = states.iter().map(BodyState::angular_velocity).collect();
    let moments: Vec<(Vec3, Vec3)> = states
        .iter()
        .map(|s| {
            (
                s.body.principal_moments(),
                s.body.principal_moments().recip(),
            )
        })
        .collect();

    let mut g = c.benchmark_group("engine/f32/one_body");
    g.throughput(Throughput::Elements(BODIES as u64));
    g.bench_function("glam_explicit_euler", |b| {
        let mut qw: Vec<(Quat, Vec3)> = states
            .iter()
            .zip(&velocities)
            .map(|(s, &w)| (s.orientation, w))
            .collect();
        b.iter(|| {
            for ((q, w), (s, &(i, inv))) in qw.iter_mut().zip(states.iter().zip(&moments)) {
                (*q, *w) = glam_explicit_euler(i, inv, *q, *w, s.torque, black_box(DT));
            }
            black_box(&qw);
        });
    });
    g.bench_function("step", |b| {
        let mut ql: Vec<(Quat, Vec3)> = states
            .iter()
            .map(|s| (s.orientation, s.angular_momentum))
            .collect();
        b.iter(|| {
            for ((q, l), s) in ql.iter_mut().zip(&states) {
                (*q, *l) = step(&s.body, *q, *l, s.torque, black_box(DT));
            }
            black_box(&ql);
        });
    });
    let framed = crowd_in_order(BODIES, [1, 2, 0]);
    g.bench_function("step_framed", |b| {
        let mut ql: Vec<(Quat, Vec3)> = framed
            .iter()
            .map(|s| (s.orientation, s.angular_momentum))
            .collect();
        b.iter(|| {
            for ((q, l), s) in ql.iter_mut().zip(&framed) {
                (*q, *l) = step(&s.body, *q, *l, s.torque, black_box(DT));
            }
            black_box(&ql);
        });
    });
    let (tensors, matrices): (Vec<BodyState>, Vec<(Mat3, Mat3)>) = crowd_of_tensors(BODIES)
        .into_iter()
        .map(|(s, i)| (s, (i, i.inverse())))
        .unzip();
    g.bench_function("glam_explicit_euler_tensor", |b| {
        let mut qw: Vec<(Quat, Vec3)> = tensors
            .iter()
            .map(|s| (s.orientation, s.angular_velocity()))
            .collect();
        b.iter(|| {
            for ((q, w), (s, (i, inv))) in qw.iter_mut().zip(tensors.iter().zip(&matrices)) {
                (*q, *w) = glam_explicit_euler_tensor(i, inv, *q, *w, s.torque, black_box(DT));
            }
            black_box(&qw);
        });
    });
    let principal: Vec<(Quat, Vec3, Vec3)> = tensors
        .iter()
        .map(|s| {
            let i = s.body.principal_moments();
            (s.body.principal_frame(), i, i.recip())
        })
        .collect();
    g.bench_function("glam_explicit_euler_principal", |b| {
        let mut qw: Vec<(Quat, Vec3)> = tensors
            .iter()
            .map(|s| (s.orientation, s.angular_velocity()))
            .collect();
        b.iter(|| {
            for ((q, w), (s, &(p, i, inv))) in qw.iter_mut().zip(tensors.iter().zip(&principal)) {
                (*q, *w) =
                    glam_explicit_euler_principal(p, i, inv, *q, *w, s.torque, black_box(DT));
            }
            black_box(&qw);
        });
    });
    g.bench_function("step_tensor", |b| {
        let mut ql: Vec<(Quat, Vec3)> = tensors
            .iter()
            .map(|s| (s.orientation, s.angular_momentum))
            .collect();
        b.iter(|| {
            for ((q, l), s) in ql.iter_mut().zip(&tensors) {
                (*q, *l) = step(&s.body, *q, *l, s.torque, black_box(DT));
            }
            black_box(&ql);
        });
    });
    g.bench_function("step_order4", |b| {
        let mut ql: Vec<(Quat, Vec3)> = states
            .iter()
            .map(|s| (s.orientation, s.angular_momentum))
            .collect();
        b.iter(|| {
            for ((q, l), s) in ql.iter_mut().zip(&states) {
                (*q, *l) = step_order4(&s.body, *q, *l, s.torque, black_box(DT));
            }
            black_box(&ql);
        });
    });
    // The torque function returns the held torque, so that the row measures the step's
    // own cost beside `step` (a torque function's work, such as gravity's lever arm, is
    // the caller's and comes on top).
    g.bench_function("step_with", |b| {
        let mut ql: Vec<(Quat, Vec3)> = states
            .iter()
            .map(|s| (s.orientation, s.angular_momentum))
            .collect();
        b.iter(|| {
            for ((q, l), s) in ql.iter_mut().zip(&states) {
                let torque = s.torque;
                (*q, *l) = step_with(&s.body, *q, *l, |_| torque, black_box(DT));
            }
            black_box(&ql);
        });
    });
    g.bench_function("explicit_gyroscopic_euler", |b| {
        let mut qw: Vec<(Quat, Vec3)> = states
            .iter()
            .zip(&velocities)
            .map(|(s, &w)| (s.orientation, w))
            .collect();
        b.iter(|| {
            for ((q, w), s) in qw.iter_mut().zip(&states) {
                (*q, *w) = explicit_gyroscopic_euler(&s.body, *q, *w, s.torque, black_box(DT));
            }
            black_box(&qw);
        });
    });
    g.bench_function("implicit_gyroscopic_euler", |b| {
        let mut qw: Vec<(Quat, Vec3)> = states
            .iter()
            .zip(&velocities)
            .map(|(s, &w)| (s.orientation, w))
            .collect();
        b.iter(|| {
            for ((q, w), s) in qw.iter_mut().zip(&states) {
                (*q, *w) = implicit_gyroscopic_euler(&s.body, *q, *w, s.torque, black_box(DT));
            }
            black_box(&qw);
        });
    });
    g.finish();

    let mut g = c.benchmark_group("engine/f32/slice");
    g.throughput(Throughput::Elements(BODIES as u64));
    g.bench_function("step_slice", |b| {
        let mut s = states.clone();
        b.iter(|| step_slice(black_box(&mut s), black_box(DT)));
    });
    g.bench_function("body_columns_step", |b| {
        let mut bodies: BodyColumns = states.iter().copied().collect();
        b.iter(|| black_box(&mut bodies).step(black_box(DT)));
    });
    g.finish();

    let wide: Vec<ga_engine::f64::BodyState> = states
        .iter()
        .map(|s| {
            let m = s.body.principal_moments().as_dvec3();
            let body = ga_engine::f64::Body::from_principal(m, DQuat::IDENTITY).expect("positive");
            let mut w = ga_engine::f64::BodyState::new(
                body,
                s.orientation.as_dquat().normalize(),
                s.angular_momentum.as_dvec3(),
            );
            w.torque = s.torque.as_dvec3();
            w
        })
        .collect();
    let mut g = c.benchmark_group("engine/f64/slice");
    g.throughput(Throughput::Elements(BODIES as u64));
    g.bench_function("glam_explicit_euler", |b| {
        let mut qw: Vec<(DQuat, DVec3)> = wide
            .iter()
            .map(|s| (s.orientation, s.angular_velocity()))
            .collect();
        let moments: Vec<(DVec3, DVec3)> = wide
            .iter()
            .map(|s| {
                let i = s.body.principal_moments();
                (i, i.recip())
            })
            .collect();
        b.iter(|| {
            for ((q, w), (s, &(i, inv))) in qw.iter_mut().zip(wide.iter().zip(&moments)) {
                (*q, *w) = glam_explicit_euler_f64(i, inv, *q, *w, s.torque, black_box(1.0 / 60.0));
            }
            black_box(&qw);
        });
    });
    g.bench_function("step", |b| {
        let mut s = wide.clone();
        b.iter(|| {
            for s in black_box(&mut s).iter_mut() {
                s.step(black_box(1.0 / 60.0));
            }
        });
    });
    g.bench_function("step_slice", |b| {
        let mut s = wide.clone();
        b.iter(|| ga_engine::f64::step_slice(black_box(&mut s), black_box(1.0 / 60.0)));
    });
    g.bench_function("body_columns_step", |b| {
        let mut bodies: ga_engine::f64::BodyColumns = wide.iter().copied().collect();
        b.iter(|| black_box(&mut bodies).step(black_box(1.0 / 60.0)));
    });
    g.finish();

    let big = crowd(1 << 20);
    let mut g = c.benchmark_group("engine/f32/rayon");
    g.throughput(Throughput::Elements(big.len() as u64));
    g.sample_size(10);
    for threads in [1, rayon::current_num_threads()] {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("pool");
        let mut s = big.clone();
        g.bench_function(format!("par_step_slice/{threads}_threads"), |b| {
            b.iter(|| pool.install(|| par_step_slice(black_box(&mut s), black_box(DT))));
        });
        let mut columns: BodyColumns = big.iter().copied().collect();
        g.bench_function(format!("body_columns_par_step/{threads}_threads"), |b| {
            b.iter(|| pool.install(|| black_box(&mut columns).par_step(black_box(DT))));
        });
    }
    g.finish();
}

criterion_group! {
    name = benches;
    config = config();
    targets = engine
}
criterion_main!(benches);
