//! `types:` and `ops:` lists cut what is emitted: only the listed types, the products
//! between them, the listed operations, and what those need.

fn items(input: &str) -> (Vec<String>, usize) {
    let raw: crate::spec::RawAlgebra = syn::parse_str(input).expect("input parses");
    let tokens = crate::expand::algebra(raw).expect("input is valid");
    let file: syn::File = syn::parse2(tokens).expect("expansion parses");
    let syn::Item::Mod(module) = &file.items[0] else {
        panic!("expected one module")
    };
    let content = &module.content.as_ref().expect("inline module").1;
    let structs = content
        .iter()
        .filter_map(|item| match item {
            syn::Item::Struct(s) => Some(s.ident.to_string()),
            _ => None,
        })
        .collect();
    let size = quote::quote!(#file).to_string().len();
    (structs, size)
}

#[test]
fn restricted_g6_emits_only_rotors_vectors_and_what_they_need() {
    let (full_structs, full_size) = items("mod g6 { metric: [1, 1, 1, 1, 1, 1], scalar: f64 }");
    let (structs, size) = items(
        "mod g6 { metric: [1, 1, 1, 1, 1, 1], scalar: f64, \
         types: [Rotor, Vector], ops: [geometric, sandwich] }",
    );
    assert_eq!(full_structs.len(), 10, "{full_structs:?}");
    // Vector * Vector is Even, Even * Vector is Odd: Odd is needed, nothing else.
    assert_eq!(structs, ["Zero", "Vector", "Even", "Odd"]);
    assert!(
        size * 5 < full_size,
        "restricted {size} bytes vs full {full_size} bytes"
    );
}

#[test]
fn user_types_hold_exactly_their_blades_in_canonical_order() {
    let (structs, _) =
        items("mod g3 { metric: [1, 1, 1], scalar: f32, types: [Plane = [e13, e12]], ops: [add] }");
    // `Plane + f64` holds s, e12 and e13: the smallest type for it is Even.
    assert_eq!(structs, ["Zero", "Even", "Plane"]);
    let raw: crate::spec::RawAlgebra =
        syn::parse_str("mod g3 { metric: [1, 1, 1], types: [Plane = [e13, e12]], ops: [add] }")
            .unwrap();
    let text = crate::expand::algebra(raw).unwrap().to_string();
    assert!(text.contains("pub struct Plane { # [doc = \"The `e12` component.\"] pub e12 : f64 , # [doc = \"The `e13` component.\"] pub e13 : f64 , }"), "{text}");
}

/// klein's motor toolkit appears only in projective algebras, and each part only where
/// its meaning holds: the Study normalisation and division by motors where `x ~x` has a
/// pseudoscalar part (3D PGA), Euler angles in 3D PGA, matrices in every PGA.
#[test]
fn the_motor_toolkit_is_emitted_only_for_projective_algebras() {
    let text = |input: &str| {
        let raw: crate::spec::RawAlgebra = syn::parse_str(input).unwrap();
        crate::expand::algebra(raw).unwrap().to_string()
    };
    let pga3 = text("mod p { metric: [0, 1, 1, 1] }");
    let pga3_last = text("mod p { metric: [1, 1, 1, 0] }");
    for module in [&pga3, &pga3_last] {
        for name in [
            "fn normalized_study",
            "fn sqrt",
            "fn constrained",
            "fn to_matrix4x4",
            "fn to_matrix3x4",
            "fn to_euler_angles",
            "Div < Bivector > for Even",
            "Div < Even > for Bivector",
        ] {
            assert!(module.contains(name), "{name} missing in 3D PGA");
        }
    }
    let pga2 = text("mod p { metric: [0, 1, 1] }");
    assert!(pga2.contains("fn to_matrix3x3") && pga2.contains("fn constrained"));
    assert!(!pga2.contains("fn normalized_study") && !pga2.contains("fn to_euler_angles"));
    for other in [
        "mod g { metric: [1, 1, 1, 1] }",
        "mod g { metric: [1, 1, 1] }",
        "mod g { metric: [1, -1, -1, -1] }",
        "mod g { metric: [0, 0, 1, 1] }",
        "mod g { metric: [0, 1, 1, -1] }",
    ] {
        let module = text(other);
        for name in [
            "fn normalized_study",
            "fn constrained",
            "fn to_matrix",
            "fn to_euler",
        ] {
            assert!(!module.contains(name), "{name} in {other}");
        }
    }
    // Left out with the operations they belong to.
    let restricted = text("mod p { metric: [0, 1, 1, 1], ops: [geometric] }");
    assert!(!restricted.contains("fn normalized_study") && !restricted.contains("fn to_matrix"));
}
