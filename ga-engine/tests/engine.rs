//! `ga_engine` against references it does not share code with: the exact free
//! rigid-body flow (elliptic functions, `exact_flow.rs`), glam's own matrices and
//! quaternions, and a step written here on glam; plus its invariants (|L| to the bit,
//! slice and one-body forms bit-equal, thread count irrelevant, golden bits).

use ga_engine::glam::{DMat3, DQuat, DVec3, Mat3, Quat, Vec3};
use ga_engine::{f32 as e32, f64 as e64, BodyError};
use ga_rigid::exact_flow::{exact_free_body, free_body_orbit};

/// glam's quaternion as the lecture's rotor `[s, e12, e13, e23]` (README conventions).
fn rotor_of(q: DQuat) -> [f64; 4] {
    [q.w, -q.z, q.y, -q.x]
}

/// The rotor `[s, e12, e13, e23]` as glam's quaternion.
fn quat_of(r: [f64; 4]) -> DQuat {
    DQuat::from_xyzw(-r[3], r[2], -r[1], r[0])
}

/// The angle between two orientations (by atan2, accurate for tiny angles).
fn angle(a: DQuat, b: DQuat) -> f64 {
    let d = a * b.inverse();
    2.0 * d.xyz().length().atan2(d.w.abs())
}

/// The exact flow from `(q, L_world)` over `t` for principal moments `i` (frame = body).
fn exact(i: [f64; 3], q: DQuat, l: DVec3, t: f64) -> (DQuat, DVec3) {
    let m0 = q.inverse() * l;
    let (r, _) = exact_free_body(i, m0.to_array(), rotor_of(q), t);
    (quat_of(r), l)
}

const T_HANDLE: [f64; 3] = [1.0, 2.0, 3.0];

#[test]
fn splitting_converges_to_the_exact_flow_at_order_two_and_four() {
    let body = e64::Body::from_principal(DVec3::from(T_HANDLE), DQuat::IDENTITY).unwrap();
    let q0 = DQuat::from_rotation_x(0.3) * DQuat::from_rotation_z(-0.2);
    let l0 = DVec3::new(0.3, 2.0, 0.4);
    let t_end = 2.0;
    let (q_ref, _) = exact(T_HANDLE, q0, l0, t_end);
    let error = |n: usize, order4: bool| {
        let h = t_end / n as f64;
        let (mut q, mut l) = (q0, l0);
        for _ in 0..n {
            (q, l) = if order4 {
                e64::step_order4(&body, q, l, DVec3::ZERO, h)
            } else {
                e64::step(&body, q, l, DVec3::ZERO, h)
            };
        }
        angle(q, q_ref)
    };
    let (e1, e2) = (error(100, false), error(200, false));
    let p2 = (e1 / e2).log2();
    assert!((p2 - 2.0).abs() < 0.1, "order {p2} ({e1:e}, {e2:e})");
    assert!(e2 < 1e-3);
    let (e1, e2) = (error(25, true), error(50, true));
    let p4 = (e1 / e2).log2();
    assert!((p4 - 4.0).abs() < 0.2, "order {p4} ({e1:e}, {e2:e})");
    assert!(e2 < 1e-5);
}

/// The step orders the principal axes itself (smallest moment first), through a frame
/// when they are not given in that order: for each of the six orders of the T-handle's
/// moments, with and without a tilted principal frame on top,
/// the step converges to the exact flow at order two, in orientation and in the body
/// momentum. A wrong axis, or a wrong sign in the frame of an odd permutation, would
/// follow a different body.
#[test]
fn every_order_of_the_moments_converges_to_the_exact_flow() {
    let orders = [
        [0, 1, 2],
        [1, 0, 2],
        [0, 2, 1],
        [2, 0, 1],
        [1, 2, 0],
        [2, 1, 0],
    ];
    let t_end = 2.0;
    for case in 0..2 * orders.len() {
        let moments = orders[case / 2].map(|k| T_HANDLE[k]);
        let frame = if case % 2 == 0 {
            DQuat::IDENTITY
        } else {
            DQuat::from_rotation_y(0.7) * DQuat::from_rotation_x(-0.4)
        };
        let body = e64::Body::from_principal(DVec3::from(moments), frame).unwrap();
        assert_eq!(body.principal_moments(), DVec3::from(moments));
        assert!(angle(body.principal_frame(), frame) < 1e-15);
        let q0 = DQuat::from_rotation_x(0.3) * DQuat::from_rotation_z(-0.2);
        let l0 = DVec3::new(0.3, 2.0, 0.4);
        // The exact flow of the principal axes' orientation `q frame`.
        let (qp_ref, _) = exact(moments, q0 * frame, l0, t_end);
        let q_ref = qp_ref * frame.inverse();
        let error = |n: usize| {
            let h = t_end / n as f64;
            let (mut q, mut l) = (q0, l0);
            for _ in 0..n {
                (q, l) = e64::step(&body, q, l, DVec3::ZERO, h);
            }
            let body_gap = ((q.inverse() * l) - (q_ref.inverse() * l0)).length();
            (angle(q, q_ref), body_gap)
        };
        let ((a1, m1), (a2, m2)) = (error(100), error(200));
        for (e1, e2) in [(a1, a2), (m1, m2)] {
            let p = (e1 / e2).log2();
            assert!(
                (p - 2.0).abs() < 0.15,
                "{moments:?}: order {p} ({e1:e}, {e2:e})"
            );
        }
        assert!(a2 < 1e-3, "{moments:?}: {a2:e}");
    }
}

/// Dullweber, Leimkuhler and McLachlan's five exact axis rotations, on the body
/// momentum only (what the energy depends on): written here with `sin` and `cos`.
fn dlm_body_momentum(inverse: [f64; 3], m: [f64; 3], h: f64) -> [f64; 3] {
    let mut m = m;
    for (k, fraction) in [(0, 0.5), (1, 0.5), (2, 1.0), (1, 0.5), (0, 0.5)] {
        let angle = fraction * h * inverse[k] * m[k];
        let (i, j) = ((k + 1) % 3, (k + 2) % 3);
        let (s, c) = angle.sin_cos();
        (m[i], m[j]) = (c * m[i] + s * m[j], c * m[j] - s * m[i]);
    }
    m
}

/// The engine's split (Casimir reference the largest moment, turns corrected for their
/// single-axis `h^2` error) against the five-turn split of Dullweber, Leimkuhler and
/// McLachlan: over 40 seeded bodies at 60 Hz (moments in [0.2, 3], given to the engine
/// in a shuffled order so that its axis frames are exercised, `h |w|` up to 0.2), its
/// largest energy excursion over 3000 steps is below the five-turn split's on every
/// body, and far below it on the whole.
#[test]
fn the_corrected_split_keeps_the_energy_better_than_the_five_turn_split() {
    let mut rng = ga_test_rng::Rng::new(0x0123_4567_89ab_cdef);
    let mut next = move || rng.next_f64();
    let h = 1.0 / 60.0;
    let mut log_ratio = 0.0;
    for case in 0..40 {
        let mut moments = [0; 3].map(|_| 0.2 + 2.8 * next());
        moments.sort_by(f64::total_cmp);
        let inverse = moments.map(|i| 1.0 / i);
        let d = DVec3::new(next() - 0.5, next() - 0.5, next() - 0.5).normalize();
        let w = d * (1.0 + 11.0 * next());
        let m0 = [moments[0] * w.x, moments[1] * w.y, moments[2] * w.z];
        let energy = |m: [f64; 3]| 0.5 * (0..3).map(|k| inverse[k] * m[k] * m[k]).sum::<f64>();
        let e0 = energy(m0);
        // The five-turn split in the sorted order.
        let (mut m, mut dlm) = (m0, 0.0f64);
        for _ in 0..3000 {
            m = dlm_body_momentum(inverse, m, h);
            dlm = dlm.max((energy(m) / e0 - 1.0).abs());
        }
        // The engine, the axes given in a rotated order (x y z -> y z x or z x y).
        let shift = 1 + case % 2;
        let given = |v: [f64; 3]| DVec3::new(v[shift % 3], v[(shift + 1) % 3], v[(shift + 2) % 3]);
        let body = e64::Body::from_principal(given(moments), DQuat::IDENTITY).unwrap();
        let (mut q, l) = (DQuat::IDENTITY, given(m0));
        let mut ours = 0.0f64;
        for _ in 0..3000 {
            (q, _) = e64::step(&body, q, l, DVec3::ZERO, h);
            ours = ours.max((body.kinetic_energy(q, l) / e0 - 1.0).abs());
        }
        assert!(ours < dlm, "case {case}: {ours:e} against {dlm:e}");
        log_ratio += (ours / dlm).log10() / 40.0;
    }
    println!("geometric mean of the ratio: 10^{log_ratio:.2}");
    assert!(log_ratio < -1.0, "{log_ratio}");
}

