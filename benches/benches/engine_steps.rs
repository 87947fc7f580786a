//! The cost of one step at engine step sizes, through the registry (issue 18): every
//! method of the report's engine table (`ENGINE_METHODS`: the engines' steps, Buss's, the
//! implicit midpoint rule on the quaternion form, the discrete Moser-Veselov step, Spiers's
//! two forms (avian's pull request #993), and
//! ours) built by `Method::integrator` as the command builds it, stepping the T-handle
//! (moments (3, 5, 9), body momentum (0, 2, 0.01), the report's `engine_runs.csv` body)
//! `STEPS` times at `h |w(0)|` = 0.1 and 0.5, one `advance` a step as an engine calls it.
//! `engine_steps/<h |w|>/<method>`, times per step; the in-process medians and each
//! method's ratio to the explicit gyroscopic Euler step of the same run are printed last
//! (issue 18's target: a step that keeps `|L|` at most 2x the explicit one's cost).

use std::time::{Duration, Instant};

use criterion::{black_box, criterion_group, criterion_main, Criterion, Throughput};
use ga_core::f64::g3::Rotor;
use ga_rigid::dynamics::{omega_from_vector, RigidBody, State};
use ga_rigid::registry::{Method, Step};
use ga_rigid_cli::report::ENGINE_METHODS;

/// Steps per timed run.
const STEPS: usize = 1000;
/// Steps before a run starts over from the T-handle's start: the explicit step gains energy
/// until it overflows (within 10^4 steps at `h |w|` = 0.1, engine_runs.csv), and a cost
/// is only meaningful on a finite state; 100 steps is under two flips at 0.5, which it
/// survives.
const RESTART: usize = 100;
/// The step sizes, as `h |w(0)|`.
const RATES: [f64; 2] = [0.1, 0.5];

/// The T-handle and its start (the values of `ga-rigid-cli/src/report/engine_steps.rs`).
fn t_handle() -> (RigidBody, State) {
    let moments = [3.0, 5.0, 9.0];
    let momentum = [0.0, 2.0, 0.01];
    let body = RigidBody::new_unphysical(moments).expect("positive moments");
    let state = State {
        rotor: Rotor::ONE,
        omega: omega_from_vector(std::array::from_fn(|k| momentum[k] / moments[k])),
    };
    (body, state)
}

/// `STEPS` steps of `method` at step `h`, one `advance` each, from the start again every
/// `RESTART` steps.
fn run(method: Method, body: &RigidBody, start: State, h: f64) -> State {
    let mut integrator = method
        .integrator(Step::Fixed(h))
        .expect("a fixed-step method");
    let mut state = start;
    for i in 0..STEPS {
        if i % RESTART == 0 {
            state = start;
        }
        state = integrator
            .advance(body, (i % RESTART) as f64 * h, state, h)
            .expect("finite within RESTART steps");
    }
    state
}

/// The median wall time per step over 31 runs, for the printed table.
fn median_per_step(method: Method, body: &RigidBody, start: State, h: f64) -> f64 {
    let mut times: Vec<Duration> = (0..31)
        .map(|_| {
            let t = Instant::now();
            black_box(run(method, body, black_box(start), h));
            t.elapsed()
        })
        .collect();
    times.sort();
    times[15].as_secs_f64() * 1e9 / STEPS as f64
}

fn engine_steps(c: &mut Criterion) {
    let (body, start) = t_handle();
    let mut table = String::new();
    for rate in RATES {
        let h = rate / start.omega.norm();
        let base = median_per_step(Method::EulerGyroExplicit, &body, start, h);
        for method in ENGINE_METHODS {
            let ns = median_per_step(method, &body, start, h);
            table.push_str(&format!(
                "| {rate} | {} | {ns:.1} | {:.2} |\n",
                method.name(),
                ns / base
            ));
        }
        let mut g = c.benchmark_group(format!("engine_steps/{rate}"));
        g.throughput(Throughput::Elements(STEPS as u64));
        for method in ENGINE_METHODS {
            g.bench_function(method.name(), |b| {
                b.iter(|| run(method, &body, black_box(start), h))
            });
        }
        g.finish();
    }
    println!(
        "\nengine_steps (in-process medians of 31 runs of {STEPS} steps):\n\
         | h |w| | method | ns per step | ratio to euler-gyro-explicit |\n\
         |---|---|---:|---:|\n{table}"
    );
}

criterion_group! {
    name = benches;
    config = Criterion::default()
        .sample_size(20)
        .measurement_time(Duration::from_secs(1))
        .warm_up_time(Duration::from_millis(300));
    targets = engine_steps
}
criterion_main!(benches);
