//! An adaptive Lie-group Runge-Kutta method of order eight: Runge-Kutta-Munthe-Kaas
//! (H. Munthe-Kaas, "High order Runge-Kutta methods on manifolds", Appl. Numer. Math. 29
//! (1999) 115-127) with the explicit 12-stage pair of order 8(5,3) of Dormand and Prince
//! as given by E. Hairer, S. P. Nørsett, G. Wanner, *Solving Ordinary Differential
//! Equations I*, 2nd ed., Springer 1993, section II.10 (the DOP853 code: its tableau,
//! error estimate and step-size control, safety 0.9, step ratio in [1/6, 3]).
//!
//! The rotor obeys `dR/dt = R A`, `A = -1/2 Omega_B`. Write `R = R0 exp(u)`; then
//! `du/dt = dexp^-1_{-u}(A)` on the Lie algebra (bivectors), a vector space, where the
//! Runge-Kutta stages are taken, while `Omega_B` takes them directly. For rotors the
//! inverse derivative of the exponential has a closed form (no truncated bracket series,
//! so the method keeps its order whatever the tableau): with `[x, y] = xy - yx`,
//!
//! ```text
//! dexp^-1_{-u}(A) = A + 1/2 [u, A] + c [u, [u, A]],   c = (1 - x cot x) / (4 x^2),
//! ```
//!
//! `x = |u|` (the eigenvalues of `ad_u` are 0 and `+-2 i x`; `c -> 1/12` as `x -> 0`, the
//! Bernoulli series `1/12 - ...`). `R` moves only by `R0 exp(u)`, so `|R ~R| = 1` by
//! construction (the adaptive driver still scales it once an accepted step, so that the
//! rounding of a million products does not add up). The error estimate is DOP853's, on the six
//! coordinates `(u, Omega_B)`, in which the method is an ordinary Runge-Kutta method.
//! Without a torque `Omega_B` does not depend on `R`, so the stages skip the exponentials
//! and only the step's end pays one. No dense output.

// The coefficients carry the published digits, beyond f64, so that they can be read
// against the sources.
#![allow(clippy::excessive_precision)]

use ga_core::f64::g3::{Bivector, Commutator};

use crate::dynamics::{RigidBody, State};
use crate::error::{self, Error};

use super::integrator::{check_finite, unit, Integrator};

/// The stages.
const S: usize = 12;

/// The nodes `c_i` (`c_12 = 1`).
const C: [f64; S] = [
    0.0,
    0.526_001_519_587_677_318_785_587_544_488E-1,
    0.789_002_279_381_515_978_178_381_316_732E-1,
    0.118_350_341_907_227_396_726_757_197_510,
    0.281_649_658_092_772_603_273_242_802_490,
    1.0 / 3.0,
    0.25,
    4.0 / 13.0,
    127.0 / 195.0,
    0.6,
    6.0 / 7.0,
    1.0,
];

