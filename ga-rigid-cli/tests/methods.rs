//! The registry-driven harness: every method of `Method::ALL` on every reference scene of
//! the report (`report::reference_scenes`) where the report runs it
//! (`TestScene::methods`: free-body-only methods skip the torqued scenes, the closed form
//! the asymmetric bodies, the exact-flow splittings the free ones), over the first few
//! radians of each scene, against the scene's reference solution (`report::references`):
//! the exact flow through Jacobi elliptic functions for a free body (itself checked against
//! the independent matrix reference and the published values in
//! `ga-rigid/tests/integrators.rs`), and Dormand-Prince at 1e-13 under a torque. Each
//! scene's two references must agree (the report's reference check) before any method is
//! measured against them. It checks
//!
//! - a fixed-step method's observed order of convergence, in the attitude and in the body
//!   momentum, against the order the registry states (`Method::order`);
//! - an adaptive method's error at a tolerance, and an exact solution's against the other
//!   reference;
//! - the invariants each method promises on a free body (`promises` below: `|m|`, the
//!   space angular momentum `L`, the energy), to rounding, and a unit rotor for every
//!   method on every scene.

use std::sync::OnceLock;

use ga_rigid::dynamics::State;
use ga_rigid::registry::{Method, Step, StepKind};
use ga_rigid_cli::report::{
    attitude_error, errors, reference_scenes, references, sample_times, TestScene, SAMPLES,
};

/// A scene cut to its first `TURN` radians (at its initial rate), with its references.
struct Prepared {
    scene: TestScene,
    /// The states of the scene's primary reference at `sample_times(scene.t_end)`.
    primary: Vec<State>,
    /// Which method the primary reference is: that method is measured against `secondary`.
    primary_method: Method,
    /// The independent second solution.
    secondary: Vec<State>,
    /// The references' disagreement (the largest of the attitude error and the relative
    /// momentum error over the samples): no error below about this is resolved.
    floor: f64,
}

/// How far each scene is run, in radians at its initial rate. The order of a method is a
/// property of its local error; a few turns of the body are enough to see it, and short
/// runs keep the harness at a few seconds in a debug build (the order-one engine steps
/// need some 10^4 steps here at their finest level).
const TURN: f64 = 8.0;

fn prepared() -> &'static [Prepared] {
    static SCENES: OnceLock<Vec<Prepared>> = OnceLock::new();
    SCENES.get_or_init(|| {
        reference_scenes()
            .unwrap()
            .into_iter()
            .map(|full| {
                let t_end = full.t_end.min(TURN / full.rate());
                let scene = TestScene::new(
                    full.name.clone(),
                    full.source.clone(),
                    full.body.clone(),
                    full.initial,
                    t_end,
                    full.coarsest_steps,
                    full.sweep,
                );
                let (primary, secondary) = references(&scene).unwrap();
                let check = errors(&scene, &primary.states, &secondary.states);
                let floor = check.attitude_max.max(check.momentum_max);
                // The references are independent solutions (the elliptic-function flow and
                // Dormand-Prince; Dormand-Prince and Lie-RK4 under a torque): their
                // agreement bounds the primary's error.
                assert!(
                    floor < 1e-9,
                    "{}: references disagree by {floor:e}",
                    scene.name
                );
                Prepared {
                    scene,
                    primary: primary.states,
                    primary_method: primary.method,
                    secondary: secondary.states,
                    floor,
                }
            })
            .collect()
    })
}

impl Prepared {
    /// The reference a run of `method` is measured against: never the method itself.
    fn reference_for(&self, method: Method) -> &[State] {
        if method == self.primary_method {
            &self.secondary
        } else {
            &self.primary
        }
    }

    /// `method` at `step` through the registry (as the report and the command build it),
    /// sampled at the scene's sample times.
    fn run(&self, method: Method, step: Step) -> Result<Vec<State>, ga_rigid::error::Error> {
        let s = &self.scene;
        method
            .integrator(step)?
            .advance_to_each(&s.body, 0.0, s.initial, &sample_times(s.t_end))
    }