#[test]
fn free_momentum_is_kept_to_the_bit_and_a_world_torque_adds_exactly_h_t() {
    let body = e32::Body::from_tensor(Mat3::from_diagonal(Vec3::new(1.0, 2.0, 3.0))).unwrap();
    let (mut q, mut l) = (Quat::from_rotation_y(0.4), Vec3::new(0.01, 2.0, -0.3));
    let l0 = l;
    for _ in 0..10_000 {
        (q, l) = e32::step(&body, q, l, Vec3::ZERO, 1.0 / 60.0);
        assert_eq!(l, l0);
    }
    assert!((q.length() - 1.0).abs() < 1e-6);
    // Two half-kicks of h/2 T per step: 2^-7 and T exactly representable, so exact sums.
    let t = Vec3::new(0.0, 0.5, -1.0);
    let (_, l) = e32::step(&body, q, Vec3::ZERO, t, 1.0 / 128.0);
    assert_eq!(l, t / 128.0);
}

#[test]
fn energy_of_the_t_handle_stays_bounded_over_many_flips() {
    let body = e64::Body::from_principal(DVec3::from(T_HANDLE), DQuat::IDENTITY).unwrap();
    let (mut q, mut l) = (DQuat::IDENTITY, DVec3::new(0.05, 2.0, 0.05));
    let e0 = body.kinetic_energy(q, l);
    let period = free_body_orbit(T_HANDLE, l.to_array()).period;
    let h = 1.0 / 60.0;
    let mut worst: f64 = 0.0;
    let steps = (20.0 * period / h) as usize;
    for _ in 0..steps {
        (q, l) = e64::step(&body, q, l, DVec3::ZERO, h);
        worst = worst.max((body.kinetic_energy(q, l) / e0 - 1.0).abs());
    }
    // Splitting error O((h |w|)^2), bounded, not growing: 20 flips, 4e-4 at most.
    assert!(worst < 4e-4, "{worst:e}");
    // The explicit gyroscopic Euler step gains energy on the same run.
    let (mut q, mut w) = (
        DQuat::IDENTITY,
        body.angular_velocity(DQuat::IDENTITY, DVec3::new(0.05, 2.0, 0.05)),
    );
    for _ in 0..steps {
        (q, w) = e64::explicit_gyroscopic_euler(&body, q, w, DVec3::ZERO, h);
    }
    let e_euler = body.kinetic_energy(q, body.angular_momentum(q, w));
    assert!(e_euler / e0 - 1.0 > 10.0 * worst, "{}", e_euler / e0 - 1.0);
}

#[test]
fn a_tensor_is_diagonalised_into_a_right_handed_frame_that_rebuilds_it() {
    let r = DMat3::from_quat(DQuat::from_euler(
        ga_engine::glam::EulerRot::ZYX,
        0.7,
        -0.4,
        1.1,
    ));
    let d = DMat3::from_diagonal(DVec3::new(1.5, 2.5, 3.25));
    let tensor = r * d * r.transpose();
    let body = e64::Body::from_tensor(tensor).unwrap();
    let p = DMat3::from_quat(body.principal_frame());
    let rebuilt = p * DMat3::from_diagonal(body.principal_moments()) * p.transpose();
    assert!(
        (rebuilt - tensor).abs_diff_eq(DMat3::ZERO, 1e-14),
        "{rebuilt}"
    );
    assert!((p.determinant() - 1.0).abs() < 1e-14);
    let mut m = body.principal_moments().to_array();
    m.sort_by(f64::total_cmp);
    for (a, b) in m.iter().zip([1.5, 2.5, 3.25]) {
        assert!((a - b).abs() < 1e-14);
    }
    // A body described by either tensor turns the same way in the world.
    let aligned = e64::Body::from_principal(DVec3::new(1.5, 2.5, 3.25), DQuat::IDENTITY).unwrap();
    let frame = DQuat::from_mat3(&r);
    let q_body = DQuat::from_rotation_y(0.2);
    let l = DVec3::new(0.3, -1.0, 2.0);
    let (mut qa, mut qb) = (q_body * frame, q_body);
    let (mut la, mut lb) = (l, l);
    // Fourth order at a small step: the order of the axes in the splitting (the eigen
    // solver may permute them) changes the result only at the method's error, ~1e-11.
    for _ in 0..100 {
        (qa, la) = e64::step_order4(&aligned, qa, la, DVec3::X, 0.01);
        (qb, lb) = e64::step_order4(&body, qb, lb, DVec3::X, 0.01);
    }
    assert!(angle(qa, qb * frame) < 1e-9, "{}", angle(qa, qb * frame));
    assert!((la - lb).length() < 1e-12);
}

#[test]
fn bad_inertia_is_an_error_not_a_panic() {
    let nan = Mat3::from_diagonal(Vec3::new(1.0, f32::NAN, 1.0));
    assert_eq!(
        e32::Body::from_tensor(nan).unwrap_err(),
        BodyError::NotFinite
    );
    let negative = Mat3::from_diagonal(Vec3::new(1.0, -2.0, 1.0));
    assert_eq!(
        e32::Body::from_tensor(negative).unwrap_err(),
        BodyError::NotPositive { axis: 1 }
    );
    let tiny = Vec3::new(1.0, 1.0, 1e-39);
    assert_eq!(
        e32::Body::from_principal(tiny, Quat::IDENTITY).unwrap_err(),
        BodyError::OutOfRange {
            axis: 2,
            min_log2: -50,
            max_log2: 50
        }
    );
    let zero_frame = Quat::from_xyzw(0.0, 0.0, 0.0, 0.0);
    assert_eq!(
        e32::Body::from_principal(Vec3::ONE, zero_frame).unwrap_err(),
        BodyError::ZeroFrame
    );
    // Each error says which quantity and what is wrong with it, in one line.
    assert_eq!(
        BodyError::ZeroFrame.to_string(),
        "inertia: the principal frame quaternion is zero"
    );
    assert_eq!(
        BodyError::NotPositive { axis: 1 }.to_string(),
        "inertia: principal moment 1 is not positive"
    );
    assert_eq!(
        BodyError::NotFinite.to_string(),
        "inertia: a component is not finite"
    );
    let range = BodyError::OutOfRange {
        axis: 2,
        min_log2: -50,
        max_log2: 50,
    }
    .to_string();
    assert_eq!(
        range,
        "inertia: principal moment 2 is outside 2^-50 ..= 2^50 \
         (8.881784197001252e-16 to 1.125899906842624e15), the range this precision steps; \
         change the units"
    );
}

#[test]
fn extreme_finite_input_gives_finite_unit_orientations() {
    // Moments at the ends of f32's range (BodyError::OutOfRange).
    let body =
        e32::Body::from_principal(Vec3::new(1e-15, 1.0, 1e15), Quat::from_rotation_x(0.1)).unwrap();
    for l in [
        Vec3::new(1e30, -1e30, 3.0),
        // Turned by an unnormalised turn at a saturated angle, the body momentum
        // overflows; the angles then saturate, and the orientation stays finite and unit.
        Vec3::new(1e37, -1e37, 3e37),
        Vec3::new(1e-30, 0.0, 0.0),
        Vec3::ZERO,
    ] {
        for dt in [1e-30, 1.0 / 60.0, 1e10, -5.0] {
            let (q, l2) = e32::step_order4(&body, Quat::from_rotation_z(2.0), l, Vec3::ONE, dt);
            assert!(
                q.is_finite() && (q.length() - 1.0).abs() < 1e-5,
                "{l} {dt} {q}"
            );
            assert!(l2.is_finite());
        }
    }
}

