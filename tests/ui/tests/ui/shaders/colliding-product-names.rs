// (Even, VectorX) and (EvenVector, X) both give `geometric_even_vector_x` in WGSL.
ga_macros::algebra! {
    pub mod g3 {
        metric: [1, 1, 1],
        types: [Even, VectorX = [e1], EvenVector = [e1, e12], X = [e2]],
        shaders: [wgsl],
    }
}

fn main() {}