    /// The state at the scene's end after `n` fixed steps in one call (the step a hair
    /// above `t_end / n`, so that rounding never adds a sub-step), and its attitude and
    /// relative body-momentum errors against the reference's end state.
    fn fixed_end_errors(
        &self,
        method: Method,
        n: u64,
    ) -> Result<(f64, f64), ga_rigid::error::Error> {
        let s = &self.scene;
        let h = s.t_end / n as f64 * (1.0 + 1e-9);
        let end = method
            .integrator(Step::Fixed(h))?
            .advance(&s.body, 0.0, s.initial, s.t_end)?;
        let reference = self
            .reference_for(method)
            .last()
            .expect("a reference sample");
        let m = s.body.body_momentum(end.omega);
        let m_ref = s.body.body_momentum(reference.omega);
        Ok((
            attitude_error(end.rotor, reference.rotor),
            (m - m_ref).norm() / m_ref.norm(),
        ))
    }
}

/// The least-squares slope of `log(error)` against `log(h)`.
fn fitted_slope(points: &[(f64, f64)]) -> f64 {
    let n = points.len() as f64;
    let (mx, my) = points.iter().fold((0.0, 0.0), |(x, y), (h, e)| {
        (x + h.ln() / n, y + e.ln() / n)
    });
    let sxy: f64 = points
        .iter()
        .map(|(h, e)| (h.ln() - mx) * (e.ln() - my))
        .sum();
    let sxx: f64 = points.iter().map(|(h, _)| (h.ln() - mx).powi(2)).sum();
    sxy / sxx
}

/// The largest error still counted in an order fit: above it the leading term of the
/// error expansion need not dominate.
const ASYMPTOTIC: f64 = 1e-2;
/// The step count beyond which refining stops once the fits have their points: beyond it
/// rounding, not truncation, sets some methods' errors (Buss's update levels off at 5e-8
/// near 2 10^4 steps on the Hairer-Lubich-Wanner body). The order-one engine steps need
/// more to reach their asymptotic range, and take them.
const MAX_STEPS: u64 = 10_000;
/// How far above the references' disagreement an error must be to count: at 100 times,
/// the reference adds at most 1% to an error, 0.01 / ln(4) < 0.01 to a slope.
const ABOVE_FLOOR: f64 = 100.0;
/// Points in an order fit.
const FIT_POINTS: usize = 3;

/// The observed order of a fixed-step method on a scene, in the attitude and in the
/// momentum: the slope over the finest `FIT_POINTS` step sizes whose errors lie
/// between `ABOVE_FLOOR` times the floor and `ASYMPTOTIC`. The step count grows by `2^(2/p)` a
/// level, so that the error falls about fourfold per level whatever the order `p`.
fn observed_orders(p: &Prepared, method: Method, order: u32) -> (Option<f64>, Option<f64>) {
    let low = ABOVE_FLOOR * p.floor.max(1e-14);
    let turn = p.scene.t_end * p.scene.rate();
    // The coarsest step: half the registry's stability limit as h |w(0)| (the limit bounds
    // h |w|max, and |w| grows under a torque or off a principal axis).
    let limit = method
        .stable_step_rate(p.scene.body.has_torque())
        .unwrap_or(4.0);
    let n0 = (turn / (0.5 * limit)).ceil();
    let growth = 2f64.powf(2.0 / f64::from(order));
    let (mut attitude, mut momentum) = (Vec::new(), Vec::new());
    let mut last_n = 0;
    for k in 0..40 {
        let n = (n0 * growth.powi(k)).ceil() as u64;
        let enough = attitude.len() >= FIT_POINTS && momentum.len() >= FIT_POINTS;
        if (n > MAX_STEPS && enough) || n > 50 * MAX_STEPS {
            break;
        }
        if n == last_n {
            continue;
        }
        last_n = n;
        let h = p.scene.t_end / n as f64;
        // A step that fails (a Newton solve with no root, a blow-up) is outside the window.
        let Ok((ea, em)) = p.fixed_end_errors(method, n) else {
            continue;
        };
        if ea > low && ea < ASYMPTOTIC {
            attitude.push((h, ea));
        }
        if em > low && em < ASYMPTOTIC {
            momentum.push((h, em));
        }
        if ea < low && em < low {
            break;
        }
    }
    let fit = |points: &[(f64, f64)]| {
        (points.len() >= FIT_POINTS).then(|| fitted_slope(&points[points.len() - FIT_POINTS..]))
    };
    (fit(&attitude), fit(&momentum))
}