/// Explicit gyroscopic Euler written directly on glam, the way engines write it.
fn glam_explicit(i: DVec3, q: DQuat, w: DVec3, t: DVec3, h: f64) -> (DQuat, DVec3) {
    let wb = q.inverse() * w;
    let tb = q.inverse() * t;
    let wb = wb + h * (tb - wb.cross(i * wb)) / i;
    let w = q * wb;
    let q = (q + DQuat::from_vec4((0.5 * h * w).extend(0.0)) * q).normalize();
    (q, w)
}

#[test]
fn the_explicit_baseline_is_the_glam_written_step() {
    let i = DVec3::new(1.0, 2.0, 3.0);
    let body = e64::Body::from_principal(i, DQuat::IDENTITY).unwrap();
    let (mut qa, mut wa) = (DQuat::from_rotation_x(0.3), DVec3::new(0.1, 1.0, 0.2));
    let (mut qb, mut wb) = (qa, wa);
    let t = DVec3::new(0.0, 0.1, 0.3);
    for _ in 0..1000 {
        (qa, wa) = e64::explicit_gyroscopic_euler(&body, qa, wa, t, 0.01);
        (qb, wb) = glam_explicit(i, qb, wb, t, 0.01);
    }
    assert!(angle(qa, qb) < 1e-11 && (wa - wb).length() < 1e-11);
}

#[test]
fn the_implicit_baseline_solves_its_equation_to_first_order_and_loses_energy() {
    let i = DVec3::new(1.0, 2.0, 3.0);
    let body = e64::Body::from_principal(i, DQuat::IDENTITY).unwrap();
    let w0 = DVec3::new(0.1, 2.0, 0.1);
    // One Newton step from w: the residual of J (w' - w) + h w' x J w' = 0 is O(h^2).
    for h in [1e-2, 5e-3] {
        let (_, w1) = e64::implicit_gyroscopic_euler(&body, DQuat::IDENTITY, w0, DVec3::ZERO, h);
        let residual = i * (w1 - w0) + h * w1.cross(i * w1);
        assert!(residual.length() < 10.0 * h * h * h, "{h} {residual}");
    }
    let (mut q, mut w) = (DQuat::IDENTITY, w0);
    let e0 = body.kinetic_energy(q, body.angular_momentum(q, w));
    for _ in 0..6000 {
        (q, w) = e64::implicit_gyroscopic_euler(&body, q, w, DVec3::ZERO, 1.0 / 60.0);
    }
    let e = body.kinetic_energy(q, body.angular_momentum(q, w));
    assert!(e < 0.99 * e0, "{e} {e0}");
}

/// The unit quaternion `(1 - t^2, 2 t e)/(1 + t^2)` about the axis `e` (a turn by
/// `4 atan t`), from `+ - * /` alone: the same bits on every target, where glam's
/// `normalize` (SSE on x86-64, NEON on AArch64, summing in different orders) and the C
/// library's `sinf` need not be. Its squared norm is within the steps' 16 ulps of 1, so
/// they take it as it is.
fn rational_turn(axis: Vec3, t: f32) -> Quat {
    let d = 1.0 + t * t;
    let s = 2.0 * t / d;
    Quat::from_xyzw(axis.x * s, axis.y * s, axis.z * s, (1.0 - t * t) / d)
}

/// A crowd of `n` bodies, some from rotated tensors, half with torques, built from exact
/// arithmetic only, so that the golden bits depend on nothing but the steps.
fn crowd32(n: usize) -> Vec<e32::BodyState> {
    (0..n)
        .map(|k| {
            let x = (k % 17) as f32;
            let moments = Vec3::new(1.0 + 0.1 * x, 2.0, 3.0 - 0.05 * x);
            let body = if k % 3 == 0 {
                e32::Body::from_principal(moments, Quat::IDENTITY).unwrap()
            } else {
                let r = Mat3::from_quat(rational_turn(Vec3::Y, 0.025 * x));
                e32::Body::from_tensor(r * Mat3::from_diagonal(moments) * r.transpose()).unwrap()
            };
            let mut s = e32::BodyState::new(
                body,
                rational_turn(Vec3::Z, 0.075 * x),
                Vec3::new(0.01 * x, 2.0 + x, -0.5),
            );
            if k % 2 == 1 {
                s.torque = Vec3::new(0.1, -0.2 * x, 0.0);
            }
            s
        })
        .collect()
}

fn crowd64(n: usize) -> Vec<e64::BodyState> {
    crowd64_of(&crowd32(n))
}

/// The f32 bodies in f64.
fn crowd64_of(crowd: &[e32::BodyState]) -> Vec<e64::BodyState> {
    crowd
        .iter()
        .map(|s| {
            let b = &s.body;
            let body = e64::Body::from_principal(
                b.principal_moments().as_dvec3(),
                b.principal_frame().as_dquat(),
            )
            .unwrap();
            let mut d = e64::BodyState::new(
                body,
                s.orientation.as_dquat().normalize(),
                s.angular_momentum.as_dvec3(),
            );
            d.torque = s.torque.as_dvec3();
            d
        })
        .collect()
}

fn bits32(states: &[e32::BodyState]) -> Vec<u32> {
    states
        .iter()
        .flat_map(|s| {
            s.orientation
                .to_array()
                .into_iter()
                .chain(s.angular_momentum.to_array())
        })
        .map(f32::to_bits)
        .collect()
}

fn bits64(states: &[e64::BodyState]) -> Vec<u64> {
    states
        .iter()
        .flat_map(|s| {
            s.orientation
                .to_array()
                .into_iter()
                .chain(s.angular_momentum.to_array())
        })
        .map(f64::to_bits)
        .collect()
}

#[test]
fn slice_form_gives_the_bits_of_one_body_at_a_time() {
    for n in [1, 7, 8, 13, 21] {
        let mut one = crowd32(n);
        let mut many = one.clone();
        for _ in 0..50 {
            for s in &mut one {
                s.step(0.02);
            }
            e32::step_slice(&mut many, 0.02);
        }
        assert_eq!(bits32(&one), bits32(&many), "f32 n={n}");
        for _ in 0..10 {
            for s in &mut one {
                s.step_order4(0.02);
            }
            e32::step_slice_order4(&mut many, 0.02);
        }
        assert_eq!(bits32(&one), bits32(&many), "f32 order 4 n={n}");

        let mut one = crowd64(n);
        let mut many = one.clone();
        for _ in 0..50 {
            for s in &mut one {
                s.step(0.02);
            }
            e64::step_slice(&mut many, 0.02);
        }
        assert_eq!(bits64(&one), bits64(&many), "f64 n={n}");
    }
}

/// BodyColumns whose moments come in each of the six orders (given without a frame: the body
/// puts them in order itself), in a seeded order, with bodies from rotated tensors among
/// them: every lane group mixes orders.
fn mixed_orders32(n: usize) -> Vec<e32::BodyState> {
    let orders = [
        [0, 1, 2],
        [0, 2, 1],
        [1, 0, 2],
        [1, 2, 0],
        [2, 0, 1],
        [2, 1, 0],
    ];
    let mut rng = ga_test_rng::Rng::new(0x51ce_0b0d_1e5a_77e1);
    (0..n)
        .map(|k| {
            let mut next = || rng.next_f32();
            let sorted = [1.0 + next(), 2.0 + next(), 3.0 + next()];
            let order = orders[(rng.next_u64() % 6) as usize];
            let moments = Vec3::from(order.map(|i| sorted[i]));
            let body = if k % 5 == 4 {
                let r = Mat3::from_quat(Quat::from_rotation_y(0.3) * Quat::from_rotation_x(0.2));
                e32::Body::from_tensor(r * Mat3::from_diagonal(moments) * r.transpose()).unwrap()
            } else {
                e32::Body::from_principal(moments, Quat::IDENTITY).unwrap()
            };
            let mut next = || rng.next_f32() - 0.5;
            let q = Quat::from_xyzw(next(), next(), next(), 1.0).normalize();
            let l = Vec3::new(next(), 8.0 * next(), next()) * 4.0;
            let mut s = e32::BodyState::new(body, q, l);
            if k % 3 == 0 {
                s.torque = Vec3::new(next(), next(), next()) * 0.1;
            }
            s
        })
        .collect()
}

