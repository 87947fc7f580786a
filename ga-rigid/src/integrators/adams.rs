//! Adams-Bashforth-Moulton in PECE form with a fixed step (E. Hairer, S. P. Nørsett,
//! G. Wanner, *Solving Ordinary Differential Equations I*, 2nd ed., Springer 1993,
//! section III.1: the explicit and implicit Adams methods, the recurrences of their
//! coefficients, and the predictor-corrector mode "PECE"), applied to the
//! rotor's four components and `Omega_B` as seven unknowns, the rotor scaled back to unit
//! norm after every step (the embedding form; docs/derivations/adams-pece.md says why
//! not the Lie-group Adams method of Faltinsen, Marthinsen and Munthe-Kaas, and why the
//! projection keeps the order).
//!
//! A method of order `p` keeps the rates of the last `k = p - 1` steps. A step predicts
//! with Adams-Bashforth of order `k` over them, evaluates the rates at the prediction,
//! corrects with Adams-Moulton of order `p` over the prediction's rate and the same `k`
//! rates, scales the rotor, and evaluates the rates at the corrected point: two
//! right-hand sides a step, whatever the order. The first `k - 1` steps are taken by the
//! fixed-step eighth-order Runge-Kutta-Munthe-Kaas step of [`LieDop853`] in Cayley
//! coordinates (each split into [`Adams::start_substeps`] equal parts), so that the start
//! is as accurate as the rest at the steps where the method reaches its accuracy.
//!
//! The coefficients are computed when the crate is compiled, in exact rational
//! arithmetic, from the recurrences of the backward-difference coefficients, and only then
//! rounded to `f64` ([`bashforth`], [`moulton`]).

use ga_core::f64::g3::{Bivector, Rotor};

use crate::dynamics::{RigidBody, State};
use crate::error::{self, Error};

use super::integrator::{check_finite, check_step, substeps, Integrator};
use super::lie_dop853::LieDop853;

/// The lowest order [`Adams::new`] takes (Heun's method: Euler predicts, the trapezoidal
/// rule corrects).
pub const MIN_ORDER: u32 = 2;
/// The highest order [`Adams::new`] takes.
pub const MAX_ORDER: u32 = 12;
/// The order the registry's race measured fastest to an attitude error of 1e-10
/// (BENCHMARKS.md): `adams-12`.
pub const DEFAULT_ORDER: u32 = 12;

/// The most rates a method keeps (`MAX_ORDER - 1`).
const K_MAX: usize = MAX_ORDER as usize - 1;

/// A fraction `num / den`, `den > 0`, in lowest terms.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Ratio {
    /// The numerator.
    pub num: i128,
    /// The denominator, positive.
    pub den: i128,
}

const fn gcd(a: i128, b: i128) -> i128 {
    let (mut a, mut b) = (a.abs(), b.abs());
    while b != 0 {
        let r = a % b;
        a = b;
        b = r;
    }
    a
}

impl Ratio {
    const fn new(num: i128, den: i128) -> Ratio {
        let g = gcd(num, den);
        let g = if g == 0 { 1 } else { g };
        let s = if den < 0 { -1 } else { 1 };
        Ratio {
            num: s * num / g,
            den: s * den / g,
        }
    }
    const fn add(self, o: Ratio) -> Ratio {
        // Reduce through the denominators' gcd first so that the products stay small.
        let g = gcd(self.den, o.den);
        Ratio::new(
            self.num * (o.den / g) + o.num * (self.den / g),
            self.den / g * o.den,
        )
    }
    const fn scale(self, n: i128, d: i128) -> Ratio {
        let a = Ratio::new(n, self.den);
        let b = Ratio::new(self.num, d);
        Ratio::new(a.num * b.num, a.den * b.den)
    }
    /// The nearest `f64` (numerator and denominator are exact in `f64` for every order
    /// here, so this is one rounding).
    #[must_use]
    pub const fn to_f64(self) -> f64 {
        self.num as f64 / self.den as f64
    }
}

