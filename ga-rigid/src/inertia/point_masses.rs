//! Inertia of a set of point masses.

use ga_core::f64::g3::*;

use super::inertia::Inertia;
use crate::error::{finite3, positive, Error};

impl Inertia {
    /// The inertia of point masses `(m, [x, y, z])` about their centre of mass:
    /// `sum m d ^ (d . B)` with `d = x - com`, in matrix form `sum m (|d|^2 1 - d d^T)`.
    ///
    /// Errors name `points` (an empty list; points on a line, whose inertia is singular)
    /// or `points[k]` (a non-positive or non-finite mass, a non-finite position).
    pub fn from_point_masses(points: &[(f64, [f64; 3])]) -> Result<Self, Error> {
        if points.is_empty() {
            return Err(Error::degenerate(
                "points",
                "the list of point masses is empty",
            ));
        }
        let mut mass = 0.0;
        let mut moment = [0.0; 3];
        for (k, &(m, x)) in points.iter().enumerate() {
            let field = format!("points[{k}]");
            positive(&field, "mass", m)?;
            finite3(&field, "position", x)?;
            mass += m;
            for i in 0..3 {
                moment[i] += m * x[i];
            }
        }
        let com = moment.map(|s| s / mass);
        // Shift to the centre of mass before summing, rather than using the parallel-axis
        // theorem afterwards, so that a cloud far from the origin keeps its precision.
        let mut j = [[0.0; 3]; 3];
        for &(m, x) in points {
            let d = [x[0] - com[0], x[1] - com[1], x[2] - com[2]];
            let d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
            for (a, row) in j.iter_mut().enumerate() {
                for (b, entry) in row.iter_mut().enumerate() {
                    let delta = if a == b { d2 } else { 0.0 };
                    *entry += m * (delta - d[a] * d[b]);
                }
            }
        }
        // Finite inputs can still overflow here (a point at 1e308 squared): say so, rather
        // than let the NaN of inf - inf reach the matrix check as "entries must be finite".
        if !(mass.is_finite() && com.iter().chain(j.iter().flatten()).all(|x| x.is_finite())) {
            return Err(Error::invalid(
                "points",
                "the masses times the squared distances overflow f64 (above 1e308): \
                 scale the units down",
            ));
        }
        let centre = Vector::new(com[0], com[1], com[2]);
        Inertia::from_rows(&j, Some(mass), centre).map_err(|e| match e {
            Error::Degenerate { .. } => Error::degenerate(
                "points",
                "the point masses lie on a line or at one point, so a principal moment is zero",
            ),
            other => other.at("points"),
        })
    }
}