/// A slice whose bodies mix all six orders of the moments (each lane put in order by its
/// own body's frame) gives each body the bits it gets stepped alone: f32 order 2 and 4
/// (eight lanes with AVX, else four; a remainder), f64 (four lanes). A lane put in order
/// by a neighbour's frame, or put back with the wrong one, would follow another body.
/// Without torque, `|L|` stays to the bit in the slice too.
#[test]
fn a_slice_of_mixed_axis_orders_gives_the_bits_of_one_body_at_a_time() {
    for n in [8, 13, 64] {
        let mut one = mixed_orders32(n);
        let start = one.clone();
        let mut many = one.clone();
        for _ in 0..60 {
            for s in &mut one {
                s.step(1.0 / 60.0);
            }
            e32::step_slice(&mut many, 1.0 / 60.0);
        }
        assert_eq!(bits32(&one), bits32(&many), "f32 n={n}");
        for _ in 0..10 {
            for s in &mut one {
                s.step_order4(1.0 / 60.0);
            }
            e32::step_slice_order4(&mut many, 1.0 / 60.0);
        }
        assert_eq!(bits32(&one), bits32(&many), "f32 order 4 n={n}");
        for (a, b) in start.iter().zip(&many) {
            if a.torque == Vec3::ZERO {
                assert_eq!(a.angular_momentum, b.angular_momentum);
            } else {
                assert_ne!(a.angular_momentum, b.angular_momentum);
            }
        }
        // The bodies really turned (a relabelling that lost the orientation would not).
        assert!(start
            .iter()
            .zip(&many)
            .all(|(a, b)| a.orientation.dot(b.orientation).abs() < 0.9999));

        let mut one = crowd64_of(&mixed_orders32(n));
        let mut many = one.clone();
        for _ in 0..60 {
            for s in &mut one {
                s.step(1.0 / 60.0);
            }
            e64::step_slice(&mut many, 1.0 / 60.0);
        }
        assert_eq!(bits64(&one), bits64(&many), "f64 n={n}");
    }
}

#[cfg(feature = "rayon")]
#[test]
fn thread_count_determinism() {
    let run = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        let mut a = crowd32(2000);
        let mut b = crowd64(1100);
        pool.install(|| {
            for _ in 0..20 {
                e32::par_step_slice(&mut a, 0.02);
                e64::par_step_slice_order4(&mut b, 0.02);
            }
        });
        (bits32(&a), bits64(&b))
    };
    let one = run(1);
    assert_eq!(one, run(2));
    let mut serial = crowd32(2000);
    for _ in 0..20 {
        e32::step_slice(&mut serial, 0.02);
    }
    assert_eq!(one.0, bits32(&serial));
}

/// FNV-1a over the bits of every state after every 100th step.
fn fnv(hash: &mut u64, bits: impl IntoIterator<Item = u64>) {
    for b in bits {
        for byte in b.to_le_bytes() {
            *hash ^= u64::from(byte);
            *hash = hash.wrapping_mul(0x0000_0100_0000_01b3);
        }
    }
}

/// 10^4 steps of a crowd in f32 and f64 (order 2 and 4, with torques), hashed. The
/// golden values were recorded on x86-64; CI runs this test there (built for the baseline
/// and for the CPU's own instructions) and as AArch64 code under qemu (the crate docs say
/// what is promised). The crowd is built from exact arithmetic (`rational_turn`): built
/// with glam's `normalize`, its inputs differed between x86-64 and AArch64 in the last bit,
/// and so did the hashes, though the steps gave the same bits from the same inputs. The
/// slice form must give them too.
#[test]
fn golden_bits_of_ten_thousand_steps() {
    let mut hash32 = 0xcbf2_9ce4_8422_2325_u64;
    let mut hash64 = 0xcbf2_9ce4_8422_2325_u64;
    let mut a = crowd32(9);
    let mut b = crowd64(9);
    let mut a_slice = a.clone();
    for step in 0..10_000 {
        for s in &mut a {
            if step % 10 == 0 {
                s.step_order4(1.0 / 60.0);
            } else {
                s.step(1.0 / 60.0);
            }
        }
        if step % 10 == 0 {
            e32::step_slice_order4(&mut a_slice, 1.0 / 60.0);
        } else {
            e32::step_slice(&mut a_slice, 1.0 / 60.0);
        }
        e64::step_slice(&mut b, 1.0 / 60.0);
        if step % 100 == 99 {
            fnv(&mut hash32, bits32(&a).into_iter().map(u64::from));
            fnv(&mut hash64, bits64(&b));
        }
    }
    assert_eq!(bits32(&a), bits32(&a_slice));
    println!("golden: {hash32:#018x} {hash64:#018x}");
    assert_eq!((hash32, hash64), GOLDEN);
}

/// Recorded by `golden_bits_of_ten_thousand_steps` (printed with `--nocapture`). The f64
/// crowd's orientations are the f32 crowd's widened and normalised in f64: widened alone
/// they are 1e-7 off unit, which the steps now normalise first.
const GOLDEN: (u64, u64) = (0x50cf_eef9_0fd0_448b, 0x95d1_dbda_4dcf_cb8f);

#[test]
fn step_with_a_constant_torque_is_step_and_keeps_a_heavy_tops_energy() {
    let body = e64::Body::from_principal(DVec3::new(1.0, 1.0, 0.4), DQuat::IDENTITY).unwrap();
    let t = DVec3::new(0.3, -0.2, 0.1);
    let q0 = DQuat::from_rotation_x(0.3);
    let l0 = DVec3::new(0.1, 0.2, 12.0);
    assert_eq!(
        e64::step_with(&body, q0, l0, |_| t, 0.01),
        e64::step(&body, q0, l0, t, 0.01)
    );
    // Gravity on a top (a torque from a potential): the energy stays within O(h^2).
    let gravity = |q: DQuat| (q * DVec3::Z * 0.1).cross(DVec3::new(0.0, 0.0, -2.0 * 9.81));
    let energy =
        |q: DQuat, l: DVec3| body.kinetic_energy(q, l) + 2.0 * 9.81 * 0.1 * (q * DVec3::Z).z;
    let (mut q, mut l) = (
        q0,
        body.angular_momentum(q0, q0 * DVec3::new(0.0, 0.0, 30.0)),
    );
    let e0 = energy(q, l);
    let mut worst: f64 = 0.0;
    for _ in 0..20_000 {
        (q, l) = e64::step_with(&body, q, l, gravity, 1.0 / 60.0);
        worst = worst.max((energy(q, l) / e0 - 1.0).abs());
    }
    assert!(worst < 1e-4, "{worst:e}");
}

/// Every form of the step on a 256 KiB thread (a quarter of the smallest default stack
/// of a spawned thread on the platforms we know): unoptimised, as `cargo test` builds
/// it, the slice forms once needed over 2 MiB of stack, which overflowed a user's test
/// thread (see "Unoptimised builds" in the engine's `splitting.rs`).
#[test]
fn every_form_runs_on_a_small_thread_stack() {
    // The same steps on the test's own thread give the bits the small thread must give: a
    // small stack must change nothing. (Were the stack too small, the process would abort
    // with a stack overflow, which fails the test binary; it cannot come back as a value.)
    let steps = || {
        let mut a = crowd32(19);
        let mut b = crowd64(19);
        e32::step_slice(&mut a, 0.02);
        e32::step_slice_order4(&mut a, 0.02);
        e64::step_slice(&mut b, 0.02);
        e64::step_slice_order4(&mut b, 0.02);
        for s in &mut a {
            s.step(0.02);
            s.step_order4(0.02);
        }
        for s in &mut b {
            s.step(0.02);
            s.step_order4(0.02);
        }
        (bits32(&a), bits64(&b))
    };
    let expected = steps();
    let on_small_stack = std::thread::Builder::new()
        .stack_size(256 << 10)
        .spawn(steps)
        .expect("a thread")
        .join()
        .expect("the steps do not panic");
    assert_eq!(on_small_stack, expected);
}

