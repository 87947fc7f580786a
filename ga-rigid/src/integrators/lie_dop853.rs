//! An adaptive Lie-group Runge-Kutta method of order eight with dense output of order
//! seven: Runge-Kutta-Munthe-Kaas (H. Munthe-Kaas, "High order Runge-Kutta methods on
//! manifolds", Appl. Numer. Math. 29 (1999) 115-127) with the explicit 12-stage pair of
//! order 8(5,3) of Dormand and Prince as given by E. Hairer, S. P. Nørsett, G. Wanner,
//! *Solving Ordinary Differential Equations I*, 2nd ed., Springer 1993, section II.10 (the
//! DOP853 code: its tableau, error estimate and step-size control, safety 0.9, step ratio
//! in [1/3, 6]), and DOP853's continuous extension (section II.6, "Dense output"; the
//! three extra stages and the coefficients `d4..d7` of the code `dop853.f`).
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
//! `x = |u|` (the eigenvalues of `ad_u` are 0 and `+-2 i x`). Below `x = 1` the stages take
//! `c` from its Bernoulli series `c = sum_n 2^(2n) |B_2n| x^(2n-2) / (4 (2n)!)`, sixteen
//! terms, which is exact to rounding there (the series converges for `x < pi`); above,
//! from `tan`. `R` moves only by `R0 exp(u)`, so `|R ~R| = 1` by construction (the
//! adaptive driver still scales it once an accepted step, so that the rounding of a
//! million products does not add up). The error estimate is DOP853's, on the six
//! coordinates `(u, Omega_B)`, in which the method is an ordinary Runge-Kutta method.
//! Without a torque `Omega_B` does not depend on `R`, so the stages skip the exponentials
//! and only the step's end pays one, from the series of `cos` and `sin x / x`.
//!
//! [`LieDop853::cayley`] takes the same steps in Cayley coordinates, `R = R0 cay(u)`
//! (Iserles, Munthe-Kaas, Nørsett, Zanna, "Lie-group methods", Acta Numerica 9 (2000),
//! section 8.3): `dcay^-1` is a polynomial, so a stage pays no series and the step no
//! sine and cosine; the order, the error estimate and the dense output are the same, the
//! error constant is not (see its documentation).
//!
//! Dense output: [`LieDop853::step`] returns a [`DenseStep`] whose [`DenseStep::at`] gives
//! the state anywhere in the step, and [`LieDop853::dense_advance`] samples a run at given
//! times without cutting a step at each of them. The continuous extension is applied to
//! the Lie-algebra coordinates `(u, Omega_B)`, so `u(theta h)` and `Omega_B(t + theta h)`
//! are polynomials of degree 7 in `theta` and the rotor is `R0 exp(u(theta h))`: unit by
//! construction, with a local error `O(h^8)`. It costs four more stages per step: the rates
//! at the step's end (the next step's first `Omega_B` rate, which the sampled run reuses)
//! and three stages at `theta = 0.1, 0.2, 7/9`.

// The coefficients carry the published digits, beyond f64, so that they can be read
// against the sources.
#![allow(clippy::excessive_precision)]

use ga_core::f64::g3::{Bivector, Commutator, Rotor};

use crate::dynamics::{RigidBody, State};
use crate::error::{self, Error};

use super::integrator::{check_finite, scaled_norm, step_limit_reached, unit, Integrator};

/// The stages.
pub(crate) const S: usize = 12;

