//! Derivatives through the generated algebras over `num_dual::Dual64`: every product,
//! `exp`, `log`, the sandwich, the norm and the inverse of random inputs moved along random
//! directions, against central finite differences of the same operation in the `f64`
//! algebra (itself checked against the reference in the other test binaries), in all six
//! test metrics. The products, being bilinear, are also checked against their exact
//! derivative `P(da, b) + P(a, db)`. G3 over `HyperDual64` checks second derivatives
//! against second differences.

use ga_core::num_dual::{Dual64, HyperDual64};
use ga_tests::harness::{dense, run};
use proptest::prelude::*;

/// The finite-difference step: with Richardson's extrapolation the truncation error is
/// `O(h^4)` and the rounding error `u |f| / h` near 1e-12 of the values' scale.
const H: f64 = 1e-4;

/// The agreement asked of a derivative with its central difference, relative to the scale
/// of the values and differences (the difference is good to about 1e-9 of it).
const FD_TOLERANCE: f64 = 1e-6;

/// Values flattened to their components, in either scalar type.
trait Flat<S> {
    fn flat(self) -> Vec<S>;
}

impl Flat<f64> for f64 {
    fn flat(self) -> Vec<f64> {
        vec![self]
    }
}

impl Flat<Dual64> for Dual64 {
    fn flat(self) -> Vec<Dual64> {
        vec![self]
    }
}

/// The derivative at 0 by Richardson's extrapolation of central differences at `h` and
/// `2h` (error `O(h^4)`), per component.
fn richardson(f: &impl Fn(f64) -> Vec<f64>, h: f64) -> Vec<f64> {
    let (p1, m1, p2, m2) = (f(h), f(-h), f(2.0 * h), f(-2.0 * h));
    (0..p1.len())
        .map(|k| (8.0 * (p1[k] - m1[k]) - (p2[k] - m2[k])) / (12.0 * h))
        .collect()
}

/// `dual` (the values and derivatives of `f(t)` at `t = 0`) against `f` in `f64` at 0 and
/// the extrapolated central difference at step `H`. Near a singular input (an inverse of
/// an almost singular element, a norm near the light cone) the difference itself is
/// inaccurate: its error is estimated by the change from step `H` to `H / 2`, and the
/// tolerance widened by ten times that estimate.
fn check_first(
    what: &str,
    dual: &[Dual64],
    f: impl Fn(f64) -> Vec<f64>,
) -> Result<(), TestCaseError> {
    let mid = f(0.0);
    prop_assert_eq!(dual.len(), mid.len());
    let fd = richardson(&f, H);
    let finer = richardson(&f, H / 2.0);
    let scale = mid.iter().chain(&fd).fold(1.0_f64, |m, x| m.max(x.abs()));
    for (k, d) in dual.iter().enumerate() {
        let error_estimate = (fd[k] - finer[k]).abs();
        prop_assert!(
            (d.re - mid[k]).abs() <= 1e-12 * scale,
            "{what}: value {k}: dual {} f64 {}",
            d.re,
            mid[k]
        );
        prop_assert!(
            (d.eps - finer[k]).abs() <= FD_TOLERANCE * scale + 10.0 * error_estimate,
            "{what}: derivative {k}: dual {} central difference {} (scale {scale}, \
             difference's error about {error_estimate})",
            d.eps,
            finer[k]
        );
    }
    Ok(())
}

/// `a + t da` as dual numbers (`t` the dual unit).
fn duals(a: &[f64], da: &[f64]) -> Vec<Dual64> {
    a.iter().zip(da).map(|(&x, &d)| Dual64::new(x, d)).collect()
}

/// `a + t da` in f64.
fn moved(a: &[f64], da: &[f64], t: f64) -> Vec<f64> {
    a.iter().zip(da).map(|(&x, &d)| x + t * d).collect()
}

/// `Flat` for the generated types of the dual (`$d`) and real (`$r`) modules.
macro_rules! flat_types {
    ($d:ident, $r:ident; $($t:ident),*) => {$(
        impl Flat<f64> for $r::$t {
            fn flat(self) -> Vec<f64> {
                self.to_array().to_vec()
            }
        }
        impl Flat<Dual64> for $d::$t {
            fn flat(self) -> Vec<Dual64> {
                self.to_array().to_vec()
            }
        }
    )*};
}

