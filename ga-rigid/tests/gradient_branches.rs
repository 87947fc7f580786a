//! Derivatives of the exact free flow (`exact_flow_generic::dual64`) at the inputs where it
//! picks a branch by exact equality: t = 0, m(0) = 0, m(0) on a principal axis, a
//! symmetric body (with the momentum perpendicular to its axis too), a sphere, a state
//! exactly on the separatrix. At each, the `Dual64`
//! derivative along every moment, every component of m(0) and the time is checked against
//! Richardson-extrapolated central differences of `exact_flow::exact_free_body` (the `f64`
//! code, continuous through each of these points), whose steps straddle the branch point.

use ga_core::num_dual::Dual64;
use ga_rigid::exact_flow::exact_free_body;
use ga_rigid::exact_flow_generic::dual64 as ed;

const R0: [f64; 4] = [0.9, 0.1, -0.3, 0.2];

/// The inputs of one evaluation: moments, m(0), R(0) and t.
#[derive(Clone, Copy, Debug)]
struct Point {
    moments: [f64; 3],
    m0: [f64; 3],
    r0: [f64; 4],
    t: f64,
}

/// A direction in the seven inputs that are seeded here: three moments, m(0), t.
type Direction = [f64; 7];

impl Point {
    fn moved(self, d: &Direction, s: f64) -> Point {
        Point {
            moments: std::array::from_fn(|j| self.moments[j] + s * d[j]),
            m0: std::array::from_fn(|j| self.m0[j] + s * d[j + 3]),
            r0: self.r0,
            t: self.t + s * d[6],
        }
    }
}

fn flat(out: ([f64; 4], [f64; 3])) -> [f64; 7] {
    let (r, m) = out;
    [r[0], r[1], r[2], r[3], m[0], m[1], m[2]]
}

fn norm(x: &[f64]) -> f64 {
    x.iter().map(|v| v * v).sum::<f64>().sqrt()
}

/// The dual run seeded along `d`: values and derivatives.
fn dual(p: Point, d: &Direction) -> ([f64; 7], [f64; 7]) {
    let moments = std::array::from_fn(|j| Dual64::new(p.moments[j], d[j]));
    let m0 = std::array::from_fn(|j| Dual64::new(p.m0[j], d[j + 3]));
    let r0 = p.r0.map(|x| Dual64::new(x, 0.0));
    let (r, m) = ed::exact_free_body(moments, m0, r0, Dual64::new(p.t, d[6]));
    let out = [r[0], r[1], r[2], r[3], m[0], m[1], m[2]];
    (out.map(|x| x.re), out.map(|x| x.eps))
}

/// Richardson's extrapolation of central differences of `exact_flow` along `d` with steps
/// `h` and `2 h`, points on both sides of `p`, rotors on the sheet of `p`'s.
fn difference(p: Point, d: &Direction, h: f64) -> [f64; 7] {
    let reference = flat(exact_free_body(p.moments, p.m0, p.r0, p.t));
    // R and -R are the same attitude, and `exact_flow` may change sheets across a branch
    // point (it does across u2 = 0 near the axis of the smallest moment): each neighbour
    // is taken on the reference's sheet.
    let at = |s: f64| {
        let q = p.moved(d, s);
        let mut out = flat(exact_free_body(q.moments, q.m0, q.r0, q.t));
        if (0..4).map(|j| out[j] * reference[j]).sum::<f64>() < 0.0 {
            out[..4].iter_mut().for_each(|x| *x = -*x);
        }
        out
    };
    let (p1, m1, p2, m2) = (at(h), at(-h), at(2.0 * h), at(-2.0 * h));
    std::array::from_fn(|j| (8.0 * (p1[j] - m1[j]) - (p2[j] - m2[j])) / (12.0 * h))
}

/// The unit directions along each moment, each component of m(0) and t, then `extra`.
fn directions(extra: &[Direction]) -> Vec<Direction> {
    let mut out: Vec<Direction> = (0..7)
        .map(|k| std::array::from_fn(|j| if j == k { 1.0 } else { 0.0 }))
        .collect();
    out.extend_from_slice(extra);
    out
}

