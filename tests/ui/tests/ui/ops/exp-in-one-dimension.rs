ga_macros::algebra! {
    pub mod g1 {
        metric: [1],
        scalar: f64,
        ops: [geometric, exp],
    }
}

fn main() {}
