//! `index.html`: the plots, and per scene the reference check, the fastest method at each
//! error level, each method's observed order, cost per step and stability verdict.

use std::fmt::Write as _;

use ga_rigid::registry::{Method, StepKind, METHODS};

use super::analysis::{
    cost_per_step_ns, error_floor, fastest_at, fastest_over, order, verdict, Order, SceneKind,
    ERROR_LEVELS, MIN_ORDER_POINTS,
};
use super::escape::esc;
use super::measure::{MIN_REPEATS, MIN_TOTAL_TIME};
use super::{Report, SceneResult, Size};

/// The file name of scene `index`'s diagram: `NN-name.svg`, lowercase letters, digits and
/// dashes only (so it is safe in any directory and URL).
#[must_use]
pub fn svg_name(index: usize, name: &str) -> String {
    let mut slug = String::new();
    for c in name.chars() {
        if c.is_ascii_alphanumeric() {
            slug.push(c.to_ascii_lowercase());
        } else if !slug.ends_with('-') {
            slug.push('-');
        }
    }
    format!("{:02}-{}.svg", index + 1, slug.trim_matches('-'))
}

const STYLE: &str = "body{font-family:sans-serif;max-width:1000px;margin:2em auto;padding:0 1em;\
color:#222;line-height:1.4}table{border-collapse:collapse;margin:.5em 0 1em}\
td,th{border:1px solid #ccc;padding:.2em .6em;text-align:left;font-size:.92em}\
th{background:#f3f3f3}td.num{text-align:right;font-variant-numeric:tabular-nums}\
img,section>svg{max-width:100%;height:auto;border:1px solid #ddd}\
g.ga-legend{cursor:pointer;pointer-events:bounding-box}g.ga-legend.ga-off{opacity:.3}\
g.ga-series.ga-off{display:none}section{margin-bottom:3em}\
.swatch{display:inline-block;width:1.4em;height:.5em;margin-right:.4em;vertical-align:middle}\
.note{color:#555;font-size:.92em}";

/// Hides and shows a method's lines in every panel of a diagram when its legend entry is
/// clicked (the groups [`super::plot::svg`] writes); the page needs nothing else to run.
const SCRIPT: &str = "document.querySelectorAll('svg g.ga-legend').forEach(function (entry) {\
 entry.addEventListener('click', function () {\
 var method = entry.getAttribute('data-method');\
 var off = !entry.classList.contains('ga-off');\
 entry.ownerSVGElement.querySelectorAll('g[data-method=\"' + method + '\"]')\
 .forEach(function (g) { g.classList.toggle('ga-off', off); });\
 });\
});";

/// The page; `svg_names[i]` is the diagram file of `report.scenes[i]` and `svgs[i]` its
/// text, drawn into the page so that its legend can hide and show lines.
#[must_use]
pub fn html(report: &Report, svg_names: &[String], svgs: &[String]) -> String {
    let mut out = String::new();
    let size = match report.size {
        Size::Quick => "quick",
        Size::Full => "full",
    };
    let _ = write!(
        out,
        "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\
         <title>ga-rigid report</title><style>{STYLE}</style></head><body>\n\
         <h1>ga-rigid: which method buys how much accuracy per microsecond</h1>\n"
    );
    let _ = write!(
        out,
        "<p>Every method on every scene ({size} run), measured at {samples} evenly spaced \
         times against a reference that is never the method itself. <b>Error</b> is the \
         angle of <code>~R_ref R</code> in rad, the largest over the run; the body \
         momentum's and energy's relative errors are in <a href=\"results.csv\">results.csv</a> \
         (one row per scene, method and step or tolerance).</p>\n\
         <p><b>Timing.</b> Each run is done once to warm up, then repeated until the \
         repetitions add up to at least {ms} ms and number at least {reps}; the plots \
         show the median, the CSV also the minimum. Wall-clock time of one thread \
         (<code>std::time::Instant</code>), on <b>{cpu}</b>, while other processes may \
         share the machine.</p>\n",
        samples = super::SAMPLES,
        ms = MIN_TOTAL_TIME.as_millis(),
        reps = MIN_REPEATS,
        cpu = esc(&report.cpu),
    );
    summary_section(&mut out, report);
    super::race::race_section(&mut out, report);
    out.push_str("<p>Colours, the same in every plot: ");
    for row in METHODS {
        let c = super::method_colour(row.method);
        let _ = write!(
            out,
            "<span style=\"white-space:nowrap;margin-right:1em\"><span class=\"swatch\" \
             style=\"background:rgb({},{},{})\"></span>{}{}</span> ",
            c.0,
            c.1,
            c.2,
            row.name,
            if row.peer.is_some() {
                " (peer, dashed)"
            } else {
                ""
            }
        );
    }
    out.push_str("</p>\n<p>Scenes: ");
    for (i, scene) in report.scenes.iter().enumerate() {
        let _ = write!(
            out,
            "{}<a href=\"#s{i}\">{}</a>",
            if i > 0 { " · " } else { "" },
            esc(&scene.name)
        );
    }
    if !report.nd_scenes.is_empty() {
        out.push_str(" · <a href=\"#four-dimensions\">Four dimensions</a>");
    }
    out.push_str("</p>\n");
    for (i, scene) in report.scenes.iter().enumerate() {
        let name = svg_names.get(i).map_or("", String::as_str);
        let svg = svgs.get(i).map_or("", String::as_str);
        section(&mut out, i, scene, name, svg);
    }
    if !report.long_runs.is_empty() {
        long_runs_section(&mut out, &report.long_runs);
    }
    if !report.engine_runs.is_empty() {
        engine_runs_section(&mut out, &report.engine_runs);
    }
    if !report.nd_scenes.is_empty() {
        super::nd::nd_section(&mut out, &report.nd_scenes);
    }
    let _ = write!(out, "<script>{SCRIPT}</script>\n</body></html>\n");
    out
}

