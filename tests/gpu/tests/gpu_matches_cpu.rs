//! Every function of the WGSL of G3 (`ga_core::f32::g3::WGSL`) and of 3D PGA
//! (`metric: [0, 1, 1, 1]`), run on a Vulkan device through wgpu on 10^4 random inputs,
//! agrees with the same operation of the Rust module on the CPU.
//!
//! Tolerance: `|gpu - cpu| <= 8 eps max(1, |cpu|)` (`eps` = 2^-23) for the arithmetic
//! functions. The inputs are uniform in [-1, 1], so every term of a sum is at most about
//! 1 in size and a rounding error is a few eps of that, not of the (possibly cancelled)
//! result. The two sides evaluate the same sums in the same order, so they differ only
//! where the GPU's compiler fuses a multiply and an add (Vulkan allows it; the Rust code
//! is not fused), which changes one rounding per fused pair: each component's tree is at
//! most four levels deep here, so 8 eps bounds it with room. `sqrt` and division are
//! correctly rounded on the CPU but only to 1 ulp and 2.5 ulps in Vulkan (`norm`,
//! `normalized`); `exp` calls `sin`/`cos`, which Vulkan bounds only absolutely (2^-11 on
//! [-pi, pi]) and the CPU's f32 `exp` replaces by its own series for angles to a half
//! turn, so `exp_bivector` is held to `2^-11` and its observed error reported.
//! `log_even` is held to the same 2^-11: it calls `atan2`, 4096 ulps in Vulkan. It runs on
//! rotors, `exp` of random bivectors with angles inside the logarithm's principal range,
//! the identity and -1, and on non-rotors (every tenth input scaled by 1.25), where its
//! `ok` must be false as the Rust's `None`.
//! G4's `exp_bivector` and `log_even` (the four-dimensional channel forms, which G3 and
//! PGA do not take) are compared the same way.
//! The test prints the largest error seen per family of functions.
//!
//! Without a Vulkan device the test says so and what it skipped, and passes, unless
//! `GA_REQUIRE_GPU=1` (what CI sets), where it fails.

use std::collections::HashMap;

use ga_gpu_tests::{blade_index, random_inputs, Gpu, Manifest, Signature};

ga_macros::algebra! {
    /// 3D PGA with the null generator first (`e1` here, `e0` in the literature).
    pub mod pga {
        metric: [0, 1, 1, 1],
        scalar: f32,
        shaders: [wgsl],
    }
}

/// Inputs per function.
const ITEMS: usize = 10_000;

/// Arithmetic tolerance, in units of `eps max(1, |cpu|)`.
const ARITHMETIC_ULPS: f64 = 8.0;

/// `exp` and `log` tolerance, 2^-11 in units of `eps max(1, |cpu|)`: Vulkan bounds `sin`
/// and `cos` by 2^-11 absolute on [-pi, pi] and `atan2` by 4096 ulps (2^-11 relative).
const TRANSCENDENTAL_ULPS: f64 = 4096.0;

/// The CPU side of one WGSL function: from the two dense inputs (and each type's field
/// positions in them) to the result's components.
type Cpu = fn(&Fields, &[f32], &[f32]) -> Vec<f32>;

/// Makes `log_even`'s inputs from the random ones (see `rotor_inputs!`).
type Rotors = fn(&Fields, &[f32], usize) -> Vec<f32>;

/// Each type's components as dense indices, in canonical order.
type Fields = HashMap<String, Vec<usize>>;

/// Components of a CPU result.
trait Flat {
    fn flat(self) -> Vec<f32>;
}

impl Flat for f32 {
    fn flat(self) -> Vec<f32> {
        vec![self]
    }
}

/// `Flat` for the types of one module (and its `Zero`, the result of vanishing products,
/// which the WGSL leaves out).
macro_rules! flat_impls {
    ($module:path; $($ty:ident),*) => {
        flat_impls!(@each $module; $($ty),*; Zero);
    };
    (@each $module:path; $($ty:ident),*; Zero) => {
        const _: () = {
            use $module as m;
        $(
            impl Flat for m::$ty {
                fn flat(self) -> Vec<f32> {
                    self.to_array().to_vec()
                }
            }
        )*
        impl Flat for m::Zero {
            fn flat(self) -> Vec<f32> {
                Vec::new()
            }
        }
        };
    };
}

