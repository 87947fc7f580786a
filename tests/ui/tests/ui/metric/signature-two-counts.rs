ga_macros::algebra! {
    pub mod sta {
        signature: (1, 3),
        scalar: f64,
    }
}

fn main() {}
