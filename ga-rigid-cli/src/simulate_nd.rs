//! `simulate` and `inertia` on 2D and 4D scenes ([`ga_rigid::nd::scene`]): the 3D
//! command's rules (step control, limits, output files and the sidecar record) with the
//! n-dimensional body's methods and CSV columns.

use std::fmt::Write as _;

use ga_rigid::limits::{Limits, StepSource};
use ga_rigid::nd::run::{plan, run, to_csv};
use ga_rigid::nd::scene::{BodyScene, NdScene};
use ga_rigid::nd::Algebra;

use crate::error::Error;
use crate::simulate::{sidecar_path, Record};
use crate::{emit_stdout, output, SimulateArgs, FLAG_NAMES};

/// A library error in the command's words: the run's flags.
fn in_flags(e: ga_rigid::error::Error) -> Error {
    Error::Library(e.renamed(&FLAG_NAMES))
}

/// `simulate` on a scene of `dimension` 2 or 4: the method is checked against the
/// dimension first, then the step control, the output paths, the scene and its limits;
/// the CSV and its record are written together, as in 3D.
pub(crate) fn simulate(args: &SimulateArgs, dimension: usize) -> Result<(), Error> {
    let method = args.method.0;
    ga_rigid::nd::run::check_method(method, dimension)
        .map_err(|e| Error::Library(e.renamed(&[("method", "--method")])))?;
    let given = method.given_step(args.dt, args.tol).map_err(in_flags)?;
    if args.plot.is_some() {
        return Err(Error::invalid(
            "--plot",
            format!("plots are drawn for 3D scenes; this scene has dimension {dimension}"),
        ));
    }
    let mut plan_out = output::OutputPlan::with_stdout_alternative();
    plan_out.input("the scene file", &args.scene)?;
    let sidecar = args.out.as_deref().map(sidecar_path);
    if let (Some(out), Some(sidecar)) = (&args.out, &sidecar) {
        plan_out.add("--out", out)?;
        plan_out.add("--out", sidecar)?;
    }
    let scene = NdScene::load(&args.scene)?;
    let limits = Limits {
        max_steps: args.max_steps,
        max_output_mb: args.max_output_mb,
        max_seconds: args.max_seconds,
        max_phase_error: args.max_phase_error,
        allow_unstable: args.allow_unstable,
    };
    let checked = plan(&scene, method, given, &limits).map_err(in_flags)?;
    let rows = run(&scene, method, checked.step).map_err(in_flags)?;
    let csv = to_csv(scene.dimension(), &rows);
    let record = Record {
        scene: &args.scene,
        method,
        step: checked.step,
        source: checked.source,
        run: scene.run(),
    };
    let mut texts: Vec<String> = Vec::new();
    if let Some(out) = &args.out {
        texts.push(csv.clone());
        texts.push(record.to_json(out));
    } else if let StepSource::Default(_) = checked.source {
        eprintln!("note: {}", record.describe_step());
    }
    let texts: Vec<&str> = texts.iter().map(String::as_str).collect();
    let staged = plan_out.stage(&texts)?;
    if args.out.is_none() {
        emit_stdout(&csv)?;
    }
    staged.publish()
}

/// The text `inertia` prints for a 2D or 4D scene: the dimension, the mass (when the
/// scene gives one), the centre of mass, the second moments `l_k`, the plane moments
/// `l_i + l_j` in canonical order and the principal rotor, numbers round-trip exact.
#[must_use]
pub fn describe_inertia(scene: &NdScene) -> String {
    match scene {
        NdScene::Planar(s) => describe(s),
        NdScene::Four(s) => describe(s),
    }
}

fn describe<A: Algebra>(scene: &BodyScene<A>) -> String {
    let list = |values: &mut dyn Iterator<Item = f64>| {
        let parts: Vec<String> = values.map(|v| format!("{v}")).collect();
        format!("[{}]", parts.join(", "))
    };
    let body = &scene.body;
    let mut out = String::new();
    // Writing to a String cannot fail.
    let _ = writeln!(out, "dimension: {}", A::DIMENSION);
    let _ = match scene.mass {
        Some(m) => writeln!(out, "mass: {m}"),
        None => writeln!(out, "mass: unknown (the scene gives second moments only)"),
    };
    let _ = writeln!(out, "about: the centre of mass");
    let _ = writeln!(
        out,
        "centre_of_mass: {}",
        list(&mut scene.centre[..A::DIMENSION].iter().copied())
    );
    let _ = writeln!(
        out,
        "second_moments: {}",
        list(&mut body.second_moments().iter().copied())
    );
    let planes = body.plane_moments();
    let _ = writeln!(
        out,
        "plane_moments: {}",
        list(&mut (0..A::PLANES.len()).map(|k| planes[k]))
    );
    let _ = writeln!(
        out,
        "rotor: {}",
        list(&mut (0..A::ROTOR_LEN).map(|k| scene.principal[k]))
    );
    out
}
