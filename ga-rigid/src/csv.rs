//! The CSV output of the `simulate` command.
//!
//! One header line, then one line per sample. Numbers are written with `{:e}`, Rust's
//! shortest representation that parses back to the same `f64` (round-trip exact), in
//! scientific notation so that tiny and huge values stay short.

use std::fmt::Write as _;

use ga_core::f64::g3::*;

/// The header line, without the line break.
pub const HEADER: &str = "t,r_s,r_e12,r_e13,r_e23,w1,w2,w3,energy,l1,l2,l3";

/// One sample of a simulation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Row {
    /// The time.
    pub t: f64,
    /// The attitude rotor (body to space), components `[s, e12, e13, e23]`.
    pub rotor: Rotor,
    /// The body angular velocity `[w1, w2, w3]` (`Omega_B = I w`).
    pub omega: [f64; 3],
    /// The total energy (kinetic, plus potential when there is a torque).
    pub energy: f64,
    /// The angular momentum in the space frame as an axial vector `[l1, l2, l3]`,
    /// conserved for a free body.
    pub momentum: [f64; 3],
}

impl Row {
    /// The row's twelve numbers in header order.
    #[must_use]
    pub fn values(&self) -> [f64; 12] {
        let r = self.rotor;
        let [w1, w2, w3] = self.omega;
        let [l1, l2, l3] = self.momentum;
        [
            self.t,
            r.s,
            r.e12,
            r.e13,
            r.e23,
            w1,
            w2,
            w3,
            self.energy,
            l1,
            l2,
            l3,
        ]
    }
}

/// Append one row, comma-separated, with a final line break.
pub fn write_row(out: &mut String, row: &Row) {
    for (k, x) in row.values().iter().enumerate() {
        if k > 0 {
            out.push(',');
        }
        // Writing to a String cannot fail.
        let _ = write!(out, "{x:e}");
    }
    out.push('\n');
}

/// The whole CSV document: the header and every row, each line ending in `\n`.
#[must_use]
pub fn to_csv(rows: &[Row]) -> String {
    let mut out = String::with_capacity(32 + rows.len() * 200);
    out.push_str(HEADER);
    out.push('\n');
    for row in rows {
        write_row(&mut out, row);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_round_trip_exactly() {
        let row = Row {
            t: 0.1,
            rotor: Rotor::new(std::f64::consts::FRAC_1_SQRT_2, -1e-300, 0.0, -0.7),
            omega: [1.0 / 3.0, -2.5e17, 0.0],
            energy: std::f64::consts::PI,
            momentum: [f64::MIN_POSITIVE, f64::MAX, -0.0],
        };
        let text = to_csv(&[row]);
        let mut lines = text.lines();
        assert_eq!(lines.next(), Some(HEADER));
        let parsed: Vec<f64> = lines
            .next()
            .unwrap()
            .split(',')
            .map(|x| x.parse().unwrap())
            .collect();
        assert_eq!(parsed.len(), 12);
        for (a, b) in parsed.iter().zip(row.values()) {
            assert_eq!(a.to_bits(), b.to_bits());
        }
    }
}
