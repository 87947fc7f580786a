//! Rigid-body methods (issue 4):
//!
//! - `rigid/symmetric_top/f64/batch`: one closed-form evaluation of a fixed symmetric top
//!   (`SymmetricTop::rotor(t)`, and `state(t)`) at 4096 seeded times, against one RK4
//!   step from each of the 4096 states: the target is a closed-form evaluation at
//!   most three RK4 steps.
//! - `rigid/step/f64/chain`: one step of each method along a trajectory of the
//!   Hairer-Vilmart body, h = 0.01, 4096 steps, each waiting for the last.
//! - `rigid/symmetric_top_1e6/f64/batch`: 10^6 different tops evaluated at one time, with
//!   rayon and on one thread, per top (criterion's throughput is then tops per second).
//! - `rigid/reach_1e-10/f64/hlw_t10`: the time to reach an attitude error of 1e-10 at
//!   t = 10 on the Hairer-Lubich-Wanner body, each method at the cheapest setting that gets
//!   there (searched before anything is timed, printed once, and asserted), against
//!   ode_solvers' Dop853 on Euler's equations in matrix form. Every iteration integrates
//!   from t = 0. `lie-dop853-cayley` is lie-dop853 in Cayley coordinates
//!   (`LieDop853::cayley`).
//!
//! The long-running groups (the 10^6 tops, the splitting's race) take 10 samples of a flat
//! sampling instead of the usual 30 linear ones, so that they fit the 2 s measurement.

mod common;

use common::{batch1, chain, config, conv, group, BATCH};
use criterion::{black_box, criterion_group, criterion_main, Criterion, SamplingMode, Throughput};
use ga_benches::rigid::{
    body, dop853, dop853_heavy, fewest_steps, heavy_top, hlw_momentum, initial_state,
    loosest_tolerance, matrix_attitude_error, rotor_matrix_error, CLOSED_FORM, HEAVY_GROUP,
    HEAVY_T_END, HLW_MOMENTS, HLW_ROTOR_AT_10, HV_MOMENTS, HV_MOMENTUM, MILLION_GROUP, RACE_GROUP,
    RACE_PEER, RACE_TARGET, RACE_T_END, RK4_STEP, SHORT_FAT_MOMENTS, SHORT_FAT_MOMENTUM,
    STEP_GROUP, TOP_GROUP,
};
use ga_core::f64::g3::{Bivector, Rotor};
use ga_rigid::dynamics::{
    omega_to_vector, RigidBody, State, SymmetricTop, DEFAULT_SYMMETRY_TOLERANCE,
};
use ga_rigid::error::Error;
use ga_rigid::integrators::{
    ComposedSplitting, DormandPrince, ExactFreeBody, ExactSplitting, ImplicitMidpoint, Integrator,
    LieDop853, LieRk4, Rk4, Splitting,
};
use ga_rigid_cli::report::attitude_error;
use ga_test_rng::Rng;
use rayon::prelude::*;

/// The step of the single-step benches: h |w| is about 0.03 on both bodies.
const STEP: f64 = 0.01;

/// The number of tops of the parallel batch.
const TOPS: usize = 1_000_000;

/// Principia's short fat top, whose momentum turns as `m(t) = (5 sin wt, 5 cos wt, 7)`
/// with `w = -14/9`: the closed form is checked against that before it is timed.
fn short_fat_top() -> (RigidBody, SymmetricTop) {
    let body = body(SHORT_FAT_MOMENTS);
    let initial = initial_state(SHORT_FAT_MOMENTS, SHORT_FAT_MOMENTUM);
    let top = SymmetricTop::new(&body, initial, DEFAULT_SYMMETRY_TOLERANCE).expect("symmetric");
    for t in [0.5, 3.0, 40.0] {
        let w = omega_to_vector(top.state(t).omega);
        let m: [f64; 3] = std::array::from_fn(|k| SHORT_FAT_MOMENTS[k] * w[k]);
        let phase = -14.0 / 9.0 * t;
        let expected = [5.0 * phase.sin(), 5.0 * phase.cos(), 7.0];
        for k in 0..3 {
            assert!((m[k] - expected[k]).abs() < 1e-12, "m({t}) = {m:?}");
        }
    }
    (body, top)
}