flat_impls!(ga_core::f32::g3; Vector, Bivector, Trivector, Even, Odd, Multivector);
flat_impls!(pga; Vector, Bivector, Trivector, Quadvector, Even, Odd, Multivector);
flat_impls!(ga_core::f32::g4; Vector, Bivector, Trivector, Quadvector, Even, Odd, Multivector);

/// A value of a module type (or `f32`) from a dense input.
macro_rules! read {
    (Scalar, $fields:ident, $x:ident) => {
        $x[0]
    };
    ($ty:ident, $fields:ident, $x:ident) => {{
        let at = &$fields[stringify!($ty)];
        $ty::from_array(::std::array::from_fn(|k| $x[at[k]]))
    }};
}

/// `name -> Cpu` for every operation of the module in scope, named as the WGSL names it.
macro_rules! cpu_table {
    (
        types: [$($ty:ident),*],
        grades: $grades:tt,
        versors: $versors:tt,
        extra: [$($name:literal => $f:expr),* $(,)?]
    ) => {{
        let mut table: HashMap<String, Cpu> = HashMap::new();
        cpu_table!(@pairs table; [Scalar, $($ty),*]; [Scalar, $($ty),*]);
        $(
            cpu_table!(@unary table, $ty, $grades);
            cpu_table!(@sandwich table, $ty, $versors);
        )*
        $( table.insert($name.to_owned(), $f); )*
        table
    }};
    (@pairs $table:ident; [$($a:ident),*]; $bs:tt) => {
        $( cpu_table!(@row $table; $a; $bs); )*
    };
    (@row $table:ident; $a:ident; [$($b:ident),*]) => {
        $( cpu_table!(@pair $table, $a, $b); )*
    };
    (@pair $table:ident, Scalar, Scalar) => {};
    (@pair $table:ident, $a:ident, $b:ident) => {
        let key = |op: &str| format!("{op}_{}_{}", snake(stringify!($a)), snake(stringify!($b)));
        table_insert(&mut $table, key("geometric"), |f, x, y| (read!($a, f, x) * read!($b, f, y)).flat());
        table_insert(&mut $table, key("outer"), |f, x, y| (read!($a, f, x) ^ read!($b, f, y)).flat());
        table_insert(&mut $table, key("inner"), |f, x, y| (read!($a, f, x) | read!($b, f, y)).flat());
        table_insert(&mut $table, key("left_contraction"), |f, x, y| read!($a, f, x).left_contraction(read!($b, f, y)).flat());
        table_insert(&mut $table, key("right_contraction"), |f, x, y| read!($a, f, x).right_contraction(read!($b, f, y)).flat());
        table_insert(&mut $table, key("scalar_product"), |f, x, y| read!($a, f, x).scalar_product(read!($b, f, y)).flat());
        table_insert(&mut $table, key("commutator"), |f, x, y| read!($a, f, x).commutator(read!($b, f, y)).flat());
        table_insert(&mut $table, key("regressive"), |f, x, y| read!($a, f, x).regressive(read!($b, f, y)).flat());
        table_insert(&mut $table, key("add"), |f, x, y| (read!($a, f, x) + read!($b, f, y)).flat());
        table_insert(&mut $table, key("sub"), |f, x, y| (read!($a, f, x) - read!($b, f, y)).flat());
    };
    (@sandwich $table:ident, $ty:ident, [$($v:ident),*]) => {
        $( table_insert(
            &mut $table,
            format!("sandwich_{}_{}", snake(stringify!($v)), snake(stringify!($ty))),
            |f, x, y| read!($v, f, x).sandwich(read!($ty, f, y)).flat(),
        ); )*
    };
    (@unary $table:ident, $ty:ident, [$($grade:ident),*]) => {
        let key = |op: &str| format!("{op}_{}", snake(stringify!($ty)));
        table_insert(&mut $table, key("reverse"), |f, x, _| read!($ty, f, x).reverse().flat());
        table_insert(&mut $table, key("grade_involution"), |f, x, _| read!($ty, f, x).grade_involution().flat());
        table_insert(&mut $table, key("conjugate"), |f, x, _| read!($ty, f, x).conjugate().flat());
        table_insert(&mut $table, key("neg"), |f, x, _| (-read!($ty, f, x)).flat());
        table_insert(&mut $table, key("dual"), |f, x, _| read!($ty, f, x).dual().flat());
        table_insert(&mut $table, key("undual"), |f, x, _| read!($ty, f, x).undual().flat());
        table_insert(&mut $table, key("norm_squared"), |f, x, _| read!($ty, f, x).norm_squared().flat());
        table_insert(&mut $table, key("norm"), |f, x, _| read!($ty, f, x).norm().flat());
        table_insert(&mut $table, key("normalized"), |f, x, _| read!($ty, f, x).normalized().flat());
        // The projections through `Multivector`, which has every grade's.
        $( table_insert(&mut $table, key(stringify!($grade)), |f, x, _| Multivector::from(read!($ty, f, x)).$grade().flat()); )*
    };
}

