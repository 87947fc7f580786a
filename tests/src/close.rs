//! Approximate comparison of multivectors, with a report that shows both values
//! and their difference component by component.

use crate::blade::blade_name;
use std::fmt::Write as _;

/// Something that can be compared component by component: a scalar, or a
/// dense reference multivector indexed by blade bitmask.
pub trait Components {
    /// The components, in order.
    fn components(&self) -> Vec<f64>;
}

impl Components for f64 {
    fn components(&self) -> Vec<f64> {
        vec![*self]
    }
}

impl Components for [f64] {
    fn components(&self) -> Vec<f64> {
        self.to_vec()
    }
}

impl Components for Vec<f64> {
    fn components(&self) -> Vec<f64> {
        self.clone()
    }
}

impl<const N: usize> Components for [f64; N] {
    fn components(&self) -> Vec<f64> {
        self.to_vec()
    }
}

impl<T: Components + ?Sized> Components for &T {
    fn components(&self) -> Vec<f64> {
        (**self).components()
    }
}

/// What a difference is measured against: one magnitude for every component, or
/// one per component.
pub trait Scale {
    /// The magnitude of each of `len` components.
    fn per_component(&self, len: usize) -> Vec<f64>;
}

impl Scale for f64 {
    fn per_component(&self, len: usize) -> Vec<f64> {
        vec![*self; len]
    }
}

impl Scale for [f64] {
    fn per_component(&self, len: usize) -> Vec<f64> {
        assert_eq!(self.len(), len, "one scale per component");
        self.to_vec()
    }
}

impl Scale for Vec<f64> {
    fn per_component(&self, len: usize) -> Vec<f64> {
        self.as_slice().per_component(len)
    }
}

impl<T: Scale + ?Sized> Scale for &T {
    fn per_component(&self, len: usize) -> Vec<f64> {
        (**self).per_component(len)
    }
}

/// The default scale: the largest component of either value, so that the
/// comparison is relative to the magnitude of the multivector.
#[must_use]
pub fn magnitude(actual: &[f64], expected: &[f64]) -> f64 {
    actual
        .iter()
        .chain(expected)
        .fold(0.0, |acc: f64, x| acc.max(x.abs()))
}

/// `Ok` when every `|actual_k - expected_k| <= rel * scale_k` (and no component
/// is NaN); otherwise a table of both values, their difference and the allowed
/// difference, failing rows marked.
///
/// Components are labelled by blade name when there are `2^n` of them (the
/// dense reference layout), by index otherwise.
///
/// # Errors
/// The report, when a component is out of tolerance.
pub fn compare(actual: &[f64], expected: &[f64], scale: &[f64], rel: f64) -> Result<(), String> {
    if actual.len() != expected.len() {
        return Err(format!(
            "lengths differ: actual has {} components, expected {}\n  actual:   {actual:?}\n  expected: {expected:?}",
            actual.len(),
            expected.len()
        ));
    }
    let allowed: Vec<f64> = scale.iter().map(|s| rel * s).collect();
    let failing: Vec<bool> = actual
        .iter()
        .zip(expected)
        .zip(&allowed)
        .map(|((a, e), tol)| {
            let difference = (a - e).abs();
            difference.is_nan() || difference > *tol
        })
        .collect();
    if !failing.contains(&true) {
        return Ok(());
    }
    let dense = actual.len().is_power_of_two() && actual.len() > 1;
    let mut report = format!("values differ by more than {rel:e} relative to their magnitude\n");
    let _ = writeln!(
        report,
        "  {:>8} {:>24} {:>24} {:>12} {:>10}",
        "", "actual", "expected", "difference", "allowed"
    );
    for (k, ((a, e), tol)) in actual.iter().zip(expected).zip(&allowed).enumerate() {
        if *a == 0.0 && *e == 0.0 {
            continue;
        }
        let label = if dense { blade_name(k) } else { k.to_string() };
        let mark = if failing[k] { "  <--" } else { "" };
        let _ = writeln!(
            report,
            "  {label:>8} {a:>24.16e} {e:>24.16e} {:>12.3e} {tol:>10.3e}{mark}",
            a - e
        );
    }
    Err(report)
}

/// Asserts that two values (scalars, arrays or dense reference multivectors) are
/// equal to a relative tolerance, printing both and their difference if not.
///
/// - `assert_close!(actual, expected)`: relative `1e-12` of the larger magnitude;
/// - `assert_close!(actual, expected, rel = r)`: relative `r` of it;
/// - `assert_close!(actual, expected, scale = s, rel = r)`: `|diff_k| <= r s_k`,
///   where `s` is one magnitude or one per component.
///
/// A format string and arguments may follow, to say which case failed.
#[macro_export]
macro_rules! assert_close {
    ($actual:expr, $expected:expr $(,)?) => {
        $crate::assert_close!($actual, $expected, rel = 1e-12)
    };
    ($actual:expr, $expected:expr, rel = $rel:expr $(, $fmt:literal $(, $arg:expr)*)? $(,)?) => {{
        let actual = $crate::close::Components::components(&$actual);
        let expected = $crate::close::Components::components(&$expected);
        let scale = $crate::close::magnitude(&actual, &expected);
        $crate::assert_close!(actual, expected, scale = scale, rel = $rel $(, $fmt $(, $arg)*)?)
    }};
    ($actual:expr, $expected:expr, scale = $scale:expr, rel = $rel:expr $(, $fmt:literal $(, $arg:expr)*)? $(,)?) => {{
        let actual = $crate::close::Components::components(&$actual);
        let expected = $crate::close::Components::components(&$expected);
        let scale = $crate::close::Scale::per_component(&$scale, actual.len());
        if let Err(report) = $crate::close::compare(&actual, &expected, &scale, $rel) {
            let context: String = ::std::string::String::new() $(+ &format!($fmt $(, $arg)*))?;
            panic!(
                "assert_close!({}, {}) failed {}\n{}",
                stringify!($actual),
                stringify!($expected),
                context,
                report
            );
        }
    }};
}

/// [`assert_close!`] for the body of a `proptest!` test: returns a test-case
/// failure (which proptest then shrinks) instead of panicking.
#[macro_export]
macro_rules! prop_assert_close {
    ($actual:expr, $expected:expr $(,)?) => {
        $crate::prop_assert_close!($actual, $expected, rel = 1e-12)
    };
    ($actual:expr, $expected:expr, rel = $rel:expr $(, $fmt:literal $(, $arg:expr)*)? $(,)?) => {{
        let actual = $crate::close::Components::components(&$actual);
        let expected = $crate::close::Components::components(&$expected);
        let scale = $crate::close::magnitude(&actual, &expected);
        $crate::prop_assert_close!(actual, expected, scale = scale, rel = $rel $(, $fmt $(, $arg)*)?)
    }};
    ($actual:expr, $expected:expr, scale = $scale:expr, rel = $rel:expr $(, $fmt:literal $(, $arg:expr)*)? $(,)?) => {{
        let actual = $crate::close::Components::components(&$actual);
        let expected = $crate::close::Components::components(&$expected);
        let scale = $crate::close::Scale::per_component(&$scale, actual.len());
        if let Err(report) = $crate::close::compare(&actual, &expected, &scale, $rel) {
            let context: String = ::std::string::String::new() $(+ &format!($fmt $(, $arg)*))?;
            return Err(::proptest::test_runner::TestCaseError::fail(format!(
                "prop_assert_close!({}, {}) failed {}\n{}",
                stringify!($actual),
                stringify!($expected),
                context,
                report
            )));
        }
    }};
}