/// How close an observed order must be to the expected one. Over three step sizes spanning a
/// factor 16 in error, with every error in the asymptotic window, the next term of the error
/// expansion moves the slope by a few hundredths; most by 0.15 (Blanes-Moan's order-six
/// splitting on the asymmetric heavy top, whose small leading term competes with the next;
/// the ga-rigid tests measured local slopes of 6.05 to 6.24 there). 0.2 passes those and
/// fails a method of the next lower or higher order by a wide margin.
const ORDER_TOLERANCE: f64 = 0.2;

/// The order a method shows on a scene in the attitude or the momentum: the registry's,
/// except where the body makes the leading error term vanish (a method may do better than
/// its order on a special body; it must not do worse anywhere).
fn expected_order(p: &Prepared, method: Method, momentum: bool, stated: u32) -> u32 {
    let body = &p.scene.body;
    let free = !body.has_torque();
    match method {
        // A symmetric body's Casimir split has one non-commuting term left: the only
        // error is the rational angles', O(h^5) a turn (ga-rigid/tests/integrators.rs,
        // `casimir_splitting_is_nearly_exact_for_a_symmetric_body`).
        Method::SplittingCasimir if free && body.symmetry_axis(1e-12).is_some() => stated + 2,
        // The corrected turns leave `alpha beta (alpha - 2 beta) / 12 m_o^2 m_m^2` of the
        // h^2 energy error (ga-rigid/src/integrators/corrected_splitting.rs), alpha and beta the
        // smallest and middle moments' inverses less the largest's. The Hairer-Lubich-Wanner
        // body (inverse moments 1/2, 1, 3/2) has alpha = 2 beta: its momentum error starts
        // at h^4; the attitude's, which integrates it, stays h^2.
        Method::SplittingCorrected if free && momentum && alpha_is_twice_beta(body.moments()) => {
            stated + 2
        }
        _ => stated,
    }
}

/// Whether a method is exact on a scene in the attitude or the momentum, so that it has no
/// order there: Spiers's turn of the body momentum is the exact flow of a free body with two
/// equal moments, and the momentum-first form's precession about `L` then makes the attitude
/// exact too (B. Spiers, "A better way to spin", the symmetric top).
fn exact_on(p: &Prepared, method: Method, momentum: bool) -> bool {
    let body = &p.scene.body;
    let symmetric = !body.has_torque() && body.symmetry_axis(1e-12).is_some();
    match method {
        Method::SpiersMomentum => symmetric,
        Method::SpiersVelocity => symmetric && momentum,
        _ => false,
    }
}

/// The errors of a method where [`exact_on`] says it is exact: at the coarsest step of the
/// order fit (half the stability limit) and at a quarter of it, within `ABOVE_FLOOR` times
/// the references' disagreement.
fn assert_exact_where_promised(p: &Prepared, method: Method) {
    let low = ABOVE_FLOOR * p.floor.max(1e-14);
    let turn = p.scene.t_end * p.scene.rate();
    let limit = method.stable_step_rate(false).unwrap_or(4.0);
    let n0 = (turn / (0.5 * limit)).ceil() as u64;
    for n in [n0, 4 * n0] {
        let (attitude, momentum) = p.fixed_end_errors(method, n).unwrap();
        for (what, error, momentum) in [("attitude", attitude, false), ("momentum", momentum, true)]
        {
            assert!(
                !exact_on(p, method, momentum) || error < low,
                "{} / {method}: {what} error {error:e} at {n} steps, exact promised",
                p.scene.name
            );
        }
    }
}