fn table_insert(table: &mut HashMap<String, Cpu>, key: String, f: Cpu) {
    table.insert(key, f);
}

fn snake(name: &str) -> String {
    let mut out = String::new();
    for (i, c) in name.chars().enumerate() {
        if c.is_ascii_uppercase() && i > 0 {
            out.push('_');
        }
        out.push(c.to_ascii_lowercase());
    }
    out
}

/// `log_even`'s `Logarithm { value, ok }` as the GPU writes it: the bivector's components
/// then 1 for `Some`; the zero bivector then 0 for `None`.
fn logarithm<B: Flat + Default>(log: Option<B>) -> Vec<f32> {
    let ok = log.is_some();
    let mut out = log.unwrap_or_default().flat();
    out.push(if ok { 1.0 } else { 0.0 });
    out
}

fn g3_table() -> HashMap<String, Cpu> {
    use ga_core::f32::g3::*;
    cpu_table!(
        types: [Vector, Bivector, Trivector, Even, Odd, Multivector],
        grades: [grade0, grade1, grade2, grade3],
        versors: [Vector, Even, Odd],
        extra: [
            "exp_bivector" => |f, x, _| read!(Bivector, f, x).exp().flat(),
            "log_even" => |f, x, _| logarithm(read!(Even, f, x).log()),
        ]
    )
}

fn pga_table() -> HashMap<String, Cpu> {
    use pga::*;
    cpu_table!(
        types: [Vector, Bivector, Trivector, Quadvector, Even, Odd, Multivector],
        grades: [grade0, grade1, grade2, grade3, grade4],
        versors: [Vector, Even, Odd],
        extra: [
            "exp_bivector" => |f, x, _| read!(Bivector, f, x).exp().flat(),
            "log_even" => |f, x, _| logarithm(read!(Even, f, x).log()),
        ]
    )
}

/// G4's exp and log only: the rest of G4 takes no form that G3 and PGA do not.
fn g4_table() -> HashMap<String, Cpu> {
    use ga_core::f32::g4::*;
    let mut table: HashMap<String, Cpu> = HashMap::new();
    table_insert(&mut table, "exp_bivector".to_owned(), |f, x, _| {
        read!(Bivector, f, x).exp().flat()
    });
    table_insert(&mut table, "log_even".to_owned(), |f, x, _| {
        logarithm(read!(Even, f, x).log())
    });
    table
}

/// The bivector of the random inputs is scaled by this before `exp` to make the rotors
/// `log_even` is run on in G3 and PGA: its components are in [-1, 1], so a Euclidean
/// rotation part has `|B| <= 1.8 sqrt 3 = 3.12`, inside the logarithm's principal range
/// `|B| < pi`.
const ROTOR_SCALE: f32 = 1.8;

/// The same for G4, whose principal range is the sum of the two plane angles below pi:
/// that sum is at most `sqrt 2 |B| <= sqrt 2 0.8 sqrt 6 = 2.77`.
const G4_ROTOR_SCALE: f32 = 0.8;

/// Rewrites the first multivector of every item into a rotor, `exp(scale B)` of the
/// item's bivector part by the CPU, for `log_even`: item 0 is the identity, item 1 is -1
/// (the chosen full turn), and every tenth item is scaled by 1.25, which is no rotor.
macro_rules! rotor_inputs {
    ($module:path) => {
        rotor_inputs!($module, ROTOR_SCALE)
    };
    ($module:path, $scale:expr) => {
        |fields: &Fields, inputs: &[f32], n: usize| -> Vec<f32> {
            use m::Bivector;
            use $module as m;
            let size = 1 << n;
            let mut out = inputs.to_vec();
            for (item, pair) in out.chunks_mut(2 * size).enumerate() {
                let x = &mut pair[..size];
                let b = read!(Bivector, fields, x);
                let mut rotor: m::Even = (b * $scale).exp();
                if item == 0 {
                    rotor = m::Even::ONE;
                } else if item == 1 {
                    rotor = -m::Even::ONE;
                } else if item % 10 == 9 {
                    rotor *= 1.25;
                }
                x.fill(0.0);
                for (&at, c) in fields["Even"].iter().zip(rotor.to_array()) {
                    x[at] = c;
                }
            }
            out
        }
    };
}

