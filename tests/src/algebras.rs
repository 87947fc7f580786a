//! The six algebras under test, and their embedding in the reference (with the
//! `f32` G2, G3 and G4 of `ga_core::f32`, checked to single-precision tolerance).
//!
//! G2, G3 and G4 are `ga_core::f64`'s; the space-time algebra, 3D projective
//! geometric algebra and 3D conformal geometric algebra are generated here, once,
//! so that every test binary links the same compiled copy instead of expanding
//! them again.

ga_macros::algebra! {
    /// The space-time algebra: `e1` is the time axis, `e2..e4` square to -1.
    pub mod sta {
        metric: [1, -1, -1, -1],
        scalar: f64,
    }
}

ga_macros::algebra! {
    /// 3D projective geometric algebra: `e4` is the null (degenerate) generator.
    pub mod pga {
        metric: [1, 1, 1, 0],
        scalar: f64,
    }
}

ga_macros::algebra! {
    /// 3D conformal geometric algebra: `e5` squares to -1.
    pub mod cga {
        metric: [1, 1, 1, 1, -1],
        scalar: f64,
    }
}

mod embedding {
    mod g2_f32 {
        use ga_core::f32::g2::*;
        crate::embed_types!(f32; Vector, Bivector, Even, Odd, Multivector);
    }
    mod g3_f32 {
        use ga_core::f32::g3::*;
        crate::embed_types!(f32; Vector, Bivector, Trivector, Even, Odd, Multivector);
    }
    mod g4_f32 {
        use ga_core::f32::g4::*;
        crate::embed_types!(
            f32;
            Vector,
            Bivector,
            Trivector,
            Quadvector,
            Even,
            Odd,
            Multivector
        );
    }
    mod g2 {
        use ga_core::f64::g2::*;
        crate::embed_types!(f64; Vector, Bivector, Even, Odd, Multivector);
    }
    mod g3 {
        use ga_core::f64::g3::*;
        crate::embed_types!(f64; Vector, Bivector, Trivector, Even, Odd, Multivector);
    }
    mod g4 {
        use ga_core::f64::g4::*;
        crate::embed_types!(
            f64;
            Vector,
            Bivector,
            Trivector,
            Quadvector,
            Even,
            Odd,
            Multivector
        );
    }
    mod sta {
        use crate::algebras::sta::*;
        crate::embed_types!(
            f64;
            Vector,
            Bivector,
            Trivector,
            Quadvector,
            Even,
            Odd,
            Multivector
        );
    }
    mod pga {
        use crate::algebras::pga::*;
        crate::embed_types!(
            f64;
            Vector,
            Bivector,
            Trivector,
            Quadvector,
            Even,
            Odd,
            Multivector
        );
    }
    mod cga {
        use crate::algebras::cga::*;
        crate::embed_types!(
            f64;
            Vector,
            Bivector,
            Trivector,
            Quadvector,
            Pentavector,
            Even,
            Odd,
            Multivector
        );
    }
}

/// Calls `$callback!` once per algebra under test with its module name, its path,
/// its dimension, its metric, every operand type (the scalar as `Scalar`), its
/// homogeneous types, and the grade projections each type has.
#[macro_export]
macro_rules! for_each_algebra {
    ($callback:ident) => {
        $callback! {
            g2, ga_core::f64::g2,
            dim = 2,
            metric = [1, 1],
            types = [Scalar, Vector, Bivector, Even, Odd, Multivector],
            grade_types = [Vector, Bivector],
            projections = [
                Vector: [grade1],
                Bivector: [grade2],
                Even: [grade0, grade2],
                Odd: [grade1],
                Multivector: [grade0, grade1, grade2],
            ],
        }
        $callback! {
            g3, ga_core::f64::g3,
            dim = 3,
            metric = [1, 1, 1],
            types = [Scalar, Vector, Bivector, Trivector, Even, Odd, Multivector],
            grade_types = [Vector, Bivector, Trivector],
            projections = [
                Vector: [grade1],
                Bivector: [grade2],
                Trivector: [grade3],
                Even: [grade0, grade2],
                Odd: [grade1, grade3],
                Multivector: [grade0, grade1, grade2, grade3],
            ],
        }
        $callback! {
            g4, ga_core::f64::g4,
            dim = 4,
            metric = [1, 1, 1, 1],
            types = [Scalar, Vector, Bivector, Trivector, Quadvector, Even, Odd, Multivector],
            grade_types = [Vector, Bivector, Trivector, Quadvector],
            projections = [
                Vector: [grade1],
                Bivector: [grade2],
                Trivector: [grade3],
                Quadvector: [grade4],
                Even: [grade0, grade2, grade4],
                Odd: [grade1, grade3],
                Multivector: [grade0, grade1, grade2, grade3, grade4],
            ],
        }
        $callback! {
            sta, ga_tests::algebras::sta,
            dim = 4,
            metric = [1, -1, -1, -1],
            types = [Scalar, Vector, Bivector, Trivector, Quadvector, Even, Odd, Multivector],
            grade_types = [Vector, Bivector, Trivector, Quadvector],
            projections = [
                Vector: [grade1],
                Bivector: [grade2],
                Trivector: [grade3],
                Quadvector: [grade4],
                Even: [grade0, grade2, grade4],
                Odd: [grade1, grade3],
                Multivector: [grade0, grade1, grade2, grade3, grade4],
            ],
        }
        $callback! {
            pga, ga_tests::algebras::pga,
            dim = 4,
            metric = [1, 1, 1, 0],
            types = [Scalar, Vector, Bivector, Trivector, Quadvector, Even, Odd, Multivector],
            grade_types = [Vector, Bivector, Trivector, Quadvector],
            projections = [
                Vector: [grade1],
                Bivector: [grade2],
                Trivector: [grade3],
                Quadvector: [grade4],
                Even: [grade0, grade2, grade4],
                Odd: [grade1, grade3],
                Multivector: [grade0, grade1, grade2, grade3, grade4],
            ],
        }
        $callback! {
            cga, ga_tests::algebras::cga,
            dim = 5,
            metric = [1, 1, 1, 1, -1],
            types = [
                Scalar, Vector, Bivector, Trivector, Quadvector, Pentavector, Even, Odd, Multivector
            ],
            grade_types = [Vector, Bivector, Trivector, Quadvector, Pentavector],
            projections = [
                Vector: [grade1],
                Bivector: [grade2],
                Trivector: [grade3],
                Quadvector: [grade4],
                Pentavector: [grade5],
                Even: [grade0, grade2, grade4],
                Odd: [grade1, grade3, grade5],
                Multivector: [grade0, grade1, grade2, grade3, grade4, grade5],
            ],
        }
    };
}

/// Calls `$callback!(($args), A, B)` for every ordered pair of the two type lists:
/// the cartesian product that `macro_rules!` cannot write as one nested
/// repetition of two independent lists.
#[macro_export]
macro_rules! cartesian {
    ($callback:ident!$args:tt; [$($a:ident),* $(,)?]; $bs:tt) => {
        $( $crate::cartesian!(@row $callback!$args; $a; $bs); )*
    };
    (@row $callback:ident!$args:tt; $a:ident; [$($b:ident),* $(,)?]) => {
        $( $callback!($args, $a, $b); )*
    };
}