/// Whether the corrected split's leftover `h^2` term vanishes on a body with these moments.
fn alpha_is_twice_beta(moments: [f64; 3]) -> bool {
    let mut inverse = moments.map(|i| 1.0 / i);
    inverse.sort_by(f64::total_cmp);
    let (alpha, beta) = (inverse[2] - inverse[0], inverse[1] - inverse[0]);
    (alpha - 2.0 * beta).abs() < 1e-12 * alpha
}

#[test]
fn fixed_step_methods_converge_at_their_registered_order_on_every_reference_scene() {
    let mut checked = 0;
    for p in prepared() {
        let (methods, _) = p.scene.methods();
        for method in methods {
            if method.step_kind() != StepKind::Fixed {
                continue;
            }
            let order = method
                .order(p.scene.body.has_torque())
                .unwrap_or_else(|| panic!("{method}: fixed step, no order"));
            let started = std::time::Instant::now();
            if accurate_below_the_window(method) {
                assert_below_the_window_at_half_the_limit(p, method);
                checked += 1;
                continue;
            }
            if exact_on(p, method, false) || exact_on(p, method, true) {
                assert_exact_where_promised(p, method);
            }
            let (attitude, momentum) = observed_orders(p, method, order);
            let elapsed = started.elapsed();
            println!(
                "{} / {method}: order {order}, observed attitude {attitude:?}, momentum {momentum:?} ({elapsed:?})",
                p.scene.name
            );
            for (what, observed) in [("attitude", attitude), ("momentum", momentum)] {
                if exact_on(p, method, what == "momentum") {
                    continue;
                }
                let observed = observed.unwrap_or_else(|| {
                    panic!(
                        "{} / {method}: too few {what} errors in the window",
                        p.scene.name
                    )
                });
                let expected = expected_order(p, method, what == "momentum", order);
                assert!(
                    (observed - f64::from(expected)).abs() < ORDER_TOLERANCE,
                    "{} / {method}: {what} order {observed:.3}, expected {expected} (registry: {order})",
                    p.scene.name
                );
            }
            checked += 1;
        }
    }
    assert!(checked > 0);
}

/// Methods of high order whose stability limit is so small that at half of it (the fit's
/// coarsest step) their error is already near the fit's window's floor: fewer than three
/// levels fit. ga-rigid/tests/adams.rs measures their orders against the matrix reference
/// and the closed-form symmetric top at steps up to their stability edge; here they must
/// be accurate at that coarsest step and converge at least two orders below their own when
/// the step halves.
fn accurate_below_the_window(method: Method) -> bool {
    matches!(method, Method::Adams10 | Method::Adams12)
}

/// At half the stability limit the attitude and momentum errors are below 1e-9; at a
/// quarter they have fallen by `2^(p-2)` or reached `ABOVE_FLOOR` times the references'
/// disagreement (the order fit's lower bound).
fn assert_below_the_window_at_half_the_limit(p: &Prepared, method: Method) {
    let low = ABOVE_FLOOR * p.floor.max(1e-14);
    let limit = method
        .stable_step_rate(p.scene.body.has_torque())
        .unwrap_or_else(|| panic!("{method}: no stability limit"));
    let order = method.order(p.scene.body.has_torque()).unwrap_or(0);
    let n = (p.scene.t_end * p.scene.rate() / (0.5 * limit)).ceil() as u64;
    let errors = |n| {
        p.fixed_end_errors(method, n)
            .unwrap_or_else(|e| panic!("{} / {method}: {e}", p.scene.name))
    };
    let (ea, em) = errors(n);
    let (fa, fm) = errors(2 * n);
    println!(
        "{} / {method}: {n} steps at half its limit, attitude {ea:.1e}, momentum {em:.1e}; \
         twice the steps {fa:.1e}, {fm:.1e} (floor {low:.1e})",
        p.scene.name
    );
    assert!(
        ea < 1e-9 && em < 1e-9,
        "{} / {method}: errors {ea:e} {em:e} at half its stability limit",
        p.scene.name
    );
    let fell = |coarse: f64, fine: f64| fine < low || fine < coarse / 2f64.powi(order as i32 - 2);
    assert!(
        fell(ea, fa) && fell(em, fm),
        "{} / {method}: errors {ea:e} {em:e}, then {fa:e} {fm:e} at half the step",
        p.scene.name
    );
}