/// The backward-difference coefficients of the explicit (`implicit = false`, `gamma_j`:
/// `gamma_j + gamma_{j-1}/2 + ... + gamma_0/(j+1) = 1`) or implicit (`gamma*_j`: the same
/// sums equal to 0 for `j >= 1`) Adams methods (HNW III.1).
const fn gammas(implicit: bool) -> [Ratio; MAX_ORDER as usize] {
    let mut g = [Ratio { num: 0, den: 1 }; MAX_ORDER as usize];
    let mut j = 0;
    while j < g.len() {
        let mut acc = if implicit && j > 0 {
            Ratio { num: 0, den: 1 }
        } else {
            Ratio { num: 1, den: 1 }
        };
        let mut i = 0;
        while i < j {
            acc = acc.add(g[i].scale(-1, (j + 1 - i) as i128));
            i += 1;
        }
        g[j] = acc;
        j += 1;
    }
    g
}

/// `n choose r`.
const fn binomial(n: usize, r: usize) -> i128 {
    let mut c: i128 = 1;
    let mut i = 0;
    while i < r {
        c = c * (n - i) as i128 / (i + 1) as i128;
        i += 1;
    }
    c
}

/// The weights `beta_i`, `i < n`, of `sum_{j<n} gamma_j nabla^j`, written on the values
/// `f_0, f_{-1}, ...` (`nabla^j f_0 = sum_i (-1)^i C(j, i) f_{-i}`).
const fn lagrange(gamma: &[Ratio; MAX_ORDER as usize], n: usize) -> [Ratio; MAX_ORDER as usize] {
    let mut beta = [Ratio { num: 0, den: 1 }; MAX_ORDER as usize];
    let mut i = 0;
    while i < n {
        let mut acc = Ratio { num: 0, den: 1 };
        let mut j = i;
        while j < n {
            let c = binomial(j, i);
            let sign = if i % 2 == 0 { 1 } else { -1 };
            acc = acc.add(gamma[j].scale(sign * c, 1));
            j += 1;
        }
        beta[i] = acc;
        i += 1;
    }
    beta
}

/// The weights of Adams-Bashforth of order `k` (`1 <= k <= MAX_ORDER`) on `f_n, f_{n-1},
/// ..., f_{n-k+1}`: `y_{n+1} = y_n + h sum_i beta_i f_{n-i}`. AB2 is `3/2, -1/2`.
#[must_use]
pub const fn bashforth(k: usize) -> [Ratio; MAX_ORDER as usize] {
    lagrange(&gammas(false), k)
}

/// The weights of Adams-Moulton of order `p` (`1 <= p <= MAX_ORDER`) on `f_{n+1}, f_n,
/// ..., f_{n-p+2}`: `y_{n+1} = y_n + h sum_i beta*_i f_{n+1-i}`. AM2 (the trapezoidal rule)
/// is `1/2, 1/2`.
#[must_use]
pub const fn moulton(p: usize) -> [Ratio; MAX_ORDER as usize] {
    lagrange(&gammas(true), p)
}

/// Both tables as `f64`, by order `p` of the PECE pair: row `p` holds AB of order `p - 1`
/// and AM of order `p`.
struct Tables {
    ab: [[f64; MAX_ORDER as usize]; MAX_ORDER as usize + 1],
    am: [[f64; MAX_ORDER as usize]; MAX_ORDER as usize + 1],
}

const TABLES: Tables = {
    let mut ab = [[0.0; MAX_ORDER as usize]; MAX_ORDER as usize + 1];
    let mut am = [[0.0; MAX_ORDER as usize]; MAX_ORDER as usize + 1];
    let mut p = MIN_ORDER as usize;
    while p <= MAX_ORDER as usize {
        let b = bashforth(p - 1);
        let m = moulton(p);
        let mut i = 0;
        while i < MAX_ORDER as usize {
            ab[p][i] = b[i].to_f64();
            am[p][i] = m[i].to_f64();
            i += 1;
        }
        p += 1;
    }
    Tables { ab, am }
};

/// The seven unknowns: the rotor's `s, e12, e13, e23`, then `Omega_B`'s `e12, e13, e23`.
type Y = [f64; 7];

#[inline(always)]
fn pack(s: &State) -> Y {
    let (r, w) = (s.rotor, s.omega);
    [r.s, r.e12, r.e13, r.e23, w.e12, w.e13, w.e23]
}

#[inline(always)]
fn unpack(y: &Y) -> State {
    State {
        rotor: Rotor {
            s: y[0],
            e12: y[1],
            e13: y[2],
            e23: y[3],
        },
        omega: Bivector {
            e12: y[4],
            e13: y[5],
            e23: y[6],
        },
    }
}

