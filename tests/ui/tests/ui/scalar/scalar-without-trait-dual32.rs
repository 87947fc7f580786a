// num-dual's `Dual32` does not implement `ga_core::Scalar` (ga-core implements it for
// `Dual64` and `HyperDual64`): one error at its path.
ga_macros::algebra! {
    pub mod g3 {
        metric: [1, 1, 1],
        scalar: num_dual::Dual32,
    }
}

fn main() {}