/// The registry's `splitting-corrected` (ga-rigid) and the engine's step are the same
/// method: a T-handle (moments 1 : 2 : 3, `|m| = 12.6`) stepped by both in f64 agrees to
/// rounding after ten steps and stays within the flips' amplification of rounding (1e-7)
/// over six flips; a wrong coefficient would part them by the method's own error, 1e-4
/// and up.
#[test]
fn the_registry_form_is_the_engines_step() {
    use ga_core::f64::g3::Rotor;
    use ga_engine::f64 as engine;
    use ga_engine::glam::{DQuat, DVec3};
    use ga_rigid::dynamics::{omega_from_vector, omega_to_vector, RigidBody, State};
    use ga_rigid::integrators::{CorrectedSplitting, Integrator};
    let moments = [1.0, 2.0, 3.0];
    let body = RigidBody::new(moments).unwrap();
    let w0 = [
        0.02 * 2.0 * std::f64::consts::TAU / 1.0,
        std::f64::consts::TAU,
        0.0,
    ];
    let mut state = State {
        rotor: Rotor::new(1.0, 0.0, 0.0, 0.0),
        omega: omega_from_vector(w0),
    };
    let engine_body = engine::Body::from_principal(DVec3::from(moments), DQuat::IDENTITY).unwrap();
    let mut q = DQuat::IDENTITY;
    let mut l = DVec3::new(moments[0] * w0[0], moments[1] * w0[1], 0.0);
    let mut integrator = CorrectedSplitting::new(1.0 / 60.0).unwrap();
    let h = 1.0 / 60.0;
    let mut worst = 0.0f64;
    for n in 0..2000 {
        state = integrator.advance(&body, n as f64 * h, state, h).unwrap();
        (q, l) = engine::step(&engine_body, q, l, DVec3::ZERO, h);
        let w = omega_to_vector(state.omega);
        let body_l = q.inverse() * l;
        let gap = (0..3).fold(0.0f64, |g, k| g.max((moments[k] * w[k] - body_l[k]).abs()));
        worst = worst.max(gap);
        if n == 9 {
            assert!(worst < 1e-13, "{worst:e}");
        }
    }
    assert!(worst < 1e-7, "{worst:e}");
}

/// The steps take any non-zero finite orientation and work on it normalised (the docs'
/// promise): a T-handle's orientation scaled by factors from 1e-150 to 1e150 (f64) and
/// 1e-19 to 1e19 (f32) gives, after one step and after 600, the orientation of the unit
/// one to rounding, which is itself the exact flow's (elliptic functions) to the
/// method's error. Used as it was, `2 q` put the step 1.4e-2 rad off after one step and
/// 2.4 rad after 600; `1000 q` gave a zero quaternion, `1e10 q` NaN.
#[test]
fn a_scaled_orientation_is_stepped_as_the_unit_one() {
    let body = e64::Body::from_principal(DVec3::from(T_HANDLE), DQuat::IDENTITY).unwrap();
    let q0 = DQuat::from_rotation_x(0.3) * DQuat::from_rotation_z(-0.2);
    let l0 = DVec3::new(0.3, 2.0, 0.4);
    let h = 1.0 / 60.0;
    let (q_ref, _) = exact(T_HANDLE, q0, l0, 600.0 * h);
    let run = |q: DQuat, steps: usize| {
        let (mut q, mut l) = (q, l0);
        for _ in 0..steps {
            (q, l) = e64::step(&body, q, l, DVec3::ZERO, h);
        }
        q
    };
    let (one, many) = (run(q0, 1), run(q0, 600));
    assert!(angle(many, q_ref) < 1e-2, "{}", angle(many, q_ref));
    for s in [2.0, 1.01, 0.99, 1e3, 1e10, 1e-3, 1e-150, 1e150] {
        let q = q0 * s;
        let (a, b) = (run(q, 1), run(q, 600));
        assert!((a.length() - 1.0).abs() < 1e-15, "{s}: {a}");
        assert!(angle(a, one) < 1e-15, "{s}: {:e}", angle(a, one));
        assert!(angle(b, many) < 1e-11, "{s}: {:e}", angle(b, many));
        // The other forms, against the same forms on the unit orientation.
        let t = DVec3::new(0.1, -0.2, 0.3);
        let (a4, _) = e64::step_order4(&body, q, l0, t, h);
        let (u4, _) = e64::step_order4(&body, q0, l0, t, h);
        assert!(angle(a4, u4) < 1e-15, "{s}: order 4 {:e}", angle(a4, u4));
        let gravity = |q: DQuat| (q * DVec3::Z).cross(DVec3::new(0.0, 0.0, -9.81));
        let (aw, lw) = e64::step_with(&body, q, l0, gravity, h);
        let (uw, luw) = e64::step_with(&body, q0, l0, gravity, h);
        assert!(
            angle(aw, uw) < 1e-15 && (lw - luw).length() < 1e-15,
            "{s}: step_with"
        );
        let (w, w0) = (body.angular_velocity(q, l0), body.angular_velocity(q0, l0));
        assert!((w - w0).length() < 1e-15 * w0.length(), "{s}: {w} {w0}");
        let (e, e0) = (body.kinetic_energy(q, l0), body.kinetic_energy(q0, l0));
        assert!((e / e0 - 1.0).abs() < 1e-15, "{s}: {e} {e0}");
        let m = body.angular_momentum(q, w0);
        assert!(
            (m - body.angular_momentum(q0, w0)).length() < 1e-14,
            "{s}: {m}"
        );
        for euler in [
            e64::explicit_gyroscopic_euler,
            e64::implicit_gyroscopic_euler,
        ] {
            let ((a, wa), (u, wu)) = (euler(&body, q, w0, t, h), euler(&body, q0, w0, t, h));
            assert!(
                angle(a, u) < 1e-15 && (wa - wu).length() < 1e-14,
                "{s}: Euler"
            );
        }
    }
    // f32, the one-body step (its quaternion in a register on x86-64) and the slice.
    let body32 = e32::Body::from_principal(Vec3::new(1.0, 2.0, 3.0), Quat::IDENTITY).unwrap();
    let (q32, l32) = (q0.as_quat(), l0.as_vec3());
    let (unit, _) = e32::step(&body32, q32, l32, Vec3::ZERO, 1.0 / 60.0);
    let scales = [2.0, 1.01, 1e3, 1e-3, 1e19, 1e-19, 3e38 / 0.99];
    let mut slice: Vec<_> = scales
        .iter()
        .map(|&s| e32::BodyState::new(body32, q32 * s, l32))
        .collect();
    e32::step_slice(&mut slice, 1.0 / 60.0);
    for (&s, state) in scales.iter().zip(&slice) {
        let (a, _) = e32::step(&body32, q32 * s, l32, Vec3::ZERO, 1.0 / 60.0);
        let gap = angle(a.as_dquat(), unit.as_dquat());
        assert!(
            gap < 1e-6 && (a.length() - 1.0).abs() < 1e-6,
            "f32 {s}: {gap:e} {a}"
        );
        assert_eq!(state.orientation, a, "f32 slice {s}");
    }
}

