//! The algebra as plain data: blades as bitmasks, the metric's sign rule, involutions.
//! Nothing here knows about syn or quote, so all of it is unit-tested directly.

mod blade;
mod metric;
#[cfg(test)]
mod sign_rule_tests;

pub use blade::{blade_name, canonical_blades, grade, parse_blade, Blade};
pub use metric::{Involution, Metric, ProductKind};
