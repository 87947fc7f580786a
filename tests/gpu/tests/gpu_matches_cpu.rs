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

/// The CPU side of one WGSL function: from the two dense inputs (and each type's field
/// positions in them) to the result's components.
type Cpu = fn(&Fields, &[f32], &[f32]) -> Vec<f32>;

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

fn g3_table() -> HashMap<String, Cpu> {
    use ga_core::f32::g3::*;
    cpu_table!(
        types: [Vector, Bivector, Trivector, Even, Odd, Multivector],
        grades: [grade0, grade1, grade2, grade3],
        versors: [Vector, Even, Odd],
        extra: ["exp_bivector" => |f, x, _| read!(Bivector, f, x).exp().flat()]
    )
}

fn pga_table() -> HashMap<String, Cpu> {
    use pga::*;
    cpu_table!(
        types: [Vector, Bivector, Trivector, Quadvector, Even, Odd, Multivector],
        grades: [grade0, grade1, grade2, grade3, grade4],
        versors: [Vector, Even, Odd],
        extra: []
    )
}

/// The family a function's error is reported under, and its tolerance in units of
/// `eps max(1, |cpu|)`.
fn family(name: &str) -> (&'static str, f64) {
    let first = name.split('_').next().unwrap_or(name);
    match first {
        "exp" => ("exp", 2f64.powi(-11) / f64::from(f32::EPSILON)),
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
fn compare(gpu: &Gpu, label: &str, source: &str, n: usize, table: &HashMap<String, Cpu>) -> String {
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
        uncompared.is_empty(),
        "{label}: WGSL functions without a CPU counterpart in this test: {uncompared:?}"
    );
    let functions: Vec<Signature> = manifest.functions.clone();
    let inputs = random_inputs(n, ITEMS, 0x5eed_0000 + n as u64);
    let started = std::time::Instant::now();
    let results = gpu
        .run(source, &manifest, &functions, n, &inputs)
        .unwrap_or_else(|e| panic!("{label}: the GPU run failed: {e}"));
    let gpu_seconds = started.elapsed().as_secs_f64();
    let size = 1 << n;
    let mut worst: HashMap<&str, (f64, String)> = HashMap::new();
    let mut failures = Vec::new();
    for (f, gpu_values) in functions.iter().zip(&results) {
        let cpu = table[&f.name];
        let (family, tolerance) = family(&f.name);
        let len = manifest.len_of(&f.result);
        for item in 0..ITEMS {
            let x = &inputs[item * 2 * size..item * 2 * size + size];
            let y = &inputs[item * 2 * size + size..(item + 1) * 2 * size];
            let expected = cpu(&fields, x, y);
            let got = &gpu_values[item * len..(item + 1) * len];
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
    assert!(
        failures.is_empty(),
        "{label}: the GPU disagrees with the CPU:\n{}",
        failures.join("\n")
    );
    let mut lines = vec![format!(
        "{label}: {} functions x {ITEMS} inputs agree (GPU {gpu_seconds:.1} s)",
        functions.len()
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
                 and {pga_functions} PGA WGSL functions on {ITEMS} inputs each. Install \
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
    let g3 = compare(&gpu, "G3", ga_core::f32::g3::WGSL, 3, &g3_table());
    eprintln!("{g3}");
    let pga = compare(&gpu, "PGA [0, 1, 1, 1]", pga::WGSL, 4, &pga_table());
    eprintln!("{pga}");
}