/// Closed-form evaluation against one RK4 step, both per item of a batch.
fn symmetric_top(c: &mut Criterion) {
    let (body, top) = short_fat_top();
    let mut rng = Rng::new(401);
    let times: Vec<f64> = (0..BATCH).map(|_| rng.uniform(0.0, 100.0)).collect();
    let states = conv(&times, |t| top.state(t));
    // Both sides compute the same motion: one RK4 step lands on the closed form.
    for (&t, &state) in times.iter().zip(&states).take(64) {
        let stepped = Rk4::step_once(&body, t, state, STEP);
        let error = attitude_error(stepped.rotor, top.rotor(t + STEP));
        assert!(
            error < 1e-10,
            "one RK4 step misses the closed form by {error:e}"
        );
    }

    let mut g = group(c, TOP_GROUP);
    batch1(&mut g, CLOSED_FORM, &times, |t| top.rotor(t));
    batch1(&mut g, "closed-form state", &times, |t| top.state(t));
    batch1(&mut g, RK4_STEP, &states, |s| {
        Rk4::step_once(&body, 0.0, s, STEP)
    });
    g.finish();
}

/// Runs `f` along the chain once, outside the timer, and returns the end state.
fn run_chain<X: Copy>(start: X, times: &[f64], f: impl Fn(X, f64) -> X) -> X {
    times.iter().fold(start, |x, &t| f(x, t))
}

/// One step of each method along a trajectory of the Hairer-Vilmart body.
fn integrator_step(c: &mut Criterion) {
    let body = body(HV_MOMENTS);
    let initial = initial_state(HV_MOMENTS, HV_MOMENTUM);
    let times: Vec<f64> = (0..BATCH).map(|k| k as f64 * STEP).collect();
    let t_end = BATCH as f64 * STEP;
    let reference = ExactFreeBody::new()
        .advance(&body, 0.0, initial, t_end)
        .expect("exact flow")
        .rotor;

    let rk4 = |s, t| Rk4::step_once(&body, t, s, STEP);
    let lie_rk4 = |s, t| LieRk4::step_once(&body, t, s, STEP);
    let midpoint = |s, t| {
        ImplicitMidpoint::step_once(&body, t, s, STEP)
            .expect("Newton converges at h |w| = 0.03")
            .0
    };
    // One step of the splitting through `advance` is all five axis flows; a long run
    // merges the outer half flows of neighbouring steps into four.
    let splitting = Splitting::new(STEP).expect("positive step");
    let splitting = |s, t| {
        let mut method = splitting;
        method.advance(&body, t, s, STEP).expect("finite")
    };
    // The adaptive pair, primed so that its proposed step covers `STEP`: every `advance`
    // is then exactly one step (checked below), with its error estimate and controller,
    // plus the first stage that a long run would get from the previous step (FSAL).
    let mut dopri = DormandPrince::new(1e-6, 1e-6).expect("positive tolerances");
    dopri.advance(&body, 0.0, initial, STEP).expect("finite");
    let dopri5 = |(s, mut method): (State, DormandPrince), t| {
        let s = method.advance(&body, t, s, STEP).expect("finite");
        (s, method)
    };
    let exact = |s, t| {
        ExactFreeBody::new()
            .advance(&body, t, s, STEP)
            .expect("finite")
    };

    let before = dopri.stats();
    let (dopri_end, after) = run_chain((initial, dopri), &times, dopri5);
    let (accepted, rejected) = (
        after.stats().accepted - before.accepted,
        after.stats().rejected - before.rejected,
    );
    assert_eq!(
        (accepted, rejected),
        (BATCH as u64, 0),
        "one dopri5 step a call"
    );
    let ends = [
        ("rk4", run_chain(initial, &times, rk4)),
        ("lie-rk4", run_chain(initial, &times, lie_rk4)),
        ("midpoint", run_chain(initial, &times, midpoint)),
        ("splitting", run_chain(initial, &times, splitting)),
        ("dopri5", dopri_end),
        ("exact", run_chain(initial, &times, exact)),
    ];
    println!(
        "{STEP_GROUP}: attitude error at t = {t_end} after {BATCH} steps of {STEP} \
         (Hairer-Vilmart body):"
    );
    for (name, end) in ends {
        let error = attitude_error(end.rotor, reference);
        println!("  {name:<10} {error:.2e}");
        assert!(error < 1e-2, "{name} is off the trajectory");
    }

    let mut g = group(c, STEP_GROUP);
    chain(&mut g, "rk4", initial, &times, rk4);
    chain(&mut g, "lie-rk4", initial, &times, lie_rk4);
    chain(&mut g, "midpoint", initial, &times, midpoint);
    chain(&mut g, "splitting", initial, &times, splitting);
    chain(&mut g, "dopri5", (initial, dopri), &times, dopri5);
    chain(&mut g, "exact", initial, &times, exact);
    g.finish();
}

