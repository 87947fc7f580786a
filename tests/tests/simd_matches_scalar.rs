//! The SIMD bodies (four SSE lanes, where the generator's cost model picks them on x86-64)
//! compute exactly what the scalar bodies compute: every product of every type pair, and
//! every sandwich, of an `f32` module against its twin generated with `simd: false`. The
//! scalar bodies sum in the SIMD bodies' order, so the two agree to the last bit (up to the
//! sign of a zero); the reference algebra checks both in `products_match_reference.rs`.

ga_macros::algebra! {
    /// G2 with SIMD bodies.
    pub mod g2 { metric: [1, 1], scalar: f32 }
}
ga_macros::algebra! {
    /// G2, scalar bodies only.
    pub mod g2_scalar { metric: [1, 1], scalar: f32, simd: false }
}
ga_macros::algebra! {
    /// G3 with SIMD bodies.
    pub mod g3 { metric: [1, 1, 1], scalar: f32 }
}
ga_macros::algebra! {
    /// G3, scalar bodies only.
    pub mod g3_scalar { metric: [1, 1, 1], scalar: f32, simd: false }
}
ga_macros::algebra! {
    /// The projective plane, a degenerate metric, with SIMD bodies.
    pub mod pga2 { metric: [1, 1, 0], scalar: f32 }
}
ga_macros::algebra! {
    /// The projective plane, scalar bodies only.
    pub mod pga2_scalar { metric: [1, 1, 0], scalar: f32, simd: false }
}
ga_macros::algebra! {
    /// A negative metric, with SIMD bodies.
    pub mod anti3 { metric: [-1, -1, 1], scalar: f32 }
}
ga_macros::algebra! {
    /// A negative metric, scalar bodies only.
    pub mod anti3_scalar { metric: [-1, -1, 1], scalar: f32, simd: false }
}

/// Every value as the components of a full multivector (a scalar product's plain scalar
/// as itself).
trait Dense {
    fn dense(self) -> Vec<f32>;
}

impl Dense for f32 {
    fn dense(self) -> Vec<f32> {
        vec![self]
    }
}

macro_rules! dense_types {
    ($module:ident: $($t:ident),*) => {
        $(impl Dense for $module::$t {
            fn dense(self) -> Vec<f32> {
                $module::Multivector::from(self).to_array().to_vec()
            }
        })*
    };
}

dense_types!(g2: Vector, Bivector, Even, Odd, Multivector, Zero);
dense_types!(g2_scalar: Vector, Bivector, Even, Odd, Multivector, Zero);
dense_types!(g3: Vector, Bivector, Trivector, Even, Odd, Multivector, Zero);
dense_types!(g3_scalar: Vector, Bivector, Trivector, Even, Odd, Multivector, Zero);
dense_types!(pga2: Vector, Bivector, Trivector, Even, Odd, Multivector, Zero);
dense_types!(pga2_scalar: Vector, Bivector, Trivector, Even, Odd, Multivector, Zero);
dense_types!(anti3: Vector, Bivector, Trivector, Even, Odd, Multivector, Zero);
dense_types!(anti3_scalar: Vector, Bivector, Trivector, Even, Odd, Multivector, Zero);

use ga_test_rng::Rng;

/// `N` components uniform in [-2, 2), rounded to `f32`.
fn array<const N: usize>(rng: &mut Rng) -> [f32; N] {
    rng.uniform_array_f32(-2.0, 2.0)
}

fn agree(what: &str, simd: Vec<f32>, scalar: Vec<f32>) {
    assert_eq!(simd, scalar, "{what}: the SIMD and scalar bodies differ");
}

macro_rules! check_pair {
    (($simd:ident, $scalar:ident, $rng:ident), $a:ident, $b:ident) => {{
        use $scalar::{
            Commutator as _, LeftContraction as _, RightContraction as _, ScalarProduct as _,
        };
        use $simd::{
            Commutator as _, LeftContraction as _, RightContraction as _, ScalarProduct as _,
        };
        for _ in 0..50 {
            let x = array::<{ $simd::$a::LEN }>(&mut $rng);
            let y = array::<{ $simd::$b::LEN }>(&mut $rng);
            let (a, b) = ($simd::$a::from_array(x), $simd::$b::from_array(y));
            let (p, q) = ($scalar::$a::from_array(x), $scalar::$b::from_array(y));
            let name = concat!(stringify!($a), " with ", stringify!($b));
            agree(
                concat!("geometric ", stringify!($a), " ", stringify!($b)),
                (a * b).dense(),
                (p * q).dense(),
            );
            agree(name, (a ^ b).dense(), (p ^ q).dense());
            agree(name, (a | b).dense(), (p | q).dense());
            agree(
                name,
                a.left_contraction(b).dense(),
                p.left_contraction(q).dense(),
            );
            agree(
                name,
                a.right_contraction(b).dense(),
                p.right_contraction(q).dense(),
            );
            agree(
                name,
                a.scalar_product(b).dense(),
                p.scalar_product(q).dense(),
            );
            agree(name, a.commutator(b).dense(), p.commutator(q).dense());
        }
    }};
}

