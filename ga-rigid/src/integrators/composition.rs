//! Symmetric compositions of a symmetric second-order step `S(h)`:
//! `Psi(h) = S(g_1 h) S(g_2 h) ... S(g_s h)` with `g_i = g_{s+1-i}` and `sum g_i = 1`
//! (E. Hairer, C. Lubich, G. Wanner, *Geometric Numerical Integration*, 2nd ed., Springer
//! 2006, section V.3.2). The coefficient sets are those with the smallest error constants
//! that chapter recommends for each order:
//!
//! - order 4, five stages: M. Suzuki, "Fractal decomposition of exponential operators with
//!   applications to many-body theories and Monte Carlo simulations", Phys. Lett. A 146
//!   (1990) 319, `g = (p, p, 1 - 4p, p, p)`, `p = 1/(4 - 4^(1/3))` (its error constant is
//!   smaller than that of Yoshida's three-stage triple jump);
//! - order 6, nine stages, and order 8, seventeen stages: W. Kahan and R.-C. Li,
//!   "Composition constants for raising the orders of unconventional schemes for ordinary
//!   differential equations", Math. Comp. 66 (1997) 1089, methods `s9odr6a` and
//!   `s17odr8a` (the digits as printed in Hairer-Lubich-Wanner, V.3.2, (3.11) and (3.12)).
//!
//! A symmetric composition of a symmetric method of order two is symmetric, so its order
//! is even; it keeps whatever the step keeps (symplecticity, `|R ~R| = 1`, `|m|`).

// The coefficients carry the published digits, beyond f64, so that they can be read
// against the sources.
#![allow(clippy::excessive_precision)]

use crate::error::Error;

/// Suzuki's `p = 1/(4 - 4^(1/3))`, to 30 digits.
const SUZUKI_P: f64 = 0.414_490_771_794_375_737_142_354_062_861;

/// The most coefficients a composition's first half (with the middle) holds: nine, for
/// Kahan and Li's seventeen stages.
pub(crate) const MAX_HALF: usize = 9;

/// The coefficients of a symmetric composition: the first half and the middle,
/// `[g_1, ..., g_(s+1)/2]`; the rest mirror them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Composition {
    order: u32,
    half: &'static [f64],
}

impl Composition {
    /// The step itself: one stage, order two.
    pub const STRANG: Composition = Composition {
        order: 2,
        half: &[1.0],
    };

    /// Suzuki's five-stage method of order four.
    pub const SUZUKI_4: Composition = Composition {
        order: 4,
        half: &[SUZUKI_P, SUZUKI_P, 1.0 - 4.0 * SUZUKI_P],
    };

    /// Kahan and Li's nine-stage method of order six (`s9odr6a`).
    pub const KAHAN_LI_6: Composition = Composition {
        order: 6,
        half: &[
            0.392_161_444_007_314_139_279_250_56,
            0.332_599_136_789_359_438_599_748_64,
            -0.706_246_172_557_639_359_809_964_82,
            0.082_213_596_293_550_800_231_490_45,
            0.798_543_990_934_829_963_398_950_35,
        ],
    };

    /// Kahan and Li's seventeen-stage method of order eight (`s17odr8a`).
    pub const KAHAN_LI_8: Composition = Composition {
        order: 8,
        half: &[
            0.130_202_483_088_890_080_878_817_63,
            0.561_162_981_775_108_384_561_964_41,
            -0.389_474_962_644_847_286_408_078_60,
            0.158_841_906_555_155_600_896_210_75,
            -0.395_903_894_133_237_577_336_231_54,
            0.184_539_640_978_315_707_091_832_54,
            0.258_374_387_686_322_047_293_979_11,
            0.295_011_723_609_310_298_870_966_24,
            -0.605_508_533_830_034_511_698_921_08,
        ],
    };

    /// The composition of this order (2, 4, 6 or 8); an error for any other.
    pub fn of_order(order: u32) -> Result<Composition, Error> {
        match order {
            2 => Ok(Self::STRANG),
            4 => Ok(Self::SUZUKI_4),
            6 => Ok(Self::KAHAN_LI_6),
            8 => Ok(Self::KAHAN_LI_8),
            _ => Err(Error::invalid(
                "order",
                format!("compositions have order 2, 4, 6 or 8, got {order}"),
            )),
        }
    }

    /// The order of the composed method.
    #[must_use]
    pub fn order(&self) -> u32 {
        self.order
    }

