ga_macros::algebra! {
    pub mod g3 {
        metric: [1, 1, 1],
        types: [Trivector, Pseudoscalar],
    }
}

fn main() {}
