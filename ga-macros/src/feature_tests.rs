//! A spec that needs a back end this build of ga-macros lacks (cargo features `wgsl` and
//! `generic`) gets one error, at the token that asks for it, naming the feature and how to
//! turn it on. trybuild cannot show this: its cases build with the `ga-tests` crate's
//! dependencies, whose ga-core turns both features on, and cargo unifies features across a
//! build. So the check runs here, on proc_macro2, with the back ends switched off by hand;
//! under `--no-default-features` the last tests also run this build's own refusal.

use crate::spec::{validate_for, BackEnds, RawAlgebra};

const NEITHER: BackEnds = BackEnds {
    wgsl: false,
    generic_scalar: false,
};
const BOTH: BackEnds = BackEnds {
    wgsl: true,
    generic_scalar: true,
};

/// Each error's message and the column where its span starts.
fn errors(back_ends: BackEnds, input: &str) -> Vec<(String, usize)> {
    let raw: RawAlgebra = syn::parse_str(input).expect("input parses");
    match validate_for(back_ends, raw.attrs, raw.vis, raw.name, raw.entries) {
        Ok(_) => Vec::new(),
        Err(error) => error
            .into_iter()
            .map(|e| (e.to_string(), e.span().start().column))
            .collect(),
    }
}

#[test]
fn shaders_without_the_wgsl_feature_is_one_error_at_wgsl_naming_the_feature() {
    let input = "pub mod g3 { metric: [1, 1, 1], scalar: f32, shaders: [wgsl] }";
    let errors = errors(NEITHER, input);
    assert_eq!(errors.len(), 1, "{errors:?}");
    let (message, column) = &errors[0];
    assert_eq!(*column, input.find("wgsl").unwrap());
    assert!(message.contains("ga-macros' `wgsl` feature"), "{message}");
    assert!(
        message.contains("enable ga-core's `wgsl` feature"),
        "{message}"
    );
}

#[test]
fn a_generic_scalar_without_the_generic_feature_is_one_error_at_the_type() {
    let input = "pub mod g3 { metric: [1, 1, 1], scalar: ::num_dual::Dual64 }";
    let errors = errors(NEITHER, input);
    assert_eq!(errors.len(), 1, "{errors:?}");
    let (message, column) = &errors[0];
    assert_eq!(*column, input.find("::num_dual").unwrap());
    assert!(
        message.contains("ga-macros' `generic` feature"),
        "{message}"
    );
    assert!(
        message.contains("enable ga-core's `dual` feature"),
        "{message}"
    );
}

#[test]
fn float_scalars_and_an_empty_shaders_list_need_no_optional_back_end() {
    for input in [
        "pub mod g3 { metric: [1, 1, 1], scalar: f64, shaders: [] }",
        "pub mod g3 { metric: [1, 1, 1], scalar: f32 }",
    ] {
        assert_eq!(errors(NEITHER, input), Vec::new(), "{input}");
    }
}

#[test]
fn with_the_back_ends_on_shaders_and_generic_scalars_validate() {
    for input in [
        "pub mod g3 { metric: [1, 1, 1], scalar: f32, shaders: [wgsl] }",
        "pub mod g3 { metric: [1, 1, 1], scalar: ::num_dual::Dual64 }",
    ] {
        assert_eq!(errors(BOTH, input), Vec::new(), "{input}");
    }
}

#[cfg(not(feature = "wgsl"))]
#[test]
fn this_build_refuses_shaders_with_the_feature_named() {
    let input = "pub mod g3 { metric: [1, 1, 1], scalar: f32, shaders: [wgsl] }";
    let raw: RawAlgebra = syn::parse_str(input).expect("input parses");
    let error = crate::expand::algebra(raw).expect_err("no WGSL back end in this build");
    assert!(error.to_string().contains("`wgsl` feature"), "{error}");
}

#[cfg(not(feature = "generic"))]
#[test]
fn this_build_refuses_a_generic_scalar_with_the_feature_named() {
    let input = "pub mod g3 { metric: [1, 1, 1], scalar: ::num_dual::Dual64 }";
    let raw: RawAlgebra = syn::parse_str(input).expect("input parses");
    let error = crate::expand::algebra(raw).expect_err("no generic back end in this build");
    assert!(error.to_string().contains("`generic` feature"), "{error}");
}