    /// The number of stages `s`.
    #[must_use]
    pub fn stages(&self) -> usize {
        2 * self.half.len() - 1
    }

    /// The coefficient `g_(i+1)` (0-based `i < s`).
    #[inline]
    #[must_use]
    pub fn gamma(&self, i: usize) -> f64 {
        let n = self.half.len();
        if i < n {
            self.half[i]
        } else {
            self.half[2 * n - 2 - i]
        }
    }

    /// All the coefficients in order.
    pub fn gammas(&self) -> impl Iterator<Item = f64> + '_ {
        (0..self.stages()).map(|i| self.gamma(i))
    }
}

/// A symmetric splitting of `H = A + B` with its own coefficients for each part,
/// `B(b_1 h) A(a_1 h) B(b_2 h) ... A(a_s h) B(b_(s+1) h)` with `a_i = a_(s+1-i)` and
/// `b_i = b_(s+2-i)`, for problems where `[B, [B, [B, A]]] = 0` (Runge-Kutta-Nystrom
/// problems: a kinetic energy quadratic in the momenta and a potential of the
/// configuration alone), which have fewer order conditions than general splittings.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Nystrom {
    order: u32,
    /// `s`, the number of `A` flows a step (and of force evaluations, the last kick of a
    /// step merging with the first of the next).
    stages: usize,
    /// `a_1 ..`: the first half of the flows' coefficients, the middle one included.
    a_half: &'static [f64],
    /// `b_1 ..`: the first half of the kicks' coefficients, the middle one included.
    b_half: &'static [f64],
}

impl Nystrom {
    /// S. Blanes and P. C. Moan, "Practical symplectic partitioned Runge-Kutta and
    /// Runge-Kutta-Nystrom methods", J. Comput. Appl. Math. 142 (2002) 313-330: the
    /// method `SRKN_6^b` of order four with six force evaluations a step (the digits as
    /// the paper prints them).
    pub const BLANES_MOAN_6: Nystrom = Nystrom {
        order: 4,
        stages: 6,
        a_half: &[
            0.245_298_957_184_271,
            0.604_872_665_711_080,
            -0.350_171_622_895_351,
        ],
        b_half: &[
            0.082_984_406_417_405_2,
            0.396_309_801_498_368,
            -0.039_056_304_922_348_6,
            0.119_524_194_013_150_8,
        ],
    };

    /// Blanes and Moan's `SRKN_11^b` (the same paper), order six with eleven force
    /// evaluations a step.
    pub const BLANES_MOAN_11: Nystrom = Nystrom {
        order: 6,
        stages: 11,
        a_half: &[
            0.123_229_775_946_271,
            0.290_553_797_799_558,
            -0.127_049_212_625_417,
            -0.246_331_761_062_075,
            0.357_208_872_795_928,
            0.204_777_054_291_470,
        ],
        b_half: &[
            0.041_464_998_518_262_4,
            0.198_128_671_918_067,
            -0.040_006_192_104_153_3,
            0.075_253_984_301_580_7,
            -0.011_511_387_420_687_9,
            0.236_669_924_786_931_1,
        ],
    };

    /// The order of the method.
    #[must_use]
    pub fn order(&self) -> u32 {
        self.order
    }

    /// The number of `A` flows a step, `s`.
    #[must_use]
    pub fn stages(&self) -> usize {
        self.stages
    }

    /// `a_(i+1)` (0-based `i < s`).
    #[must_use]
    pub fn a(&self, i: usize) -> f64 {
        self.a_half[i.min(self.stages - 1 - i)]
    }

