//! The CSV output of the `simulate` command.
//!
//! One header line, then one line per sample. Every number has 17 significant digits,
//! enough to read back the very same `f64`, written in plain decimal (`0.10000000000000001`,
//! `-2.5000000000000000`, `0.0000000000000000`) when its decimal exponent is between -5
//! and 15, and in scientific notation (`1.2345678901234567e-7`) only outside that range.
//! Negative zero is written as zero.

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
        write_number(out, *x);
    }
    out.push('\n');
}

/// The number of significant digits of every number: the fewest that always give back
/// the same `f64` when read.
pub const SIGNIFICANT_DIGITS: usize = 17;

/// Append one number in the format of the module documentation.
pub fn write_number(out: &mut String, x: f64) {
    // `-0` would read as a negative value to a person; it is the same number as `0`.
    let x = if x == 0.0 { 0.0 } else { x };
    let scientific = format!("{x:.*e}", SIGNIFICANT_DIGITS - 1);
    let Some((mantissa, exponent)) = scientific.split_once('e') else {
        // NaN and infinities have no exponent; rows are checked finite before writing.
        out.push_str(&scientific);
        return;
    };
    let exponent: i32 = exponent.parse().unwrap_or(0);
    if !(-5..=15).contains(&exponent) {
        out.push_str(&scientific);
        return;
    }
    let (sign, mantissa) = match mantissa.strip_prefix('-') {
        Some(m) => ("-", m),
        None => ("", mantissa),
    };
    let digits: String = mantissa.chars().filter(char::is_ascii_digit).collect();
    out.push_str(sign);
    if exponent >= 0 {
        let split = exponent as usize + 1;
        out.push_str(&digits[..split]);
        out.push('.');
        out.push_str(&digits[split..]);
    } else {
        out.push_str("0.");
        for _ in 1..-exponent {
            out.push('0');
        }
        out.push_str(&digits);
    }
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

    fn number(x: f64) -> String {
        let mut out = String::new();
        write_number(&mut out, x);
        out
    }

    #[test]
    fn numbers_are_plain_decimal_with_17_significant_digits() {
        assert_eq!(number(10.0), "10.000000000000000");
        assert_eq!(number(0.0), "0.0000000000000000");
        assert_eq!(number(-0.0), "0.0000000000000000");
        assert_eq!(number(0.1), "0.10000000000000001");
        assert_eq!(number(-2.5), "-2.5000000000000000");
        assert_eq!(number(1.5e-5), "0.000015000000000000000");
        assert_eq!(number(1234567.0), "1234567.0000000000");
        assert_eq!(number(1e15), "1000000000000000.0");
        assert_eq!(number(1e16), "1.0000000000000000e16");
        assert_eq!(number(-(2f64.powi(-23))), "-1.1920928955078125e-7");
        assert_eq!(number(f64::MIN_POSITIVE), "2.2250738585072014e-308");
    }

    #[test]
    fn numbers_read_back_to_the_same_f64() {
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
            // Bit for bit, except that negative zero is written as zero.
            let b = if b == 0.0 { 0.0 } else { b };
            assert_eq!(a.to_bits(), b.to_bits());
        }
    }
}
