//! Prints, per scene and method, what ten minutes at 60 Hz in rapier3d measure: the
//! T-handle's flip period against the exact one and its energy and |L| drift, the top's
//! energy and conserved momenta, and the cost per body-step.
//! Run: `cargo run --release -p ga-rapier-example`; `-- --quick` runs one minute with
//! fewer timed bodies (what CI runs, in its debug build, to show the example works: the
//! figures worth reading come from the release build's ten minutes).

use ga_rapier_example::{
    cost_per_body_step, engine_step_cost, run_t_handle, run_top, t_handle, Method, Scene, DT,
    TEN_MINUTES,
};

/// How long each body is simulated, how many bodies a timed world holds (one world step's
/// fixed work spread over them) and how many timings the median is taken of.
struct Settings {
    steps: usize,
    timed_bodies: usize,
    samples: usize,
}

/// The settings the arguments ask for: none (ten minutes, the figures in BENCHMARKS.md) or
/// `--quick` (one minute, a smaller world); anything else is refused with its name.
fn settings(args: &[String]) -> Result<Settings, String> {
    match args {
        [] => Ok(Settings {
            steps: TEN_MINUTES,
            timed_bodies: 1000,
            samples: 31,
        }),
        [quick] if quick == "--quick" => Ok(Settings {
            steps: TEN_MINUTES / 10,
            timed_bodies: 50,
            samples: 3,
        }),
        [other, ..] => Err(format!(
            "ga-rapier-example: unknown argument `{other}` (the only one is --quick)"
        )),
    }
}

fn cpu() -> String {
    std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|s| {
            s.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split(':').nth(1))
                .map(|m| m.trim().to_string())
        })
        .unwrap_or_else(|| "unknown CPU".to_string())
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let Settings {
        steps,
        timed_bodies,
        samples,
    } = match settings(&args) {
        Ok(settings) => settings,
        Err(message) => {
            eprintln!("{message}");
            std::process::exit(2);
        }
    };
    println!(
        "rapier3d 0.36 with its default IntegrationParameters (dt = {DT:.6} s, {} substeps), \
         {steps} steps ({:.0} min at 60 Hz), f32; CPU: {}",
        ga_rapier_example::World::new(Default::default()).substeps(),
        steps as f64 * DT as f64 / 60.0,
        cpu()
    );
    println!(
        "cost: median of {samples} timings of 20 steps of a world of {timed_bodies} bodies, per body-step"
    );
    println!();

    let exact = t_handle::exact_period();
    println!(
        "T-handle, moments 1 : 2 : 3, L0 = {} (body frame), no gravity; exact flip period {exact:.6} s (ga-rigid, elliptic functions)",
        t_handle::initial_momentum()
    );
    println!(
        "  {:<24} {:>12} {:>9} {:>6} {:>11} {:>11} {:>11} {:>11} {:>10}",
        "method",
        "flip period",
        "vs exact",
        "flips",
        "energy end",
        "energy max",
        "|L| end",
        "|L| max",
        "ns/body"
    );
    for method in Method::ALL {
        let r = run_t_handle(method, steps);
        let cost = cost_per_body_step(Scene::THandle, method, timed_bodies, 20, samples);
        println!(
            "  {:<24} {:>10.6} s {:>+8.3}% {:>6} {:>+11.2e} {:>11.2e} {:>+11.2e} {:>11.2e} {:>10.0}",
            method.name(),
            r.period,
            100.0 * (r.period / exact - 1.0),
            r.flips,
            r.energy.end,
            r.energy.worst,
            r.momentum.end,
            r.momentum.worst,
            cost
        );
        if method == Method::RapierWithEngineStep {
            println!(
                "  (rapier's pose lands within {:.1e} rad of the step's orientation; the step alone: {:.0} ns/body)",
                r.landing,
                engine_step_cost(timed_bodies, 20, samples)
            );
        }
    }
    println!();

    let top = ga_rapier_example::top::SHAPE;
    println!(
        "top: mass {}, moments {} about the centre of mass, {} above the tip, spin {} rad/s, tilt {} rad, g = {}",
        top.mass,
        top.moments,
        ga_rapier_example::top::ARM,
        ga_rapier_example::top::SPIN,
        ga_rapier_example::top::TILT,
        ga_rapier_example::top::G
    );
    println!("  rapier: the tip held at the ground's origin by a spherical impulse joint, rapier's gravity");
    println!("  with the engine: step_with about the tip (gravity's torque), no joint; rapier given the velocities that land its pose there");
    println!("  then the same body free (no joint, no gravity), spun about its symmetry axis (its smallest moment) with a 1 % wobble: the spin is constant in the exact motion");
    for (scene, title) in [(Scene::Top, "on its tip"), (Scene::SpinningFree, "free")] {
        println!(
            "  {:<10} {:<24} {:>11} {:>11} {:>11} {:>11} {:>11} {:>11} {:>10} {:>10}",
            "",
            "method",
            "energy end",
            "energy max",
            "L_z end",
            "L_z max",
            "spin end",
            "spin max",
            "tip off",
            "ns/body"
        );
        for method in Method::ALL {
            let r = run_top(scene, method, steps);
            let cost = cost_per_body_step(scene, method, timed_bodies, 20, samples);
            println!(
                "  {:<10} {:<24} {:>+11.2e} {:>11.2e} {:>+11.2e} {:>11.2e} {:>+11.2e} {:>11.2e} {:>8.1e} m {:>10.0}",
                title,
                method.name(),
                r.energy.end,
                r.energy.worst,
                r.vertical.end,
                r.vertical.worst,
                r.spin.end,
                r.spin.worst,
                r.tip,
                cost
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn arguments_choose_the_run_or_are_refused_by_name() {
        assert_eq!(settings(&[]).map(|s| s.steps), Ok(TEN_MINUTES));
        let quick = settings(&["--quick".to_string()]).map(|s| (s.steps, s.samples));
        assert_eq!(quick, Ok((3_600, 3)));
        let refused = settings(&["--seconds".to_string(), "5".to_string()]).err();
        assert!(refused.is_some_and(|m| m.contains("`--seconds`") && m.contains("--quick")));
    }
}