/// A zero or non-finite orientation has no rotation to normalise: the steps return a
/// NaN orientation (and the momentum kicked as usual), and do not panic.
#[test]
fn a_zero_or_non_finite_orientation_gives_nan_not_a_panic() {
    let body = e64::Body::from_principal(DVec3::from(T_HANDLE), DQuat::IDENTITY).unwrap();
    let l = DVec3::new(0.3, 2.0, 0.4);
    for q in [
        DQuat::from_xyzw(0.0, 0.0, 0.0, 0.0),
        DQuat::from_xyzw(f64::NAN, 0.0, 0.0, 1.0),
        DQuat::from_xyzw(f64::INFINITY, 0.0, 0.0, 1.0),
    ] {
        let (a, m) = e64::step(&body, q, l, DVec3::X, 0.01);
        assert!(a.is_nan(), "{q}: {a}");
        assert_eq!(m, l + DVec3::X * 0.01);
        assert!(e64::step_order4(&body, q, l, DVec3::ZERO, 0.01).0.is_nan());
        assert!(body.kinetic_energy(q, l).is_nan());
    }
}

/// Moments the step's precision cannot carry are refused with the range, not stepped to
/// NaN: f32 moments from 1.2e-38 to 1e-24 and f64 ones down to 1e-164 were accepted and
/// gave NaN at `|w| = 0.6`, `dt = 1/60`. Moments inside the range step as the exact flow
/// (elliptic functions) of the same angular velocity, whatever their scale, at the ends
/// of the range and for `|w|` from 1e-3 to 10.
#[test]
fn moments_outside_the_precisions_range_are_refused_and_those_inside_step_exactly() {
    let refused32 =
        |m: f32| e32::Body::from_principal(Vec3::new(m, 2.0 * m, 3.0 * m), Quat::IDENTITY);
    let refused64 =
        |m: f64| e64::Body::from_principal(DVec3::new(m, 2.0 * m, 3.0 * m), DQuat::IDENTITY);
    for m in [1.2e-38, 1e-30, 1e-24, 1e-16, 2e15, 1e30] {
        let e = refused32(m).unwrap_err();
        assert_eq!(
            e,
            BodyError::OutOfRange {
                axis: 0,
                min_log2: -50,
                max_log2: 50
            },
            "f32 {m:e}"
        );
        assert!(e.to_string().contains("8.881784197001252e-16"), "{e}");
    }
    for m in [1e-164, 1e-300, 1e-152, 1e160] {
        assert!(
            matches!(
                refused64(m),
                Err(BodyError::OutOfRange {
                    min_log2: -500,
                    max_log2: 500,
                    ..
                })
            ),
            "f64 {m:e}"
        );
    }
    let q0 = DQuat::from_rotation_x(0.3) * DQuat::from_rotation_z(-0.2);
    let h = 1.0 / 60.0;
    for size in [1e-3, 0.6, 10.0] {
        // The body-frame angular velocity, and the T-handle's exact flow for it.
        let wb = DVec3::new(0.3, 0.8, -0.2).normalize() * size;
        let l_unit = q0 * (DVec3::from(T_HANDLE) * wb);
        let (q_ref, _) = exact(T_HANDLE, q0, l_unit, h);
        for m in [2f32.powi(-50), 1e-15, 1.0, 1e14] {
            let body = refused32(m).unwrap();
            let l = (l_unit * f64::from(m)).as_vec3();
            let (q, _) = e32::step(&body, q0.as_quat(), l, Vec3::ZERO, h as f32);
            let gap = angle(q.as_dquat(), q_ref);
            assert!(
                gap < 0.1 * (h * size).powi(3) + 2e-7,
                "f32 {m:e} |w| {size}: {gap:e}"
            );
        }
        for m in [2f64.powi(-500), 1e-150, 1.0, 1e150] {
            let body = refused64(m).unwrap();
            let (q, _) = e64::step(&body, q0, l_unit * m, DVec3::ZERO, h);
            let gap = angle(q, q_ref);
            // The method's error a step, O((h |w|)^3), and rounding.
            assert!(
                gap < 0.1 * (h * size).powi(3) + 1e-15,
                "f64 {m:e} |w| {size}: {gap:e}"
            );
        }
    }
}

/// A finite tensor near f64::MAX has moments past the range, not a non-finite entry; a
/// frame of any non-zero size is a rotation (`(1e200, 0, 0, 1e200)` was refused as
/// zero); and a zero momentum does not turn the body even at `dt = MAX` (which gave NaN).
#[test]
fn huge_tensors_and_frames_and_steps_are_named_for_what_they_are() {
    let huge = DMat3::from_diagonal(DVec3::new(1.7e308, 1.0e308, 1.2e308));
    assert!(matches!(
        e64::Body::from_tensor(huge),
        Err(BodyError::OutOfRange { axis: 0, .. })
    ));
    let quarter = DQuat::from_rotation_x(core::f64::consts::FRAC_PI_2);
    for size in [1e200, 1e-200, 1e300, 5e-324] {
        let frame = DQuat::from_xyzw(size, 0.0, 0.0, size);
        let body = e64::Body::from_principal(DVec3::from(T_HANDLE), frame).unwrap();
        assert!(angle(body.principal_frame(), quarter) < 1e-15, "{size:e}");
    }
    let frame = Quat::from_xyzw(1e-30, 0.0, 0.0, 1e-30);
    let body = e32::Body::from_principal(Vec3::new(1.0, 2.0, 3.0), frame).unwrap();
    assert!(angle(body.principal_frame().as_dquat(), quarter) < 1e-7);
    let q = Quat::from_rotation_y(0.4);
    for dt in [f32::MAX, -f32::MAX, 1e30] {
        let (next, l) = e32::step(&body, q, Vec3::ZERO, Vec3::ZERO, dt);
        assert_eq!(l, Vec3::ZERO);
        assert!(
            angle(next.as_dquat(), q.as_dquat()) < 1e-6,
            "{dt:e}: {next}"
        );
        // The fourth-order step's outer substep, `1.35 dt`, overflows at `dt = MAX`
        // (documented: finite, unit, not the flow).
        let (next, _) = e32::step_order4(&body, q, Vec3::ZERO, Vec3::ZERO, dt);
        assert!((next.length() - 1.0).abs() < 1e-6, "order 4 {dt:e}: {next}");
        if dt.abs() < 1e38 {
            assert!(
                angle(next.as_dquat(), q.as_dquat()) < 1e-6,
                "order 4 {dt:e}: {next}"
            );
        }
    }
    let body = e64::Body::from_principal(DVec3::from(T_HANDLE), DQuat::IDENTITY).unwrap();
    let (next, _) = e64::step(&body, q.as_dquat(), DVec3::ZERO, DVec3::ZERO, f64::MAX);
    assert!(angle(next, q.as_dquat()) < 1e-15, "{next}");
}

/// The implicit gyroscopic Euler step is one Newton iteration on
/// `f(x) = J (x - w) + h x x J x` from `x = w` (Catto 2015): written here on glam, the
/// Jacobian by central differences of `f` (exact to rounding, `f` being quadratic), on a
/// body where every term of the Jacobian is large (three distinct moments, a body
/// velocity with three large components, `h |w| = 0.6`, a tilted orientation and a
/// torque). A sign flipped in the engine's Jacobian moves the result by about `h^2 |w|^2`.
#[test]
fn the_implicit_baseline_is_one_newton_step_with_the_residuals_own_jacobian() {
    let i = DVec3::new(1.0, 2.0, 3.0);
    let body = e64::Body::from_principal(i, DQuat::IDENTITY).unwrap();
    let q = DQuat::from_rotation_y(0.5) * DQuat::from_rotation_x(-0.3);
    let (w, t, h) = (
        q * DVec3::new(3.0, -2.0, 4.0),
        DVec3::new(0.5, -1.0, 0.2),
        0.1,
    );
    let wb = q.inverse() * w;
    let f = |x: DVec3| i * (x - wb) + h * x.cross(i * x);
    let d = 1e-3;
    let column = |e: DVec3| (f(wb + d * e) - f(wb - d * e)) / (2.0 * d);
    let jacobian = DMat3::from_cols(column(DVec3::X), column(DVec3::Y), column(DVec3::Z));
    let x = wb - jacobian.inverse() * f(wb) + h * (q.inverse() * t) / i;
    let w_ref = q * x;
    let (q1, w1) = e64::implicit_gyroscopic_euler(&body, q, w, t, h);
    assert!((w1 - w_ref).length() < 1e-12, "{w1} {w_ref}");
    // The orientation turned by the new velocity, first order.
    let q_ref = (q + DQuat::from_vec4((0.5 * h * w1).extend(0.0)) * q).normalize();
    assert!(angle(q1, q_ref) < 1e-14, "{:e}", angle(q1, q_ref));
}