/// The answer first: per kind of scene and error level, the fastest stepping method over
/// all the kind's scenes, and the exact or closed form where one applies.
fn summary_section(out: &mut String, report: &Report) {
    let mut kinds: Vec<SceneKind> = report.scenes.iter().map(|s| s.kind).collect();
    kinds.sort();
    kinds.dedup();
    out.push_str(
        "<h2>Which method to use</h2>\n<p>For each kind of scene and each largest attitude \
         error, the stepping method of this library that reaches that error on <i>every</i> \
         scene of the kind in the least time (its fastest run at that error on each scene, \
         summed over the scenes). Below it the best <b>peer</b> (what people use today: \
         ode_solvers' Dop853 and Dopri5 on the quaternion form, the engines' gyroscopic Euler \
         steps, Buss's method) by the same rule, with the ratio of the two times. Where the \
         bodies have an exact or closed-form solution (no steps: it is evaluated at the sample \
         times) and it is faster than every stepper, it is the answer and heads the cell. \
         Where none of our steppers reached a level on every scene, the cell names the fastest method \
         of any kind on each scene that reached it.</p>\n<table><tr><th>kind (scenes)</th>",
    );
    for level in ERROR_LEVELS {
        let _ = write!(out, "<th>≤ {level:.0e} rad</th>");
    }
    out.push_str("</tr>\n");
    for kind in kinds {
        let scenes: Vec<&SceneResult> = report.scenes.iter().filter(|s| s.kind == kind).collect();
        let names: Vec<String> = scenes.iter().map(|s| esc(&s.name)).collect();
        let _ = write!(
            out,
            "<tr><td>{} ({})<br><span class=\"note\">{}</span></td>",
            kind.label(),
            scenes.len(),
            names.join("; ")
        );
        for level in ERROR_LEVELS {
            let ours = |m: Method| m.info().peer.is_none();
            let stepper = fastest_over(&scenes, level, |m| {
                ours(m) && m.step_kind() != StepKind::AtSamples
            });
            let exact = fastest_over(&scenes, level, |m| m.step_kind() == StepKind::AtSamples);
            let peer = fastest_over(&scenes, level, |m| !ours(m));
            out.push_str("<td>");
            // The exact form is the answer where it beats every stepper: a stepper far
            // slower than it must not be the headline.
            let exact_first = match (&exact, &stepper) {
                (Some(e), Some(s)) => e.time_us < s.time_us,
                (Some(_), None) => true,
                (None, _) => false,
            };
            if let (true, Some(pick)) = (exact_first, &exact) {
                let _ = write!(
                    out,
                    "<b>{}</b> (no steps)<br>{:.1} µs",
                    pick.method.name(),
                    pick.time_us
                );
                if let Some(s) = &stepper {
                    let _ = write!(
                        out,
                        "<br><span class=\"note\">fastest stepper {}: {:.1} µs ({:.1}x the exact \
                         form's time; for torques and bodies without one)</span>",
                        s.method.name(),
                        s.time_us,
                        s.time_us / pick.time_us
                    );
                }
            } else {
                match &stepper {
                    Some(pick) => {
                        let _ = write!(
                            out,
                            "<b>{}</b><br>{:.1} µs",
                            pick.method.name(),
                            pick.time_us
                        );
                    }
                    None => {
                        out.push_str("none of our steppers reached it on every scene");
                        let each: Vec<String> = scenes
                            .iter()
                            .map(|scene| {
                                let who =
                                    fastest_at(scene, level).map_or("nobody", |r| r.method.name());
                                format!("{}: {who}", esc(&scene.name))
                            })
                            .collect();
                        let _ = write!(
                            out,
                            "<br><span class=\"note\">fastest there: {}</span>",
                            each.join("; ")
                        );
                    }
                }
            }
            match (&peer, &stepper) {
                (Some(p), Some(s)) => {
                    let _ = write!(
                        out,
                        "<br><span class=\"note\">best peer {}: {:.1} µs; our stepper takes \
                         {:.2}x</span>",
                        p.method.name(),
                        p.time_us,
                        s.time_us / p.time_us
                    );
                }
                (Some(p), None) => {
                    let _ = write!(
                        out,
                        "<br><span class=\"note\">best peer {}: {:.1} µs</span>",
                        p.method.name(),
                        p.time_us
                    );
                }
                (None, _) => out.push_str("<br><span class=\"note\">no peer reached it</span>"),
            }
            if let (false, Some(pick)) = (exact_first, &exact) {
                let _ = write!(
                    out,
                    "<br><span class=\"note\">{} (no steps): {:.1} µs</span>",
                    pick.method.name(),
                    pick.time_us
                );
            }
            out.push_str("</td>");
        }
        out.push_str("</tr>\n");
    }
    out.push_str("</table>\n");
}

