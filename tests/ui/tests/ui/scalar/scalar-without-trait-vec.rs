// A generic type path: one error at it, naming the missing `ga_core::Scalar`.
ga_macros::algebra! {
    pub mod g3 {
        metric: [1, 1, 1],
        scalar: Vec<f64>,
    }
}

fn main() {}
