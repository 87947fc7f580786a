//! One work-precision diagram per four-dimensional scene, as SVG text: the largest
//! attitude error against the median run time, log-log, one panel of the seven methods of
//! the n-dimensional body. The 3D diagrams' rules: each method a line through its
//! settings in its own colour (Okabe and Ito's palette, [`super::super::style`]) and its
//! family's marker (circle for order two, square for order four, triangle for adaptive
//! and closed form), no dashed lines (no peers here), no point labels, the legend under
//! the chart.

use plotters::prelude::*;

use ga_rigid::error::Error;

use super::methods::{Family, NdMethod};
use super::run::NdSceneResult;
use crate::report::plot::marker;
use crate::report::style::{Marker, PALETTE};

/// Errors below this are drawn at it: a log axis has no zero.
const ERROR_FLOOR: f64 = 1e-17;

/// The diagram's size, and the height of the legend under the chart.
const SIZE: (u32, u32) = (760, 600);
const LEGEND_HEIGHT: u32 = 84;

/// The legend's columns.
const COLUMNS: usize = 4;

/// A method's colour: its place in [`NdMethod::ALL`], so no two share one.
#[must_use]
pub fn nd_colour(method: NdMethod) -> RGBColor {
    let place = NdMethod::ALL.iter().position(|&m| m == method).unwrap_or(0);
    PALETTE[place % PALETTE.len()]
}

/// A method's marker: its family's, as the 3D panels'.
#[must_use]
pub fn nd_marker(method: NdMethod) -> Marker {
    match method.family() {
        Family::SecondOrder => Marker::Circle,
        Family::FourthOrder => Marker::Square,
        Family::AdaptiveOrExact => Marker::Triangle,
    }
}

/// The file name of four-dimensional scene `index`'s diagram: `4d-NN-name.svg`, the
/// name without its leading "4D".
#[must_use]
pub fn nd_svg_name(index: usize, name: &str) -> String {
    let name = name.strip_prefix("4D ").unwrap_or(name);
    format!("4d-{}", crate::report::svg_name(index, name))
}

/// The scene's work-precision diagram as an SVG document.
pub fn nd_svg(scene: &NdSceneResult) -> Result<String, Error> {
    let mut text = String::new();
    draw(scene, &mut text).map_err(|e| Error::invalid("plot", e.to_string()))?;
    Ok(text)
}

/// The methods of a scene, in legend order.
fn methods(scene: &NdSceneResult) -> Vec<NdMethod> {
    NdMethod::ALL
        .into_iter()
        .filter(|&m| scene.rows.iter().any(|r| r.method == m))
        .collect()
}

/// A method's drawn points: (median run time in µs, largest attitude error).
fn points(scene: &NdSceneResult, method: NdMethod) -> Vec<(f64, f64)> {
    scene
        .rows
        .iter()
        .filter(|r| r.method == method)
        .filter_map(|r| Some((r.time_us()?, r.errors?.attitude_max.max(ERROR_FLOOR))))
        .filter(|(t, e)| t.is_finite() && e.is_finite() && *t > 0.0)
        .collect()
}

type DrawResult = Result<(), Box<dyn std::error::Error>>;

fn draw(scene: &NdSceneResult, text: &mut String) -> DrawResult {
    let all: Vec<(f64, f64)> = methods(scene)
        .into_iter()
        .flat_map(|m| points(scene, m))
        .collect();
    let (mut t_lo, mut t_hi, mut e_lo, mut e_hi) = (1.0, 10.0, 1e-10, 1.0);
    if !all.is_empty() {
        let fold = |f: fn(&(f64, f64)) -> f64, init: f64, pick: fn(f64, f64) -> f64| {
            all.iter().map(f).fold(init, pick)
        };
        t_lo = fold(|p| p.0, f64::MAX, f64::min);
        t_hi = fold(|p| p.0, f64::MIN, f64::max);
        e_lo = fold(|p| p.1, f64::MAX, f64::min);
        e_hi = fold(|p| p.1, f64::MIN, f64::max);
    }
    // At least two decades each way, so that a log axis gets whole-decade ticks.
    let widen = |lo: f64, hi: f64| {
        let mid = (lo * hi).sqrt();
        let half = (hi / lo).sqrt().max(10.0);
        (mid / half)..(mid * half)
    };
    let root = SVGBackend::with_string(text, SIZE).into_drawing_area();
    root.fill(&WHITE)?;
    let root = root.titled(&scene.name, ("sans-serif", 20))?;
    let (chart_area, legend_area) = root.split_vertically(SIZE.1 - 30 - LEGEND_HEIGHT);
    let mut chart = ChartBuilder::on(&chart_area)
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(64)
        .build_cartesian_2d(
            widen(t_lo / 2.0, t_hi * 2.0).log_scale(),
            widen(e_lo / 5.0, e_hi * 5.0).log_scale(),
        )?;
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
    let methods = methods(scene);
    for &method in &methods {
        let colour = nd_colour(method);
        let pts = points(scene, method);
        chart.draw_series(LineSeries::new(pts.iter().copied(), colour.stroke_width(2)))?;
        chart.draw_series(
            pts.iter()
                .map(|&p| EmptyElement::at(p) + marker(nd_marker(method), colour)),
        )?;
    }
    let font = ("sans-serif", 14).into_font();
    let column = (SIZE.0 as i32 - 40) / COLUMNS as i32;
    for (k, &method) in methods.iter().enumerate() {
        let (x, y) = (
            20 + column * (k % COLUMNS) as i32,
            14 + 26 * (k / COLUMNS) as i32,
        );
        let colour = nd_colour(method);
        legend_area.draw(&PathElement::new(
            vec![(x, y), (x + 26, y)],
            colour.stroke_width(2),
        ))?;
        legend_area.draw(&(EmptyElement::at((x + 13, y)) + marker(nd_marker(method), colour)))?;
        let failed = scene
            .rows
            .iter()
            .filter(|r| r.method == method && r.failure.is_some())
            .count();
        let mut name = method.name().to_string();
        if failed > 0 {
            name.push_str(&format!(" ({failed} failed)"));
        }
        legend_area.draw(&Text::new(name, (x + 34, y - 7), font.clone()))?;
    }
    root.present()?;
    Ok(())
}
