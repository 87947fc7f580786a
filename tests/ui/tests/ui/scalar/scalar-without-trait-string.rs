// A scalar type that does not implement `ga_core::Scalar` is one error at its token (it
// was 1106 errors inside the generated code).
ga_macros::algebra! {
    pub mod g3 {
        metric: [1, 1, 1],
        scalar: String,
    }
}

fn main() {}