/// 10^6 seeded tops: symmetric bodies with a random symmetry axis and ratio of moments,
/// random attitudes and angular velocities.
fn million_tops() -> Vec<SymmetricTop> {
    let mut rng = Rng::new(402);
    (0..TOPS)
        .map(|_| {
            let axis = (rng.next_u64() % 3) as usize;
            let mut moments = [1.0; 3];
            moments[axis] = rng.uniform(0.2, 1.9);
            let body = RigidBody::new(moments).expect("a physical symmetric body");
            let [s, e12, e13, e23] = rng.unit_array();
            let [w12, w13, w23] = rng.uniform_array(-2.0, 2.0);
            let state = State {
                rotor: Rotor::new(s, e12, e13, e23),
                omega: Bivector::new(w12, w13, w23),
            };
            SymmetricTop::new(&body, state, DEFAULT_SYMMETRY_TOLERANCE).expect("symmetric")
        })
        .collect()
}

/// 10^6 tops at one time, with rayon and on one thread.
fn million(c: &mut Criterion) {
    let tops = million_tops();
    let t = 1.7;
    let mut out: Vec<Rotor> = tops.iter().map(|top| top.rotor(t)).collect();
    let parallel: Vec<Rotor> = tops.par_iter().map(|top| top.rotor(t)).collect();
    assert!(parallel == out, "rayon and the serial loop disagree");
    let mut g = c.benchmark_group(MILLION_GROUP);
    g.throughput(Throughput::Elements(TOPS as u64))
        .sample_size(10)
        .sampling_mode(SamplingMode::Flat);
    g.bench_function("rayon", |bencher| {
        bencher.iter(|| {
            let t = black_box(t);
            out.par_iter_mut()
                .zip(black_box(&tops).par_iter())
                .for_each(|(o, top)| *o = top.rotor(t));
            black_box(&mut out);
        })
    });
    g.bench_function("serial", |bencher| {
        bencher.iter(|| {
            let t = black_box(t);
            for (o, top) in out.iter_mut().zip(black_box(&tops)) {
                *o = top.rotor(t);
            }
            black_box(&mut out);
        })
    });
    g.finish();
}

/// A method behind the trait object the race's fixed-step methods share.
fn boxed<M: Integrator + 'static>(method: Result<M, Error>) -> Result<Box<dyn Integrator>, Error> {
    Ok(Box::new(method?))
}

/// Builds a fixed-step method from its number of steps over the race.
type Build = Box<dyn Fn(u64) -> Result<Box<dyn Integrator>, Error>>;

/// A fixed-step method of the race: its name, and how to build it from the step count.
struct FixedStep {
    name: &'static str,
    build: Build,
}