/// The family a function's error is reported under, and its tolerance in units of
/// `eps max(1, |cpu|)`.
fn family(name: &str) -> (&'static str, f64) {
    let first = name.split('_').next().unwrap_or(name);
    match first {
        "exp" => ("exp", TRANSCENDENTAL_ULPS),
        "log" => ("log", TRANSCENDENTAL_ULPS),
        "norm" | "normalized" => ("norm", ARITHMETIC_ULPS),
        "geometric" => ("geometric", ARITHMETIC_ULPS),
        "outer" | "inner" | "left" | "right" | "scalar" | "commutator" | "regressive" => {
            ("other products", ARITHMETIC_ULPS)
        }
        "sandwich" => ("sandwich", ARITHMETIC_ULPS),
        _ => ("sums, involutions, duals, projections", ARITHMETIC_ULPS),
    }
}

/// Runs one module and returns the report lines; panics on a disagreement or an
/// uncompared function.
fn compare(
    gpu: &Gpu,
    label: &str,
    source: &str,
    n: usize,
    table: &HashMap<String, Cpu>,
    rotors: Rotors,
    every: bool,
) -> String {
    let manifest = Manifest::of(source).expect("the emitted WGSL parses");
    let fields: Fields = manifest
        .fields
        .iter()
        .map(|(ty, names)| (ty.clone(), names.iter().map(|f| blade_index(f)).collect()))
        .collect();
    let uncompared: Vec<&str> = manifest
        .functions
        .iter()
        .filter(|f| !table.contains_key(&f.name))
        .map(|f| f.name.as_str())
        .collect();
    assert!(
        uncompared.is_empty() || !every,
        "{label}: WGSL functions without a CPU counterpart in this test: {uncompared:?}"
    );
    let mut manifest = manifest;
    manifest.functions.retain(|f| table.contains_key(&f.name));
    // `log_even` runs on rotors (and some non-rotors), everything else on the random
    // multivectors themselves.
    let random = random_inputs(n, ITEMS, 0x5eed_0000 + n as u64);
    let rotors = rotors(&fields, &random, n);
    let (logs, others): (Vec<Signature>, Vec<Signature>) = manifest
        .functions
        .iter()
        .cloned()
        .partition(|f| f.name.starts_with("log_"));
    let size = 1 << n;
    let mut worst: HashMap<&str, (f64, String)> = HashMap::new();
    let mut failures = Vec::new();
    let mut gpu_seconds = 0.0;
    let mut refused = 0;
    for (functions, inputs) in [(&others, &random), (&logs, &rotors)] {
        if functions.is_empty() {
            continue;
        }
        let started = std::time::Instant::now();
        let results = gpu
            .run(source, &manifest, functions, n, inputs)
            .unwrap_or_else(|e| panic!("{label}: the GPU run failed: {e}"));
        gpu_seconds += started.elapsed().as_secs_f64();
        for (f, gpu_values) in functions.iter().zip(&results) {
            let cpu = table[&f.name];
            let (family, tolerance) = family(&f.name);
            let len = manifest.len_of(&f.result);
            for item in 0..ITEMS {
                let x = &inputs[item * 2 * size..item * 2 * size + size];
                let y = &inputs[item * 2 * size + size..(item + 1) * 2 * size];
                let expected = cpu(&fields, x, y);
                assert_eq!(expected.len(), len, "{label}: {} has {len} floats", f.name);
                let got = &gpu_values[item * len..(item + 1) * len];
                if family == "log" && expected[len - 1] == 0.0 {
                    refused += 1;
                }
                for (k, (&c, &g)) in expected.iter().zip(got).enumerate() {
                    if !c.is_finite() || !g.is_finite() {
                        // A null element's `normalized`: both sides must be non-finite.
                        if c.is_finite() != g.is_finite() {
                            failures.push(format!("{}[{k}] item {item}: cpu {c}, gpu {g}", f.name));
                        }
                        continue;
                    }
                    let scale = f64::from(c.abs()).max(1.0) * f64::from(f32::EPSILON);
                    let error = f64::from(g - c).abs() / scale;
                    let entry = worst.entry(family).or_insert((0.0, String::new()));
                    if error > entry.0 {
                        *entry = (error, format!("{}[{k}]", f.name));
                    }
                    if error > tolerance && failures.len() < 20 {
                        failures.push(format!(
                            "{}[{k}] item {item}: cpu {c}, gpu {g} ({error:.1} eps)",
                            f.name
                        ));
                    }
                }
            }
        }
    }
    assert!(
        failures.is_empty(),
        "{label}: the GPU disagrees with the CPU:\n{}",
        failures.join("\n")
    );
    let mut lines = vec![format!(
        "{label}: {} functions x {ITEMS} inputs agree (GPU {gpu_seconds:.1} s); log_even \
         refused {refused} non-rotors on both sides",
        manifest.functions.len()
    )];
    let mut families: Vec<_> = worst.into_iter().collect();
    families.sort_by(|a, b| a.0.cmp(b.0));
    for (family, (error, at)) in families {
        lines.push(if at.is_empty() {
            format!("  {family}: bit for bit")
        } else {
            format!("  {family}: largest |gpu - cpu| = {error:.2} eps max(1, |cpu|) at {at}")
        });
    }
    lines.join("\n")
}