/// What a method keeps exactly (to rounding) on a free body.
#[derive(Clone, Copy, Debug, Default)]
struct Promises {
    /// The Casimir `|m|`.
    momentum_norm: bool,
    /// The space angular momentum `L = R m ~R` (and with it `|m|`).
    space_momentum: bool,
    /// The kinetic energy.
    energy: bool,
}

/// The invariants each method promises on a free body, from its documentation. The match
/// has no wildcard: a new method in the registry does not compile here until its promises
/// are stated.
fn promises(method: Method) -> Promises {
    let none = Promises::default();
    let all = Promises {
        momentum_norm: true,
        space_momentum: true,
        energy: true,
    };
    // Compositions of exact rotations of `m` about body axes, each the flow of a part of
    // the Hamiltonian that is invariant under rotations in space (Dullweber-Leimkuhler-
    // McLachlan; Buss: `L` moves only by the torque's impulse; Moser-Veselov: its
    // `Omega` turns the attitude and, transposed, the body momentum).
    let rotations = Promises {
        momentum_norm: true,
        space_momentum: true,
        energy: false,
    };
    match method {
        Method::ClosedForm | Method::Exact => all,
        // Without a torque each step is the exact free flow.
        Method::ExactSplitting
        | Method::ExactSplitting4
        | Method::ExactSplitting6
        | Method::ExactSplitting8 => all,
        Method::Splitting
        | Method::SplittingCayley
        | Method::SplittingCasimir
        | Method::SplittingCorrected
        | Method::Splitting4
        | Method::Splitting6
        | Method::Splitting8
        | Method::Buss2 => rotations,
        // The discrete Moser-Veselov step keeps its energy too (a discrete Lagrangian
        // whose energy is the kinetic energy; McLachlan-Zanna 2005).
        Method::MoserVeselov => all,
        // Spiers's velocity form turns `m` (`|m|` kept) and then the attitude by the new
        // rate, which moves `L`; the momentum-first form turns the attitude so that `L` stays
        // (B. Spiers, "A better way to spin"). Neither keeps the energy of an asymmetric body.
        Method::SpiersVelocity => Promises {
            momentum_norm: true,
            space_momentum: false,
            energy: false,
        },
        Method::SpiersMomentum => rotations,
        // The implicit midpoint rule keeps every quadratic invariant of the ODE: `|m|^2`
        // and the energy, not `L`, which is not quadratic in its unknowns.
        Method::Midpoint | Method::MidpointQuaternion => Promises {
            momentum_norm: true,
            space_momentum: false,
            energy: true,
        },
        Method::Rk4
        | Method::LieRk4
        | Method::Dopri
        | Method::LieDop853
        | Method::LieDop853Cayley
        | Method::Adams10
        | Method::Adams12
        | Method::Dop853Quaternion
        | Method::Dopri5Quaternion
        | Method::EulerGyroExplicit
        | Method::EulerGyroImplicit => none,
    }
}

/// The bound on a promised invariant's relative drift and on `|R ~R - 1|`. A run here
/// takes some 200 steps of a few roundings each (a random walk of some 1e-15), and the
/// implicit methods solve their equations to rounding; 1e-12 leaves a wide margin and is
/// far below any truncation error at these steps (h |w| = 0.05: above 1e-6 for every
/// method that does not keep the invariant).
const INVARIANT_BOUND: f64 = 1e-12;

/// The adaptive methods' tolerance here (relative; the absolute one a thousandth of it).
const ADAPTIVE_TOL: f64 = 1e-8;
/// How far above its tolerance an adaptive method's global error may be: the tolerance
/// bounds each step's local error, and some tens of steps a radian add up (the
/// published-value tests of ga-rigid allow 1e3 times the tolerance).
const ADAPTIVE_FACTOR: f64 = 1e3;
/// How close an exact solution must come to the other reference: the references agree to
/// some 1e-11 (`floor`), and the elliptic functions and the closed form are accurate to
/// rounding.
const EXACT_BOUND: f64 = 1e-9;