/// The right-hand side on the seven unknowns.
#[inline(always)]
fn rate(body: &RigidBody, t: f64, y: &Y) -> Y {
    let s = unpack(y);
    let r = RigidBody::rotor_rate(&s);
    let w = body.omega_rate(t, &s);
    [r.s, r.e12, r.e13, r.e23, w.e12, w.e13, w.e23]
}

/// The rotor components of `y` scaled to unit norm; NaN where the norm has overflowed or
/// vanished (an unstable run), so that the end's finiteness check sees it rather than a
/// rotor divided down to zero.
#[inline(always)]
fn normalise(y: &mut Y) {
    let mut n = (y[0] * y[0] + y[1] * y[1] + y[2] * y[2] + y[3] * y[3]).sqrt();
    if !(n.is_finite() && n > 0.0) {
        n = f64::NAN;
    }
    for v in &mut y[..4] {
        *v /= n;
    }
}

/// The rates of the last steps and where they end, so that a call that continues where
/// the last one stopped continues its history rather than starting again.
#[derive(Clone, Debug)]
struct History {
    /// Each rate twice, at `i` and `i + k`, so that the `k` newest are always the
    /// contiguous `rates[head..head + k]`, newest first.
    rates: [Y; 2 * K_MAX],
    head: usize,
    /// How many rates are held (at most `k`).
    filled: usize,
    /// The time, state and sub-step the history ends with, and the body it was taken on
    /// (its address: only compared, never read).
    t: f64,
    y: Y,
    h: f64,
    body: usize,
}

impl History {
    fn empty() -> History {
        History {
            rates: [[0.0; 7]; 2 * K_MAX],
            head: 0,
            filled: 0,
            t: f64::NAN,
            y: [f64::NAN; 7],
            h: f64::NAN,
            body: 0,
        }
    }

    #[inline(always)]
    fn push(&mut self, k: usize, f: Y) {
        self.head = if self.head == 0 { k - 1 } else { self.head - 1 };
        self.rates[self.head] = f;
        self.rates[self.head + k] = f;
        self.filled = (self.filled + 1).min(k);
    }
}

/// Adams-Bashforth-Moulton PECE of order `p` with fixed step `h` on the seven-unknown
/// embedding of `(R, Omega_B)`, the rotor scaled to unit norm after every step.
///
/// A call to [`Integrator::advance`] that starts where the previous one ended (the same
/// body, time, state and sub-step length to a few roundings) continues with the rates it
/// kept; any other call starts afresh with `p - 2` Runge-Kutta steps. Not geometric:
/// energy and `|m|` drift at order `p`, and its stability region is small (the registry's
/// limit).
#[derive(Clone, Debug)]
pub struct Adams {
    step: f64,
    order: u32,
    start_substeps: u32,
    starter: LieDop853,
    history: History,
}

impl Adams {
    /// Order `order` (from [`MIN_ORDER`] to [`MAX_ORDER`]) with sub-steps of at most `step`
    /// (finite and positive); the start's Runge-Kutta steps each in one piece.
    pub fn new(step: f64, order: u32) -> Result<Self, Error> {
        Self::with_start(step, order, 1)
    }

    /// [`Adams::new`] whose start splits each of its `p - 2` Runge-Kutta steps into
    /// `start_substeps` (at least 1) equal parts.
    pub fn with_start(step: f64, order: u32, start_substeps: u32) -> Result<Self, Error> {
        let step = check_step(step)?;
        if !(MIN_ORDER..=MAX_ORDER).contains(&order) {
            return Err(Error::invalid(
                "order",
                format!("the Adams order must be from {MIN_ORDER} to {MAX_ORDER}, got {order}"),
            ));
        }
        if start_substeps == 0 {
            return Err(Error::invalid(
                "start_substeps",
                "the start's sub-steps per step must be at least 1, got 0",
            ));
        }
        // The tolerances are unused: the start takes fixed steps (`step_once`).
        let starter = LieDop853::cayley(1.0, 1.0)?;
        Ok(Adams {
            step,
            order,
            start_substeps,
            starter,
            history: History::empty(),
        })
    }

    /// The largest sub-step.
    #[must_use]
    pub fn step(&self) -> f64 {
        self.step
    }

