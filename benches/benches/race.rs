//! The race to an attitude error of 1e-10 against what people use today (issue 18):
//! `race/reach_1e-10/<scene>`, one function per method of the registry (ours and the
//! peers: ode_solvers' Dop853 and Dopri5 on the quaternion form, the engines' gyroscopic
//! Euler steps, Buss's method, implicit midpoint on the quaternion form, the discrete
//! Moser-Veselov step), each at the cheapest setting that reaches the error at the
//! scene's end time, searched before anything is timed and printed once. Every method is
//! built by `Method::integrator`, as the command and the report build it, and every
//! iteration integrates the whole run from t = 0.
//!
//! Scenes are the report's: the Hairer-Lubich-Wanner and Hairer-Vilmart bodies (T = 10),
//! the heavy symmetric top and the asymmetric heavy top (T = 4), and the gravity-gradient
//! satellite (T = 4 pi). The reference at the end is the exact flow for free bodies and
//! the report's reference (Dormand-Prince at 1e-13, checked against lie-rk4 at
//! `h |w| = 1e-3`) under a torque.
//!
//! A short run: `RACE_METHODS=adams-10,dop853-quaternion` races only the named methods,
//! and `RACE_SCENES=asymmetric` only the scenes whose names contain one of the given
//! (comma-separated) words; both unset race everything.

use std::time::{Duration, Instant};

use criterion::{black_box, criterion_group, criterion_main, Criterion};
use ga_rigid::dynamics::State;
use ga_rigid::integrators::Integrator;
use ga_rigid::registry::{Method, Step, StepKind};
use ga_rigid_cli::report::{attitude_error, reference_scenes, references, TestScene};

/// The attitude error every method must reach at the end time.
const TARGET: f64 = 1e-10;
/// The most fixed steps tried before a method is said to miss the target.
const MAX_STEPS: u64 = 1 << 20;

/// The scenes of the race, by their report names.
const SCENES: [&str; 5] = [
    "Hairer-Lubich-Wanner body",
    "Hairer-Vilmart driver",
    "heavy top",
    "asymmetric heavy top",
    "gravity-gradient satellite",
];

/// Whether the environment variable `var` is unset or one of its comma-separated entries
/// satisfies `matches`.
fn listed(var: &str, matches: impl Fn(&str) -> bool) -> bool {
    std::env::var(var).map_or(true, |list| list.split(',').any(|w| matches(w.trim())))
}

/// A whole run of `method` at `step` from the scene's start to its end.
fn run(scene: &TestScene, method: Method, step: Step) -> Option<State> {
    let mut integrator = method.integrator(step).ok()?;
    integrator
        .advance(&scene.body, 0.0, scene.initial, scene.t_end)
        .ok()
}

/// The steps a whole run takes: the accepted steps of an adaptive method, the fixed
/// steps of the others (`None` for a solution evaluated at the end).
fn steps(scene: &TestScene, method: Method, step: Step) -> Option<u64> {
    match step {
        Step::Fixed(h) => Some((scene.t_end / h).round() as u64),
        Step::Tolerance(_) => {
            let mut integrator = method.integrator(step).ok()?;
            integrator
                .advance(&scene.body, 0.0, scene.initial, scene.t_end)
                .ok()?;
            integrator.accepted_steps()
        }
        Step::AtSamples => None,
    }
}

/// The error of a run, or infinity when it failed.
fn error(scene: &TestScene, reference: &State, method: Method, step: Step) -> f64 {
    run(scene, method, step).map_or(f64::INFINITY, |s| {
        let e = attitude_error(s.rotor, reference.rotor);
        if e.is_nan() {
            f64::INFINITY
        } else {
            e
        }
    })
}

