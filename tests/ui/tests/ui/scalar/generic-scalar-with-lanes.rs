// A scalar type other than f32/f64 is the scalar code path only: no batch lanes.
ga_macros::algebra! {
    pub mod g3 {
        metric: [1, 1, 1],
        scalar: num_dual::Dual64,
        lanes: [4],
    }
}

fn main() {}
