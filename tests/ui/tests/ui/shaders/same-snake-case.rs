// `PlaneA` and `Plane_a` are both `plane_a` in WGSL function names.
#[allow(non_camel_case_types)]
mod inner {
    ga_macros::algebra! {
        pub mod g3 {
            metric: [1, 1, 1],
            types: [PlaneA = [e12], Plane_a = [e13]],
            shaders: [wgsl],
        }
    }
}

fn main() {}