/// The nodes `c_i` (`c_12 = 1`).
pub(crate) const C: [f64; S] = [
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
pub(crate) const A: [&[f64]; S] = [
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
pub(crate) const B: [f64; S] = [
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
pub(crate) const BHH: [f64; 3] = [
    0.244_094_488_188_976_377_952_755_905_512,
    0.733_846_688_281_611_857_341_361_741_547,
    0.220_588_235_294_117_647_058_823_529_412E-1,
];

/// The eighth- minus the fifth-order weights.
pub(crate) const E: [f64; S] = [
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

/// The stages of the continuous extension: the twelve, the rates at the step's end
/// (stage 13, node 1, weights `B`) and three more.
const SD: usize = 16;

/// The nodes of stages 14, 15 and 16.
const C_DENSE: [f64; 3] = [0.1, 0.2, 7.0 / 9.0];

/// The rows `a_ij`, `j <= 13`, of stages 14 to 16 (`dop853.f`, `a141..a1615`).
const A_DENSE: [&[f64]; 3] = [
    &[
        5.616_750_228_304_795_233_929_092_196_81E-2,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
        2.535_002_102_166_248_110_887_947_653_33E-1,
        -2.462_390_374_708_024_899_174_414_754_41E-1,
        -1.241_914_232_638_163_604_690_101_406_26E-1,
        1.532_917_982_787_656_973_120_632_268_5E-1,
        8.201_052_295_634_689_884_916_666_020_57E-3,
        7.567_897_660_545_699_761_386_035_895_84E-3,
        -8.298E-3,
    ],
    &[
        3.183_464_816_350_214_050_607_684_732_61E-2,
        0.0,
        0.0,
        0.0,
        0.0,
        2.830_090_967_236_677_552_883_229_614_02E-2,
        5.354_198_830_743_856_762_237_973_843_72E-2,
        -5.492_374_857_139_098_846_465_693_403_06E-2,
        0.0,
        0.0,
        -1.083_473_286_972_493_228_585_093_169_94E-4,
        3.825_710_908_356_584_129_549_201_923_23E-4,
        -3.404_650_086_874_045_608_029_771_144_92E-4,
        1.413_124_436_746_325_002_780_746_183_66E-1,
    ],
    &[
        -4.288_963_015_837_919_234_085_735_386_92E-1,
        0.0,
        0.0,
        0.0,
        0.0,
        -4.697_621_415_361_163_843_144_494_472_06,
        7.683_421_196_062_599_041_842_409_538_78,
        4.068_989_818_397_110_079_702_135_543_31,
        3.567_271_874_552_811_092_706_695_430_21E-1,
        0.0,
        0.0,
        0.0,
        -1.399_024_165_159_014_621_294_180_097_34E-3,
        2.947_514_789_152_772_338_955_627_214_9,
        -9.150_958_472_179_870_010_818_701_871_38,
    ],
];

/// The coefficients `d4..d7` of the interpolation polynomial on stages 1 to 16
/// (`dop853.f`, `d41..d716`).
const D: [[f64; SD]; 4] = [
    [
        -8.428_938_276_109_012_865_135_349_114_2,
        0.0,
        0.0,
        0.0,
        0.0,
        5.667_149_535_193_777_696_253_178_359E-1,
        -3.068_949_945_949_891_691_279_730_472_7,
        2.384_667_656_512_069_828_772_814_968,
        2.117_034_582_445_028_276_715_514_994_6,
        -8.713_915_837_779_729_920_678_990_749E-1,
        2.240_437_430_260_788_275_854_177_165,
        6.315_787_787_694_688_181_557_024_929E-1,
        -8.899_033_645_133_331_082_069_811_74E-2,
        1.814_850_552_085_472_725_665_640_496_2E1,
        -9.194_632_392_478_355_400_045_198_443_6,
        -4.436_036_387_594_893_966_431_057_2,
    ],
    [
        1.042_750_864_257_913_460_341_315_100_9E1,
        0.0,
        0.0,
        0.0,
        0.0,
        2.422_834_917_752_581_828_843_017_531_9E2,
        1.652_004_517_172_702_819_850_539_488_7E2,
        -3.745_467_547_226_902_027_951_831_215_2E2,
        -2.211_366_685_312_530_603_627_093_857_8E1,
        7.733_432_668_472_263_838_960_389_880_8,
        -3.067_408_473_108_939_818_206_121_362_6E1,
        -9.332_130_526_430_227_872_956_722_170_6,
        1.569_723_812_177_084_388_613_109_107_5E1,
        -3.113_940_321_956_517_767_728_285_041_1E1,
        -9.352_924_358_844_478_386_571_386_266_4,
        3.581_684_148_639_408_375_246_589_854E1,
    ],
    [
        1.998_505_324_200_243_382_098_765_361_7E1,
        0.0,
        0.0,
        0.0,
        0.0,
        -3.870_373_087_493_517_655_510_590_174_2E2,
        -1.891_781_381_951_675_688_283_083_832_8E2,
        5.278_081_592_054_236_490_056_101_668_6E2,
        -1.157_390_253_995_963_012_614_187_113_4E1,
        6.881_232_694_696_300_016_966_692_266_1,
        -1.000_605_096_691_083_840_318_386_098,
        7.777_137_798_053_443_209_286_926_574E-1,
        -2.778_205_752_353_508_406_593_200_433_9,
        -6.019_669_523_126_412_075_826_738_084_6E1,
        8.432_040_550_667_716_101_815_990_378_4E1,
        1.199_229_113_618_278_932_803_513_003E1,
    ],
    [
        -2.569_393_346_270_374_900_331_258_612_9E1,
        0.0,
        0.0,
        0.0,
        0.0,
        -1.541_897_486_902_364_337_405_399_362_7E2,
        -2.315_293_791_760_454_956_753_603_910_9E2,
        3.576_391_179_106_141_237_828_534_991E2,
        9.340_532_418_362_431_000_390_769_170_4E1,
        -3.745_832_313_645_163_315_687_513_935_1E1,
        1.040_996_495_089_623_004_514_724_618_4E2,
        2.984_029_342_666_050_312_334_436_357_9E1,
        -4.353_345_659_001_114_375_443_217_505_8E1,
        9.632_455_395_918_828_294_839_495_06E1,
        -3.917_726_167_561_543_916_523_148_617_2E1,
        -1.497_268_362_579_856_258_142_212_527_6E2,
    ],
];

pub(crate) const SAFETY: f64 = 0.9;
/// The step may shrink to a third and grow to six times per step (DOP853's defaults,
/// `WORK(3) = 0.333`, `WORK(4) = 6`).
pub(crate) const MIN_RATIO: f64 = 0.333;
pub(crate) const MAX_RATIO: f64 = 6.0;
/// DOP853 stretches a step by up to 1 % rather than leave a sliver of a last step.
pub(crate) const STRETCH: f64 = 1.01;

/// The Taylor coefficients of `c(x) = (1 - x cot x) / (4 x^2)` in powers of `x^2`:
/// `2^(2n) |B_2n| / (4 (2n)!)`, `n = 1..16` (`1/12, 1/180, 1/1890, 1/18900, ...`).
const C_SERIES: [f64; 16] = [
    8.333_333_333_333_333_333_333E-2,
    5.555_555_555_555_555_555_556E-3,
    5.291_005_291_005_291_005_291E-4,
    5.291_005_291_005_291_005_291E-5,
    5.344_449_788_894_233_338_68E-6,
    5.411_010_702_015_993_021_28E-7,
    5.481_486_962_968_444_449_93E-8,
    5.553_652_197_494_919_769_01E-9,
    5.626_961_629_202_248_213_55E-10,
    5.701_287_801_148_045_716_47E-11,
    5.776_608_149_750_656_024_13E-12,
    5.852_926_704_956_220_989_8E-13,
    5.930_254_350_058_413_573_76E-14,
    6.008_603_833_326_926_544_77E-15,
    6.087_988_507_295_842_182_78E-16,
    6.168_422_011_293_018_676_47E-17,
];

/// `4 C_SERIES`, the series of `4 c` that the stages use (a power of two: exact).
const C4_SERIES: [f64; 16] = {
    let mut a = C_SERIES;
    let mut i = 0;
    while i < a.len() {
        a[i] *= 4.0;
        i += 1;
    }
    a
};

/// `4 c(x)` from its series below `x^2 = 1`, where sixteen terms reach rounding (the next
/// is `6e-18` against `c = 0.089`). Estrin's scheme keeps the dependency chain four
/// products deep instead of Horner's sixteen. (Ten terms would do below `x^2 = 1/4`, but
/// the branch costs more than the six products it saves.)
#[inline]
fn c4_series(x2: f64) -> f64 {
    let a = &C4_SERIES;
    let x4 = x2 * x2;
    let x8 = x4 * x4;
    let x16 = x8 * x8;
    let pair = |i: usize| a[i] + a[i + 1] * x2;
    let quad = |i: usize| pair(i) + pair(i + 2) * x4;
    let oct = |i: usize| quad(i) + quad(i + 4) * x8;
    oct(0) + oct(8) * x16
}

/// `4 c(x) = (1 - x cot x) / x^2` from `x^2`: the series below `x^2 = 1`, `tan` above.
#[inline]
fn c4_of(x2: f64) -> f64 {
    if x2 < 1.0 {
        c4_series(x2)
    } else {
        let x = x2.sqrt();
        (1.0 - x / x.tan()) / x2
    }
}

/// `dexp^-1_{-u}(a) = a + 1/2 [u, a] + c [u, [u, a]]` in closed form; the commutator trait
/// is `(xy - yx)/2`, half the bracket, so with `g = u.commutator(a)` this is
/// `a + g + 4 c u.commutator(g)`.
#[inline(always)]
fn dexpinv(u: Bivector, a: Bivector) -> Bivector {
    let x2 = u.e12 * u.e12 + u.e13 * u.e13 + u.e23 * u.e23;
    let g = u.commutator(a);
    a + g + u.commutator(g) * c4_of(x2)
}

/// The Taylor coefficients `(-1)^n / (2n + k)!`, `n = 0..9`, of `cos x` (`k = 0`) and of
/// `sin x / x` (`k = 1`) in powers of `x^2`.
const fn trig_series(k: u32) -> [f64; 10] {
    let mut a = [0.0; 10];
    let mut factorial = 1.0;
    let mut n = 0;
    while n < 10 {
        a[n] = if n % 2 == 0 {
            1.0 / factorial
        } else {
            -1.0 / factorial
        };
        let m = 2 * n as u32 + k;
        factorial *= ((m + 1) * (m + 2)) as f64;
        n += 1;
    }
    a
}

const COS_SERIES: [f64; 10] = trig_series(0);
const SINC_SERIES: [f64; 10] = trig_series(1);

/// A ten-term series in `x^2` by Estrin's scheme.
#[inline(always)]
fn series10(a: &[f64; 10], x2: f64) -> f64 {
    let x4 = x2 * x2;
    let x8 = x4 * x4;
    let pair = |i: usize| a[i] + a[i + 1] * x2;
    let quad = |i: usize| pair(i) + pair(i + 2) * x4;
    (quad(0) + quad(4) * x8) + pair(8) * (x8 * x8)
}

/// `exp(u) = cos|u| + u sin|u| / |u|` from the two series below `|u| = 1`, where ten terms
/// reach rounding (the first left out is at most `1/19! = 8e-18`), and ga-core's `exp`
/// above: the step's end and the stages of a torqued body pay no `sin` and `cos`.
#[inline]
fn exp(u: Bivector) -> Rotor {
    let x2 = u.e12 * u.e12 + u.e13 * u.e13 + u.e23 * u.e23;
    if x2 >= 1.0 {
        return u.exp();
    }
    let weight = series10(&SINC_SERIES, x2);
    Rotor::new(
        series10(&COS_SERIES, x2),
        weight * u.e12,
        weight * u.e13,
        weight * u.e23,
    )
}

/// The Cayley map `cay(u) = (1 + u/2)(1 - u/2)^-1 = (1 - |u|^2/4 + u) / (1 + |u|^2/4)`
/// (A. Iserles, H. Munthe-Kaas, S. P. Nørsett, A. Zanna, "Lie-group methods", Acta
/// Numerica 9 (2000) 215-365, section 8.3): a unit rotor for every bivector `u`
/// (`u^2 = -|u|^2`), the identity plus `u` to first order like `exp(u)`, for one division.
#[inline]
fn cay(u: Bivector) -> Rotor {
    let quarter = 0.25 * (u.e12 * u.e12 + u.e13 * u.e13 + u.e23 * u.e23);
    let d = 1.0 / (1.0 + quarter);
    Rotor::new((1.0 - quarter) * d, d * u.e12, d * u.e13, d * u.e23)
}

/// `dcay^-1_u(a) = (1 + u/2) a (1 - u/2) = a + 1/2 [u, a] - 1/4 u a u`, the rate of `u`
/// for which `d/dt cay(u) = cay(u) a`. For bivectors `u a u = |u|^2 a - 2 (u . a) u` with
/// the Euclidean dot product of the components (`u a + a u = -2 u . a`), and the
/// commutator trait is `(xy - yx)/2`, so this is
/// `(1 - |u|^2/4) a + u.commutator(a) + 1/2 (u . a) u`: a polynomial, no series.
#[inline(always)]
fn dcayinv(u: Bivector, a: Bivector) -> Bivector {
    let x2 = u.e12 * u.e12 + u.e13 * u.e13 + u.e23 * u.e23;
    let dot = u.e12 * a.e12 + u.e13 * a.e13 + u.e23 * a.e23;
    a * (1.0 - 0.25 * x2) + u.commutator(a) + u * (0.5 * dot)
}

/// The coordinates of the group, chosen at compile time in the stages: the exponential
/// (Munthe-Kaas) or the Cayley map.
#[inline(always)]
fn map<const CAYLEY: bool>(u: Bivector) -> Rotor {
    if CAYLEY {
        cay(u)
    } else {
        exp(u)
    }
}

/// The inverse derivative of [`map`].
#[inline(always)]
fn map_rate<const CAYLEY: bool>(u: Bivector, a: Bivector) -> Bivector {
    if CAYLEY {
        dcayinv(u, a)
    } else {
        dexpinv(u, a)
    }
}

/// A point or rate of the six coordinates `(u, Omega_B)` the stages live in, packed in
/// one array so that the stage combinations run two coordinates an instruction.
type Six = [f64; 6];

/// `(u, Omega_B)` packed.
#[inline(always)]
fn six(u: Bivector, omega: Bivector) -> Six {
    [u.e12, u.e13, u.e23, omega.e12, omega.e13, omega.e23]
}

/// `(u, Omega_B)` unpacked.
#[inline(always)]
fn halves(y: &Six) -> (Bivector, Bivector) {
    (
        Bivector::new(y[0], y[1], y[2]),
        Bivector::new(y[3], y[4], y[5]),
    )
}

/// `y0 + h sum_j w_j x_j` over the nonzero `w_j`: the tables are constants, so once the
/// loops unroll the zero weights cost nothing.
#[inline(always)]
fn combine(y0: &Six, h: f64, w: &[f64], x: &[Six]) -> Six {
    let mut sum = [0.0; 6];
    for (&wj, xj) in w.iter().zip(x) {
        if wj != 0.0 {
            for (s, xc) in sum.iter_mut().zip(xj) {
                *s += wj * xc;
            }
        }
    }
    std::array::from_fn(|c| y0[c] + h * sum[c])
}

/// `sum_j w_j x_j` over the nonzero `w_j`.
#[inline(always)]
fn weighted(w: &[f64], x: &[Six]) -> Six {
    combine(&[0.0; 6], 1.0, w, x)
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
/// and absolute tolerances, and dense output of order seven ([`LieDop853::step`],
/// [`LieDop853::dense_advance`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LieDop853 {
    rtol: f64,
    atol: f64,
    max_steps: u64,
    /// The run's bound on all its steps ([`Integrator::limit_steps`]), counted in `stats`
    /// (from construction); it replaces `max_steps`.
    run_limit: Option<u64>,
    next_step: Option<f64>,
    stats: LieDop853Stats,
    cayley: bool,
}

/// One step's result: the Lie-algebra increment, the new `Omega_B`, and the error norm.
struct Trial {
    u: Bivector,
    omega: Bivector,
    error: f64,
}

/// One accepted step: its signed length, whether it ends the interval, and its result.
struct Accepted {
    h: f64,
    last: bool,
    trial: Trial,
}

/// The stage rates `(du/dt, dOmega_B/dt)` of a step, the twelve of the method and the
/// four of the continuous extension.
type Rates = [Six; SD];

/// One accepted step of [`LieDop853`] with its continuous extension of order seven: the
/// state at any time of the step, from [`DenseStep::at`].
///
/// With `theta = (t - t0) / h`, the Lie-algebra increment `u` and `Omega_B` are
/// polynomials of degree 7 in `theta` (DOP853's, Hairer-Nørsett-Wanner II.6) and the rotor
/// is `R0 exp(u)` (`R0 cay(u)` in Cayley coordinates), unit by construction. Between steps
/// the output is continuous: `theta = 0` gives the step's start and `theta = 1` its end
/// (to rounding).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DenseStep {
    t0: f64,
    t1: f64,
    h: f64,
    start: State,
    end: State,
    /// Whether the step was taken in Cayley coordinates (`R0 cay(u)`) rather than `R0 exp(u)`.
    cayley: bool,
    /// The coefficients `r2..r8` of DOP853's polynomial for `(u, Omega_B)`; `r1` is
    /// `(0, Omega_B(t0))`.
    r: [Six; 7],
}

impl DenseStep {
    /// The time the step starts at.
    #[must_use]
    pub fn start_time(&self) -> f64 {
        self.t0
    }

    /// The time the step ends at.
    #[must_use]
    pub fn end_time(&self) -> f64 {
        self.t1
    }

    /// The state at the start.
    #[must_use]
    pub fn start_state(&self) -> State {
        self.start
    }

    /// The state at the end: the step's own result (the rotor scaled to unit norm), which
    /// the next step starts from.
    #[must_use]
    pub fn end_state(&self) -> State {
        self.end
    }

    /// The interpolated state at time `t`, which must lie in the step (between
    /// [`DenseStep::start_time`] and [`DenseStep::end_time`], both included); an
    /// [`Error::OutOfRange`] naming `t` otherwise.
    pub fn at(&self, t: f64) -> Result<State, Error> {
        let (lo, hi) = if self.h > 0.0 {
            (self.t0, self.t1)
        } else {
            (self.t1, self.t0)
        };
        if !(lo..=hi).contains(&t) {
            return Err(Error::OutOfRange {
                field: "t".to_string(),
                value: t,
                start: self.t0,
                end: self.t1,
            });
        }
        // The last step of an interval ends on its end time, a rounding away from t0 + h.
        let theta = ((t - self.t0) / self.h).clamp(0.0, 1.0);
        let (u, omega) = halves(&polynomial(
            &six(Bivector::ZERO, self.start.omega),
            &self.r,
            theta,
        ));
        Ok(State {
            rotor: self.start.rotor * if self.cayley { cay(u) } else { exp(u) },
            omega,
        })
    }
}

/// DOP853's interpolation polynomial `y0 + theta (r2 + (1 - theta) (r3 + theta (r4 + ...)))`.
#[inline]
fn polynomial(y0: &Six, r: &[Six; 7], theta: f64) -> Six {
    let s = 1.0 - theta;
    std::array::from_fn(|c| {
        let [r2, r3, r4, r5, r6, r7, r8] = r.map(|ri| ri[c]);
        let tail = r5 + (r6 + (r7 + r8 * theta) * s) * theta;
        y0[c] + (r2 + (r3 + (r4 + tail * s) * theta) * s) * theta
    })
}

impl LieDop853 {
    /// The method with tolerances `rtol` and `atol` (finite and positive) and at most 10^6
    /// steps per call of [`Integrator::advance`] or [`LieDop853::dense_advance`].
    pub fn new(rtol: f64, atol: f64) -> Result<Self, Error> {
        error::positive("rtol", "tolerance", rtol)?;
        error::positive("atol", "tolerance", atol)?;
        Ok(LieDop853 {
            rtol,
            atol,
            max_steps: 1_000_000,
            run_limit: None,
            next_step: None,
            stats: LieDop853Stats::default(),
            cayley: false,
        })
    }

    /// The same method in Cayley coordinates, `R = R0 cay(u)` with `dcay^-1` a polynomial
    /// (Iserles, Munthe-Kaas, Nørsett, Zanna 2000, section 8.3): the stages pay no series
    /// for `dexp^-1` and the step no sine and cosine. Same order, tableau, error estimate,
    /// controller and dense output, and the rotor stays unit by construction; the error
    /// constant differs (on the Hairer-Vilmart body about twice exp's at the same
    /// tolerance, on the Hairer-Lubich-Wanner body the same number of steps to 1e-10).
    pub fn cayley(rtol: f64, atol: f64) -> Result<Self, Error> {
        Ok(LieDop853 {
            cayley: true,
            ..LieDop853::new(rtol, atol)?
        })
    }

    /// `R0 exp(u)` or `R0 cay(u)`, the coordinates this method steps in.
    #[inline]
    fn moved(&self, rotor: Rotor, u: Bivector) -> Rotor {
        rotor * if self.cayley { cay(u) } else { exp(u) }
    }

    /// The work done so far.
    #[must_use]
    pub fn stats(&self) -> LieDop853Stats {
        self.stats
    }

    /// The twelve stages of one step of length `h` from `state` at `t`, whose `Omega_B`
    /// rate `rate0` is known; the rates are left in `rates` for the dense output.
    fn trial(
        &self,
        body: &RigidBody,
        t: f64,
        state: &State,
        h: f64,
        rate0: Bivector,
        rates: &mut Rates,
    ) -> Trial {
        if self.cayley {
            self.trial_in::<true>(body, t, state, h, rate0, rates)
        } else {
            self.trial_in::<false>(body, t, state, h, rate0, rates)
        }
    }

    /// [`LieDop853::trial`] in the coordinates `CAYLEY` chooses.
    fn trial_in<const CAYLEY: bool>(
        &self,
        body: &RigidBody,
        t: f64,
        state: &State,
        h: f64,
        rate0: Bivector,
        rates: &mut Rates,
    ) -> Trial {
        let torque = body.has_torque();
        let y0 = six(Bivector::ZERO, state.omega);
        rates[0] = six(state.omega * -0.5, rate0);
        // Written out stage by stage, so that each combination is straight-line code with
        // its constant coefficients and no product by a zero one.
        macro_rules! stages {
            ($($i:literal)*) => {$(
                let (u, omega) = halves(&combine(&y0, h, A[$i], rates));
                let stage = State {
                    rotor: if torque {
                        state.rotor * map::<CAYLEY>(u)
                    } else {
                        state.rotor
                    },
                    omega,
                };
                rates[$i] = six(
                    map_rate::<CAYLEY>(u, omega * -0.5),
                    body.omega_rate(t + C[$i] * h, &stage),
                );
            )*};
        }
        stages!(1 2 3 4 5 6 7 8 9 10 11);
        let b = weighted(&B, rates);
        let y1: Six = std::array::from_fn(|c| y0[c] + h * b[c]);
        let err8 = weighted(&E, rates);
        let err3 = combine(&b, -1.0, &BHH, &[rates[0], rates[8], rates[11]]);
        // DOP853's norm: the fifth-order estimate, damped by the third-order one, with the
        // scale `atol + rtol max(|y0|, |y1|)` per coordinate; `u` runs from 0, and a
        // rotor's coordinates are of order one, so its scale is `atol + rtol`.
        let weights: Six = std::array::from_fn(|c| {
            let size = if c < 3 {
                1.0
            } else {
                y0[c].abs().max(y1[c].abs())
            };
            1.0 / (self.atol + self.rtol * size)
        });
        let (mut sum8, mut sum3) = (0.0, 0.0);
        for c in 0..6 {
            let (a8, a3) = (err8[c] * weights[c], err3[c] * weights[c]);
            sum8 += a8 * a8;
            sum3 += a3 * a3;
        }
        let mut deno = sum8 + 0.01 * sum3;
        if deno <= 0.0 {
            deno = 1.0;
        }
        let (u, omega) = halves(&y1);
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
        let mut rates: Rates = [[0.0; 6]; SD];
        let rate0 = body.omega_rate(t, &state);
        let trial = self.trial(body, t, &state, h, rate0, &mut rates);
        State {
            rotor: self.moved(state.rotor, trial.u),
            omega: trial.omega,
        }
    }

    /// One step of length `h` taken whatever its error estimate says, with its dense
    /// output: [`LieDop853::step_once`] and its continuous extension, for measuring the
    /// interpolation's order.
    #[must_use]
    pub fn dense_step_once(&self, body: &RigidBody, t: f64, state: State, h: f64) -> DenseStep {
        let mut rates: Rates = [[0.0; 6]; SD];
        let rate0 = body.omega_rate(t, &state);
        let trial = self.trial(body, t, &state, h, rate0, &mut rates);
        self.dense(body, t, &state, h, t + h, &trial, &mut rates).0
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
        let h0 = (100.0 * h).min(h1.max(h)).min(h_max);
        if h0 > 0.0 && h0.is_finite() {
            return h0;
        }
        // The squares above overflow when |w| is near 1e80 (its rate near 1e160), which
        // left h = 0; the same estimate from norms taken with scaling.
        let scale = |wi: f64| self.atol + self.rtol * wi.abs();
        let root3 = 3f64.sqrt() / (self.atol + self.rtol);
        let (w3, r3) = (parts(w), parts(rate));
        let n0 = scaled_norm(&[
            w3[0] / scale(w3[0]),
            w3[1] / scale(w3[1]),
            w3[2] / scale(w3[2]),
            root3,
        ]);
        let spin = 0.5 * scaled_norm(&w3);
        let n1 = scaled_norm(&[
            r3[0] / scale(w3[0]),
            r3[1] / scale(w3[1]),
            r3[2] / scale(w3[2]),
            spin * root3,
        ]);
        let h = if n0 <= 1e-5 || n1 <= 1e-5 {
            1e-6
        } else {
            0.01 * n0 / n1
        };
        let h1 = (0.01 / n1.max(1e-15) * (1.0 / h.max(1e-300))).powf(1.0 / 8.0) * h;
        (100.0 * h).min(h1.max(h)).min(h_max)
    }

    /// One accepted step from `state` at `t` toward `t_end` (never past it), retrying
    /// rejected ones with DOP853's controller; `attempts` counts the tries of the current
    /// call against `max_steps`.
    // Private, and each argument is a different thing (the start, the end, the scratch
    // space, the count): a struct would only rename them.
    #[allow(clippy::too_many_arguments)]
    fn accepted_step(
        &mut self,
        body: &RigidBody,
        t: f64,
        state: &State,
        t_end: f64,
        rate0: Bivector,
        rates: &mut Rates,
        attempts: &mut u64,
    ) -> Result<Accepted, Error> {
        let dir = (t_end - t).signum();
        let remaining = (t_end - t).abs();
        let mut h = match self.next_step {
            Some(h) => h.min(remaining),
            None => self.initial_step(body, t, state, remaining),
        };
        let mut rejected_last = false;
        loop {
            *attempts += 1;
            if let Some(limit) = self.run_limit {
                if self.stats.accepted + self.stats.rejected >= limit {
                    return Err(step_limit_reached(self.name(), limit, t, t_end));
                }
            } else if *attempts > self.max_steps {
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
            let last = STRETCH * h >= remaining;
            let hs = dir * if last { remaining } else { h };
            let trial = self.trial(body, t, state, hs, rate0, rates);
            let err = trial.error;
            if !err.is_finite() {
                return Err(Error::NotFinite {
                    field: self.name().to_string(),
                    what: "the integrated state",
                    value: err,
                });
            }
            // err^(1/8) by three square roots, cheaper than `powf`.
            let fac11 = err.sqrt().sqrt().sqrt();
            if err <= 1.0 {
                self.stats.accepted += 1;
                let fac = (fac11 / SAFETY).clamp(1.0 / MAX_RATIO, 1.0 / MIN_RATIO);
                let mut h_new = hs.abs() / fac;
                if rejected_last {
                    h_new = h_new.min(hs.abs());
                }
                // A truncated last step says nothing about the next: keep the larger.
                self.next_step = Some(if last && h_new < h { h } else { h_new });
                return Ok(Accepted { h: hs, last, trial });
            }
            h = hs.abs() / (fac11 / SAFETY).min(1.0 / MIN_RATIO);
            self.stats.rejected += 1;
            rejected_last = true;
        }
    }

    /// The continuous extension of an accepted step of signed length `h` from `state` at
    /// `t`, ending at `t1`, from its twelve stages in `rates`: the rates at the end (stage
    /// 13) and stages 14 to 16, then DOP853's coefficients. Also returns the `Omega_B` rate
    /// at the end, the next step's first.
    #[allow(clippy::too_many_arguments)] // As for `accepted_step`.
    fn dense(
        &self,
        body: &RigidBody,
        t: f64,
        state: &State,
        h: f64,
        t1: f64,
        trial: &Trial,
        rates: &mut Rates,
    ) -> (DenseStep, Bivector) {
        if self.cayley {
            self.dense_in::<true>(body, t, state, h, t1, trial, rates)
        } else {
            self.dense_in::<false>(body, t, state, h, t1, trial, rates)
        }
    }

    /// [`LieDop853::dense`] in the coordinates `CAYLEY` chooses.
    #[allow(clippy::too_many_arguments)] // As for `accepted_step`.
    fn dense_in<const CAYLEY: bool>(
        &self,
        body: &RigidBody,
        t: f64,
        state: &State,
        h: f64,
        t1: f64,
        trial: &Trial,
        rates: &mut Rates,
    ) -> (DenseStep, Bivector) {
        let torque = body.has_torque();
        // The step's end scaled to unit, as the next step starts from it: its rate is then
        // the next step's first exactly, so a sampled run takes the steps of `advance`.
        let end = State {
            rotor: unit(state.rotor * map::<CAYLEY>(trial.u)),
            omega: trial.omega,
        };
        let y0 = six(Bivector::ZERO, state.omega);
        let y1 = six(trial.u, trial.omega);
        rates[S] = six(
            map_rate::<CAYLEY>(trial.u, trial.omega * -0.5),
            body.omega_rate(t1, &end),
        );
        for (i, (row, c)) in A_DENSE.iter().zip(C_DENSE).enumerate() {
            let (u, omega) = halves(&combine(&y0, h, row, rates));
            let stage = State {
                rotor: if torque {
                    state.rotor * map::<CAYLEY>(u)
                } else {
                    state.rotor
                },
                omega,
            };
            rates[S + 1 + i] = six(
                map_rate::<CAYLEY>(u, omega * -0.5),
                body.omega_rate(t + c * h, &stage),
            );
        }
        let r2: Six = std::array::from_fn(|c| y1[c] - y0[c]);
        let r3: Six = std::array::from_fn(|c| h * rates[0][c] - r2[c]);
        let r4: Six = std::array::from_fn(|c| r2[c] - h * rates[S][c] - r3[c]);
        let [r5, r6, r7, r8] = D.map(|d| combine(&[0.0; 6], h, &d, rates));
        let dense = DenseStep {
            t0: t,
            t1,
            h,
            start: *state,
            end,
            cayley: CAYLEY,
            r: [r2, r3, r4, r5, r6, r7, r8],
        };
        (dense, halves(&rates[S]).1)
    }

    /// One accepted step with its dense output from `state` at `t`, whose `Omega_B` rate
    /// is `rate0`, toward `t_end`; also the `Omega_B` rate at the step's end.
    fn dense_step(
        &mut self,
        body: &RigidBody,
        t: f64,
        state: &State,
        t_end: f64,
        rate0: Bivector,
        attempts: &mut u64,
    ) -> Result<(DenseStep, Bivector), Error> {
        let mut rates: Rates = [[0.0; 6]; SD];
        let step = self.accepted_step(body, t, state, t_end, rate0, &mut rates, attempts)?;
        let t1 = if step.last { t_end } else { t + step.h };
        let (dense, rate1) = self.dense(body, t, state, step.h, t1, &step.trial, &mut rates);
        check_finite(self.name(), dense.end)?;
        Ok((dense, rate1))
    }

    /// One adaptive step from `state` at `t` toward `t_end` (the step never passes it),
    /// with its dense output: the building block of a user's own loop, e.g. a physics
    /// engine that samples a body at its frame times. The step's size comes from the
    /// tolerances and the step before; the step ends at [`DenseStep::end_time`], with
    /// state [`DenseStep::end_state`]. An error if `t` or `t_end` is not finite, if they
    /// are equal, or if the solution stops being finite.
    ///
    /// ```
    /// use ga_core::f64::g3::{Bivector, Rotor};
    /// use ga_rigid::dynamics::{RigidBody, State};
    /// use ga_rigid::integrators::LieDop853;
    ///
    /// let body = RigidBody::new([1.0, 2.0, 2.5])?;
    /// let mut state = State { rotor: Rotor::ONE, omega: Bivector::new(0.2, -1.0, 0.1) };
    /// let mut method = LieDop853::new(1e-10, 1e-10)?;
    /// let mut t = 0.0;
    /// while t < 5.0 {
    ///     let step = method.step(&body, t, state, 5.0)?;
    ///     let middle = step.at(0.5 * (step.start_time() + step.end_time()))?;
    ///     assert!((middle.rotor.norm() - 1.0).abs() < 1e-15);
    ///     (t, state) = (step.end_time(), step.end_state());
    /// }
    /// assert_eq!(t, 5.0);
    /// # Ok::<(), ga_rigid::error::Error>(())
    /// ```
    pub fn step(
        &mut self,
        body: &RigidBody,
        t: f64,
        state: State,
        t_end: f64,
    ) -> Result<DenseStep, Error> {
        error::finite("t", "time", t)?;
        error::finite("t_end", "time", t_end)?;
        if t_end == t {
            return Err(Error::invalid(
                "t_end",
                format!(
                    "a step needs an end time other than its start {}",
                    error::num(t)
                ),
            ));
        }
        let rate0 = body.omega_rate(t, &state);
        let mut attempts = 0;
        Ok(self
            .dense_step(body, t, &state, t_end, rate0, &mut attempts)?
            .0)
    }

    /// The state at `t + dt` from `state` at `t`, like [`Integrator::advance`], calling
    /// `sample(t_i, state_i)` for each of `times` on the way, in order, from the dense
    /// output: the steps are the ones `advance` would take, never cut at a sample time.
    /// `times` must lie between `t` and `t + dt` (both included) and follow the direction
    /// of `dt`; they are checked before anything is integrated. Nothing is allocated.
    ///
    /// ```
    /// use ga_core::f64::g3::{Bivector, Rotor};
    /// use ga_rigid::dynamics::{RigidBody, State};
    /// use ga_rigid::integrators::LieDop853;
    ///
    /// let body = RigidBody::new([1.0, 2.0, 2.5])?;
    /// let state = State { rotor: Rotor::ONE, omega: Bivector::new(0.2, -1.0, 0.1) };
    /// let times: Vec<f64> = (0..=100).map(|i| 0.1 * f64::from(i)).collect();
    /// let mut samples = Vec::with_capacity(times.len());
    /// let end = LieDop853::new(1e-10, 1e-10)?
    ///     .dense_advance(&body, 0.0, state, 10.0, &times, |t, s| samples.push((t, s)))?;
    /// assert_eq!(samples.len(), 101);
    /// assert_eq!(samples[100].1, end);
    /// # Ok::<(), ga_rigid::error::Error>(())
    /// ```
    pub fn dense_advance(
        &mut self,
        body: &RigidBody,
        t: f64,
        state: State,
        dt: f64,
        times: &[f64],
        mut sample: impl FnMut(f64, State),
    ) -> Result<State, Error> {
        error::finite("t", "time", t)?;
        error::finite("dt", "time step", dt)?;
        let t_end = t + dt;
        let dir = if dt < 0.0 { -1.0 } else { 1.0 };
        let mut previous = t;
        for (i, &ti) in times.iter().enumerate() {
            // The field's name is written only for an error: a run allocates nothing.
            let field = || format!("times[{i}]");
            if !ti.is_finite() {
                return Err(Error::NotFinite {
                    field: field(),
                    what: "sample time",
                    value: ti,
                });
            }
            if (ti - t) * dir < 0.0 || (ti - t_end) * dir > 0.0 {
                return Err(Error::OutOfRange {
                    field: field(),
                    value: ti,
                    start: t,
                    end: t_end,
                });
            }
            if (ti - previous) * dir < 0.0 {
                return Err(Error::invalid(
                    field(),
                    format!(
                        "sample times must follow the direction of dt, but {} comes after {}",
                        error::num(ti),
                        error::num(previous)
                    ),
                ));
            }
            previous = ti;
        }
        let state = check_finite(self.name(), state)?;
        if dt == 0.0 {
            for &ti in times {
                sample(ti, state);
            }
            return Ok(state);
        }
        let (mut t, mut state) = (t, state);
        let mut rate = body.omega_rate(t, &state);
        let mut attempts = 0;
        let mut pending = times;
        loop {
            let (step, rate1) = self.dense_step(body, t, &state, t_end, rate, &mut attempts)?;
            let last = step.t1 == t_end;
            while let Some((&ti, rest)) = pending.split_first() {
                if !last && (ti - step.t1) * dir > 0.0 {
                    break;
                }
                sample(
                    ti,
                    if ti == step.t1 {
                        step.end
                    } else {
                        step.at(ti)?
                    },
                );
                pending = rest;
            }
            (t, state, rate) = (step.t1, step.end, rate1);
            if last {
                return Ok(state);
            }
        }
    }
}

impl Integrator for LieDop853 {
    fn name(&self) -> &'static str {
        if self.cayley {
            "lie-dop853-cayley"
        } else {
            "lie-dop853"
        }
    }

    fn accepted_steps(&self) -> Option<u64> {
        Some(self.stats.accepted)
    }

    fn limit_steps(&mut self, max_steps: u64) {
        self.run_limit = Some(max_steps);
    }

    fn advance_to_each(
        &mut self,
        body: &RigidBody,
        t: f64,
        state: State,
        times: &[f64],
    ) -> Result<Vec<State>, Error> {
        let Some(&last) = times.last() else {
            return Ok(Vec::new());
        };
        let mut out = Vec::with_capacity(times.len());
        self.dense_advance(body, t, state, last - t, times, |_, s| out.push(s))?;
        Ok(out)
    }

    fn advance(&mut self, body: &RigidBody, t: f64, state: State, dt: f64) -> Result<State, Error> {
        error::finite("dt", "time step", dt)?;
        if dt == 0.0 {
            return check_finite(self.name(), state);
        }
        let t_end = t + dt;
        let (mut t, mut state) = (t, state);
        let mut rates: Rates = [[0.0; 6]; SD];
        let mut attempts = 0;
        loop {
            let rate0 = body.omega_rate(t, &state);
            let step =
                self.accepted_step(body, t, &state, t_end, rate0, &mut rates, &mut attempts)?;
            state = State {
                // Unit by construction; scaling once a step keeps the rounding of the
                // products from adding up over millions of steps.
                rotor: unit(self.moved(state.rotor, step.trial.u)),
                omega: step.trial.omega,
            };
            if step.last {
                return check_finite(self.name(), state);
            }
            t += step.h;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The run's limit replaces the bound per call and names `max_steps` when reached.
    #[test]
    fn the_runs_step_limit_stops_the_run_and_is_named() {
        let body = RigidBody::new([1.0, 2.0, 3.0]).unwrap();
        let state = State {
            rotor: Rotor::ONE,
            omega: crate::dynamics::omega_from_vector([0.5, 4.0, 0.3]),
        };
        let mut lie = LieDop853::new(1e-8, 1e-11).unwrap();
        lie.limit_steps(100);
        let mid = lie.advance(&body, 0.0, state, 2.0).unwrap();
        let e = lie.advance(&body, 2.0, mid, 1000.0).unwrap_err();
        assert_eq!(e.field(), Some("max_steps"), "{e}");
        assert!(
            e.to_string()
                .contains("lie-dop853 needs more than 100 steps"),
            "{e}"
        );
    }

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

    /// Stage `i`'s row of the whole tableau: the method's, the weights `B` for stage 13
    /// (the rates at the step's end) and the continuous extension's.
    fn row(i: usize) -> &'static [f64] {
        match i {
            _ if i < S => A[i],
            S => &B,
            _ => A_DENSE[i - S - 1],
        }
    }

    /// The nodes of all sixteen stages.
    fn nodes() -> [f64; SD] {
        let mut c = [0.0; SD];
        c[..S].copy_from_slice(&C);
        c[S] = 1.0;
        c[S + 1..].copy_from_slice(&C_DENSE);
        c
    }

    /// The weight DOP853's interpolation polynomial gives stage `i` at `theta`:
    /// `y(theta) = y0 + h sum_i b_i(theta) k_i`, from `r2 = sum b_i k_i`, `r3 = k1 - r2`,
    /// `r4 = r2 - k13 - r3` and `r5..r8 = sum d_i k_i` (in units of `h`).
    fn dense_weight(i: usize, theta: f64) -> f64 {
        let unit_at = |j: usize| if i == j { 1.0 } else { 0.0 };
        let r2 = if i < S { B[i] } else { 0.0 };
        let r3 = unit_at(0) - r2;
        let r4 = r2 - unit_at(S) - r3;
        let [r5, r6, r7, r8] = D.map(|d| d[i]);
        let s = 1.0 - theta;
        theta * (r2 + s * (r3 + theta * (r4 + s * (r5 + theta * (r6 + s * (r7 + theta * r8))))))
    }

    /// The extra stages' rows sum to their nodes, and the continuous extension meets the
    /// conditions of order seven with weights `b_i(theta)`: the quadrature conditions
    /// `sum b_i(theta) c_i^(k-1) = theta^k / k`, k <= 7, and the tree conditions
    /// `sum b_i(theta) a_ij c_j = theta^3 / 6`, `sum b_i(theta) c_i a_ij c_j = theta^4 / 8`,
    /// `sum b_i(theta) a_ij c_j^2 = theta^4 / 12` (Hairer-Nørsett-Wanner II.2 and II.6). A
    /// typo in any `d` or extra `a` fails one of them.
    #[test]
    fn continuous_extension_satisfies_the_conditions_of_order_seven() {
        let c = nodes();
        for (i, (row, ci)) in A_DENSE.iter().zip(C_DENSE).enumerate() {
            assert_eq!(row.len(), S + 1 + i);
            let sum: f64 = row.iter().sum();
            assert!(
                (sum - ci).abs() < 1e-14,
                "stage {}: {sum} vs {ci}",
                S + 2 + i
            );
        }
        let a_dot = |i: usize, power: i32| -> f64 {
            row(i)
                .iter()
                .enumerate()
                .map(|(j, a)| a * c[j].powi(power))
                .sum()
        };
        for theta in [0.1, 0.3, 0.5, 0.77, 1.0] {
            let weighted_sum = |f: &dyn Fn(usize) -> f64| -> f64 {
                (0..SD).map(|i| dense_weight(i, theta) * f(i)).sum()
            };
            for k in 1..=7 {
                let q = weighted_sum(&|i| c[i].powi(k - 1));
                let expected = theta.powi(k) / f64::from(k);
                assert!((q - expected).abs() < 1e-13, "theta {theta}, k = {k}: {q}");
            }
            let trees = [
                (weighted_sum(&|i| a_dot(i, 1)), theta.powi(3) / 6.0),
                (weighted_sum(&|i| c[i] * a_dot(i, 1)), theta.powi(4) / 8.0),
                (weighted_sum(&|i| a_dot(i, 2)), theta.powi(4) / 12.0),
            ];
            for (n, (q, expected)) in trees.into_iter().enumerate() {
                assert!((q - expected).abs() < 1e-13, "theta {theta}, tree {n}: {q}");
            }
        }
        // Order seven, not eight: the eighth quadrature condition fails mid-step.
        let q8: f64 = (0..SD).map(|i| dense_weight(i, 0.5) * c[i].powi(7)).sum();
        assert!((q8 - 0.5f64.powi(8) / 8.0).abs() > 1e-8);
    }

    /// `C_SERIES` against `2^(2n) |B_2n| / (4 (2n)!)` from the Bernoulli numbers `B_2` to
    /// `B_32` (Abramowitz and Stegun, Table 23.2).
    #[test]
    fn c_series_coefficients_come_from_the_bernoulli_numbers() {
        let bernoulli: [(f64, f64); 16] = [
            (1.0, 6.0),
            (1.0, 30.0),
            (1.0, 42.0),
            (1.0, 30.0),
            (5.0, 66.0),
            (691.0, 2730.0),
            (7.0, 6.0),
            (3617.0, 510.0),
            (43867.0, 798.0),
            (174_611.0, 330.0),
            (854_513.0, 138.0),
            (236_364_091.0, 2730.0),
            (8_553_103.0, 6.0),
            (23_749_461_029.0, 870.0),
            (8_615_841_276_005.0, 14322.0),
            (7_709_321_041_217.0, 510.0),
        ];
        let mut factorial = 1.0;
        for (n, (&(p, q), &coefficient)) in bernoulli.iter().zip(&C_SERIES).enumerate() {
            let two_n = 2 * (n + 1);
            factorial *= ((two_n - 1) * two_n) as f64;
            let expected = 2f64.powi(two_n as i32) * (p / q) / (4.0 * factorial);
            assert!(
                (coefficient / expected - 1.0).abs() < 1e-15,
                "n = {}: {coefficient:e} vs {expected:e}",
                n + 1
            );
        }
    }

    /// `c(x) = (1 - x cot x) / (4 x^2)` against values computed to 20 digits with mpmath
    /// (docs/references.md), on both sides of the cut at `x^2 = 1` (the series below, `tan`
    /// above) and across the range the stages see; and the series meets the closed form at
    /// the cut.
    #[test]
    fn c_matches_high_precision_values_on_both_sides_of_the_cut() {
        let reference = [
            (0.0, 0.083_333_333_333_333_333_333),
            (1e-6, 0.083_333_338_888_889_417_989),
            (1e-4, 0.083_333_888_894_179_947_09),
            (0.01, 0.083_388_941_851_905_350_515),
            (0.1, 0.083_894_233_344_144_169_744),
            (0.249_999, 0.084_756_133_313_403_228_768),
            (0.250_001, 0.084_756_144_974_145_993_714),
            (0.5, 0.086_250_351_839_705_822_867),
            (0.99, 0.089_408_949_132_802_225_899),
            (0.999_999, 0.089_476_839_219_475_129_048),
            (1.000_001, 0.089_476_852_813_360_971_979),
            (1.01, 0.089_544_888_153_285_023_54),
            (2.0, 0.097_091_353_093_505_925_839),
            (4.0, 0.119_707_194_295_035_720_47),
            (9.0, 0.612_382_157_063_988_900_23),
        ];
        for (x2, expected) in reference {
            let c = 0.25 * c4_of(x2);
            assert!(
                (c / expected - 1.0).abs() < 4e-16,
                "x^2 = {x2}: {c:e} vs {expected:e}"
            );
        }
        let x = 1.0f64;
        let closed = (1.0 - x / x.tan()) / 4.0;
        assert!((0.25 * c4_series(1.0 - 1e-16) / closed - 1.0).abs() < 1e-15);
    }

    /// The series exponential against ga-core's on both sides of its cut at `|u| = 1`.
    #[test]
    fn series_exponential_matches_ga_core() {
        let mut worst = 0.0_f64;
        for i in 0..=240 {
            let size = f64::from(i) / 200.0;
            let direction = Bivector::new(0.3, -0.8, 0.52);
            let direction = direction * (1.0 / (0.09f64 + 0.64 + 0.2704).sqrt());
            let u = direction * size;
            let (a, b) = (exp(u), u.exp());
            for d in [a.s - b.s, a.e12 - b.e12, a.e13 - b.e13, a.e23 - b.e23] {
                worst = worst.max(d.abs());
            }
        }
        assert!(worst < 3e-16, "{worst:e}");
        assert_eq!(COS_SERIES[1], -0.5);
        assert_eq!(SINC_SERIES[1], -1.0 / 6.0);
        assert_eq!(COS_SERIES[9], -1.0 / 6_402_373_705_728_000.0);
    }

    /// `cay(u)` is a unit rotor, agrees with `exp(u)` to second order, and `dcay^-1` is its
    /// inverse derivative: `d/de cay(u + e v) = cay(u) a` for `v = dcay^-1_u(a)`, checked by
    /// a central difference with ga-core's geometric product.
    #[test]
    fn cayley_map_is_unit_and_dcayinv_inverts_its_derivative() {
        let a = Bivector::new(0.3, -0.7, 0.2);
        for scale in [1e-3, 0.1, 0.5, 1.0, 3.0, 20.0] {
            let u = Bivector::new(0.6, -0.48, 0.64) * scale;
            let r = cay(u);
            let norm = r.s * r.s + r.e12 * r.e12 + r.e13 * r.e13 + r.e23 * r.e23;
            assert!((norm - 1.0).abs() < 3e-16, "scale {scale}: {norm}");
            let v = dcayinv(u, a);
            let e = 1e-5;
            let slope = (cay(u + v * e) - cay(u - v * e)) * (0.5 / e);
            let gap = slope - r * a;
            let size = [gap.s, gap.e12, gap.e13, gap.e23]
                .into_iter()
                .map(f64::abs)
                .fold(0.0, f64::max);
            assert!(size < 1e-8, "scale {scale}: {size:e}");
        }
        let u = Bivector::new(0.6, -0.48, 0.64) * 1e-3;
        let (c, e) = (cay(u), u.exp());
        for d in [c.s - e.s, c.e12 - e.e12, c.e13 - e.e13, c.e23 - e.e23] {
            assert!(d.abs() < 1e-9, "{d:e}");
        }
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
