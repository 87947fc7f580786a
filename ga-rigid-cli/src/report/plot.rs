//! One work-precision diagram per scene, as SVG text: the largest attitude error over the
//! run against the median run time, log-log, one line per method with its points
//! labelled by step or tolerance, the legend in its own panel beside the plot.

use plotters::prelude::*;

use ga_rigid::csv::Row;
use ga_rigid::error::Error;
use ga_rigid::registry::Method;

use super::SceneResult;

/// Errors below this are drawn at it: a log axis has no zero.
const ERROR_FLOOR: f64 = 1e-17;

/// Each method's colour, the same in every diagram (by the method's place in
/// [`Method::ALL`]; a method added later takes the next colour of the palette).
#[must_use]
pub fn method_colour(method: Method) -> RGBColor {
    const PALETTE: [RGBColor; 21] = [
        RGBColor(140, 86, 75),   // brown
        RGBColor(0, 0, 0),       // black
        RGBColor(214, 39, 40),   // red
        RGBColor(255, 127, 14),  // orange
        RGBColor(44, 160, 44),   // green
        RGBColor(31, 119, 180),  // blue
        RGBColor(148, 103, 189), // purple
        RGBColor(227, 119, 194), // pink
        RGBColor(23, 190, 207),  // cyan
        RGBColor(188, 189, 34),  // olive
        // The high-order steppers of issue 11: darker tones, apart from the ten above.
        RGBColor(0, 90, 50),   // dark green
        RGBColor(8, 48, 107),  // navy
        RGBColor(103, 0, 13),  // maroon
        RGBColor(127, 39, 4),  // rust
        RGBColor(63, 0, 125),  // indigo
        RGBColor(0, 109, 119), // teal
        // The peers (drawn dashed): greys and muted tones.
        RGBColor(110, 110, 110), // grey
        RGBColor(184, 134, 11),  // dark gold
        RGBColor(170, 0, 170),   // magenta
        RGBColor(90, 160, 0),    // lime
        RGBColor(80, 80, 140),   // slate
    ];
    let index = Method::ALL.iter().position(|&m| m == method).unwrap_or(0);
    PALETTE[index % PALETTE.len()]
}

/// The scene's work-precision diagram as an SVG document.
pub fn svg(scene: &SceneResult) -> Result<String, Error> {
    let mut text = String::new();
    draw(scene, &mut text).map_err(|e| Error::invalid("plot", e.to_string()))?;
    Ok(text)
}

type DrawResult = Result<(), Box<dyn std::error::Error>>;

fn draw(scene: &SceneResult, text: &mut String) -> DrawResult {
    let mut methods: Vec<Method> = scene.rows.iter().map(|r| r.method).collect();
    methods.dedup();
    let points = |method: Method| -> Vec<(f64, f64, String)> {
        scene
            .rows
            .iter()
            .filter(|r| r.method == method)
            .filter_map(|r| {
                let e = r.errors?.attitude_max.max(ERROR_FLOOR);
                Some((r.time_us()?, e, r.label()))
            })
            .filter(|(t, e, _)| t.is_finite() && e.is_finite() && *t > 0.0)
            .collect()
    };
    let all: Vec<(f64, f64, String)> = methods.iter().flat_map(|&m| points(m)).collect();
    let (mut t_lo, mut t_hi, mut e_lo, mut e_hi) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for (t, e, _) in &all {
        t_lo = t_lo.min(*t);
        t_hi = t_hi.max(*t);
        e_lo = e_lo.min(*e);
        e_hi = e_hi.max(*e);
    }
    if all.is_empty() {
        (t_lo, t_hi, e_lo, e_hi) = (1.0, 10.0, 1e-10, 1.0);
    }
    // Room around the points, and for the labels to the right of the last ones; at
    // least two decades each way, so that a log axis gets a few whole-decade ticks
    // rather than a crowd of labels inside one decade.
    let widen = |lo: f64, hi: f64| {
        let mid = (lo * hi).sqrt();
        let half = (hi / lo).sqrt().max(10.0);
        (mid / half)..(mid * half)
    };
    let x_range = widen(t_lo / 2.0, t_hi * 6.0);
    let y_range = widen(e_lo / 5.0, e_hi * 5.0);

    let root = SVGBackend::with_string(text, (1000, 640)).into_drawing_area();
    root.fill(&WHITE)?;
    let (plot_area, legend_area) = root.split_horizontally(760);
    let mut chart = ChartBuilder::on(&plot_area)
        .caption(&scene.name, ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(48)
        .y_label_area_size(80)
        .build_cartesian_2d(x_range.log_scale(), y_range.log_scale())?;
    chart
        .configure_mesh()
        .x_desc("run time, median of repeated runs (µs)")
        .y_desc("largest attitude error over the run (rad)")
        .x_label_formatter(&|x| format!("{x:.0e}"))
        .y_label_formatter(&|y| format!("{y:.0e}"))
        .label_style(("sans-serif", 13))
        .axis_desc_style(("sans-serif", 15))
        .light_line_style(RGBColor(235, 235, 235))
        .draw()?;
    for (i, &method) in methods.iter().enumerate() {
        let colour = method_colour(method);
        let pts = points(method);
        // Labels above the points for every other method, below for the rest: lines that
        // run close together keep their labels apart.
        let label_dy = if i % 2 == 0 { -13 } else { 5 };
        // Peers dashed, ours solid: which line is whose shows without the legend.
        if method.info().peer.is_some() {
            chart.draw_series(DashedLineSeries::new(
                pts.iter().map(|(t, e, _)| (*t, *e)),
                6,
                4,
                colour.stroke_width(2),
            ))?;
        } else {
            chart.draw_series(LineSeries::new(
                pts.iter().map(|(t, e, _)| (*t, *e)),
                colour.stroke_width(2),
            ))?;
        }
        // Only a line's two ends are labelled (its coarsest and finest setting): a label on
        // every point crowded the plot; the CSV has every setting.
        let last = pts.len().saturating_sub(1);
        chart.draw_series(pts.iter().enumerate().map(|(k, (t, e, label))| {
            let text = if k == 0 || k == last {
                label.clone()
            } else {
                String::new()
            };
            EmptyElement::at((*t, *e))
                + Circle::new((0, 0), 4, colour.filled())
                + Text::new(
                    text,
                    (6, label_dy),
                    ("sans-serif", 11).into_font().color(&colour),
                )
        }))?;
    }

    legend_area.fill(&WHITE)?;
    let font = ("sans-serif", 15).into_font();
    legend_area.draw(&Text::new("method", (10, 40), font.clone()))?;
    for (i, &method) in methods.iter().enumerate() {
        let y = 70 + 24 * i as i32;
        let colour = method_colour(method);
        legend_area.draw(&Rectangle::new([(10, y), (34, y + 4)], colour.filled()))?;
        let failed = scene
            .rows
            .iter()
            .filter(|r| r.method == method && r.failure.is_some())
            .count();
        let peer = if method.info().peer.is_some() {
            " (peer)"
        } else {
            ""
        };
        let name = if failed > 0 {
            format!("{}{peer} ({failed} failed)", method.name())
        } else {
            format!("{}{peer}", method.name())
        };
        legend_area.draw(&Text::new(name, (42, y - 6), font.clone()))?;
    }
    root.present()?;
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
