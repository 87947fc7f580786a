ga_macros::algebra! {
    pub mod sta {
        metric: [1, -1, -1, -1],
        scalar: f64,
        derive: [mint],
    }
}

fn main() {}