#[test]
fn every_g3_and_pga_wgsl_function_on_a_vulkan_device_matches_the_cpu() {
    let g3_functions = Manifest::of(ga_core::f32::g3::WGSL).map_or(0, |m| m.functions.len());
    let pga_functions = Manifest::of(pga::WGSL).map_or(0, |m| m.functions.len());
    let gpu = match Gpu::vulkan() {
        Ok(gpu) => gpu,
        Err(why) => {
            let message = format!(
                "NO VULKAN DEVICE ({why}): SKIPPED the GPU comparison of {g3_functions} G3 \
                 and {pga_functions} PGA WGSL functions and of G4's exp and log on {ITEMS} \
                 inputs each. Install \
                 Mesa's lavapipe (Debian: apt-get install mesa-vulkan-drivers) to run it."
            );
            assert!(
                std::env::var("GA_REQUIRE_GPU").as_deref() != Ok("1"),
                "{message} GA_REQUIRE_GPU=1 asks for a device."
            );
            eprintln!("{message}");
            return;
        }
    };
    eprintln!("Vulkan device: {}", gpu.description);
    let g3 = compare(
        &gpu,
        "G3",
        ga_core::f32::g3::WGSL,
        3,
        &g3_table(),
        rotor_inputs!(ga_core::f32::g3),
        true,
    );
    eprintln!("{g3}");
    let pga = compare(
        &gpu,
        "PGA [0, 1, 1, 1]",
        pga::WGSL,
        4,
        &pga_table(),
        rotor_inputs!(pga),
        true,
    );
    eprintln!("{pga}");
    let g4 = compare(
        &gpu,
        "G4, exp and log only",
        ga_core::f32::g4::WGSL,
        4,
        &g4_table(),
        rotor_inputs!(ga_core::f32::g4, G4_ROTOR_SCALE),
        false,
    );
    eprintln!("{g4}");
}

/// The manifest's field names map to blade bitmaps (generator `k` is bit `k - 1`).
/// (Here rather than in the library's unit tests, so that CI runs this package's tests as
/// one test target built with the workspace's features.)
#[test]
fn blade_index_reads_the_generators() {
    assert_eq!(blade_index("s"), 0);
    assert_eq!(blade_index("e1"), 1);
    assert_eq!(blade_index("e13"), 0b101);
    assert_eq!(blade_index("e1234"), 0b1111);
}

/// The random inputs: `count` pairs of `2^n` components (2 x 100 x 8 at `n = 3`), in
/// `[-1, 1)` with both signs well represented.
#[test]
fn random_inputs_are_in_the_unit_interval() {
    let xs = random_inputs(3, 100, 7);
    assert_eq!(xs.len(), 1600);
    assert!(xs.iter().all(|x| (-1.0..1.0).contains(x)));
    assert!(xs.iter().any(|x| *x < -0.5) && xs.iter().any(|x| *x > 0.5));
}
