ga_macros::algebra! {
    pub mod g0 {
        metric: [],
        scalar: f64,
    }
}

fn main() {}