/// The rows `a_ij`, `j < i`, of stages 2 to 12.
const A: [&[f64]; S] = [
    &[],
    &[5.260_015_195_876_773_187_855_875_444_88E-2],
    &[
        1.972_505_698_453_789_945_445_953_291_83E-2,
        5.917_517_095_361_369_836_337_859_875_49E-2,
    ],
    &[
        2.958_758_547_680_684_918_168_929_937_75E-2,
        0.0,
        8.876_275_643_042_054_754_506_789_813_24E-2,
    ],
    &[
        2.413_651_341_592_666_855_023_697_986_65E-1,
        0.0,
        -8.845_494_793_282_860_853_448_649_627_17E-1,
        9.248_340_032_617_920_031_157_379_665_43E-1,
    ],
    &[
        3.703_703_703_703_703_703_703_703_703_7E-2,
        0.0,
        0.0,
        1.708_286_087_294_738_712_796_044_821_73E-1,
        1.254_676_875_668_224_250_166_918_141_23E-1,
    ],
    &[
        3.710_937_5E-2,
        0.0,
        0.0,
        1.702_522_110_195_440_393_149_780_602_72E-1,
        6.021_653_898_045_596_068_502_193_972_83E-2,
        -1.757_812_5E-2,
    ],
    &[
        3.709_200_011_850_479_271_087_793_198_36E-2,
        0.0,
        0.0,
        1.703_839_257_122_399_938_102_140_547_05E-1,
        1.072_620_304_463_732_846_518_091_991_68E-1,
        -1.531_943_774_862_440_175_279_361_582_36E-2,
        8.273_789_163_814_022_887_584_737_660_02E-3,
    ],
    &[
        6.241_109_587_160_757_171_144_295_778_12E-1,
        0.0,
        0.0,
        -3.360_892_629_446_941_294_068_571_098_25,
        -8.682_193_468_417_260_068_181_898_914_53E-1,
        2.759_209_969_944_670_830_494_156_007_97E1,
        2.015_406_755_047_789_340_861_867_889_79E1,
        -4.348_988_418_106_995_884_773_662_551_44E1,
    ],
    &[
        4.776_625_364_382_643_658_904_339_085_27E-1,
        0.0,
        0.0,
        -2.488_114_619_971_667_641_926_425_864_68,
        -5.902_908_268_368_429_963_714_464_757_43E-1,
        2.123_005_144_818_119_423_472_889_498_97E1,
        1.527_923_363_288_242_358_325_969_229_38E1,
        -3.328_821_096_898_486_291_944_532_655_87E1,
        -2.033_120_170_850_862_613_582_229_285_93E-2,
    ],
    &[
        -9.371_424_300_859_873_257_170_402_165_8E-1,
        0.0,
        0.0,
        5.186_372_428_844_063_708_300_238_532_09,
        1.091_437_348_996_729_578_185_002_546_54,
        -8.149_787_010_746_926_125_139_972_673_57,
        -1.852_006_565_999_695_986_415_661_807_01E1,
        2.273_948_709_935_050_428_189_700_567_34E1,
        2.493_605_552_679_652_389_870_893_967_62,
        -3.046_764_471_898_219_500_382_366_902_2,
    ],
    &[
        2.273_310_147_516_538_207_923_597_684_49,
        0.0,
        0.0,
        -1.053_449_546_673_725_019_840_666_898_79E1,
        -2.000_872_058_224_862_499_096_757_184_44,
        -1.795_893_186_311_879_891_727_659_505_34E1,
        2.794_888_452_941_996_005_084_998_088_37E1,
        -2.858_998_277_135_023_694_740_655_086_74,
        -8.872_856_933_530_629_544_335_492_892_58,
        1.236_056_717_579_430_306_472_662_015_28E1,
        6.433_927_460_157_635_303_559_704_840_46E-1,
    ],
];

/// The weights of order eight.
const B: [f64; S] = [
    5.429_373_411_656_876_223_805_357_663_63E-2,
    0.0,
    0.0,
    0.0,
    0.0,
    4.450_312_892_752_408_881_441_139_505_66,
    1.891_517_899_314_500_383_042_815_990_44,
    -5.801_203_960_010_584_781_467_211_422_7,
    3.111_643_669_578_198_944_089_160_623_7E-1,
    -1.521_609_496_625_160_785_561_788_068_05E-1,
    2.013_654_008_040_303_483_747_765_375_01E-1,
    4.471_061_572_777_259_051_768_855_690_43E-2,
];

/// The third-order weights on stages 1, 9 and 12 for the second error estimate.
const BHH: [f64; 3] = [
    0.244_094_488_188_976_377_952_755_905_512,
    0.733_846_688_281_611_857_341_361_741_547,
    0.220_588_235_294_117_647_058_823_529_412E-1,
];

/// The eighth- minus the fifth-order weights.
const E: [f64; S] = [
    0.131_200_449_941_948_807_325_010_299_6E-1,
    0.0,
    0.0,
    0.0,
    0.0,
    -0.122_515_644_637_620_444_072_056_975_3E1,
    -0.495_758_949_657_250_191_521_407_995_2,
    0.166_437_718_245_498_653_696_153_041_5E1,
    -0.350_328_848_749_973_681_688_648_729_0,
    0.334_179_118_713_017_479_029_731_884_1,
    0.819_232_064_851_157_124_657_074_261_3E-1,
    -0.223_553_078_638_862_952_588_442_784_5E-1,
];