macro_rules! check_sandwich {
    (($simd:ident, $scalar:ident, $rng:ident), $v:ident, $x:ident) => {{
        use $scalar::Sandwich as _;
        use $simd::Sandwich as _;
        for _ in 0..50 {
            let r = array::<{ $simd::$v::LEN }>(&mut $rng);
            let y = array::<{ $simd::$x::LEN }>(&mut $rng);
            let simd = $simd::$v::from_array(r).sandwich($simd::$x::from_array(y));
            let scalar = $scalar::$v::from_array(r).sandwich($scalar::$x::from_array(y));
            agree(
                concat!(stringify!($v), " sandwich ", stringify!($x)),
                simd.dense(),
                scalar.dense(),
            );
        }
    }};
}

macro_rules! check_unit_sandwich {
    (($simd:ident, $scalar:ident, $rng:ident), $x:ident) => {{
        use $scalar::SandwichUnit as _;
        use $simd::SandwichUnit as _;
        for _ in 0..50 {
            let r = array::<{ $simd::Even::LEN }>(&mut $rng);
            let y = array::<{ $simd::$x::LEN }>(&mut $rng);
            let simd = $simd::Even::from_array(r).sandwich_unit($simd::$x::from_array(y));
            let scalar = $scalar::Even::from_array(r).sandwich_unit($scalar::$x::from_array(y));
            agree(
                concat!("unit sandwich ", stringify!($x)),
                simd.dense(),
                scalar.dense(),
            );
        }
    }};
}

#[test]
fn g2_simd_products_and_sandwiches_equal_the_scalar_bodies() {
    let mut rng = Rng::new(2);
    ga_tests::cartesian!(check_pair!(g2, g2_scalar, rng); [Vector, Bivector, Even, Odd, Multivector]; [Vector, Bivector, Even, Odd, Multivector]);
    ga_tests::cartesian!(check_sandwich!(g2, g2_scalar, rng); [Vector, Even, Odd]; [Vector, Bivector, Even, Odd, Multivector]);
    check_unit_sandwich!((g2, g2_scalar, rng), Vector);
    check_unit_sandwich!((g2, g2_scalar, rng), Bivector);
    check_unit_sandwich!((g2, g2_scalar, rng), Even);
    check_unit_sandwich!((g2, g2_scalar, rng), Odd);
    check_unit_sandwich!((g2, g2_scalar, rng), Multivector);
}

macro_rules! three_dimensional {
    ($name:ident, $simd:ident, $scalar:ident, $seed:expr) => {
        #[test]
        fn $name() {
            let mut rng = Rng::new($seed);
            ga_tests::cartesian!(
                check_pair!($simd, $scalar, rng);
                [Vector, Bivector, Trivector, Even, Odd, Multivector];
                [Vector, Bivector, Trivector, Even, Odd, Multivector]
            );
            ga_tests::cartesian!(
                check_sandwich!($simd, $scalar, rng);
                [Vector, Even, Odd];
                [Vector, Bivector, Trivector, Even, Odd, Multivector]
            );
            for_each_unit!($simd, $scalar, rng);
        }
    };
}

macro_rules! for_each_unit {
    ($simd:ident, $scalar:ident, $rng:ident) => {
        check_unit_sandwich!(($simd, $scalar, $rng), Vector);
        check_unit_sandwich!(($simd, $scalar, $rng), Bivector);
        check_unit_sandwich!(($simd, $scalar, $rng), Trivector);
        check_unit_sandwich!(($simd, $scalar, $rng), Even);
        check_unit_sandwich!(($simd, $scalar, $rng), Odd);
        check_unit_sandwich!(($simd, $scalar, $rng), Multivector);
    };
}

three_dimensional!(
    g3_simd_products_and_sandwiches_equal_the_scalar_bodies,
    g3,
    g3_scalar,
    3
);
three_dimensional!(
    degenerate_metric_simd_products_and_sandwiches_equal_the_scalar_bodies,
    pga2,
    pga2_scalar,
    5
);
three_dimensional!(
    negative_metric_simd_products_and_sandwiches_equal_the_scalar_bodies,
    anti3,
    anti3_scalar,
    7
);

/// The emitted SIMD helper module exists only where SIMD bodies were written: a module
/// generated with `simd: false` has no `unsafe` code at all, so it compiles under
/// `#![forbid(unsafe_code)]` (checked here by the twin modules compiling in this file's
/// `forbid` scope).
#[forbid(unsafe_code)]
mod forbidden {
    ga_macros::algebra! {
        /// G3 without SIMD bodies, inside `forbid(unsafe_code)`.
        pub mod g3 { metric: [1, 1, 1], scalar: f32, simd: false }
    }
}

#[test]
fn a_scalar_only_module_computes_without_unsafe() {
    let r = forbidden::g3::Even::new(0.5, 0.5, 0.5, 0.5);
    let q = g3::Even::new(0.5, 0.5, 0.5, 0.5);
    assert_eq!((r * r).to_array(), (q * q).to_array());
}
