//! One work-precision diagram per scene, as SVG text: the largest attitude error over the
//! run against the median run time, log-log, in five panels of at most eight methods
//! ([`super::style`]): each method a line through its settings, in its own colour and
//! marker, the peers dashed, the legend under each panel. Points are not labelled with
//! their step or tolerance (labels on crowded lines overprint each other); results.csv
//! and the page's tables hold every setting.

use plotters::coord::Shift;
use plotters::prelude::*;

use ga_rigid::csv::Row;
use ga_rigid::error::Error;
use ga_rigid::registry::Method;

use super::style::{panel, style, Marker, Panel};
use super::SceneResult;

/// Errors below this are drawn at it: a log axis has no zero.
const ERROR_FLOOR: f64 = 1e-17;

/// The size of one panel (a chart and its legend) in pixels.
const PANEL: (u32, u32) = (620, 470);

/// The height of the legend under each chart: four rows of two columns.
const LEGEND_HEIGHT: u32 = 104;

/// The prefix of the text elements that mark a group's start (`@@ga-group:CLASS:METHOD`)
/// and end (`@@ga-group-end`) in plotters' output; no text of the diagram starts with it.
const GROUP_MARK: &str = "@@ga-group";

/// The scene's work-precision diagram as an SVG document.
pub fn svg(scene: &SceneResult) -> Result<String, Error> {
    let mut text = String::new();
    draw(scene, &mut text).map_err(|e| Error::invalid("plot", e.to_string()))?;
    Ok(groups_from_marks(&text))
}

/// `text` with each group mark (a whole `<text ...>` element whose content is a mark)
/// replaced by the tag it stands for.
fn groups_from_marks(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(at) = rest.find(GROUP_MARK) {
        let (Some(open), Some(close)) = (rest[..at].rfind("<text"), rest[at..].find("</text>"))
        else {
            break;
        };
        out.push_str(&rest[..open]);
        let mark = rest[at..at + close].trim();
        match mark
            .strip_prefix(GROUP_MARK)
            .and_then(|m| m.strip_prefix(':'))
        {
            Some(class_and_method) => {
                let (class, method) = class_and_method.split_once(':').unwrap_or(("", ""));
                out.push_str(&format!("<g class=\"{class}\" data-method=\"{method}\">"));
            }
            None => out.push_str("</g>"),
        }
        rest = rest[at + close + "</text>".len()..].trim_start_matches('\n');
        out.push('\n');
    }
    out.push_str(rest);
    out
}

/// Marks the start of `method`'s group of class `class` in the drawing (see [`svg`]).
fn begin_group<DB: DrawingBackend>(
    area: &DrawingArea<DB, Shift>,
    class: &str,
    method: Method,
) -> DrawResult
where
    DB::ErrorType: 'static,
{
    let mark = format!("{GROUP_MARK}:{class}:{}", method.name());
    area.draw(&Text::new(mark, (0, 0), ("sans-serif", 1)))?;
    Ok(())
}

/// Marks the end of the group begun last.
fn end_group<DB: DrawingBackend>(area: &DrawingArea<DB, Shift>) -> DrawResult
where
    DB::ErrorType: 'static,
{
    area.draw(&Text::new(
        format!("{GROUP_MARK}-end"),
        (0, 0),
        ("sans-serif", 1),
    ))?;
    Ok(())
}

type DrawResult = Result<(), Box<dyn std::error::Error>>;

/// A method's drawn points: (median run time in µs, largest attitude error), in the order
/// of its settings.
fn points(scene: &SceneResult, method: Method) -> Vec<(f64, f64)> {
    scene
        .rows
        .iter()
        .filter(|r| r.method == method)
        .filter_map(|r| {
            let e = r.errors?.attitude_max.max(ERROR_FLOOR);
            Some((r.time_us()?, e))
        })
        .filter(|(t, e)| t.is_finite() && e.is_finite() && *t > 0.0)
        .collect()
}

/// Our method to draw beside the peers: the fastest of ours to reach the smallest error
/// any peer reached on this scene; without such a run, ours that reached the smallest
/// error.
#[must_use]
pub fn fastest_of_ours_to_the_peers_best(scene: &SceneResult) -> Option<Method> {
    let mut ours: Vec<Method> = scene
        .rows
        .iter()
        .map(|r| r.method)
        .filter(|&m| !panel(m).is_peers())
        .collect();
    ours.dedup();
    let peers_best = scene
        .rows
        .iter()
        .filter(|r| panel(r.method).is_peers())
        .flat_map(|r| points(scene, r.method))
        .map(|(_, e)| e)
        .fold(f64::INFINITY, f64::min);
    let fastest = ours
        .iter()
        .filter_map(|&m| {
            let t = points(scene, m)
                .into_iter()
                .filter(|&(_, e)| e <= peers_best)
                .map(|(t, _)| t)
                .fold(f64::INFINITY, f64::min);
            t.is_finite().then_some((t, m))
        })
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .map(|(_, m)| m);
    fastest.or_else(|| {
        ours.iter()
            .filter_map(|&m| {
                let e = points(scene, m)
                    .into_iter()
                    .map(|(_, e)| e)
                    .fold(f64::INFINITY, f64::min);
                e.is_finite().then_some((e, m))
            })
            .min_by(|a, b| a.0.total_cmp(&b.0))
            .map(|(_, m)| m)
    })
}

