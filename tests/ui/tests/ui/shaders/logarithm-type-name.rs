ga_macros::algebra! {
    pub mod g3 {
        metric: [1, 1, 1],
        types: [Even, Logarithm = [e12]],
        shaders: [wgsl],
    }
}

fn main() {}