const SAFETY: f64 = 0.9;
/// The step may shrink to a sixth and grow to three times per step (DOP853's defaults).
const MIN_RATIO: f64 = 1.0 / 6.0;
const MAX_RATIO: f64 = 3.0;

/// `dexp^-1_{-u}(a) = a + 1/2 [u, a] + c [u, [u, a]]` in closed form; the commutator trait
/// is `(xy - yx)/2`, half the bracket.
#[inline]
fn dexpinv(u: Bivector, a: Bivector) -> Bivector {
    let x2 = u.e12 * u.e12 + u.e13 * u.e13 + u.e23 * u.e23;
    // c(x) = (1 - x cot x) / (4 x^2); its Taylor series where the quotient would cancel.
    let c = if x2 < 1e-2 {
        1.0 / 12.0 + x2 * (1.0 / 180.0 + x2 * (1.0 / 1890.0 + x2 * (1.0 / 18900.0)))
    } else {
        let x = x2.sqrt();
        (1.0 - x / x.tan()) / (4.0 * x2)
    };
    let ua = u.commutator(a) * 2.0;
    a + ua * 0.5 + u.commutator(ua) * (2.0 * c)
}

/// Counts of the work done so far by a [`LieDop853`] integrator.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct LieDop853Stats {
    /// Steps accepted.
    pub accepted: u64,
    /// Steps rejected and retried with a smaller step.
    pub rejected: u64,
}

/// Runge-Kutta-Munthe-Kaas with the Dormand-Prince 8(5,3) pair, adaptive, with relative
/// and absolute tolerances.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LieDop853 {
    rtol: f64,
    atol: f64,
    max_steps: u64,
    next_step: Option<f64>,
    stats: LieDop853Stats,
}

/// One step's result: the Lie-algebra increment, the new `Omega_B`, and the error norm.
struct Trial {
    u: Bivector,
    omega: Bivector,
    error: f64,
}

impl LieDop853 {
    /// The method with tolerances `rtol` and `atol` (finite and positive) and at most 10^6
    /// steps per call of [`Integrator::advance`].
    pub fn new(rtol: f64, atol: f64) -> Result<Self, Error> {
        error::positive("rtol", "tolerance", rtol)?;
        error::positive("atol", "tolerance", atol)?;
        Ok(LieDop853 {
            rtol,
            atol,
            max_steps: 1_000_000,
            next_step: None,
            stats: LieDop853Stats::default(),
        })
    }

    /// The work done so far.
    #[must_use]
    pub fn stats(&self) -> LieDop853Stats {
        self.stats
    }

    /// The twelve stages of one step of length `h` from `state` at `t`.
    fn trial(&self, body: &RigidBody, t: f64, state: &State, h: f64) -> Trial {
        let torque = body.has_torque();
        let mut k = [Bivector::ZERO; S];
        let mut l = [Bivector::ZERO; S];
        for i in 0..S {
            let mut u = Bivector::ZERO;
            let mut v = Bivector::ZERO;
            for (j, &a) in A[i].iter().enumerate() {
                if a != 0.0 {
                    u += k[j] * a;
                    v += l[j] * a;
                }
            }
            let stage = State {
                rotor: if torque && i > 0 {
                    state.rotor * (u * h).exp()
                } else {
                    state.rotor
                },
                omega: state.omega + v * h,
            };
            k[i] = dexpinv(u * h, stage.omega * -0.5);
            l[i] = body.omega_rate(t + C[i] * h, &stage);
        }
        let weighted = |w: &[f64], x: &[Bivector; S]| {
            w.iter()
                .zip(x)
                .fold(Bivector::ZERO, |sum, (&wi, &xi)| sum + xi * wi)
        };
        let (bk, bl) = (weighted(&B, &k), weighted(&B, &l));
        let u = bk * h;
        let omega = state.omega + bl * h;
        let err8 = (weighted(&E, &k), weighted(&E, &l));
        let bhh =
            |b: Bivector, x: &[Bivector; S]| b - x[0] * BHH[0] - x[8] * BHH[1] - x[11] * BHH[2];
        let err3 = (bhh(bk, &k), bhh(bl, &l));
        // DOP853's norm: the fifth-order estimate, damped by the third-order one.
        let rotor_scale = self.atol + self.rtol;
        let parts = |b: Bivector| [b.e12, b.e13, b.e23];
        let (mut sum8, mut sum3) = (0.0, 0.0);
        for (a8, a3) in parts(err8.0).into_iter().zip(parts(err3.0)) {
            sum8 += (a8 / rotor_scale).powi(2);
            sum3 += (a3 / rotor_scale).powi(2);
        }
        let omega_scales = parts(state.omega)
            .into_iter()
            .zip(parts(omega))
            .map(|(w0, w1)| self.atol + self.rtol * w0.abs().max(w1.abs()));
        for ((b8, b3), scale) in parts(err8.1)
            .into_iter()
            .zip(parts(err3.1))
            .zip(omega_scales)
        {
            sum8 += (b8 / scale).powi(2);
            sum3 += (b3 / scale).powi(2);
        }
        let mut deno = sum8 + 0.01 * sum3;
        if deno <= 0.0 {
            deno = 1.0;
        }
        Trial {
            u,
            omega,
            error: h.abs() * sum8 / (6.0 * deno).sqrt(),
        }
    }