fn section(out: &mut String, index: usize, scene: &SceneResult, svg_name: &str, svg: &str) {
    let _ = write!(
        out,
        "<section id=\"s{index}\"><h2>{}</h2>\n<p>{}; t_end = {:e}, |w(0)| = {:.3e} rad/s. \
         Click a legend entry to hide or show its method's lines; the diagram alone: \
         <a href=\"{}\">{}</a>.</p>\n{}\n",
        esc(&scene.name),
        esc(&scene.source),
        scene.t_end,
        scene.rate,
        esc(svg_name),
        esc(svg_name),
        svg.trim(),
    );
    let c = &scene.check;
    let _ = writeln!(
        out,
        "<p><b>Reference:</b> {} (runs of that method itself are measured against {}). \
         <b>Check:</b> the two agree to {:.1e} rad in attitude and {:.1e} in relative body \
         momentum (largest over the samples), so errors below about that level are not \
         resolved.</p>",
        esc(&c.primary),
        esc(&c.secondary),
        c.errors.attitude_max,
        c.errors.momentum_max,
    );
    out.push_str(
        "<table><tr><th>largest attitude error</th><th>fastest method</th><th>setting</th>\
         <th>median time (µs)</th></tr>\n",
    );
    for level in ERROR_LEVELS {
        match fastest_at(scene, level) {
            Some(row) => {
                let _ = writeln!(
                    out,
                    "<tr><td>≤ {level:.0e}</td><td>{}</td><td>{}</td><td class=\"num\">{:.1}</td></tr>",
                    row.method.name(),
                    esc(&row.label()),
                    row.time_us().unwrap_or(f64::NAN)
                );
            }
            None => {
                let _ = writeln!(
                    out,
                    "<tr><td>≤ {level:.0e}</td><td colspan=\"3\">no run reached it</td></tr>"
                );
            }
        }
    }
    out.push_str(
        "</table>\n<table><tr><th>method</th><th>observed order</th><th>cost per step (ns)</th>\
         <th>energy drift at the finest setting</th><th>accuracy by step size (error &lt; 0.1 kept or lost)</th></tr>\n",
    );
    let mut methods: Vec<Method> = scene.rows.iter().map(|r| r.method).collect();
    methods.dedup();
    for method in methods {
        let floor = error_floor(scene);
        let order = match (method.step_kind(), order(scene, method)) {
            (StepKind::AtSamples, _) => "– (no steps)".to_string(),
            // Error against the mean step of runs at several tolerances is not the
            // method's order: the controller chooses the steps.
            (StepKind::Adaptive, Order::Fitted(p, n)) => {
                format!("– (adaptive; error falls as mean step^{p:.1} over {n} tolerances)")
            }
            (_, Order::Fitted(p, n)) => format!("{p:.2} ({n} runs)"),
            (_, Order::TooFewPoints(n)) => format!(
                "– ({n} runs with error between {floor:.0e} and 0.1; {MIN_ORDER_POINTS} needed)"
            ),
        };
        let cost = cost_per_step_ns(scene, method).map_or("–".to_string(), |c| format!("{c:.0}"));
        // The last row of a method is its finest step or tightest tolerance.
        let drift = scene
            .rows
            .iter()
            .rfind(|r| r.method == method)
            .and_then(|r| r.errors)
            .map_or("–".to_string(), |e| format!("{:.1e}", e.energy_max));
        let _ = writeln!(
            out,
            "<tr><td>{}{}</td><td class=\"num\">{order}</td><td class=\"num\">{cost}</td>\
             <td class=\"num\">{drift}</td><td>{}</td></tr>",
            method.name(),
            if method.info().peer.is_some() {
                " (peer)"
            } else {
                ""
            },
            esc(&verdict(scene, method))
        );
    }
    let _ = write!(
        out,
        "</table>\n<p class=\"note\">Observed order: slope of log error against log mean \
         step, over runs whose error lies between this scene's floor, {:.1e} (ten times the \
         references' disagreement, at least 1e-12), and 0.1, fitted with at least {} such \
         runs.",
        error_floor(scene),
        MIN_ORDER_POINTS
    );
    out.push_str(" Cost per step: median time over steps (evaluations for methods without steps), median over settings. Energy drift: the largest relative drift over the run. Accuracy by step size: a run keeps the solution while its attitude and relative momentum errors stay below 0.1 over the whole run; h|w| is the (mean) step times the initial rate. This is not the registry's stability limit that <code>ga-rigid simulate</code> checks before a run (the h|w|max beyond which a method's numbers blow up, listed in <code>--help</code>): a method can lose the accuracy well before it loses stability.</p>\n");
    for (what, why) in &scene.left_out {
        let _ = writeln!(
            out,
            "<p class=\"note\">Left out: <b>{}</b>: {}.</p>",
            esc(what),
            esc(why)
        );
    }
    let failures: Vec<_> = scene
        .rows
        .iter()
        .filter_map(|r| Some((r, r.failure.as_ref()?)))
        .collect();
    for (row, why) in failures {
        let _ = writeln!(
            out,
            "<p class=\"note\">Failed: <b>{}</b> at {}: {}</p>",
            row.method.name(),
            esc(&row.label()),
            esc(why)
        );
    }
    out.push_str("</section>\n");
}