/// The methods drawn in `which`: those of the scene in that panel, and beside the peers
/// our fastest to their best.
fn panel_methods(scene: &SceneResult, which: Panel) -> Vec<Method> {
    let mut methods: Vec<Method> = which
        .methods()
        .into_iter()
        .filter(|&m| scene.rows.iter().any(|r| r.method == m))
        .collect();
    if which.is_peers() {
        methods.extend(fastest_of_ours_to_the_peers_best(scene));
    }
    methods
}

fn draw(scene: &SceneResult, text: &mut String) -> DrawResult {
    // One pair of axes for the five panels, so that they compare at a glance.
    let all: Vec<(f64, f64)> = scene
        .rows
        .iter()
        .map(|r| r.method)
        .flat_map(|m| points(scene, m))
        .collect();
    let (mut t_lo, mut t_hi, mut e_lo, mut e_hi) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for (t, e) in &all {
        t_lo = t_lo.min(*t);
        t_hi = t_hi.max(*t);
        e_lo = e_lo.min(*e);
        e_hi = e_hi.max(*e);
    }
    if all.is_empty() {
        (t_lo, t_hi, e_lo, e_hi) = (1.0, 10.0, 1e-10, 1.0);
    }
    // Room around the points; at least two decades each way, so that a log axis gets a
    // few whole-decade ticks rather than a crowd of labels inside one decade.
    let widen = |lo: f64, hi: f64| {
        let mid = (lo * hi).sqrt();
        let half = (hi / lo).sqrt().max(10.0);
        (mid / half)..(mid * half)
    };
    let x_range = widen(t_lo / 2.0, t_hi * 2.0);
    let y_range = widen(e_lo / 5.0, e_hi * 5.0);

    let size = (2 * PANEL.0, 3 * PANEL.1 + 40);
    let root = SVGBackend::with_string(text, size).into_drawing_area();
    root.fill(&WHITE)?;
    let root = root.titled(&scene.name, ("sans-serif", 22))?;
    let areas = root.split_evenly((3, 2));
    for (area, which) in areas.iter().zip(Panel::ALL) {
        let (chart_area, legend_area) = area.split_vertically(PANEL.1 - LEGEND_HEIGHT);
        let methods = panel_methods(scene, which);
        let mut chart = ChartBuilder::on(&chart_area)
            .caption(which.title(), ("sans-serif", 16))
            .margin(10)
            .x_label_area_size(40)
            .y_label_area_size(64)
            .build_cartesian_2d(x_range.clone().log_scale(), y_range.clone().log_scale())?;
        chart
            .configure_mesh()
            .x_desc("median run time (µs)")
            .y_desc("largest attitude error (rad)")
            .x_label_formatter(&|x| format!("{x:.0e}"))
            .y_label_formatter(&|y| format!("{y:.0e}"))
            .label_style(("sans-serif", 12))
            .axis_desc_style(("sans-serif", 13))
            .light_line_style(RGBColor(235, 235, 235))
            .draw()?;
        for &method in &methods {
            let look = style(method);
            let pts = points(scene, method);
            begin_group(&chart_area, "ga-series", method)?;
            if look.dashed {
                chart.draw_series(DashedLineSeries::new(
                    pts.iter().copied(),
                    6,
                    4,
                    look.colour.stroke_width(2),
                ))?;
            } else {
                chart.draw_series(LineSeries::new(
                    pts.iter().copied(),
                    look.colour.stroke_width(2),
                ))?;
            }
            chart.draw_series(
                pts.iter()
                    .map(|&p| EmptyElement::at(p) + marker(look.marker, look.colour)),
            )?;
            end_group(&chart_area)?;
        }
        legend(&legend_area, scene, &methods)?;
    }
    root.present()?;
    Ok(())
}

/// A marker centred on its point.
pub(crate) fn marker<DB: DrawingBackend>(
    shape: Marker,
    colour: RGBColor,
) -> DynElement<'static, DB, (i32, i32)> {
    match shape {
        Marker::Circle => Circle::new((0, 0), 4, colour.filled()).into_dyn(),
        Marker::Square => Rectangle::new([(-4, -4), (4, 4)], colour.filled()).into_dyn(),
        Marker::Triangle => TriangleMarker::new((0, 0), 5, colour.filled()).into_dyn(),
        Marker::Ring => Circle::new((0, 0), 4, colour.stroke_width(2)).into_dyn(),
        Marker::OpenSquare => Rectangle::new([(-4, -4), (4, 4)], colour.stroke_width(2)).into_dyn(),
    }
}