    /// One step of length `h` taken whatever its error estimate says: the method with a
    /// fixed step, for measuring its order.
    #[must_use]
    pub fn step_once(&self, body: &RigidBody, t: f64, state: State, h: f64) -> State {
        let trial = self.trial(body, t, &state, h);
        State {
            rotor: state.rotor * trial.u.exp(),
            omega: trial.omega,
        }
    }

    /// A first step from the size of the rates (Hairer-Nørsett-Wanner II.4, order 8).
    fn initial_step(&self, body: &RigidBody, t: f64, state: &State, h_max: f64) -> f64 {
        let w = state.omega;
        let rate = body.omega_rate(t, state);
        let parts = |b: Bivector| [b.e12, b.e13, b.e23];
        let mut d0 = 0.0;
        let mut d1 = 0.0;
        for (wi, ri) in parts(w).into_iter().zip(parts(rate)) {
            let scale = self.atol + self.rtol * wi.abs();
            d0 += (wi / scale).powi(2);
            d1 += (ri / scale).powi(2);
        }
        // The rotor's own rate is |Omega|/2 against a scale of order one.
        let spin = 0.5 * (w.e12 * w.e12 + w.e13 * w.e13 + w.e23 * w.e23).sqrt();
        d1 += 3.0 * (spin / (self.atol + self.rtol)).powi(2);
        d0 += 3.0 / (self.atol + self.rtol).powi(2);
        let h = if d0 <= 1e-10 || d1 <= 1e-10 {
            1e-6
        } else {
            0.01 * (d0 / d1).sqrt()
        };
        let h1 = (0.01 / d1.sqrt().max(1e-15) * (1.0 / h.max(1e-300))).powf(1.0 / 8.0) * h;
        (100.0 * h).min(h1.max(h)).min(h_max)
    }
}

