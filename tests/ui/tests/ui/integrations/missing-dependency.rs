// The test crate does not depend on mint: one error, at `mint` in the list.
ga_macros::algebra! {
    pub mod g3 {
        metric: [1, 1, 1],
        scalar: f64,
        derive: [mint],
    }
}

fn main() {}