    /// The order `p`.
    #[must_use]
    pub fn order(&self) -> u32 {
        self.order
    }

    /// The parts each start step is split into.
    #[must_use]
    pub fn start_substeps(&self) -> u32 {
        self.start_substeps
    }

    /// The sub-step to continue the kept history with, if it continues at `(t, y)` on
    /// `body` with `n` sub-steps of `h`: the history's own step, so that the steps stay
    /// equal to the bit. A caller's sample times are sums and differences of its own
    /// (`t_k`, `t_{k+1} - t_k`), so the start and the sub-step may differ from the
    /// history's by roundings of the times; up to 16 of them over the call, which moves its
    /// end by no more than the rounding of `t`, it continues.
    fn continued_step(&self, body: usize, t: f64, y: &Y, n: u64, h: f64) -> Option<f64> {
        let hist = &self.history;
        let slack = 16.0 * f64::EPSILON * (t.abs() + (n as f64 * h).abs());
        (hist.filled > 0
            && hist.body == body
            && hist.y == *y
            && (t - hist.t).abs() <= slack
            && (n as f64 * (h - hist.h)).abs() <= slack)
            .then_some(hist.h)
    }

    /// `n` steps of `h` from `(t, y)`, for `K = p - 1` kept rates.
    fn run<const K: usize>(&mut self, body: &RigidBody, t: f64, y: Y, n: u64, h: f64) -> Y {
        let p = K + 1;
        let ab: [f64; K] = core::array::from_fn(|i| TABLES.ab[p][i]);
        let am0 = TABLES.am[p][0];
        let am: [f64; K] = core::array::from_fn(|i| TABLES.am[p][i + 1]);
        let key = body as *const RigidBody as usize;
        let h = match self.continued_step(key, t, &y, n, h) {
            Some(kept) => kept,
            None => {
                self.history.filled = 0;
                self.history.head = 0;
                self.history.push(K, rate(body, t, &y));
                h
            }
        };
        let (mut t, mut y) = (t, y);
        let hist = &mut self.history;
        for i in 0..n {
            let ti = t + i as f64 * h;
            let t1 = t + (i + 1) as f64 * h;
            if hist.filled < K {
                let mut s = unpack(&y);
                let m = self.start_substeps;
                let hs = h / f64::from(m);
                for j in 0..m {
                    s = self.starter.step_once(body, ti + f64::from(j) * hs, s, hs);
                }
                y = pack(&s);
                normalise(&mut y);
            } else {
                let past: &[Y; K] = (&hist.rates[hist.head..hist.head + K])
                    .try_into()
                    .unwrap_or_else(|_| unreachable!("the window holds K rates"));
                let mut sp = [0.0; 7];
                let mut sc = [0.0; 7];
                for (j, f) in past.iter().enumerate() {
                    for c in 0..7 {
                        sp[c] += ab[j] * f[c];
                        sc[c] += am[j] * f[c];
                    }
                }
                let yp: Y = core::array::from_fn(|c| y[c] + h * sp[c]);
                let fp = rate(body, t1, &yp);
                for c in 0..7 {
                    y[c] += h * (sc[c] + am0 * fp[c]);
                }
                normalise(&mut y);
            }
            hist.push(K, rate(body, t1, &y));
        }
        t += n as f64 * h;
        hist.t = t;
        hist.y = y;
        hist.h = h;
        hist.body = key;
        y
    }
}