impl Integrator for LieDop853 {
    fn name(&self) -> &'static str {
        "lie-dop853"
    }

    fn advance(&mut self, body: &RigidBody, t: f64, state: State, dt: f64) -> Result<State, Error> {
        error::finite("dt", "time step", dt)?;
        if dt == 0.0 {
            return check_finite(self.name(), state);
        }
        let dir = dt.signum();
        let t_end = t + dt;
        let (mut t, mut state) = (t, state);
        let mut h = match self.next_step {
            Some(h) => h.min(dt.abs()),
            None => self.initial_step(body, t, &state, dt.abs()),
        };
        let mut rejected_last = false;
        let mut steps = 0_u64;
        loop {
            let remaining = (t_end - t) * dir;
            if remaining <= 0.0 {
                break;
            }
            steps += 1;
            if steps > self.max_steps {
                return Err(Error::invalid(
                    "lie-dop853",
                    format!(
                        "more than {} steps needed before t = {t_end}",
                        self.max_steps
                    ),
                ));
            }
            if 0.1 * h <= f64::EPSILON * t.abs() || !h.is_finite() {
                return Err(Error::invalid(
                    "lie-dop853",
                    format!("step size underflow ({h:e}) at t = {t}"),
                ));
            }
            let last = h >= remaining;
            let hs = dir * if last { remaining } else { h };
            let trial = self.trial(body, t, &state, hs);
            let err = trial.error;
            if !err.is_finite() {
                return Err(Error::NotFinite {
                    field: self.name().to_string(),
                    what: "the integrated state",
                    value: err,
                });
            }
            let fac11 = err.powf(1.0 / 8.0);
            let fac = (fac11 / SAFETY).clamp(1.0 / MAX_RATIO, 1.0 / MIN_RATIO);
            if err <= 1.0 {
                self.stats.accepted += 1;
                state = State {
                    // Unit by construction; scaling once a step keeps the rounding of
                    // the products from adding up over millions of steps.
                    rotor: unit(state.rotor * trial.u.exp()),
                    omega: trial.omega,
                };
                t = if last { t_end } else { t + hs };
                let mut h_new = hs.abs() / fac;
                if rejected_last {
                    h_new = h_new.min(hs.abs());
                }
                // A truncated last step says nothing about the next: keep the larger.
                if !(last && h_new < h) {
                    h = h_new;
                }
                rejected_last = false;
            } else {
                h = hs.abs() / (fac11 / SAFETY).min(1.0 / MIN_RATIO);
                self.stats.rejected += 1;
                rejected_last = true;
            }
        }
        self.next_step = Some(h);
        check_finite(self.name(), state)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `c_i = sum_j a_ij`, and the quadrature conditions `sum b_i c_i^(k-1) = 1/k` of
    /// order eight: a typo in a coefficient fails one of them.
    #[test]
    fn tableau_satisfies_row_sums_and_quadrature_conditions() {
        for i in 0..S {
            let sum: f64 = A[i].iter().sum();
            assert!((sum - C[i]).abs() < 1e-14, "row {i}: {sum} vs {}", C[i]);
        }
        for k in 1..=8 {
            let q: f64 = (0..S).map(|i| B[i] * C[i].powi(k - 1)).sum();
            assert!((q - 1.0 / f64::from(k)).abs() < 1e-13, "k = {k}: {q}");
        }
        // The fifth-order weights B - E integrate to order five.
        for k in 1..=5 {
            let q: f64 = (0..S).map(|i| (B[i] - E[i]) * C[i].powi(k - 1)).sum();
            assert!((q - 1.0 / f64::from(k)).abs() < 1e-13, "k = {k}: {q}");
        }
        // sum b_i a_ij c_j = 1/6, a condition on A itself.
        let q: f64 = (0..S)
            .map(|i| B[i] * A[i].iter().enumerate().map(|(j, a)| a * C[j]).sum::<f64>())
            .sum();
        assert!((q - 1.0 / 6.0).abs() < 1e-13, "{q}");
    }

    #[test]
    fn dexpinv_matches_its_bernoulli_series_on_both_branches() {
        let a = Bivector::new(0.3, -0.7, 0.2);
        for scale in [0.01, 0.09, 0.11, 0.5] {
            let u = Bivector::new(0.6, 0.0, 0.8) * scale;
            let bracket = |x: Bivector, y: Bivector| x.commutator(y) * 2.0;
            let ad1 = bracket(u, a);
            let ad2 = bracket(u, ad1);
            let ad4 = bracket(u, bracket(u, ad2));
            let ad6 = bracket(u, bracket(u, ad4));
            let ad8 = bracket(u, bracket(u, ad6));
            let series = a + ad1 * 0.5 + ad2 * (1.0 / 12.0) - ad4 * (1.0 / 720.0)
                + ad6 * (1.0 / 30240.0)
                - ad8 * (1.0 / 1_209_600.0);
            let d = dexpinv(u, a) - series;
            let size = (d.e12 * d.e12 + d.e13 * d.e13 + d.e23 * d.e23).sqrt();
            assert!(
                size < 1e-15 + 1e-3 * scale.powi(10),
                "scale {scale}: {size:e}"
            );
        }
    }
}
