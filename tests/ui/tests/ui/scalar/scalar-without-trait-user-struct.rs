// A user's own number type without `ga_core::Scalar`: one error at its path.
#[derive(Clone, Copy, Debug, PartialEq, PartialOrd)]
pub struct Meters(pub f64);

ga_macros::algebra! {
    pub mod g2 {
        metric: [1, 1],
        scalar: crate::Meters,
    }
}

fn main() {}