/// The legend under a panel: two columns, each entry the method's line (dashed for peers)
/// with its marker, and its name with the number of its runs that failed.
fn legend(
    area: &DrawingArea<SVGBackend<'_>, Shift>,
    scene: &SceneResult,
    methods: &[Method],
) -> DrawResult {
    let font = ("sans-serif", 14).into_font();
    let column = (PANEL.0 - 40) as i32 / 2;
    for (k, &method) in methods.iter().enumerate() {
        let (x, y) = (20 + column * (k as i32 / 4), 12 + 22 * (k as i32 % 4));
        let look = style(method);
        let line = look.colour.stroke_width(2);
        begin_group(area, "ga-legend", method)?;
        if look.dashed {
            area.draw(&PathElement::new(vec![(x, y), (x + 10, y)], line))?;
            area.draw(&PathElement::new(vec![(x + 16, y), (x + 26, y)], line))?;
        } else {
            area.draw(&PathElement::new(vec![(x, y), (x + 26, y)], line))?;
        }
        area.draw(&(EmptyElement::at((x + 13, y)) + marker(look.marker, look.colour)))?;
        let failed = scene
            .rows
            .iter()
            .filter(|r| r.method == method && r.failure.is_some())
            .count();
        let mut name = method.name().to_string();
        if failed > 0 {
            name.push_str(&format!(" ({failed} failed)"));
        }
        area.draw(&Text::new(name, (x + 34, y - 7), font.clone()))?;
        end_group(area)?;
    }
    Ok(())
}

/// A tick label: zero as `0` (not a rounding residue like -2.2e-16), plain decimals for
/// moderate sizes, scientific otherwise.
fn tick(y: f64, span: f64) -> String {
    if y.abs() <= 1e-9 * span {
        "0".to_string()
    } else if (1e-2..1e4).contains(&y.abs()) {
        format!("{y:.3}")
    } else {
        format!("{y:.2e}")
    }
}

/// A quick look at one `simulate` run as an SVG document: the body angular velocity
/// components against time above, the relative energy drift `(E - E0) / |E0|` below.
pub fn simulation_svg(rows: &[Row], title: &str) -> Result<String, Error> {
    let mut text = String::new();
    draw_simulation(rows, title, &mut text).map_err(|e| Error::invalid("plot", e.to_string()))?;
    Ok(text)
}

fn draw_simulation(rows: &[Row], title: &str, text: &mut String) -> DrawResult {
    let t_end = rows.last().map_or(1.0, |r| r.t).max(f64::MIN_POSITIVE);
    let e0 = rows.first().map_or(1.0, |r| r.energy);
    let scale = if e0 == 0.0 { 1.0 } else { e0.abs() };
    let drift: Vec<(f64, f64)> = rows
        .iter()
        .map(|r| (r.t, (r.energy - e0) / scale))
        .collect();
    let bounds = |values: &mut dyn Iterator<Item = f64>| {
        let (lo, hi) = values.fold((f64::MAX, f64::MIN), |(a, b), x| (a.min(x), b.max(x)));
        // Room above and below; a constant gets a band around it.
        let pad = if hi > lo {
            0.05 * (hi - lo)
        } else {
            lo.abs().max(1e-300) * 0.1 + 1e-300
        };
        (lo - pad)..(hi + pad)
    };
    let w_range = bounds(&mut rows.iter().flat_map(|r| r.omega));
    // Head room for the legend, so that it covers no curve.
    let w_range = w_range.start..(w_range.end + 0.3 * (w_range.end - w_range.start));
    let w_span = w_range.end - w_range.start;
    let d_range = bounds(&mut drift.iter().map(|d| d.1));

    let root = SVGBackend::with_string(text, (960, 720)).into_drawing_area();
    root.fill(&WHITE)?;
    let root = root.titled(title, ("sans-serif", 20))?;
    let (upper, lower) = root.split_vertically(400);
    let mut chart = ChartBuilder::on(&upper)
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(80)
        .build_cartesian_2d(0.0..t_end, w_range)?;
    chart
        .configure_mesh()
        .x_desc("time t (s)")
        .y_desc("body angular velocity (rad/s)")
        .y_label_formatter(&|y| tick(*y, w_span))
        .label_style(("sans-serif", 13))
        .axis_desc_style(("sans-serif", 15))
        .draw()?;
    let colours = [
        RGBColor(214, 39, 40),
        RGBColor(44, 160, 44),
        RGBColor(31, 119, 180),
    ];
    for (k, &colour) in colours.iter().enumerate() {
        chart
            .draw_series(LineSeries::new(
                rows.iter().map(|r| (r.t, r.omega[k])),
                colour.stroke_width(2),
            ))?
            .label(format!("w{}", k + 1))
            .legend(move |(x, y)| Rectangle::new([(x, y - 2), (x + 20, y + 2)], colour.filled()));
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font(("sans-serif", 14))
        .draw()?;

    let mut chart = ChartBuilder::on(&lower)
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(80)
        .build_cartesian_2d(0.0..t_end, d_range)?;
    chart
        .configure_mesh()
        .x_desc("time t (s)")
        .y_desc("relative energy drift (E - E0) / |E0|")
        .y_label_formatter(&|y| format!("{y:.1e}"))
        .label_style(("sans-serif", 13))
        .axis_desc_style(("sans-serif", 15))
        .draw()?;
    chart.draw_series(LineSeries::new(drift, BLACK.stroke_width(2)))?;
    root.present()?;
    Ok(())
}