/// The free flow leaves the world momentum alone, so over one step of the fourth-order
/// method (three substeps, four kicks) a constant world torque must change `L` by
/// exactly `h T`, to the rounding of four sums, whatever the body: f64 and f32, one body
/// and slice. A kick with a wrong weight changes it by a fraction of `h T`.
#[test]
fn a_fourth_order_step_kicks_the_momentum_by_exactly_h_t() {
    let body =
        e64::Body::from_principal(DVec3::new(1.0, 2.0, 3.0), DQuat::from_rotation_z(0.4)).unwrap();
    let q = DQuat::from_rotation_x(0.3);
    let (l, t) = (DVec3::new(0.3, 2.0, 0.4), DVec3::new(0.7, -1.3, 2.1));
    for h in [0.05, 1.0 / 60.0, 0.3] {
        let (_, next) = e64::step_order4(&body, q, l, t, h);
        let bound = 8.0 * f64::EPSILON * (l.length() + (h * t).length());
        assert!(
            (next - l - h * t).length() < bound,
            "{h}: {}",
            next - l - h * t
        );
        let b32 = e32::Body::from_principal(Vec3::new(1.0, 2.0, 3.0), Quat::IDENTITY).unwrap();
        let (l32, t32, h32) = (l.as_vec3(), t.as_vec3(), h as f32);
        let mut slice = vec![e32::BodyState::new(b32, q.as_quat(), l32); 9];
        for s in &mut slice {
            s.torque = t32;
        }
        e32::step_slice_order4(&mut slice, h32);
        let (_, one) = e32::step_order4(&b32, q.as_quat(), l32, t32, h32);
        let bound = 8.0 * f32::EPSILON * (l32.length() + (h32 * t32).length());
        for next in slice.iter().map(|s| s.angular_momentum).chain([one]) {
            assert!((next - l32 - h32 * t32).length() < bound, "f32 {h}: {next}");
        }
    }
}

/// A slice steps each body in the form its own range decides (division-free turns where
/// `h^2 |L|^2 reach < 1` and `|L| < 1e18`, else the divided form with its clamps), not its
/// group's first lane's: slices mixing a T-handle in range, a body of moments
/// (1e-3, 1, 1e3) whose `reach` (1e6) puts it out of range at `|L| = 1`, and a T-handle at
/// `|L| = 1e19`, with each kind in turn first in every group of four and of eight, give
/// each body the bits it gets stepped alone (f32 and f64, order 2 and 4).
#[test]
fn a_slice_steps_each_body_by_its_own_range() {
    let kinds32 = [
        (Vec3::new(1.0, 2.0, 3.0), Vec3::new(0.3, 1.0, -0.4)),
        (Vec3::new(1e-3, 1.0, 1e3), Vec3::new(0.3, 1.0, -0.4)),
        (Vec3::new(1.0, 2.0, 3.0), Vec3::new(0.3, 1.0, -0.4) * 1e19),
    ];
    for lead in 0..3 {
        let kind = |i: usize| {
            if i.is_multiple_of(4) {
                lead
            } else {
                (lead + 1 + i % 2) % 3
            }
        };
        let mut one: Vec<_> = (0..24)
            .map(|i| {
                let (moments, l) = kinds32[kind(i)];
                let body = e32::Body::from_principal(moments, Quat::IDENTITY).unwrap();
                let q = Quat::from_rotation_y(0.1 * i as f32);
                let mut s = e32::BodyState::new(body, q, l);
                s.torque = Vec3::new(0.1, 0.0, -0.2);
                s
            })
            .collect();
        let mut one64: Vec<_> = one
            .iter()
            .map(|s| {
                let body = e64::Body::from_principal(
                    s.body.principal_moments().as_dvec3(),
                    DQuat::IDENTITY,
                )
                .unwrap();
                e64::BodyState::new(
                    body,
                    s.orientation.as_dquat(),
                    s.angular_momentum.as_dvec3(),
                )
            })
            .collect();
        let (mut many, mut many64) = (one.clone(), one64.clone());
        for step in 0..20 {
            let order4 = step % 4 == 3;
            for s in &mut one {
                let (q, l) = if order4 {
                    e32::step_order4(
                        &s.body,
                        s.orientation,
                        s.angular_momentum,
                        s.torque,
                        1.0 / 60.0,
                    )
                } else {
                    e32::step(
                        &s.body,
                        s.orientation,
                        s.angular_momentum,
                        s.torque,
                        1.0 / 60.0,
                    )
                };
                (s.orientation, s.angular_momentum) = (q, l);
            }
            for s in &mut one64 {
                if order4 {
                    s.step_order4(1.0 / 60.0);
                } else {
                    s.step(1.0 / 60.0);
                }
            }
            if order4 {
                e32::step_slice_order4(&mut many, 1.0 / 60.0);
                e64::step_slice_order4(&mut many64, 1.0 / 60.0);
            } else {
                e32::step_slice(&mut many, 1.0 / 60.0);
                e64::step_slice(&mut many64, 1.0 / 60.0);
            }
            assert_eq!(
                bits32(&one),
                bits32(&many),
                "f32, kind {lead} first, step {step}"
            );
            assert_eq!(
                bits64(&one64),
                bits64(&many64),
                "f64, kind {lead} first, step {step}"
            );
        }
    }
}

/// Where each step is the better choice, as the docs say: on a T-handle spun near its
/// middle axis (`|w| = 1`, so `h |w| = h`), over 3000 steps, the fourth-order step's
/// largest energy excursion is far below `step`'s at `h |w| = 0.1` and far above it at
/// `h |w| = 2`; the implicit gyroscopic Euler step only loses energy at `h |w| = 0.05`, and
/// gains half again and more at 2. The energy is computed here from the body momentum on
/// glam.
#[test]
fn step_order4_is_the_better_choice_only_for_small_steps() {
    let moments = DVec3::from(T_HANDLE);
    let body = e64::Body::from_principal(moments, DQuat::IDENTITY).unwrap();
    let energy = |q: DQuat, l: DVec3| {
        let m = q.inverse() * l;
        0.5 * (m * m / moments).element_sum()
    };
    let w0 = DVec3::new(0.05, 1.0, 0.05).normalize();
    let l0 = moments * w0;
    let e0 = energy(DQuat::IDENTITY, l0);
    let run = |h: f64| {
        let (mut q2, mut q4, mut l2, mut l4) = (DQuat::IDENTITY, DQuat::IDENTITY, l0, l0);
        let (mut qi, mut wi) = (DQuat::IDENTITY, w0);
        let (mut worst2, mut worst4, mut highest) = (0.0f64, 0.0f64, 0.0f64);
        let mut implicit = 1.0;
        for _ in 0..3000 {
            (q2, l2) = e64::step(&body, q2, l2, DVec3::ZERO, h);
            (q4, l4) = e64::step_order4(&body, q4, l4, DVec3::ZERO, h);
            (qi, wi) = e64::implicit_gyroscopic_euler(&body, qi, wi, DVec3::ZERO, h);
            worst2 = worst2.max((energy(q2, l2) / e0 - 1.0).abs());
            worst4 = worst4.max((energy(q4, l4) / e0 - 1.0).abs());
            implicit = energy(qi, qi * (moments * (qi.inverse() * wi))) / e0;
            highest = highest.max(implicit);
        }
        (worst2, worst4, (highest, implicit))
    };
    let (small2, small4, _) = run(0.1);
    assert!(
        small4 < small2 / 20.0,
        "h|w| 0.1: {small4:e} against {small2:e}"
    );
    let (large2, large4, (grown, _)) = run(2.0);
    assert!(
        large4 > 5.0 * large2,
        "h|w| 2: {large4:e} against {large2:e}"
    );
    assert!(grown > 1.5, "implicit at h|w| 2: E/E0 up to {grown}");
    let (_, _, (highest, damped)) = run(0.05);
    assert!(
        highest <= 1.0 && damped < 0.9,
        "implicit at h|w| 0.05: {highest} {damped}"
    );
}