/// The table of [`super::long_runs`]: one row per run with its verdict.
fn long_runs_section(out: &mut String, rows: &[super::LongRun]) {
    let unit: Vec<u64> = rows
        .iter()
        .filter(|r| r.check == "unit rotor")
        .map(|r| r.steps)
        .collect();
    let full = unit.iter().all(|&steps| steps >= super::UNIT_STEPS);
    let range = |values: &[f64]| {
        let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = values.iter().copied().fold(0.0, f64::max);
        if lo == hi {
            format!("{lo}")
        } else {
            format!("{lo} to {hi}")
        }
    };
    let unit_steps: Vec<f64> = unit.iter().map(|&s| s as f64).collect();
    let periods: Vec<f64> = rows
        .iter()
        .filter(|r| r.check == "invariants")
        .map(|r| r.periods)
        .collect();
    let _ = writeln!(
        out,
        "<section id=\"long-runs\"><h2>Long runs</h2>\n<p>The unit-rotor check runs every \
         method over {} steps (<code>|R ~R - 1|</code> at most {:.0e} after every step); the \
         invariant check runs the compositions and splittings over {} periods (the energy \
         error is bounded when its largest value over the last tenth is at most {} times \
         that over the first tenth, and the conserved momentum stays within {:.0e} \
         relative). {}Details in <a href=\"long_runs.csv\">long_runs.csv</a>.</p>",
        range(&unit_steps),
        super::UNIT_DEFECT_BOUND,
        range(&periods),
        super::ENERGY_GROWTH,
        super::MOMENTUM_BOUND,
        if full {
            ""
        } else {
            "This quick run goes a hundredth as far as the full report; its verdicts are for \
             that length only. "
        },
    );
    out.push_str(
        "<table><tr><th>check</th><th>method</th><th>scene</th><th>steps</th>\
         <th>max |R~R - 1|</th><th>energy, first tenth</th><th>energy, last tenth</th>\
         <th>momentum</th><th>verdict</th></tr>\n",
    );
    for r in rows {
        let invariant = r.check == "invariants";
        let cell = |x: f64| {
            if invariant {
                format!("{x:.1e}")
            } else {
                String::new()
            }
        };
        let _ = writeln!(
            out,
            "<tr><td>{}</td><td>{}</td><td>{}</td><td class=\"num\">{}</td>\
             <td class=\"num\">{:.1e}</td><td class=\"num\">{}</td><td class=\"num\">{}</td>\
             <td class=\"num\">{}</td><td>{}</td></tr>",
            r.check,
            r.method.name(),
            esc(r.scene),
            r.steps,
            r.unit_defect,
            cell(r.energy_first),
            cell(r.energy_last),
            cell(r.momentum_max),
            esc(&super::long_run_verdict(r)),
        );
    }
    out.push_str("</table></section>\n");
}