/// The cheapest step control that reaches [`TARGET`]: the fewest fixed steps (doubling,
/// then bisection), the loosest tolerance (by halves of a decade), or none.
fn cheapest(scene: &TestScene, reference: &State, method: Method) -> Option<(Step, f64)> {
    let t_end = scene.t_end;
    match method.step_kind() {
        StepKind::AtSamples => {
            let e = error(scene, reference, method, Step::AtSamples);
            (e <= TARGET).then_some((Step::AtSamples, e))
        }
        StepKind::Fixed => {
            let at = |n: u64| error(scene, reference, method, Step::Fixed(t_end / n as f64));
            let mut hi = 8;
            while at(hi) > TARGET {
                hi *= 2;
                if hi > MAX_STEPS {
                    return None;
                }
            }
            let mut lo = hi / 2;
            while hi - lo > 1.max(hi / 64) {
                let mid = (lo + hi) / 2;
                if at(mid) <= TARGET {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            Some((Step::Fixed(t_end / hi as f64), at(hi)))
        }
        StepKind::Adaptive => (6..=30)
            .map(|k| 10f64.powf(-f64::from(k) / 2.0))
            .find_map(|tol| {
                let e = error(scene, reference, method, Step::Tolerance(tol));
                (e <= TARGET).then_some((Step::Tolerance(tol), e))
            }),
    }
}

/// The median wall time of whole runs, for the printed table (criterion's own figures
/// follow in its output).
fn median_time(scene: &TestScene, method: Method, step: Step) -> Duration {
    let mut times: Vec<Duration> = (0..31)
        .map(|_| {
            let start = Instant::now();
            black_box(run(scene, method, step));
            start.elapsed()
        })
        .collect();
    times.sort();
    times[times.len() / 2]
}

fn race(c: &mut Criterion) {
    let scenes: Vec<TestScene> = reference_scenes()
        .expect("the suite builds")
        .into_iter()
        .filter(|s| SCENES.contains(&s.name.as_str()))
        .filter(|s| listed("RACE_SCENES", |word| s.name.contains(word)))
        .collect();
    let mut table = String::new();
    for scene in &scenes {
        let (primary, _) = references(scene).expect("references");
        let reference = *primary.states.last().expect("samples");
        let (methods, _) = scene.methods();
        let mut found = Vec::new();
        println!(
            "race/reach_1e-10: {} (t_end = {}):",
            scene.name, scene.t_end
        );
        for method in methods {
            if !listed("RACE_METHODS", |name| name == method.name()) {
                continue;
            }
            match cheapest(scene, &reference, method) {
                Some((step, e)) => {
                    let setting = match step {
                        Step::Fixed(h) => format!("{} steps", (scene.t_end / h).round()),
                        Step::Tolerance(tol) => format!("tol {tol:.1e}"),
                        Step::AtSamples => "one evaluation".to_string(),
                    };
                    let time = median_time(scene, method, step);
                    let per_step = steps(scene, method, step).map_or(String::new(), |n| {
                        format!(
                            "  {n} steps, {:.0} ns a step",
                            time.as_secs_f64() * 1e9 / n as f64
                        )
                    });
                    println!(
                        "  {:<20} {setting:<14} error {e:.1e}  median {:.1} us{per_step}",
                        method.name(),
                        time.as_secs_f64() * 1e6
                    );
                    found.push((method, step, time));
                }
                None => println!("  {:<20} misses {TARGET:e}", method.name()),
            }
        }
        let best = |filter: &dyn Fn(Method) -> bool| {
            found
                .iter()
                .filter(|(m, _, _)| filter(*m))
                .min_by_key(|f| f.2)
        };
        // Dop853 on the quaternion form where it finishes; otherwise the best peer that does
        // (ode_solvers' Dop853 stops on the satellite: "the problem seems to become stiff").
        let peer =
            best(&|m| m == Method::Dop853Quaternion).or_else(|| best(&|m| m.info().peer.is_some()));
        let ours_stepper =
            best(&|m| m.info().peer.is_none() && m.step_kind() != StepKind::AtSamples);
        let ours_any = best(&|m| m.info().peer.is_none());
        if let (Some(peer), Some(s), Some(a)) = (peer, ours_stepper, ours_any) {
            let peer = peer.2;
            table.push_str(&format!(
                "| {} | {} {:.1} | {} {:.1} ({:.2}) | {} {:.1} ({:.2}) |\n",
                scene.name,
                best(&|m| m.info().peer.is_some() && found.iter().any(|f| f.0 == m && f.2 == peer))
                    .map_or("", |f| f.0.name()),
                peer.as_secs_f64() * 1e6,
                s.0.name(),
                s.2.as_secs_f64() * 1e6,
                s.2.as_secs_f64() / peer.as_secs_f64(),
                a.0.name(),
                a.2.as_secs_f64() * 1e6,
                a.2.as_secs_f64() / peer.as_secs_f64(),
            ));
        }
        let mut g = c.benchmark_group(format!("race/reach_1e-10/{}", scene.name));
        g.sample_size(10)
            .measurement_time(Duration::from_secs(1))
            .warm_up_time(Duration::from_millis(300));
        for (method, step, _) in &found {
            g.bench_function(method.name(), |b| b.iter(|| run(scene, *method, *step)));
        }
        g.finish();
    }
    println!(
        "\nrace/reach_1e-10 (median us of whole runs; ratio to the peer):\n\
         | scene | peer (dop853-quaternion where it finishes) | fastest of our steppers | fastest of ours |\n\
         |---|---|---|---|\n{table}"
    );
}

criterion_group!(benches, race);
criterion_main!(benches);
