//! `inverse()` of every type inverted by a linear solve, on inputs near singular: a
//! `Some` must be the exact inverse to the bound its docs state (summing absolute values,
//! `2^-26` relative in `f64`, `2^-23` in `f32`), against a double-double inverse of the
//! same input (tests/src/double_double.rs, which shares nothing with the generated code).
//!
//! The inputs are `b z b' + eps c` for random `b`, `b'` and `c` of the type's parity and a
//! zero divisor `z`: `1 + e_B` for a blade with `e_B^2 = 1`, or a null blade `e_B`
//! (`e_B^2 = 0`); `eps` is 0 or log-uniform in 1e-18..1, so the condition numbers run
//! from moderate to infinite. The test also asks that both answers occur, so that it
//! cannot pass by always saying `None`.

use std::cell::Cell;

use ga_tests::double_double;
use ga_tests::embed::Embed;
use ga_tests::harness::{dense, run};
use ga_tests::Algebra;
use proptest::prelude::*;

/// Cases per type.
const CASES: u32 = 256;

/// Which components an operand holds.
#[derive(Clone, Copy)]
enum Parity {
    Full,
    Even,
    Odd,
}

fn keep(dense: &[f64], parity: Parity) -> Vec<f64> {
    dense
        .iter()
        .enumerate()
        .map(|(blade, &c)| {
            let even = blade.count_ones() % 2 == 0;
            match parity {
                Parity::Full => c,
                Parity::Even if even => c,
                Parity::Odd if !even => c,
                _ => 0.0,
            }
        })
        .collect()
}

/// The zero divisors `1 + e_B` (`e_B^2 = 1`) and null blades `e_B`, over the blades other
/// than the scalar (even blades only for an even or odd type, so that `b z b'` keeps the
/// type's parity).
fn zero_divisors(algebra: &Algebra, parity: Parity) -> Vec<Vec<f64>> {
    (1..algebra.size())
        .filter(|blade| matches!(parity, Parity::Full) || blade.count_ones() % 2 == 0)
        .filter_map(|blade| {
            let square = algebra.blade_product(blade, blade).0;
            if square == 1.0 {
                let mut z = algebra.scalar(1.0);
                z[blade] = 1.0;
                Some(z)
            } else if square == 0.0 {
                Some(algebra.basis(blade, 1.0))
            } else {
                None
            }
        })
        .collect()
}

/// Checks one type: `eval` takes a dense input, returns it as the type holds it and its
/// generated inverse (dense); `tolerance` is the documented relative bound.
fn check(
    algebra: &Algebra,
    name: &str,
    parity: Parity,
    tolerance: f64,
    eval: impl Fn(&[f64]) -> (Vec<f64>, Option<Vec<f64>>),
) {
    let size = algebra.size();
    let divisors = zero_divisors(algebra, parity);
    assert!(
        !divisors.is_empty(),
        "{name}: no zero divisor to build from"
    );
    let (left, right) = match parity {
        Parity::Full => (Parity::Full, Parity::Full),
        Parity::Even => (Parity::Even, Parity::Even),
        Parity::Odd => (Parity::Even, Parity::Odd),
    };
    let (somes, nones) = (Cell::new(0u32), Cell::new(0u32));
    let strategy = (
        dense(size),
        dense(size),
        dense(size),
        any::<prop::sample::Index>(),
        -18.0..0.0f64,
        0..8u8,
    );
    run(CASES, &strategy, |(b, b2, c, which, exponent, zero)| {
        let z = &divisors[which.index(divisors.len())];
        let singular = algebra.geometric(&algebra.geometric(&keep(&b, left), z), &keep(&b2, right));
        let eps = if zero == 0 { 0.0 } else { 10f64.powf(exponent) };
        let a = algebra.add(&singular, &algebra.scale(&keep(&c, right), eps));
        let largest = a.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        if largest == 0.0 {
            return Ok(());
        }
        let (value, got) = eval(&algebra.scale(&a, 1.0 / largest));
        let Some(got) = got else {
            nones.set(nones.get() + 1);
            return Ok(());
        };
        somes.set(somes.get() + 1);
        let reference = double_double::inverse(algebra, &value);
        let Some((exact, residual)) = reference else {
            return Err(TestCaseError::fail(format!(
                "{name}::inverse of {value:?} is {got:?}, but the input is singular"
            )));
        };
        let exact_sum: f64 = exact.iter().map(|v| v.abs()).sum();
        // The reference itself is right to its residual (relative, summing absolute
        // values), which must leave room for the bound under test.
        prop_assert!(
            residual <= 1e-6 * tolerance,
            "{}: the double-double reference is unreliable for {:?} (residual {:e})",
            name,
            value,
            residual
        );
        let error: f64 = got.iter().zip(&exact).map(|(x, y)| (x - y).abs()).sum();
        prop_assert!(
            error <= tolerance * exact_sum,
            "{}::inverse of {:?} is {:?}, exact {:?}: relative error {:e} > {:e}",
            name,
            value,
            got,
            exact,
            error / exact_sum,
            tolerance
        );
        Ok(())
    });
    let (somes, nones) = (somes.get(), nones.get());
    assert!(
        somes >= CASES / 16 && nones >= CASES / 16,
        "{name}: {somes} inverses and {nones} None of {CASES}: the inputs do not reach \
         both sides of the certificate"
    );
}

/// Checks each listed type of an algebra.
macro_rules! near_singular {
    ($test:ident, $path:path, $s:ident, metric = $metric:expr, types = [$($ty:ident: $parity:ident),*]) => {
        #[test]
        fn $test() {
            use $path as alg;
            let algebra = Algebra::new(&$metric);
            let tolerance = if stringify!($s) == "f32" {
                f64::from(f32::EPSILON)
            } else {
                2f64.powi(-26)
            };
            $(
                check(&algebra, stringify!($ty), Parity::$parity, tolerance, |dense| {
                    let value = <alg::$ty as Embed<alg::Multivector>>::from_reference(dense);
                    let got = value.inverse().map(|i| alg::Multivector::from(i).to_reference());
                    (value.to_reference(), got)
                });
            )*
        }
    };
}

near_singular!(g2_multivector, ga_core::f64::g2, f64, metric = [1, 1], types = [Multivector: Full]);
near_singular!(g3_multivector, ga_core::f64::g3, f64, metric = [1, 1, 1], types = [Multivector: Full]);
near_singular!(
    g4_even_odd_multivector, ga_core::f64::g4, f64, metric = [1, 1, 1, 1],
    types = [Even: Even, Odd: Odd, Multivector: Full]
);
near_singular!(
    f32_g2_multivector, ga_core::f32::g2, f32, metric = [1, 1], types = [Multivector: Full]
);
near_singular!(
    f32_g3_multivector, ga_core::f32::g3, f32, metric = [1, 1, 1], types = [Multivector: Full]
);
near_singular!(
    f32_g4_even_odd_multivector, ga_core::f32::g4, f32, metric = [1, 1, 1, 1],
    types = [Even: Even, Odd: Odd, Multivector: Full]
);
near_singular!(
    sta_even_odd_multivector, ga_tests::algebras::sta, f64, metric = [1, -1, -1, -1],
    types = [Even: Even, Odd: Odd, Multivector: Full]
);
near_singular!(
    pga_even_odd_multivector, ga_tests::algebras::pga, f64, metric = [1, 1, 1, 0],
    types = [Even: Even, Odd: Odd, Multivector: Full]
);
near_singular!(
    cga_even_odd_multivector, ga_tests::algebras::cga, f64, metric = [1, 1, 1, 1, -1],
    types = [Even: Even, Odd: Odd, Multivector: Full]
);