/// A product of two multivectors moved along `da` and `db`, against central differences
/// and against the bilinear derivative `P(da, b) + P(a, db)`.
macro_rules! product {
    ($what:expr, ($a:ident, $da:ident, $b:ident, $db:ident), |$x:ident, $y:ident| $e:expr) => {{
        let dual = {
            let ($x, $y) = (dmv(&$a, &$da), dmv(&$b, &$db));
            Flat::<Dual64>::flat($e)
        };
        let real = |t: f64| {
            let ($x, $y) = (rmv(&$a, &$da, t), rmv(&$b, &$db, t));
            Flat::<f64>::flat($e)
        };
        check_first($what, &dual, real)?;
        let zero = vec![0.0; N];
        let left = {
            let ($x, $y) = (rmv(&$da, &zero, 0.0), rmv(&$b, &zero, 0.0));
            Flat::<f64>::flat($e)
        };
        let right = {
            let ($x, $y) = (rmv(&$a, &zero, 0.0), rmv(&$db, &zero, 0.0));
            Flat::<f64>::flat($e)
        };
        let exact: Vec<f64> = left.iter().zip(&right).map(|(p, q)| p + q).collect();
        let scale = exact.iter().fold(1.0_f64, |m, v| m.max(v.abs()));
        for (k, v) in dual.iter().enumerate() {
            prop_assert!(
                (v.eps - exact[k]).abs() <= 1e-12 * scale,
                "{}: derivative {k}: dual {} exact {}",
                $what,
                v.eps,
                exact[k]
            );
        }
    }};
}

macro_rules! derivative_tests {
    ($name:ident, dual = $($d:ident)::+, real = $($r:ident)::+, log = $log:tt $(,)?) => {
        mod $name {
            use super::*;
            use $($d)::+ as d;
            use $($r)::+ as r;
            use d::{Commutator as _, LeftContraction as _, RightContraction as _};
            use d::{Sandwich as _, ScalarProduct as _};
            use r::{Commutator as _, LeftContraction as _, RightContraction as _};
            use r::{Sandwich as _, ScalarProduct as _};

            const N: usize = r::Multivector::LEN;
            const NB: usize = r::Bivector::LEN;
            const NE: usize = r::Even::LEN;

            flat_types!(d, r; Multivector, Even, Bivector);

            fn dmv(a: &[f64], da: &[f64]) -> d::Multivector {
                d::Multivector::from_array(duals(a, da).try_into().unwrap())
            }
            fn rmv(a: &[f64], da: &[f64], t: f64) -> r::Multivector {
                r::Multivector::from_array(moved(a, da, t).try_into().unwrap())
            }

            #[test]
            fn every_product_differentiates() {
                let s = (dense(N), dense(N), dense(N), dense(N));
                run(64, &s, |(a, da, b, db)| {
                    product!("geometric", (a, da, b, db), |x, y| x * y);
                    product!("outer", (a, da, b, db), |x, y| x ^ y);
                    product!("inner", (a, da, b, db), |x, y| x | y);
                    product!("left contraction", (a, da, b, db), |x, y| x.left_contraction(y));
                    product!("right contraction", (a, da, b, db), |x, y| x.right_contraction(y));
                    product!("scalar product", (a, da, b, db), |x, y| x.scalar_product(y));
                    product!("commutator", (a, da, b, db), |x, y| x.commutator(y));
                    Ok(())
                });
            }

            #[test]
            fn exp_differentiates() {
                // Bivectors up to about 4 in size: both the series and the closed form.
                let s = (dense(NB), dense(NB), 0.01..0.4f64);
                run(64, &s, |(b, db, size)| {
                    let b: Vec<f64> = b.iter().map(|x| x * size).collect();
                    let dual = d::Bivector::from_array(duals(&b, &db).try_into().unwrap())
                        .exp()
                        .flat();
                    check_first("exp", &dual, |t| {
                        r::Bivector::from_array(moved(&b, &db, t).try_into().unwrap())
                            .exp()
                            .flat()
                    })
                });
            }

            derivative_tests!(@log $log, NB);

            #[test]
            fn sandwich_differentiates() {
                let s = (dense(NE), dense(NE), dense(N), dense(N));
                run(64, &s, |(e, de, x, dx)| {
                    let e: Vec<f64> = e.iter().map(|v| v * 0.2).collect();
                    let dual = d::Even::from_array(duals(&e, &de).try_into().unwrap())
                        .sandwich(dmv(&x, &dx))
                        .flat();
                    check_first("sandwich", &dual, |t| {
                        r::Even::from_array(moved(&e, &de, t).try_into().unwrap())
                            .sandwich(rmv(&x, &dx, t))
                            .flat()
                    })
                });
            }

            #[test]
            fn norm_and_inverse_differentiate() {
                let s = (dense(N), dense(N));
                run(64, &s, |(a, da)| {
                    check_first("norm", &dmv(&a, &da).norm().flat(), |t| {
                        rmv(&a, &da, t).norm().flat()
                    })?;
                    let (Some(inv), Some(_), Some(_)) = (
                        dmv(&a, &da).inverse(),
                        rmv(&a, &da, H).inverse(),
                        rmv(&a, &da, -H).inverse(),
                    ) else {
                        return Ok(());
                    };
                    check_first("inverse", &inv.flat(), |t| {
                        rmv(&a, &da, t).inverse().unwrap().flat()
                    })
                });
            }
        }
    };
    (@log true, $nb:ident) => {
        /// `log` of the rotor `exp(B)` for bivectors `B` small enough to stay on the
        /// principal branch, moved along `dB`: against central differences and against
        /// `log(exp(B(t))) = B(t)`, whose derivative is `dB`.
        #[test]
        fn log_differentiates() {
            let s = (dense($nb), dense($nb));
            run(64, &s, |(b, db)| {
                let b: Vec<f64> = b.iter().map(|x| x * 0.05).collect();
                let dual_b = d::Bivector::from_array(duals(&b, &db).try_into().unwrap());
                let real = |t: f64| {
                    r::Bivector::from_array(moved(&b, &db, t).try_into().unwrap())
                        .exp()
                        .log()
                };
                let (Some(dual), Some(_), Some(_), Some(_)) =
                    (dual_b.exp().log(), real(0.0), real(H), real(-H))
                else {
                    return Err(TestCaseError::fail("log of exp(B) undefined"));
                };
                let dual = dual.flat();
                check_first("log", &dual, |t| real(t).unwrap().flat())?;
                for (k, v) in dual.iter().enumerate() {
                    prop_assert!(
                        (v.eps - db[k]).abs() <= 1e-9 * (1.0 + db[k].abs()),
                        "log(exp(B)): derivative {k}: {} against dB {}",
                        v.eps,
                        db[k]
                    );
                }
                Ok(())
            });
        }
    };
    (@log false, $nb:ident) => {};
}

