//! The WGSL that `algebra!` emits (`shaders: [wgsl]`) parses and validates with naga
//! for ga-core's G2, G3 and G4 and for user algebras in every metric kind the tests use
//! (Euclidean, degenerate as in PGA with the null generator first or last, Minkowski,
//! conformal; restricted by `types:`/`ops:` and with a user type), and naga's back ends
//! translate it to SPIR-V and GLSL, so both routes a user may take are exercised. The
//! functions' names follow docs/generated-api.md; a few are checked by name here.

use naga::back::{glsl, spv};
use naga::valid::{Capabilities, ValidationFlags, Validator};

ga_macros::algebra! {
    /// Space-time algebra, Minkowski signature.
    pub mod sta {
        metric: [1, -1, -1, -1],
        scalar: f32,
        shaders: [wgsl],
    }
}

ga_macros::algebra! {
    /// The Minkowski plane: no bivector squares to -1, so `log(-1)` has no plane to
    /// turn in and `log_even` takes the Rust's `None` branch for it.
    pub mod minkowski_plane {
        metric: [1, -1],
        scalar: f32,
        shaders: [wgsl],
    }
}

ga_macros::algebra! {
    /// 3D PGA, the null generator first (`e0` of the literature is `e1` here).
    pub mod pga {
        metric: [0, 1, 1, 1],
        scalar: f32,
        shaders: [wgsl],
    }
}

ga_macros::algebra! {
    /// 3D PGA, the null generator last.
    pub mod pga_last {
        metric: [1, 1, 1, 0],
        scalar: f64,
        shaders: [wgsl],
    }
}

ga_macros::algebra! {
    /// 3D conformal geometric algebra.
    pub mod cga {
        metric: [1, 1, 1, 1, -1],
        scalar: f32,
        shaders: [wgsl],
    }
}

ga_macros::algebra! {
    /// A restricted 2D PGA: rotors, vectors and a user type, three operations.
    pub mod restricted {
        metric: [0, 1, 1],
        scalar: f32,
        types: [Rotor, Vector, Point = [e12, e13, e23]],
        ops: [geometric, regressive, sandwich],
        shaders: [wgsl],
    }
}

/// Parses, validates and writes SPIR-V and GLSL (a compute entry point is needed for
/// GLSL, so one that calls nothing is appended); panics with naga's message on failure.
fn check(name: &str, source: &str) -> naga::Module {
    let module = naga::front::wgsl::parse_str(source)
        .unwrap_or_else(|e| panic!("{name}: WGSL does not parse:\n{}", e.emit_to_string(source)));
    let info = Validator::new(ValidationFlags::all(), Capabilities::empty())
        .validate(&module)
        .unwrap_or_else(|e| panic!("{name}: WGSL does not validate: {e:?}"));
    let words = spv::write_vec(&module, &info, &spv::Options::default(), None)
        .unwrap_or_else(|e| panic!("{name}: SPIR-V back end failed: {e:?}"));
    assert_eq!(words[0], 0x0723_0203, "{name}: SPIR-V magic number");

    // GLSL needs an entry point; one that uses a function keeps it in the output.
    let with_entry = format!("{source}\n@compute @workgroup_size(1)\nfn main() {{\n}}\n",);
    let entry_module = naga::front::wgsl::parse_str(&with_entry).expect("parsed above");
    let entry_info = Validator::new(ValidationFlags::all(), Capabilities::empty())
        .validate(&entry_module)
        .expect("validated above");
    let mut glsl_text = String::new();
    let options = glsl::Options {
        version: glsl::Version::Desktop(450),
        ..glsl::Options::default()
    };
    let pipeline = glsl::PipelineOptions {
        shader_stage: naga::ShaderStage::Compute,
        entry_point: "main".to_owned(),
        multiview: None,
    };
    let mut writer = glsl::Writer::new(
        &mut glsl_text,
        &entry_module,
        &entry_info,
        &options,
        &pipeline,
        naga::proc::BoundsCheckPolicies::default(),
    )
    .unwrap_or_else(|e| panic!("{name}: GLSL back end failed: {e:?}"));
    writer
        .write()
        .unwrap_or_else(|e| panic!("{name}: GLSL back end failed: {e:?}"));
    assert!(glsl_text.starts_with("#version 450"), "{name}: GLSL header");
    module
}