/// The race to an attitude error of 1e-10 at t = 10 on the Hairer-Lubich-Wanner body.
fn race(c: &mut Criterion) {
    let moments = HLW_MOMENTS;
    let m0 = hlw_momentum();
    let body = body(moments);
    let initial = initial_state(moments, m0);
    let published = {
        let [s, e12, e13, e23] = HLW_ROTOR_AT_10;
        Rotor::new(s, e12, e13, e23)
    };
    let reference = ExactFreeBody::new()
        .advance(&body, 0.0, initial, RACE_T_END)
        .expect("exact flow")
        .rotor;
    // The published value has twelve decimals.
    assert!(attitude_error(reference, published) < 2e-12);

    let run = |mut method: Box<dyn Integrator>| {
        method.advance(&body, 0.0, black_box(initial), RACE_T_END)
    };
    let error_of = |end: Result<State, Error>| {
        end.map_or(f64::INFINITY, |s| attitude_error(s.rotor, reference))
    };

    // The settings, searched before anything is timed.
    println!(
        "{RACE_GROUP}: cheapest settings to an attitude error of {RACE_TARGET:e} at t = \
         {RACE_T_END} (Hairer-Lubich-Wanner body):"
    );
    let mut fixed = vec![
        FixedStep {
            name: "rk4",
            build: Box::new(|n| boxed(Rk4::new(RACE_T_END / n as f64))),
        },
        FixedStep {
            name: "lie-rk4",
            build: Box::new(|n| boxed(LieRk4::new(RACE_T_END / n as f64))),
        },
    ];
    // The splitting's axis order changes its error constant by orders of magnitude
    // (Fasso 2003): take the best order at 1000 steps, then its fewest steps.
    let orders = [
        [0, 1, 2],
        [0, 2, 1],
        [1, 0, 2],
        [1, 2, 0],
        [2, 0, 1],
        [2, 1, 0],
    ];
    let splitting = |n: u64, order| {
        Splitting::new(RACE_T_END / n as f64).and_then(|m| m.with_axis_order(order))
    };
    let by_order: Vec<([usize; 3], f64)> = orders
        .iter()
        .map(|&order| {
            (
                order,
                error_of(splitting(1000, order).and_then(|m| run(Box::new(m)))),
            )
        })
        .collect();
    let (order, _) = by_order
        .iter()
        .copied()
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .expect("six orders");
    println!(
        "  splitting axis orders at 1000 steps: {}",
        by_order
            .iter()
            .map(|(o, e)| format!("{o:?} {e:.2e}"))
            .collect::<Vec<_>>()
            .join(", ")
    );
    fixed.push(FixedStep {
        name: "splitting",
        build: Box::new(move |n| boxed(splitting(n, order))),
    });
    // Its compositions to order 4, 6, 8 (issue 11), with the same axis order.
    for (name, k) in [("splitting-4", 4), ("splitting-6", 6), ("splitting-8", 8)] {
        fixed.push(FixedStep {
            name,
            build: Box::new(move |n| {
                boxed(
                    ComposedSplitting::new(RACE_T_END / n as f64, k)
                        .and_then(|m| m.with_axis_order(order)),
                )
            }),
        });
    }

    let mut g = c.benchmark_group(RACE_GROUP);
    for method in &fixed {
        let (n, error) = fewest_steps(RACE_TARGET, 256, 1 << 23, |n| {
            error_of((method.build)(n).and_then(run))
        })
        .unwrap_or_else(|| panic!("{} misses {RACE_TARGET:e} at 2^23 steps", method.name));
        let h = RACE_T_END / n as f64;
        let detail = if method.name.starts_with("splitting") {
            format!(", axis order {order:?}")
        } else {
            String::new()
        };
        println!(
            "  {:<18} {n} steps (h = {h:.4e}{detail}), error {error:.3e}",
            method.name
        );
        let timed = || run((method.build)(n).expect("valid step"));
        let error = error_of(timed());
        assert!(error <= RACE_TARGET, "{}: error {error:e}", method.name);
        if method.name == "splitting" {
            // About 30 ms an integration: 10 flat samples fit the measurement time.
            g.sample_size(10).sampling_mode(SamplingMode::Flat);
        } else {
            g.sample_size(30).sampling_mode(SamplingMode::Auto);
        }
        g.bench_function(method.name, |bencher| bencher.iter(timed));
    }
    g.sample_size(30).sampling_mode(SamplingMode::Auto);

    let dopri = |tol: f64| DormandPrince::new(tol, tol);
    let (tol, error) = loosest_tolerance(RACE_TARGET, |tol| {
        dopri(tol).map(|m| error_of(run(Box::new(m))))
    })
    .expect("dopri5 reaches the target");
    let mut method = dopri(tol).expect("valid tolerance");
    method
        .advance(&body, 0.0, initial, RACE_T_END)
        .expect("finite");
    let stats = method.stats();
    println!(
        "  {:<18} rtol = atol = {tol:.3e}, {} steps ({} rejected), {} evaluations, error \
         {error:.3e}",
        "dopri5", stats.accepted, stats.rejected, stats.evaluations
    );
    let timed = || run(Box::new(dopri(tol).expect("valid tolerance")));
    assert!(error_of(timed()) <= RACE_TARGET);
    g.bench_function("dopri5", |bencher| bencher.iter(timed));

    let lie = |tol: f64| LieDop853::new(tol, tol);
    let (tol, error) = loosest_tolerance(RACE_TARGET, |tol| {
        lie(tol).map(|m| error_of(run(Box::new(m))))
    })
    .expect("lie-dop853 reaches the target");
    let mut method = lie(tol).expect("valid tolerance");
    method
        .advance(&body, 0.0, initial, RACE_T_END)
        .expect("finite");
    let stats = method.stats();
    println!(
        "  {:<18} rtol = atol = {tol:.3e}, {} steps ({} rejected), error {error:.3e}",
        "lie-dop853", stats.accepted, stats.rejected
    );
    let timed = || run(Box::new(lie(tol).expect("valid tolerance")));
    assert!(error_of(timed()) <= RACE_TARGET);
    g.bench_function("lie-dop853", |bencher| bencher.iter(timed));

    // The same method in Cayley coordinates: no series for dexp^-1, no sine or cosine.
    let cayley = |tol: f64| LieDop853::cayley(tol, tol);
    let (tol, error) = loosest_tolerance(RACE_TARGET, |tol| {
        cayley(tol).map(|m| error_of(run(Box::new(m))))
    })
    .expect("lie-dop853 in Cayley coordinates reaches the target");
    let mut method = cayley(tol).expect("valid tolerance");
    method
        .advance(&body, 0.0, initial, RACE_T_END)
        .expect("finite");
    let stats = method.stats();
    println!(
        "  {:<18} rtol = atol = {tol:.3e}, {} steps ({} rejected), error {error:.3e}",
        "lie-dop853-cayley", stats.accepted, stats.rejected
    );
    let timed = || run(Box::new(cayley(tol).expect("valid tolerance")));
    assert!(error_of(timed()) <= RACE_TARGET);
    g.bench_function("lie-dop853-cayley", |bencher| bencher.iter(timed));

    let exact = || run(Box::new(ExactFreeBody::new()));
    let error = exact().map_or(f64::INFINITY, |s| attitude_error(s.rotor, published));
    println!(
        "  {:<18} one evaluation, error {error:.3e} (against the published R(10))",
        "exact"
    );
    assert!(error <= RACE_TARGET);
    g.bench_function("exact", |bencher| bencher.iter(exact));

    let peer = |tol: f64| dop853(moments, black_box(m0), RACE_T_END, tol);
    let (tol, error) = loosest_tolerance(RACE_TARGET, |tol| {
        peer(tol).map(|(end, _)| matrix_attitude_error(&end, reference))
    })
    .expect("Dop853 reaches the target");
    let (_, stats) = peer(tol).expect("integrates");
    println!(
        "  {RACE_PEER:<18} rtol = atol = {tol:.3e}, {} steps ({} rejected), {} evaluations, \
         error {error:.3e} (|M - M_ref|_F / sqrt 2)",
        stats.accepted_steps, stats.rejected_steps, stats.num_eval
    );
    let timed = || peer(tol).expect("integrates").0;
    assert!(matrix_attitude_error(&timed(), reference) <= RACE_TARGET);
    g.bench_function(RACE_PEER, |bencher| bencher.iter(timed));
    g.finish();
}

