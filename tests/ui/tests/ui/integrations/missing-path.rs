// A path that names no crate: one error, at the path.
ga_macros::algebra! {
    pub mod g3 {
        metric: [1, 1, 1],
        scalar: f64,
        derive: [bytemuck = not_a_dependency::bytemuck],
    }
}

fn main() {}
