//! Which closed form `Bivector::exp` and `Even::log` take, decided once per plan so that
//! the Rust and the WGSL back ends split the cases alike (docs/derivations/exp-log.md).

use super::{Plan, TypeId};
use crate::spec::Op;

/// The form of `exp` and `log` for a dimension and metric.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ExpLogForm {
    /// `n <= 3`: `B B` is a scalar.
    Plane,
    /// `n = 4` with `I I = +1`: two commuting channels `(B +- B I) / 2`, each a plane.
    Channels,
    /// `n = 4` with `I I` of -1 or 0, and `n = 5`: `B B = s + Q` with `Q = B ^ B`, on
    /// the commutative algebra `{1, Q}`.
    Quartic,
    /// `n >= 6`: no closed form; `exp` by scaling and squaring of the Taylor series, and
    /// no `log`.
    Series,
}

impl Plan {
    /// The form of `Bivector::exp`, where the module has it.
    pub fn exp_form(&self) -> Option<ExpLogForm> {
        let n = self.metric.dimension();
        let emitted = n >= 2 && self.has(Op::Exp) && self.emitted.contains(&TypeId::grade(2));
        emitted.then(|| self.exp_log_form())
    }

    /// The form of `Even::log`, where the module has it (dimensions 2 to 4).
    pub fn log_form(&self) -> Option<ExpLogForm> {
        let n = self.metric.dimension();
        let emitted =
            (2..=4).contains(&n) && self.has(Op::Log) && self.emitted.contains(&TypeId::even(n));
        emitted.then(|| self.exp_log_form())
    }

    fn exp_log_form(&self) -> ExpLogForm {
        match self.metric.dimension() {
            0..=3 => ExpLogForm::Plane,
            4 if self.metric.pseudoscalar_square() > 0 => ExpLogForm::Channels,
            4 | 5 => ExpLogForm::Quartic,
            _ => ExpLogForm::Series,
        }
    }
}