/// An engine that stores the angular velocity converts once into a `BodyState` and keeps
/// the momentum from then on: the state's velocity is the one given (to rounding), an
/// angular impulse adds to the momentum exactly, and a free body's `|L|` is then kept to
/// the bit over a second of 60 Hz steps, impulse included.
#[test]
fn a_body_state_made_from_the_velocity_keeps_the_momentum_and_takes_impulses_exactly() {
    let body = e32::Body::from_tensor(Mat3::from_cols_array(&[
        2.0, 0.1, 0.0, 0.1, 1.0, 0.0, 0.0, 0.0, 3.0,
    ]))
    .unwrap();
    let q = Quat::from_rotation_y(0.4) * Quat::from_rotation_x(-0.2);
    let w = Vec3::new(0.3, 2.0, -0.1);
    let mut state = e32::BodyState::from_angular_velocity(body, q, w);
    assert_eq!(state.angular_momentum, body.angular_momentum(q, w));
    let back = state.angular_velocity();
    assert!(
        (back - w).length() <= 4.0 * f32::EPSILON * w.length(),
        "{back} {w}"
    );

    let impulse = Vec3::new(0.25, -0.5, 0.125);
    let before = state.angular_momentum;
    state.apply_angular_impulse(impulse);
    assert_eq!(state.angular_momentum, before + impulse);

    let l = state.angular_momentum;
    for _ in 0..60 {
        state.step(1.0 / 60.0);
    }
    assert_eq!(state.angular_momentum, l, "free |L| kept to the bit");

    // A solver that writes a velocity: the momentum is I(q) w for the state's orientation.
    state.set_angular_velocity(w);
    assert_eq!(
        state.angular_momentum,
        body.angular_momentum(state.orientation, w)
    );
}

/// `BodyColumns` (the column store) gives each body the bits it gets stepped alone: bodies of
/// all six moment orders and turned frames, with and without torques, counts that fill
/// whole blocks and counts that leave a partly filled one (f32 blocks of eight, f64 of
/// four), order 2 and 4. A lane that read a neighbour's constants, or an empty lane's
/// result written over a body, would follow another body.
#[test]
fn body_columns_give_the_bits_of_one_body_at_a_time() {
    for n in [1, 3, 8, 13, 64] {
        let mut one = mixed_orders32(n);
        let mut bodies: e32::BodyColumns = one.iter().copied().collect();
        assert_eq!(bodies.len(), n);
        for round in 0..70 {
            if round < 60 {
                one.iter_mut().for_each(|s| s.step(1.0 / 60.0));
                bodies.step(1.0 / 60.0);
            } else {
                one.iter_mut().for_each(|s| s.step_order4(1.0 / 60.0));
                bodies.step_order4(1.0 / 60.0);
            }
        }
        let stepped: Vec<_> = bodies.iter().collect();
        assert_eq!(bits32(&one), bits32(&stepped), "f32 n={n}");

        let mut one = crowd64_of(&mixed_orders32(n));
        let mut bodies: e64::BodyColumns = one.iter().copied().collect();
        for _ in 0..60 {
            one.iter_mut().for_each(|s| s.step(1.0 / 60.0));
            bodies.step(1.0 / 60.0);
        }
        one.iter_mut().for_each(|s| s.step_order4(1.0 / 60.0));
        bodies.step_order4(1.0 / 60.0);
        let stepped: Vec<_> = bodies.iter().collect();
        assert_eq!(bits64(&one), bits64(&stepped), "f64 n={n}");
    }
}

/// `BodyColumns` against a `Vec<BodyState>` doing the same: a seeded run of pushes, swap
/// removals, whole-body replacements, torques, impulses, written velocities and steps;
/// after each, every index reads the model's body to the bit (orientation, momentum,
/// torque, inertia through the velocity), and the index past the end reads `None`.
#[test]
fn body_columns_behave_as_a_vec_of_body_states() {
    let pool = mixed_orders32(40);
    let mut rng = ga_test_rng::Rng::new(0x0bad_cafe_f00d_d00d);
    let mut model: Vec<e32::BodyState> = Vec::new();
    let mut bodies = e32::BodyColumns::with_capacity(4);
    let (mut removed, mut edited) = (0, 0);
    for round in 0..2_000 {
        let pick = rng.next_u64() as usize;
        let vector = Vec3::new(rng.next_f32(), rng.next_f32(), rng.next_f32()) - 0.5;
        let n = model.len();
        match rng.next_u64() % 8 {
            0 | 1 if n < 30 => {
                model.push(pool[pick % pool.len()]);
                bodies.push(pool[pick % pool.len()]);
            }
            2 if n > 0 => {
                let i = pick % n;
                assert_eq!(
                    bits32(&[bodies.swap_remove(i).unwrap()]),
                    bits32(&[model.swap_remove(i)])
                );
                removed += 1;
            }
            3 if n > 0 => {
                let (i, other) = (pick % n, pool[(pick / 7) % pool.len()]);
                model[i] = other;
                bodies.get_mut(i).unwrap().set(other);
            }
            4 if n > 0 => {
                let i = pick % n;
                model[i].torque = vector;
                bodies.get_mut(i).unwrap().set_torque(vector);
                edited += 1;
            }
            5 if n > 0 => {
                let i = pick % n;
                model[i].apply_angular_impulse(vector);
                bodies.get_mut(i).unwrap().apply_angular_impulse(vector);
            }
            6 if n > 0 => {
                let i = pick % n;
                model[i].set_angular_velocity(vector);
                bodies.get_mut(i).unwrap().set_angular_velocity(vector);
            }
            _ => {
                model.iter_mut().for_each(|s| s.step(1.0 / 60.0));
                bodies.step(1.0 / 60.0);
            }
        }
        assert_eq!(bodies.len(), model.len(), "round {round}");
        assert!(bodies.get(model.len()).is_none() && bodies.get_mut(model.len()).is_none());
        assert!(bodies.swap_remove(model.len()).is_none());
        for (i, s) in model.iter().enumerate() {
            let got = bodies.get(i).unwrap();
            let view = bodies.get_mut(i).unwrap();
            assert_eq!(bits32(&[got]), bits32(&[*s]), "round {round}, body {i}");
            assert_eq!(view.torque().to_array(), s.torque.to_array());
            assert_eq!(view.orientation(), s.orientation);
            assert_eq!(view.angular_momentum(), s.angular_momentum);
            assert_eq!(view.angular_velocity(), s.angular_velocity());
            assert_eq!(got.body.principal_moments(), s.body.principal_moments());
            assert_eq!(got.body.principal_frame(), s.body.principal_frame());
        }
    }
    assert!(removed > 100 && edited > 100, "{removed} {edited}");
}

/// `BodyColumns::par_step` gives `BodyColumns::step`'s bits on one thread and on two.
#[cfg(feature = "rayon")]
#[test]
fn body_columns_step_in_parallel_as_in_series() {
    let crowd = crowd32(5_000);
    let run = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        let mut bodies: e32::BodyColumns = crowd.iter().copied().collect();
        pool.install(|| (0..20).for_each(|_| bodies.par_step(0.02)));
        bits32(&bodies.iter().collect::<Vec<_>>())
    };
    let mut serial: e32::BodyColumns = crowd.iter().copied().collect();
    (0..20).for_each(|_| serial.step(0.02));
    let serial = bits32(&serial.iter().collect::<Vec<_>>());
    assert_eq!(run(1), serial);
    assert_eq!(run(2), serial);
}