/// The dual derivative at `p` against differences along every direction: the values are
/// `exact_flow`'s to 1e-12 and the derivatives agree to `1e-8` relative to the column's
/// size (absolute below a column size of 1).
fn check(name: &str, p: Point, extra: &[Direction]) {
    let reference = flat(exact_free_body(p.moments, p.m0, p.r0, p.t));
    let mut worst: f64 = 0.0;
    for d in directions(extra) {
        let (values, derivative) = dual(p, &d);
        for (v, r) in values.iter().zip(&reference) {
            assert!(
                (v - r).abs() <= 1e-12,
                "{name}: value {values:?} against {reference:?}"
            );
        }
        let fd = difference(p, &d, 1e-3);
        let diff: Vec<f64> = derivative.iter().zip(&fd).map(|(a, b)| a - b).collect();
        let error = norm(&diff) / norm(&fd).max(1.0);
        worst = worst.max(error);
        assert!(
            error <= 1e-8,
            "{name} along {d:?}: dual {derivative:?} against differences {fd:?}: {error:e}"
        );
    }
    println!("{name}: worst disagreement with the differences {worst:.2e}");
}

#[test]
fn derivatives_at_time_zero_include_the_rate() {
    let p = Point {
        moments: [2.0, 1.0, 2.0 / 3.0],
        m0: [0.3, 0.8, -0.5],
        r0: R0,
        t: 0.0,
    };
    check("t = 0, general body", p, &[]);
    check(
        "t = 0, symmetric body",
        Point {
            moments: [2.0, 2.0, 1.0],
            ..p
        },
        &[],
    );
    check(
        "t = 0, sphere",
        Point {
            moments: [2.0; 3],
            ..p
        },
        &[],
    );
}

#[test]
fn derivatives_at_zero_momentum_include_the_first_order_rotation() {
    let p = Point {
        moments: [1.0, 2.0, 3.0],
        m0: [0.0; 3],
        r0: R0,
        t: 2.0,
    };
    check("m0 = 0", p, &[[0.0, 0.0, 0.0, 0.6, -0.3, 0.2, 0.0]]);
}

#[test]
fn derivatives_on_a_principal_axis_follow_the_linearised_motion() {
    let base = Point {
        moments: [1.0, 2.0, 3.0],
        m0: [0.0, 0.0, 1.5],
        r0: R0,
        t: 2.0,
    };
    let tilt = [0.0, 0.0, 0.0, 0.7, -0.4, 0.2, 0.3];
    // The stable axes (largest and smallest moment), the unstable middle one, a negative
    // component, and a longer time.
    check("m0 on axis 3", base, &[tilt]);
    check(
        "m0 on axis 1",
        Point {
            m0: [1.5, 0.0, 0.0],
            ..base
        },
        &[tilt],
    );
    check(
        "m0 on axis 2 (unstable)",
        Point {
            m0: [0.0, 1.5, 0.0],
            ..base
        },
        &[tilt],
    );
    check(
        "m0 on -axis 3, t = 9",
        Point {
            m0: [0.0, 0.0, -1.5],
            t: 9.0,
            ..base
        },
        &[tilt],
    );
    // The derivative of m(t) along m0's first component is the linearised solution
    // (cos(t/2), 2 sin(t/2), 0) at moments (1, 2, 3), m0 = (0, 0, 1.5).
    let (_, d) = dual(base, &[0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]);
    let truth = [1.0_f64.cos(), 2.0 * 1.0_f64.sin(), 0.0];
    for j in 0..3 {
        assert!(
            (d[4 + j] - truth[j]).abs() <= 1e-13,
            "{:?} against {truth:?}",
            &d[4..]
        );
    }
}