impl Integrator for Adams {
    fn name(&self) -> &'static str {
        const NAMES: [&str; MAX_ORDER as usize + 1] = [
            "", "", "adams-2", "adams-3", "adams-4", "adams-5", "adams-6", "adams-7", "adams-8",
            "adams-9", "adams-10", "adams-11", "adams-12",
        ];
        // `new` admits only MIN_ORDER..=MAX_ORDER.
        NAMES[self.order as usize]
    }

    fn advance(&mut self, body: &RigidBody, t: f64, state: State, dt: f64) -> Result<State, Error> {
        error::finite("t", "time", t)?;
        let (n, h) = substeps(self.step, dt)?;
        if n == 0 {
            return Ok(state);
        }
        let y = pack(&state);
        let y = match self.order {
            2 => self.run::<1>(body, t, y, n, h),
            3 => self.run::<2>(body, t, y, n, h),
            4 => self.run::<3>(body, t, y, n, h),
            5 => self.run::<4>(body, t, y, n, h),
            6 => self.run::<5>(body, t, y, n, h),
            7 => self.run::<6>(body, t, y, n, h),
            8 => self.run::<7>(body, t, y, n, h),
            9 => self.run::<8>(body, t, y, n, h),
            10 => self.run::<9>(body, t, y, n, h),
            11 => self.run::<10>(body, t, y, n, h),
            _ => self.run::<11>(body, t, y, n, h),
        };
        let end = check_finite(self.name(), unpack(&y));
        if end.is_err() {
            // Nothing of a run that stopped being finite is worth continuing.
            self.history = History::empty();
        }
        end
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn r(num: i128, den: i128) -> Ratio {
        Ratio::new(num, den)
    }

    /// The low orders against the values printed in every textbook (HNW III.1).
    #[test]
    fn low_order_coefficients_are_the_textbook_ones() {
        assert_eq!(bashforth(1)[..1], [r(1, 1)]);
        assert_eq!(bashforth(2)[..2], [r(3, 2), r(-1, 2)]);
        assert_eq!(bashforth(3)[..3], [r(23, 12), r(-16, 12), r(5, 12)]);
        assert_eq!(
            bashforth(4)[..4],
            [r(55, 24), r(-59, 24), r(37, 24), r(-9, 24)]
        );
        assert_eq!(moulton(1)[..1], [r(1, 1)]);
        assert_eq!(moulton(2)[..2], [r(1, 2), r(1, 2)]);
        assert_eq!(moulton(3)[..3], [r(5, 12), r(8, 12), r(-1, 12)]);
        assert_eq!(moulton(4)[..4], [r(9, 24), r(19, 24), r(-5, 24), r(1, 24)]);
        // The backward-difference coefficients as HNW III.1 prints them.
        let g = gammas(false);
        assert_eq!(g[..5], [r(1, 1), r(1, 2), r(5, 12), r(3, 8), r(251, 720)]);
        let g = gammas(true);
        assert_eq!(
            g[..5],
            [r(1, 1), r(-1, 2), r(-1, 12), r(-1, 24), r(-19, 720)]
        );
    }

    /// Every order's weights integrate the polynomials of its degree exactly: the order
    /// conditions `sum_i beta_i (-i)^q = 1/(q+1)` (AB on `0, -1, ...`) and
    /// `sum_i beta*_i (1-i)^q = 1/(q+1)` (AM on `1, 0, -1, ...`), in exact arithmetic,
    /// up to the highest order.
    #[test]
    fn every_order_meets_its_order_conditions_exactly() {
        for k in 1..=MAX_ORDER as usize {
            for (beta, shift) in [(bashforth(k), 0), (moulton(k), 1)] {
                for q in 0..k {
                    let mut sum = r(0, 1);
                    for (i, b) in beta.iter().enumerate().take(k) {
                        let x = shift - i as i128;
                        sum = sum.add(b.scale(x.pow(q as u32), 1));
                    }
                    assert_eq!(sum, r(1, q as i128 + 1), "k {k} q {q}");
                }
            }
            assert!(bashforth(k)[k..].iter().all(|b| b.num == 0));
        }
    }

    #[test]
    fn the_tables_round_the_exact_weights() {
        let m = moulton(12);
        assert_eq!(TABLES.am[12][3], m[3].num as f64 / m[3].den as f64);
        assert!(m.iter().all(|b| b.num.abs() < 1 << 53 && b.den < 1 << 53));
        let b = bashforth(11);
        assert!(b.iter().all(|b| b.num.abs() < 1 << 53 && b.den < 1 << 53));
    }

    #[test]
    fn bad_order_and_start_are_named() {
        let e = Adams::new(0.1, 13).unwrap_err().to_string();
        assert_eq!(e, "order: the Adams order must be from 2 to 12, got 13");
        let e = Adams::new(0.1, 1).unwrap_err().to_string();
        assert!(e.starts_with("order: "), "{e}");
        let e = Adams::with_start(0.1, 10, 0).unwrap_err().to_string();
        assert!(e.starts_with("start_substeps: "), "{e}");
        let e = Adams::new(-0.1, 10).unwrap_err().to_string();
        assert!(e.starts_with("step: "), "{e}");
        assert!(Adams::new(f64::NAN, 10).is_err());
    }
}
