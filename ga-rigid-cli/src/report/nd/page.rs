//! The page's "Four dimensions" section: per scene its diagram, the reference and its
//! check, and per method the observed order and the energy drift.

use std::fmt::Write as _;

use ga_rigid::registry::StepKind;

use super::methods::NdMethod;
use super::plot::{nd_colour, nd_svg_name};
use super::run::{nd_error_floor, nd_order, NdSceneResult};
use crate::report::analysis::{Order, MIN_ORDER_POINTS};
use crate::report::escape::esc;

/// The section, with the diagrams' file names from [`nd_svg_name`].
pub fn nd_section(out: &mut String, scenes: &[NdSceneResult]) {
    out.push_str(
        "<section id=\"four-dimensions\"><h2>Four dimensions</h2>\n<p>The rigid body of \
         <code>ga_rigid::nd</code> in G4: six planes of rotation, angular velocities that \
         need not be simple (a double rotation in two orthogonal planes at once). Every method \
         of the n-dimensional body at a sweep of steps or tolerances, measured as the 3D scenes \
         are, against a reference that is never the method itself. <b>Error</b> is the angle \
         of the relative rotation <code>~R_ref R</code>: a rotation of R<sup>4</sup> turns by \
         two angles θ<sub>1</sub>, θ<sub>2</sub> in two orthogonal planes, and the error is \
         <code>sqrt(θ1² + θ2²)</code> with each in [-π, π], which is <code>2 |log(±~R_ref R)|</code> \
         for the shorter logarithm and the 3D angle for a simple rotation. <b>Energy drift</b>: \
         the largest <code>|E(t) - E(0)| / E(0)</code> of the run over the samples. The adaptive \
         methods of the n-dimensional body have no dense output, so a run stops at each of the \
         samples: at loose tolerances the sample spacing, not the tolerance, sets their steps. \
         Rows in \
         <a href=\"nd_results.csv\">nd_results.csv</a>. Colours and markers are these plots' \
         own: ",
    );
    for method in NdMethod::ALL {
        let c = nd_colour(method);
        let _ = write!(
            out,
            "<span style=\"white-space:nowrap;margin-right:1em\"><span class=\"swatch\" \
             style=\"background:rgb({},{},{})\"></span>{}</span> ",
            c.0,
            c.1,
            c.2,
            method.name()
        );
    }
    out.push_str(
        "(circles order two, squares order four, triangles adaptive or closed form).</p>\n",
    );
    for (i, scene) in scenes.iter().enumerate() {
        scene_section(out, i, scene);
    }
    out.push_str("</section>\n");
}

fn scene_section(out: &mut String, index: usize, scene: &NdSceneResult) {
    let svg = nd_svg_name(index, &scene.name);
    let _ = write!(
        out,
        "<h3 id=\"nd{index}\">{}</h3>\n<p>{}; t_end = {:e}, |Omega_B(0)| = {:.3e} rad/s.</p>\n\
         <img src=\"{}\" alt=\"work-precision diagram of {}\">\n",
        esc(&scene.name),
        esc(&scene.source),
        scene.t_end,
        scene.rate,
        esc(&svg),
        esc(&scene.name),
    );
    let c = &scene.check;
    let _ = write!(
        out,
        "<p><b>Reference:</b> {} (runs of that method itself are measured against {}). \
         <b>Check:</b> the two agree to {:.1e} rad in attitude and {:.1e} in Omega_B relative \
         to |Omega_B(0)| (largest over the samples), so errors below about that level are not \
         resolved.",
        esc(&c.primary),
        esc(&c.secondary),
        c.errors.attitude_max,
        c.errors.omega_max,
    );
    if let Some((published, dr, dw)) = &c.published {
        let _ = write!(
            out,
            " <b>Check against published values:</b> at t = {} the reference's R differs from \
             the published R by at most {dr:.1e} per component and its Omega_B by {dw:.1e} \
             ({}).",
            published.t,
            esc(published.source)
        );
    }
    if let Some((start, largest, at)) = c.growth {
        let _ = write!(
            out,
            " <b>Instability:</b> the part of Omega_B outside the two planes of the steady \
             double rotation grows from {start:.1e} at t = 0 to {largest:.2} at t = {at:.1} \
             (on the reference), {:.0} times: the equilibrium is unstable, and the errors of \
             every method grow with the perturbation.",
            largest / start
        );
    }
    out.push_str("</p>\n");
    out.push_str(
        "<table><tr><th>method</th><th>observed order</th><th>smallest error (rad)</th>\
         <th>its median time (µs)</th><th>energy drift at the finest setting</th></tr>\n",
    );
    let floor = nd_error_floor(scene);
    for method in NdMethod::ALL {
        let rows: Vec<_> = scene.rows.iter().filter(|r| r.method == method).collect();
        if rows.is_empty() {
            continue;
        }
        let order = match (method.step_kind(), nd_order(scene, method)) {
            (StepKind::AtSamples, _) => "– (no steps)".to_string(),
            (StepKind::Adaptive, Order::Fitted(p, n)) => {
                format!("– (adaptive; error falls as mean step^{p:.1} over {n} tolerances)")
            }
            (_, Order::Fitted(p, n)) => format!("{p:.2} ({n} runs)"),
            (_, Order::TooFewPoints(n)) => format!(
                "– ({n} runs with error between {floor:.0e} and 0.1; {MIN_ORDER_POINTS} needed)"
            ),
        };
        let best = rows
            .iter()
            .filter_map(|r| Some((r.errors?.attitude_max, r.time_us()?)))
            .min_by(|a, b| a.0.total_cmp(&b.0));
        let (best_error, best_time) = best.map_or(("–".to_string(), "–".to_string()), |b| {
            (format!("{:.1e}", b.0), format!("{:.1}", b.1))
        });
        // The last row of a method is its finest step or tightest tolerance.
        let drift = rows
            .last()
            .and_then(|r| r.errors)
            .map_or("–".to_string(), |e| format!("{:.1e}", e.energy_max));
        let failed = rows.iter().filter(|r| r.failure.is_some()).count();
        let _ = writeln!(
            out,
            "<tr><td>{}{}</td><td class=\"num\">{order}</td><td class=\"num\">{best_error}</td>\
             <td class=\"num\">{best_time}</td><td class=\"num\">{drift}</td></tr>",
            method.name(),
            if failed > 0 {
                format!(" ({failed} failed)")
            } else {
                String::new()
            },
        );
    }
    let _ = writeln!(
        out,
        "</table>\n<p class=\"note\">Observed order: slope of log error against log mean step \
         over runs whose error lies between {floor:.1e} (ten times the references' \
         disagreement, at least 1e-12) and 0.1, with at least {MIN_ORDER_POINTS} such runs.</p>"
    );
    for row in scene.rows.iter().filter(|r| r.failure.is_some()) {
        let _ = writeln!(
            out,
            "<p class=\"note\">Failed: <b>{}</b> at {} = {:e}: {}</p>",
            row.method.name(),
            row.param_kind(),
            row.param,
            esc(row.failure.as_deref().unwrap_or(""))
        );
    }
}
