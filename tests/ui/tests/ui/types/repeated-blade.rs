ga_macros::algebra! {
    pub mod g3 {
        metric: [1, 1, 1],
        scalar: f64,
        types: [Vector, Plane = [e12, e13, e12]],
    }
}

fn main() {}
