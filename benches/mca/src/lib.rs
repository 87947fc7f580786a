//! One-item loops over slices, `#[no_mangle]` so that run.sh finds them in the assembly:
//! `b_*` batch (items independent), `c_*` chain (each step waits for the last), `k_*` the
//! slice kernels, glam beside each.
#![allow(missing_docs)]

use d::Sandwich as _;
use d::SandwichUnit as _;
use f::Sandwich as _;
use f::SandwichUnit as _;
use ga_core::f32::g3 as f;
use ga_core::f64::g3 as d;
macro_rules! batch2 {
    ($name:ident, $a:ty, $b:ty, $o:ty, |$x:ident, $y:ident| $e:expr) => {
        #[no_mangle]
        #[inline(never)]
        pub fn $name(a: &[$a], b: &[$b], o: &mut [$o]) {
            for ((o, &$x), &$y) in o.iter_mut().zip(a).zip(b) {
                *o = $e;
            }
        }
    };
}
macro_rules! chain {
    ($name:ident, $a:ty, $acc:ty, |$r:ident, $x:ident| $e:expr) => {
        #[no_mangle]
        #[inline(never)]
        pub fn $name(a: &[$a], mut $x: $acc) -> $acc {
            for &$r in a {
                $x = $e;
            }
            $x
        }
    };
}
batch2!(b_rr_f32_ga, f::Even, f::Even, f::Even, |x, y| x * y);
batch2!(b_rr_f32_glam, glam::Quat, glam::Quat, glam::Quat, |x, y| x
    * y);
batch2!(b_rv_f32_ga, f::Even, f::Vector, f::Vector, |x, y| x
    .sandwich(y));
batch2!(b_rvu_f32_ga, f::Even, f::Vector, f::Vector, |x, y| x
    .sandwich_unit(y));
batch2!(b_rv_f32_glam, glam::Quat, glam::Vec3, glam::Vec3, |x, y| x
    * y);
batch2!(b_rr_f64_ga, d::Even, d::Even, d::Even, |x, y| x * y);
batch2!(
    b_rr_f64_glam,
    glam::DQuat,
    glam::DQuat,
    glam::DQuat,
    |x, y| x * y
);
batch2!(b_rv_f64_ga, d::Even, d::Vector, d::Vector, |x, y| x
    .sandwich(y));
batch2!(b_rvu_f64_ga, d::Even, d::Vector, d::Vector, |x, y| x
    .sandwich_unit(y));
batch2!(
    b_rv_f64_glam,
    glam::DQuat,
    glam::DVec3,
    glam::DVec3,
    |x, y| x * y
);
chain!(c_rr_f32_ga, f::Even, f::Even, |r, x| x * r);
chain!(c_rr_f32_glam, glam::Quat, glam::Quat, |r, x| x * r);
chain!(c_rv_f32_ga, f::Even, f::Vector, |r, x| r.sandwich(x));
chain!(c_rvu_f32_ga, f::Even, f::Vector, |r, x| r.sandwich_unit(x));
chain!(c_rv_f32_glam, glam::Quat, glam::Vec3, |r, x| r * x);
chain!(c_rr_f64_ga, d::Even, d::Even, |r, x| x * r);
chain!(c_rr_f64_glam, glam::DQuat, glam::DQuat, |r, x| x * r);
chain!(c_rv_f64_ga, d::Even, d::Vector, |r, x| r.sandwich(x));
chain!(c_rvu_f64_ga, d::Even, d::Vector, |r, x| r.sandwich_unit(x));
chain!(c_rv_f64_glam, glam::DQuat, glam::DVec3, |r, x| r * x);
use ga_core::f32::g4 as f4;
use ga_core::f64::g4 as d4;
batch2!(g4_rr_f32, f4::Even, f4::Even, f4::Even, |x, y| x * y);
batch2!(g4_rr_f64, d4::Even, d4::Even, d4::Even, |x, y| x * y);
batch2!(g4_rv_f32, f4::Even, f4::Vector, f4::Vector, |x, y| {
    use f4::Sandwich;
    x.sandwich(y)
});
batch2!(g4_rv_f64, d4::Even, d4::Vector, d4::Vector, |x, y| {
    use d4::Sandwich;
    x.sandwich(y)
});
batch2!(
    g4_mm_f32,
    f4::Multivector,
    f4::Multivector,
    f4::Multivector,
    |x, y| x * y
);
batch2!(
    g4_mm_f64,
    d4::Multivector,
    d4::Multivector,
    d4::Multivector,
    |x, y| x * y
);
batch2!(
    g3_mm_f32,
    f::Multivector,
    f::Multivector,
    f::Multivector,
    |x, y| x * y
);
batch2!(
    g3_mm_f64,
    d::Multivector,
    d::Multivector,
    d::Multivector,
    |x, y| x * y
);
batch2!(g3_vv_f32, f::Vector, f::Vector, f::Even, |x, y| x * y);