#[test]
fn derivatives_of_a_symmetric_body_include_breaking_the_symmetry() {
    let p = Point {
        moments: [2.0, 2.0, 1.0],
        m0: [0.3, 0.8, -0.5],
        r0: R0,
        t: 3.0,
    };
    let both = [0.5, -1.0, 0.3, 0.1, 0.0, -0.2, 0.4];
    check("i1 = i2 = 2, i3 = 1", p, &[both]);
    check(
        "i1 = i2 = 2, i3 = 3",
        Point {
            moments: [2.0, 2.0, 3.0],
            ..p
        },
        &[both],
    );
    check(
        "i2 = i3 = 2, i1 = 3",
        Point {
            moments: [3.0, 2.0, 2.0],
            ..p
        },
        &[both],
    );
    check(
        "i1 = i3 = 2, i2 = 1",
        Point {
            moments: [2.0, 1.0, 2.0],
            ..p
        },
        &[both],
    );
    let (_, d) = dual(p, &[0.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
    let truth = [0.0417, 0.0744, -0.259, 0.140];
    for j in 0..4 {
        assert!(
            (d[j] - truth[j]).abs() <= 1e-3,
            "dR/di2 {:?} against {truth:?}",
            &d[..4]
        );
    }
}

#[test]
fn derivatives_of_a_sphere_include_every_moment() {
    let p = Point {
        moments: [2.0; 3],
        m0: [0.3, 0.8, -0.5],
        r0: R0,
        t: 3.0,
    };
    check(
        "sphere",
        p,
        &[
            [1.0, -0.5, 0.3, 0.2, 0.1, -0.3, 0.5],
            [1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        ],
    );
}

#[test]
fn derivatives_exactly_on_the_separatrix_are_its_limit() {
    // Moments (15, 21, 35) scale to (3/7, 3/5, 1), where (i2 - i1)/i1 and (i3 - i2)/i3 are
    // the same double, so m0 = (x, y, x) lies exactly on the separatrix.
    let p = Point {
        moments: [15.0, 21.0, 35.0],
        m0: [10.0, 4.0, 10.0],
        r0: R0,
        t: 3.0,
    };
    check("separatrix", p, &[[0.2, -0.1, 0.3, 0.5, 0.4, -0.2, 0.1]]);
    check(
        "separatrix, t = -2",
        Point {
            t: -2.0,
            m0: [-10.0, 4.0, 10.0],
            ..p
        },
        &[],
    );
}

/// The dual run seeded along `dr` in R(0) alone, against Richardson-extrapolated central
/// differences of `exact_flow` (R(0) is normalised by both).
fn check_r0(name: &str, p: Point, dr: [f64; 4]) {
    let moments = p.moments.map(|x| Dual64::new(x, 0.0));
    let m0 = p.m0.map(|x| Dual64::new(x, 0.0));
    let r0 = std::array::from_fn(|j| Dual64::new(p.r0[j], dr[j]));
    let (r, m) = ed::exact_free_body(moments, m0, r0, Dual64::new(p.t, 0.0));
    let derivative = [r[0], r[1], r[2], r[3], m[0], m[1], m[2]].map(|x| x.eps);
    let at = |s: f64| {
        flat(exact_free_body(
            p.moments,
            p.m0,
            std::array::from_fn(|j| p.r0[j] + s * dr[j]),
            p.t,
        ))
    };
    let h = 1e-3;
    let (p1, m1, p2, m2) = (at(h), at(-h), at(2.0 * h), at(-2.0 * h));
    let fd: [f64; 7] =
        std::array::from_fn(|j| (8.0 * (p1[j] - m1[j]) - (p2[j] - m2[j])) / (12.0 * h));
    let diff: Vec<f64> = derivative.iter().zip(&fd).map(|(a, b)| a - b).collect();
    let error = norm(&diff) / norm(&fd).max(1.0);
    assert!(
        error <= 1e-8,
        "{name} along R0 {dr:?}: dual {derivative:?} against differences {fd:?}: {error:e}"
    );
}

/// The case the branch rule once left open: a symmetric body whose momentum is
/// perpendicular to the symmetry axis turns steadily about it (any axis of the equal pair
/// is principal), and moving one of the equal moments alone tips the momentum out of the
/// plane, at first order `m_s = g m_a m_b t` with `g = 1/i_b - 1/i_a`.
#[test]
fn derivatives_of_a_symmetric_body_with_the_momentum_perpendicular_to_its_axis() {
    let both = [0.5, -1.0, 0.3, 0.1, 0.0, -0.2, 0.4];
    let cases = [
        ("i1 = i2 = 2, i3 = 1", [2.0, 2.0, 1.0], [0.3, 0.8, 0.0], 3.0),
        ("i1 = i2 = 2, i3 = 3", [2.0, 2.0, 3.0], [0.3, 0.8, 0.0], 3.0),
        (
            "i2 = i3 = 2, i1 = 3",
            [3.0, 2.0, 2.0],
            [0.0, 0.8, -0.5],
            3.0,
        ),
        (
            "i1 = i3 = 2, i2 = 1",
            [2.0, 1.0, 2.0],
            [0.3, 0.0, -0.5],
            3.0,
        ),
        (
            "i1 = i2 = 2, i3 = 1, t = 9",
            [2.0, 2.0, 1.0],
            [-0.6, 0.2, 0.0],
            9.0,
        ),
    ];
    for (name, moments, m0, t) in cases {
        let p = Point {
            moments,
            m0,
            r0: R0,
            t,
        };
        check(name, p, &[both]);
        for dr in [[1.0, 0.0, 0.0, 0.0], [0.0, 0.3, -0.2, 0.5]] {
            check_r0(name, p, dr);
        }
    }
}