/// The step of the invariant runs: h |w(0)| = 0.05, below every stability limit, and a
/// whole number of steps between samples.
fn invariant_steps(p: &Prepared) -> u64 {
    let n = (p.scene.t_end * p.scene.rate() / 0.05).ceil() as u64;
    n.div_ceil(SAMPLES) * SAMPLES
}

#[test]
fn every_method_keeps_a_unit_rotor_and_the_free_body_invariants_it_promises() {
    for p in prepared() {
        let s = &p.scene;
        let free = !s.body.has_torque();
        let (methods, _) = s.methods();
        let m0 = s.body.body_momentum(s.initial.omega).norm();
        let l0 = s.body.space_momentum(&s.initial);
        let e0 = s.body.energy(s.initial.omega);
        for method in methods {
            let step = match method.step_kind() {
                StepKind::Fixed => Step::Fixed(s.t_end / invariant_steps(p) as f64 * (1.0 + 1e-9)),
                StepKind::Adaptive => Step::Tolerance(ADAPTIVE_TOL),
                StepKind::AtSamples => Step::AtSamples,
            };
            let states = match p.run(method, step) {
                Ok(states) => states,
                // ode_solvers' Dop853 gives up on the satellite, its stiffness test firing
                // at t = 0.16 (the report shows the failed row): a known limit of the peer,
                // not ours, kept in view here so that any other failure fails.
                Err(e)
                    if method == Method::Dop853Quaternion
                        && s.name == "gravity-gradient satellite"
                        && e.to_string().contains("stiff") =>
                {
                    println!("{} / {method}: {e}", s.name);
                    continue;
                }
                Err(e) => panic!("{} / {method}: {e}", s.name),
            };
            let accuracy = errors(s, &states, p.reference_for(method));
            let error = accuracy.attitude_max.max(accuracy.momentum_max);
            match method.step_kind() {
                StepKind::Adaptive => assert!(
                    error < ADAPTIVE_FACTOR * ADAPTIVE_TOL,
                    "{} / {method}: error {error:e} at tol {ADAPTIVE_TOL:e}",
                    s.name
                ),
                StepKind::AtSamples => assert!(
                    error < EXACT_BOUND,
                    "{} / {method}: {error:e} off the other reference",
                    s.name
                ),
                StepKind::Fixed => {}
            }
            let promised = promises(method);
            let (mut unit, mut norm, mut space, mut energy) = (0f64, 0f64, 0f64, 0f64);
            for state in &states {
                let r = state.rotor;
                unit = unit
                    .max((r.s * r.s + r.e12 * r.e12 + r.e13 * r.e13 + r.e23 * r.e23 - 1.0).abs());
                norm = norm.max((s.body.body_momentum(state.omega).norm() - m0).abs() / m0);
                space = space.max((s.body.space_momentum(state) - l0).norm() / l0.norm());
                energy = energy.max((s.body.energy(state.omega) - e0).abs() / e0);
            }
            println!(
                "{} / {method}: error {error:.1e}, |R~R - 1| {unit:.1e}, |m| {norm:.1e}, L {space:.1e}, energy {energy:.1e}",
                s.name
            );
            assert!(
                unit < INVARIANT_BOUND,
                "{} / {method}: |R~R - 1| = {unit:e}",
                s.name
            );
            if !free {
                continue;
            }
            for (what, kept, drift) in [
                (
                    "|m|",
                    promised.momentum_norm || promised.space_momentum,
                    norm,
                ),
                ("L", promised.space_momentum, space),
                ("energy", promised.energy, energy),
            ] {
                assert!(
                    !kept || drift < INVARIANT_BOUND,
                    "{} / {method}: {what} drifts by {drift:e}",
                    s.name
                );
            }
        }
    }
}
