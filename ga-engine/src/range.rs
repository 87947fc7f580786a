//! The projective form's range: the steps for which the division-free turns
//! (`projective.rs`) run. Inside it their numerators neither overflow nor underflow and
//! the result stays in the starting quaternion's hemisphere, so it is normalised without
//! the hemisphere test; outside it the divided turns (`divided.rs`) run with their
//! clamps. docs/derivations/projective-turns.md has the proof; a unit test in
//! `free_flow.rs` checks the hemisphere at the range's edge.

/// The projective form's range, as bounds on each turn's `b^2`, `|lambda| b^2` and
/// `|1 - e|`, and on the turn about `L`'s `w^2`: then each turn's squared norm
/// `g = (e - lambda b^2)^2 + b^2` lies in `[0.81, 1.2725]`, and the four turns move the
/// quaternion by less than 1.07 rad. `Split::reach` is the largest of the quotients by
/// these (per `h^2 |L|^2`).
pub(crate) const RANGE: [f64; 4] = [0.0625, 0.05, 0.05, 0.0625];

/// The largest squared body momentum the projective form takes (`|L| < 1e18`).
pub(crate) const FAST_MOMENTUM2: f64 = 1e36;