/// The race to an attitude error of 1e-10 at t = 4 on the report's heavy top (a Lagrange
/// top: gravity on a centre of mass up the symmetry axis), against a Dop853 run at
/// tolerance 1e-14 that two independent geometric methods confirm. Every side is measured
/// by `|M - M_ref|_F / sqrt 2` against that reference.
fn heavy_race(c: &mut Criterion) {
    let (body, initial) = heavy_top();
    let (reference, stats) = dop853_heavy(HEAVY_T_END, 1e-14).expect("the reference integrates");
    // Two geometric methods that share no code with Dop853 or with each other's steps.
    let lie_end = LieDop853::new(1e-14, 1e-14)
        .and_then(|mut m| m.advance(&body, 0.0, initial, HEAVY_T_END))
        .expect("finite");
    let split_end = ExactSplitting::with_order(HEAVY_T_END / 400.0, 8)
        .and_then(|mut m| m.advance(&body, 0.0, initial, HEAVY_T_END))
        .expect("finite");
    let (lie_gap, split_gap) = (
        rotor_matrix_error(lie_end.rotor, &reference),
        rotor_matrix_error(split_end.rotor, &reference),
    );
    println!(
        "{HEAVY_GROUP}: reference Dop853 at 1e-14 ({} steps); lie-dop853 at 1e-14 differs by \
         {lie_gap:.2e}, exact-splitting-8 at h = 1e-2 by {split_gap:.2e}",
        stats.accepted_steps
    );
    assert!(
        lie_gap < 1e-11 && split_gap < 1e-11,
        "the reference is not tight"
    );

    let run = |mut method: Box<dyn Integrator>| {
        method.advance(&body, 0.0, black_box(initial), HEAVY_T_END)
    };
    let error_of = |end: Result<State, Error>| {
        end.map_or(f64::INFINITY, |s| rotor_matrix_error(s.rotor, &reference))
    };
    let h = |n: u64| HEAVY_T_END / n as f64;
    let fixed = vec![
        FixedStep {
            name: "rk4",
            build: Box::new(move |n| boxed(Rk4::new(h(n)))),
        },
        FixedStep {
            name: "lie-rk4",
            build: Box::new(move |n| boxed(LieRk4::new(h(n)))),
        },
        FixedStep {
            name: "splitting",
            build: Box::new(move |n| boxed(Splitting::new(h(n)))),
        },
        FixedStep {
            name: "splitting-4",
            build: Box::new(move |n| boxed(ComposedSplitting::new(h(n), 4))),
        },
        FixedStep {
            name: "splitting-8",
            build: Box::new(move |n| boxed(ComposedSplitting::new(h(n), 8))),
        },
        FixedStep {
            name: "exact-splitting",
            build: Box::new(move |n| boxed(ExactSplitting::new(h(n)))),
        },
        FixedStep {
            name: "exact-splitting-4",
            build: Box::new(move |n| boxed(ExactSplitting::with_order(h(n), 4))),
        },
        FixedStep {
            name: "exact-splitting-6",
            build: Box::new(move |n| boxed(ExactSplitting::with_order(h(n), 6))),
        },
        FixedStep {
            name: "exact-splitting-8",
            build: Box::new(move |n| boxed(ExactSplitting::with_order(h(n), 8))),
        },
    ];
    println!("{HEAVY_GROUP}: cheapest settings to {RACE_TARGET:e} at t = {HEAVY_T_END}:");
    let mut g = c.benchmark_group(HEAVY_GROUP);
    for method in &fixed {
        let found = fewest_steps(RACE_TARGET, 64, 1 << 22, |n| {
            error_of((method.build)(n).and_then(run))
        });
        let Some((n, error)) = found else {
            println!("  {:<18} misses {RACE_TARGET:e} at 2^22 steps", method.name);
            continue;
        };
        println!(
            "  {:<18} {n} steps (h = {:.4e}), error {error:.3e}",
            method.name,
            h(n)
        );
        let timed = || run((method.build)(n).expect("valid step"));
        assert!(error_of(timed()) <= RACE_TARGET, "{}", method.name);
        let slow = n > 20_000 || (method.name.starts_with("splitting") && n > 2_000);
        if slow {
            g.sample_size(10).sampling_mode(SamplingMode::Flat);
        } else {
            g.sample_size(30).sampling_mode(SamplingMode::Auto);
        }
        g.bench_function(method.name, |bencher| bencher.iter(timed));
    }
    g.sample_size(30).sampling_mode(SamplingMode::Auto);

    let dopri = |tol: f64| DormandPrince::new(tol, tol);
    match loosest_tolerance(RACE_TARGET, |tol| {
        dopri(tol).map(|m| error_of(run(Box::new(m))))
    }) {
        Some((tol, error)) => {
            println!(
                "  {:<18} rtol = atol = {tol:.3e}, error {error:.3e}",
                "dopri5"
            );
            let timed = || run(Box::new(dopri(tol).expect("valid tolerance")));
            g.bench_function("dopri5", |bencher| bencher.iter(timed));
        }
        None => println!(
            "  {:<18} misses {RACE_TARGET:e} at tolerance 1e-15",
            "dopri5"
        ),
    }
    let lie = |tol: f64| LieDop853::new(tol, tol);
    let (tol, error) = loosest_tolerance(RACE_TARGET, |tol| {
        lie(tol).map(|m| error_of(run(Box::new(m))))
    })
    .expect("lie-dop853 reaches the target");
    let mut method = lie(tol).expect("valid tolerance");
    method
        .advance(&body, 0.0, initial, HEAVY_T_END)
        .expect("finite");
    println!(
        "  {:<18} rtol = atol = {tol:.3e}, {} steps ({} rejected), error {error:.3e}",
        "lie-dop853",
        method.stats().accepted,
        method.stats().rejected
    );
    let timed = || run(Box::new(lie(tol).expect("valid tolerance")));
    g.bench_function("lie-dop853", |bencher| bencher.iter(timed));

    let peer = |tol: f64| dop853_heavy(HEAVY_T_END, black_box(tol));
    let (tol, error) = loosest_tolerance(RACE_TARGET, |tol| {
        peer(tol).map(|(end, _)| matrix_attitude_error_against(&end, &reference))
    })
    .expect("Dop853 reaches the target");
    let (_, stats) = peer(tol).expect("integrates");
    println!(
        "  {RACE_PEER:<18} rtol = atol = {tol:.3e}, {} steps ({} rejected), {} evaluations, \
         error {error:.3e}",
        stats.accepted_steps, stats.rejected_steps, stats.num_eval
    );
    let timed = || peer(tol).expect("integrates").0;
    g.bench_function(RACE_PEER, |bencher| bencher.iter(timed));
    g.finish();
}

/// `|M - M_ref|_F / sqrt 2` between two matrix states.
fn matrix_attitude_error_against(
    y: &ga_benches::rigid::MatrixState,
    reference: &ga_benches::rigid::MatrixState,
) -> f64 {
    let squared: f64 = (0..9).map(|i| (y[i] - reference[i]).powi(2)).sum();
    (0.5 * squared).sqrt()
}

criterion_group! {
    name = benches;
    config = config();
    targets = symmetric_top, integrator_step, million, race, heavy_race
}
criterion_main!(benches);