derivative_tests!(
    g2,
    dual = ga_tests::dual_algebras::g2,
    real = ga_core::f64::g2,
    log = true
);
derivative_tests!(
    g3,
    dual = ga_core::dual64::g3,
    real = ga_core::f64::g3,
    log = true
);
derivative_tests!(
    g4,
    dual = ga_tests::dual_algebras::g4,
    real = ga_core::f64::g4,
    log = true
);
derivative_tests!(
    sta,
    dual = ga_tests::dual_algebras::sta,
    real = ga_tests::algebras::sta,
    log = true
);
derivative_tests!(
    pga,
    dual = ga_tests::dual_algebras::pga,
    real = ga_tests::algebras::pga,
    log = true
);
derivative_tests!(
    cga,
    dual = ga_tests::dual_algebras::cga,
    real = ga_tests::algebras::cga,
    log = false
);

/// G3 over `HyperDual64` along one direction (`eps1 = eps2 = d`): `eps1` is the first
/// derivative (equal to `Dual64`'s) and `eps1eps2` the second, against the second
/// difference `(f(h) - 2 f(0) + f(-h)) / h^2`.
mod second_derivatives {
    use super::*;
    use d::Sandwich as _;
    use ga_core::dual64::g3 as d;
    use ga_core::f64::g3 as r;
    use ga_tests::dual_algebras::g3_hyper as h;
    use h::Sandwich as _;
    use r::Sandwich as _;

    /// The second difference's step: truncation `h^2 f'''' / 12` and rounding `4 u |f| / h^2`
    /// balance near 1e-4, both near 1e-8 of the scale.
    const H2: f64 = 1e-4;

    fn hyper(a: &[f64], da: &[f64]) -> Vec<HyperDual64> {
        a.iter()
            .zip(da)
            .map(|(&x, &d)| HyperDual64::new(x, d, d, 0.0))
            .collect()
    }

