// `norm_squared_` of X and `norm_` of SquaredX are both `norm_squared_x` in WGSL.
ga_macros::algebra! {
    pub mod g2 {
        metric: [1, 1],
        types: [X = [e1], SquaredX = [e2]],
        ops: [norm],
        shaders: [wgsl],
    }
}

fn main() {}
