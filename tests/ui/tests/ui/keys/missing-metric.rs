ga_macros::algebra! {
    pub mod g3 {
        scalar: f64,
    }
}

fn main() {}