    /// `b_(i+1)` (0-based `i <= s`).
    #[must_use]
    pub fn b(&self, i: usize) -> f64 {
        self.b_half[i.min(self.stages - i)]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const ALL: [Composition; 4] = [
        Composition::STRANG,
        Composition::SUZUKI_4,
        Composition::KAHAN_LI_6,
        Composition::KAHAN_LI_8,
    ];

    #[test]
    fn coefficients_sum_to_one_and_mirror() {
        for c in ALL {
            let sum: f64 = c.gammas().sum();
            assert!((sum - 1.0).abs() < 4e-16, "order {}: sum {sum}", c.order());
            let g: Vec<f64> = c.gammas().collect();
            let mirrored: Vec<f64> = g.iter().rev().copied().collect();
            assert_eq!(g, mirrored);
        }
        for c in ALL {
            assert!(c.half.len() <= MAX_HALF, "order {}", c.order());
        }
        assert_eq!(Composition::KAHAN_LI_8.stages(), 17);
        assert_eq!(Composition::KAHAN_LI_6.stages(), 9);
        assert_eq!(Composition::SUZUKI_4.stages(), 5);
    }

    /// Of the order conditions of a symmetric composition (Hairer-Lubich-Wanner V.3.2),
    /// those of a single commuting flow read `sum g^k = 0` for odd `k < order`.
    #[test]
    fn odd_power_sums_vanish_below_the_order() {
        for c in &ALL[1..] {
            for k in (3..c.order()).step_by(2) {
                let sum: f64 = c.gammas().map(|g| g.powi(k as i32)).sum();
                assert!(
                    sum.abs() < 1e-15,
                    "order {}: sum g^{k} = {sum:e}",
                    c.order()
                );
            }
            // The first condition beyond the order fails: the order is not higher.
            let k = c.order() as i32 + 1;
            let sum: f64 = c.gammas().map(|g| g.powi(k)).sum();
            assert!(sum.abs() > 1e-4, "order {}: sum g^{k} = {sum:e}", c.order());
        }
    }

    /// The pendulum `q'' = -sin q`.
    fn rate(y: [f64; 2]) -> [f64; 2] {
        [y[1], -y[0].sin()]
    }

    /// Classical RK4, a method that shares nothing with the compositions.
    fn rk4(mut y: [f64; 2], t: f64, n: u32) -> [f64; 2] {
        let h = t / f64::from(n);
        let add = |y: [f64; 2], k: [f64; 2], a: f64| [y[0] + a * k[0], y[1] + a * k[1]];
        for _ in 0..n {
            let k1 = rate(y);
            let k2 = rate(add(y, k1, 0.5 * h));
            let k3 = rate(add(y, k2, 0.5 * h));
            let k4 = rate(add(y, k3, h));
            y = [
                y[0] + h / 6.0 * (k1[0] + 2.0 * (k2[0] + k3[0]) + k4[0]),
                y[1] + h / 6.0 * (k1[1] + 2.0 * (k2[1] + k3[1]) + k4[1]),
            ];
        }
        y
    }

    /// `n` composed steps of Stormer-Verlet (kick, drift, kick) over `[0, t]`.
    fn composed(c: Composition, mut y: [f64; 2], t: f64, n: u32) -> [f64; 2] {
        let h = t / f64::from(n);
        for _ in 0..n {
            for g in c.gammas() {
                let tau = g * h;
                y[1] -= 0.5 * tau * y[0].sin();
                y[0] += tau * y[1];
                y[1] -= 0.5 * tau * y[0].sin();
            }
        }
        y
    }

    /// The observed order on a nonlinear problem, where every order condition counts
    /// (a linear one would hide some), against RK4 at a fine step.
    #[test]
    fn observed_order_on_the_pendulum() {
        let (y0, t) = ([2.0, 0.0], 4.0);
        let reference = rk4(y0, t, 40_000);
        for (c, steps) in [
            (Composition::STRANG, [40, 80, 160, 320]),
            (Composition::SUZUKI_4, [20, 40, 80, 160]),
            (Composition::KAHAN_LI_6, [10, 14, 20, 28]),
            (Composition::KAHAN_LI_8, [8, 10, 12, 14]),
        ] {
            let (mut xs, mut ys) = (Vec::new(), Vec::new());
            for n in steps {
                let y = composed(c, y0, t, n);
                let error = (y[0] - reference[0]).hypot(y[1] - reference[1]);
                xs.push((t / f64::from(n)).ln());
                ys.push(error.ln());
            }
            let n = xs.len() as f64;
            let (mx, my) = (xs.iter().sum::<f64>() / n, ys.iter().sum::<f64>() / n);
            let sxy: f64 = xs.iter().zip(&ys).map(|(x, y)| (x - mx) * (y - my)).sum();
            let sxx: f64 = xs.iter().map(|x| (x - mx) * (x - mx)).sum();
            let order = sxy / sxx;
            println!("order {}: observed {order:.3}", c.order());
            assert!(
                (order - f64::from(c.order())).abs() < 0.1,
                "order {}: observed {order}",
                c.order()
            );
        }
    }

    const NYSTROMS: [Nystrom; 2] = [Nystrom::BLANES_MOAN_6, Nystrom::BLANES_MOAN_11];

    #[test]
    fn nystrom_coefficients_sum_to_one_and_mirror() {
        for c in NYSTROMS {
            let s = c.stages();
            let a: Vec<f64> = (0..s).map(|i| c.a(i)).collect();
            let b: Vec<f64> = (0..=s).map(|i| c.b(i)).collect();
            let (sum_a, sum_b) = (a.iter().sum::<f64>(), b.iter().sum::<f64>());
            assert!(
                (sum_a - 1.0).abs() < 4e-15,
                "order {}: sum a {sum_a}",
                c.order()
            );
            assert!(
                (sum_b - 1.0).abs() < 4e-15,
                "order {}: sum b {sum_b}",
                c.order()
            );
            assert!(a.iter().eq(a.iter().rev()) && b.iter().eq(b.iter().rev()));
            assert!(s < 2 * MAX_HALF);
        }
        assert_eq!(Nystrom::BLANES_MOAN_6.stages(), 6);
        assert_eq!(Nystrom::BLANES_MOAN_11.stages(), 11);
    }

    /// The quadrature conditions, the order conditions of `q'' = f(t)` (drift `A`, kick
    /// `B` of a time-dependent force; `[B, [B, A]] = 0` there, so every Nystrom method
    /// must meet them): `sum b_i c_i^k = 1 / (k + 1)` for `k < order`, with `c_i` the time
    /// the `i`-th kick acts at, `a_1 + ... + a_(i-1)`. The published digits meet them to
    /// about 1e-15; a typo in a coefficient breaks one.
    #[test]
    fn nystrom_coefficients_meet_the_quadrature_conditions() {
        for c in NYSTROMS {
            let s = c.stages();
            let mut time = 0.0;
            let nodes: Vec<(f64, f64)> = (0..=s)
                .map(|i| {
                    let node = (c.b(i), time);
                    if i < s {
                        time += c.a(i);
                    }
                    node
                })
                .collect();
            for k in 0..c.order() as i32 {
                let sum: f64 = nodes.iter().map(|(b, t)| b * t.powi(k)).sum();
                let expected = 1.0 / f64::from(k + 1);
                assert!(
                    (sum - expected).abs() < 1e-14,
                    "order {}: sum b c^{k} = {sum} against {expected}",
                    c.order()
                );
            }
        }
    }

    /// `n` steps of a Nystrom splitting (kick first) of the pendulum over `[0, t]`.
    fn nystrom(c: Nystrom, mut y: [f64; 2], t: f64, n: u32) -> [f64; 2] {
        let h = t / f64::from(n);
        for _ in 0..n {
            for i in 0..c.stages() {
                y[1] -= c.b(i) * h * y[0].sin();
                y[0] += c.a(i) * h * y[1];
            }
            y[1] -= c.b(c.stages()) * h * y[0].sin();
        }
        y
    }

    /// The observed order on the pendulum, a Runge-Kutta-Nystrom problem where every
    /// condition of that class counts. Amplitude 1 over `t = 8`: at amplitude 2 the
    /// optimised leading error term of `SRKN_6^b` is so small that the slope is still 3.9
    /// when rounding sets in.
    #[test]
    fn nystrom_observed_order_on_the_pendulum() {
        let (y0, t) = ([1.0, 0.0], 8.0);
        let reference = rk4(y0, t, 40_000);
        for (c, steps) in [
            (Nystrom::BLANES_MOAN_6, [20, 28, 40, 56]),
            (Nystrom::BLANES_MOAN_11, [14, 20, 28, 40]),
        ] {
            let (mut xs, mut ys) = (Vec::new(), Vec::new());
            for n in steps {
                let y = nystrom(c, y0, t, n);
                let error = (y[0] - reference[0]).hypot(y[1] - reference[1]);
                xs.push((t / f64::from(n)).ln());
                ys.push(error.ln());
            }
            let n = xs.len() as f64;
            let (mx, my) = (xs.iter().sum::<f64>() / n, ys.iter().sum::<f64>() / n);
            let sxy: f64 = xs.iter().zip(&ys).map(|(x, y)| (x - mx) * (y - my)).sum();
            let sxx: f64 = xs.iter().map(|x| (x - mx) * (x - mx)).sum();
            let order = sxy / sxx;
            println!("nystrom order {}: observed {order:.3}", c.order());
            assert!(
                (order - f64::from(c.order())).abs() < 0.1,
                "order {}: observed {order}",
                c.order()
            );
        }
    }

    #[test]
    fn unknown_orders_are_refused() {
        assert!(Composition::of_order(3).is_err());
        assert_eq!(Composition::of_order(8).unwrap(), Composition::KAHAN_LI_8);
    }
}