    fn check_second(
        what: &str,
        hyper: &[HyperDual64],
        dual: &[Dual64],
        f: impl Fn(f64) -> Vec<f64>,
    ) -> Result<(), TestCaseError> {
        let (mid, plus, minus) = (f(0.0), f(H2), f(-H2));
        let second: Vec<f64> = (0..mid.len())
            .map(|k| (plus[k] - 2.0 * mid[k] + minus[k]) / (H2 * H2))
            .collect();
        let scale = mid
            .iter()
            .chain(&second)
            .fold(1.0_f64, |m, x| m.max(x.abs()));
        for k in 0..mid.len() {
            prop_assert!(
                (hyper[k].eps1 - dual[k].eps).abs() <= 1e-12 * scale,
                "{what}: first derivative {k}: hyper-dual {} dual {}",
                hyper[k].eps1,
                dual[k].eps
            );
            prop_assert!(
                (hyper[k].eps1eps2 - second[k]).abs() <= 1e-4 * scale,
                "{what}: second derivative {k}: hyper-dual {} second difference {}",
                hyper[k].eps1eps2,
                second[k]
            );
        }
        Ok(())
    }

    #[test]
    fn exp_sandwich_norm_and_product_have_second_derivatives() {
        let s = (dense(3), dense(3), dense(3), dense(3));
        run(64, &s, |(b, db, x, dx)| {
            let b: Vec<f64> = b.iter().map(|v| v * 0.3).collect();
            let hb = h::Bivector::from_array(hyper(&b, &db).try_into().unwrap());
            let db_ = d::Bivector::from_array(duals(&b, &db).try_into().unwrap());
            let hx = h::Vector::from_array(hyper(&x, &dx).try_into().unwrap());
            let dx_ = d::Vector::from_array(duals(&x, &dx).try_into().unwrap());
            let rb = |t: f64| r::Bivector::from_array(moved(&b, &db, t).try_into().unwrap());
            let rx = |t: f64| r::Vector::from_array(moved(&x, &dx, t).try_into().unwrap());

            check_second("exp", &hb.exp().to_array(), &db_.exp().to_array(), |t| {
                rb(t).exp().to_array().to_vec()
            })?;
            check_second(
                "rotor sandwich",
                &hb.exp().sandwich(hx).to_array(),
                &db_.exp().sandwich(dx_).to_array(),
                |t| rb(t).exp().sandwich(rx(t)).to_array().to_vec(),
            )?;
            check_second("norm", &[hx.norm()], &[dx_.norm()], |t| vec![rx(t).norm()])?;
            check_second(
                "geometric",
                &(hx * hb).to_array(),
                &(dx_ * db_).to_array(),
                |t| (rx(t) * rb(t)).to_array().to_vec(),
            )?;
            let (Some(hl), Some(dl)) = (hb.exp().log(), db_.exp().log()) else {
                return Err(TestCaseError::fail("log of exp(B) undefined"));
            };
            check_second("log", &hl.to_array(), &dl.to_array(), |t| {
                rb(t).exp().log().unwrap().to_array().to_vec()
            })
        });
    }
}

/// A restricted module over `Dual64` carries the same derivatives as the full one.
#[test]
fn a_restricted_dual_module_agrees_with_the_full_one() {
    use full::Sandwich as _;
    use ga_core::dual64::g3 as full;
    use ga_tests::dual_algebras::g3_rotors as restricted;
    use restricted::Sandwich as _;
    let s = (dense(3), dense(3), dense(3), dense(3));
    run(32, &s, |(b, db, x, dx)| {
        let b: Vec<f64> = b.iter().map(|v| v * 0.3).collect();
        let (bd, xd) = (duals(&b, &db), duals(&x, &dx));
        let rf = full::Bivector::from_array(bd.clone().try_into().unwrap()).exp();
        let rr = restricted::Bivector::from_array(bd.try_into().unwrap()).exp();
        let yf = rf.sandwich(full::Vector::from_array(xd.clone().try_into().unwrap()));
        let yr = rr.sandwich(restricted::Vector::from_array(xd.try_into().unwrap()));
        for (f, r) in yf.to_array().iter().zip(yr.to_array()) {
            prop_assert!((f.re - r.re).abs() <= 1e-12 * (1.0 + f.re.abs()));
            prop_assert!((f.eps - r.eps).abs() <= 1e-12 * (1.0 + f.eps.abs()));
        }
        Ok(())
    });
}