/// The names of the module's functions.
fn functions(module: &naga::Module) -> Vec<String> {
    module
        .functions
        .iter()
        .filter_map(|(_, f)| f.name.clone())
        .collect()
}

#[test]
fn ga_core_g2_g3_g4_wgsl_validates_and_translates_to_spirv_and_glsl() {
    for (name, source) in [
        ("g2", ga_core::f32::g2::WGSL),
        ("g3", ga_core::f32::g3::WGSL),
        ("g4", ga_core::f32::g4::WGSL),
    ] {
        let module = check(name, source);
        let names = functions(&module);
        for expected in [
            "geometric_even_even",
            "outer_vector_vector",
            "regressive_bivector_bivector",
            "sandwich_even_vector",
            "reverse_even",
            "dual_vector",
            "normalized_even",
            "exp_bivector",
            "log_even",
        ] {
            // In G2 two bivectors do not span the space: their join vanishes.
            if name == "g2" && expected == "regressive_bivector_bivector" {
                continue;
            }
            assert!(
                names.iter().any(|n| n == expected),
                "{name} lacks {expected}"
            );
        }
    }
}

#[test]
fn user_algebras_in_every_metric_kind_validate_and_translate() {
    for (name, source) in [
        ("sta", sta::WGSL),
        ("pga [0,1,1,1]", pga::WGSL),
        ("pga [1,1,1,0] f64", pga_last::WGSL),
        ("cga", cga::WGSL),
        ("restricted", restricted::WGSL),
    ] {
        check(name, source);
    }
}

#[test]
fn exp_and_log_are_emitted_wherever_the_rust_module_has_them() {
    // Rust: `Bivector::exp` in closed form up to five dimensions, `Even::log` for two to
    // four; G4 and the space-time algebra take the four-dimensional forms (`I I` = +1
    // by channels, -1 complex), PGA the dual-number one, CGA the five-dimensional exp.
    for (name, source, log) in [
        ("g2", ga_core::f32::g2::WGSL, true),
        ("g3", ga_core::f32::g3::WGSL, true),
        ("g4", ga_core::f32::g4::WGSL, true),
        ("minkowski plane", minkowski_plane::WGSL, true),
        ("sta", sta::WGSL, true),
        ("pga [0,1,1,1]", pga::WGSL, true),
        ("pga [1,1,1,0] f64", pga_last::WGSL, true),
        ("cga", cga::WGSL, false),
    ] {
        let names = functions(&check(name, source));
        assert!(
            names.iter().any(|n| n == "exp_bivector"),
            "{name} lacks exp"
        );
        assert_eq!(
            names.iter().any(|n| n == "log_even"),
            log,
            "{name}: log_even present where the Rust has Even::log"
        );
    }
}

#[test]
fn types_and_ops_restrict_the_shader_module_as_they_restrict_the_rust_one() {
    let module = check("restricted", restricted::WGSL);
    let names = functions(&module);
    assert!(names.iter().any(|n| n == "geometric_even_point"));
    assert!(names.iter().any(|n| n == "regressive_point_point"));
    assert!(names.iter().any(|n| n == "sandwich_even_point"));
    for absent in ["outer_", "inner_", "add_", "reverse_", "norm_", "exp_"] {
        assert!(
            !names.iter().any(|n| n.starts_with(absent)),
            "`ops` left out {absent}*, but the WGSL has it: {names:?}"
        );
    }
    let structs: Vec<&str> = module
        .types
        .iter()
        .filter_map(|(_, t)| t.name.as_deref())
        .collect();
    assert!(structs.contains(&"Point"), "{structs:?}");
    assert!(!structs.contains(&"Multivector"), "{structs:?}");
}
