ga_macros::algebra! {
    pub mod big {
        signature: (4, 3, 1),
        scalar: f64,
    }
}

fn main() {}
