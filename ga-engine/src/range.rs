//! The projective form's range: the steps for which the division-free turns
//! (`projective.rs`) run. Inside it their numerators neither overflow nor underflow and
//! the result stays in the starting quaternion's hemisphere; outside it the divided turns
//! (`divided.rs`) run with their clamps.

/// The projective form's range, as bounds on each turn's `b^2`, `|lambda| b^2` and
/// `|1 - e|`, and on the turn about `L`'s `w^2`: then each turn's
/// `g = (e - lambda b^2)^2 + b^2` lies in `[0.81, 1.27]` and `g^31 < 1.7e3`.
/// `Split::reach` is the largest of the quotients by these (per `h^2 |L|^2`).
///
/// In that range the result stays in the starting quaternion's hemisphere, so it is
/// normalised without the hemisphere test (a dot product and a select fewer at the end
/// of the step's chain; `free_flow_normalized` in `free_flow.rs`). A turn `p + b e_K`
/// (times `D^2 > 0`) has the half-angle `atan(|b| / p) <= atan(0.25 / 0.9) = 0.271` rad,
/// the turn about `L`, `(1 - w^2/3) + w L/|L|`, at most `atan(0.25 / 0.979) = 0.251`.
/// Half-angles are distances on the unit sphere of quaternions, so the four turns move
/// `q_p` by at most 1.07 rad, and the result's dot product with `q_p` is at least
/// `cos 1.07 = 0.48` times their norms: the test would never negate (a unit test checks
/// it at the range's edge).
pub(crate) const RANGE: [f64; 4] = [0.0625, 0.05, 0.05, 0.0625];

/// The largest squared body momentum the projective form takes (`|L| < 1e18`).
pub(crate) const FAST_MOMENTUM2: f64 = 1e36;