/// The table of [`super::engine_runs`]: per method and engine step size, the energy and
/// momentum errors and the flip period against the exact one.
fn engine_runs_section(out: &mut String, rows: &[super::EngineRun]) {
    let steps = rows.iter().map(|r| r.steps).max().unwrap_or(0);
    let _ = writeln!(
        out,
        "<section id=\"engine-steps\"><h2>At engine step sizes</h2>\n<p>Each body stepped \
         {steps} times at <code>h |w(0)|</code> from {} to {}, as an engine steps at a fixed \
         frame rate. Largest relative errors of the energy and of the space angular momentum \
         over the run; the mean time between flips (sign changes of the body momentum's \
         second component) against the exact flow's. Peers (marked) are the engines' \
         gyroscopic Euler steps, Buss's method, the implicit midpoint rule on the quaternion, \
         the discrete Moser-Veselov step and Spiers's steps (avian's pull request #993). \
         Details in <a href=\"engine_runs.csv\">engine_runs.csv</a>.</p>",
        super::ENGINE_RATES[0],
        super::ENGINE_RATES[super::ENGINE_RATES.len() - 1],
    );
    for body in super::ENGINE_BODIES {
        let runs: Vec<super::EngineRun> = rows.iter().filter(|r| r.body == body).cloned().collect();
        if !runs.is_empty() {
            engine_body_table(out, body, &runs);
        }
    }
    out.push_str("</section>\n");
}

/// One body's table of [`engine_runs_section`] and the verdicts under it.
fn engine_body_table(out: &mut String, body: super::EngineBody, rows: &[super::EngineRun]) {
    let about = if body == super::T_HANDLE {
        "the Dzhanibekov body, flipping about its middle axis"
    } else {
        "the two smaller moments 2 % apart: nearly the symmetric top, for which Spiers's step \
         is exact"
    };
    let _ = writeln!(
        out,
        "<h3>{}</h3>\n<p>{about}: moments {:?}, body momentum {:?}; the exact flow flips \
         every {:.3} s.</p>",
        esc(body.name),
        body.moments,
        body.momentum,
        body.exact_flip_period(),
    );
    out.push_str(
        "<table><tr><th>method</th><th>h|w|</th><th>energy error, largest \
         |E - E0| / E0</th><th>momentum error, largest |L - L0| / |L0| (L the space \
         angular momentum, a vector)</th><th>flips</th><th>flip period error</th>\
         <th>status</th></tr>\n",
    );
    for r in rows {
        // A run that stopped has no flip statistics worth reading: its flips happened while
        // it was already leaving the solution.
        let (flips, flip) = match (&r.failure, r.flip_error()) {
            (Some(_), _) => ("-".to_string(), "- (stopped)".to_string()),
            (None, Some(e)) => (r.flips.to_string(), format!("{:+.2} %", 100.0 * e)),
            (None, None) => (r.flips.to_string(), "fewer than two flips".to_string()),
        };
        let status = match &r.failure {
            Some(why) => format!("stopped: {why}"),
            None => "ran".to_string(),
        };
        let _ = writeln!(
            out,
            "<tr><td>{}{}</td><td class=\"num\">{}</td><td class=\"num\">{:.1e}</td>\
             <td class=\"num\">{:.1e}</td><td class=\"num\">{flips}</td>\
             <td class=\"num\">{flip}</td><td>{}</td></tr>",
            r.method.name(),
            if r.method.info().peer.is_some() {
                " (peer)"
            } else {
                ""
            },
            r.rate,
            r.energy_max,
            r.momentum_max,
            esc(&status),
        );
    }
    let (momentum, energy, flip) = super::ENGINE_BOUNDS;
    let _ = writeln!(
        out,
        "</table>\n<p>The fastest runs that keep <code>|L|</code> to {momentum:e}, the energy \
         to {energy:e} and the flip period within {}% (times of the runs above, each 10^5 \
         steps or the quick size, in this harness's generic stepping, not the engine's own \
         code). ga_engine steps with splitting-corrected: of the second-order steps within the \
         bounds, the one with the smallest energy error on the T-handle.</p>\n<ul>",
        100.0 * flip
    );
    for line in super::engine_verdicts(rows) {
        let _ = writeln!(out, "<li>{}</li>", esc(&line));
    }
    out.push_str("</ul>\n");
}
