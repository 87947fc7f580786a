//! Trajectory derivatives: `lie-rk4` (free or heavy body) and the free body's `splitting`
//! written
//! once over any scalar type of `algebra!` and instantiated for `f64` (`gradients::f64`,
//! the same arithmetic as the registry's methods, which it is tested against) and, with the
//! feature `dual`, for `num_dual::Dual64` (`gradients::dual64`): one run with dual moments
//! or a dual initial angular velocity gives `dR(T)/d(i_k)` or `dR(T)/dw_k(0)` exactly for
//! the discrete method (the derivative of the very map the `f64` run computes).
//!
//! The registry's integrators (`integrators::LieRk4`, `integrators::Splitting`) keep their
//! own `f64` code, untouched: this file is a second instantiation for differentiation, not
//! a replacement, so that their speed does not depend on it.

/// The free-body steppers over the G3 module `$alg` whose scalar is `$s`.
macro_rules! free_body_steppers {
    ($(#[$doc:meta])* $name:ident, $alg:path, $s:ty) => {
        $(#[$doc])*
        pub mod $name {
            use $alg::{Bivector, Commutator as _, Rotor, Sandwich as _, Vector};
            use ga_core::Scalar;

            use crate::error::Error;

            /// The scalar type of this instantiation.
            pub type Real = $s;

            /// A constant of the scalar type.
            #[inline]
            fn k(x: f64) -> $s {
                <$s as Scalar>::from_f64(x)
            }

            /// A body: principal moments and their reciprocals, and optionally gravity
            /// (`mass`, the field `g` in space, the centre of mass in the body frame).
            #[derive(Clone, Copy, Debug)]
            pub struct FreeBody {
                moments: [$s; 3],
                inverse_moments: [$s; 3],
                gravity: Option<($s, Vector, Vector)>,
            }

            /// Attitude rotor and body angular velocity bivector, as `dynamics::State`.
            #[derive(Clone, Copy, Debug)]
            pub struct State {
                /// Body to space, `y = R x ~R`.
                pub rotor: Rotor,
                /// `Omega_B = w1 e23 - w2 e13 + w3 e12`.
                pub omega: Bivector,
            }

            impl State {
                /// The attitude `rotor` and the angular velocity vector `w`.
                #[must_use]
                pub fn new(rotor: Rotor, w: [$s; 3]) -> Self {
                    State {
                        rotor,
                        omega: Bivector::new(w[2], -w[1], w[0]),
                    }
                }

                /// The identity attitude and the angular velocity vector `w`.
                #[must_use]
                pub fn from_w(w: [$s; 3]) -> Self {
                    State {
                        rotor: Rotor::ONE,
                        omega: Bivector::new(w[2], -w[1], w[0]),
                    }
                }
            }

            impl FreeBody {
                /// A body with these principal moments; their real parts are checked as
                /// `RigidBody::new_unphysical` checks moments (positive and finite; the
                /// triangle inequality is not asked, so that test bodies such as Hairer,
                /// Lubich and Wanner's (2, 1, 2/3) can be used).
                pub fn new(moments: [$s; 3]) -> Result<Self, Error> {
                    crate::dynamics::RigidBody::new_unphysical(moments.map(|i| i.re()))?;
                    Ok(FreeBody {
                        moments,
                        inverse_moments: moments.map(|i| <$s as Scalar>::ONE / i),
                        gravity: None,
                    })
                }

                /// The same body in a uniform field: `dynamics::Gravity`'s torque
                /// `c ^ (~R (m g) R)` (a heavy top pivoted at the origin). Only `lie-rk4`
                /// takes a torque; `splitting` asks for a free body.
                #[must_use]
                pub fn with_gravity(mut self, mass: $s, g: Vector, com_offset: Vector) -> Self {
                    self.gravity = Some((mass, g, com_offset));
                    self
                }

                /// The gravity torque at attitude `rotor` (zero for a free body).
                #[inline]
                fn torque(&self, rotor: Rotor) -> Bivector {
                    match self.gravity {
                        Some((mass, g, com_offset)) => {
                            let force_body = rotor.reverse().sandwich(g * mass);
                            com_offset ^ force_body
                        }
                        None => Bivector::ZERO,
                    }
                }

                /// `I(B)` on the body bivector basis (as `RigidBody::inertia`).
                #[inline]
                fn inertia(&self, b: Bivector) -> Bivector {
                    let [i1, i2, i3] = self.moments;
                    Bivector::new(i3 * b.e12, i2 * b.e13, i1 * b.e23)
                }

                /// `I^-1(B)`.
                #[inline]
                fn inertia_inverse(&self, b: Bivector) -> Bivector {
                    let [j1, j2, j3] = self.inverse_moments;
                    Bivector::new(j3 * b.e12, j2 * b.e13, j1 * b.e23)
                }

                /// Euler's equations, `dOmega/dt = I^-1(Omega x I(Omega) + torque)`, as
                /// `RigidBody::omega_rate`.
                #[inline]
                #[must_use]
                pub fn omega_rate(&self, rotor: Rotor, omega: Bivector) -> Bivector {
                    let momentum = self.inertia(omega);
                    self.inertia_inverse(omega.commutator(momentum) + self.torque(rotor))
                }

                /// One RKMK4 step of length `h` (as `LieRk4::step_once`).
                #[must_use]
                pub fn lie_rk4_step(&self, state: State, h: $s) -> State {
                    let (r0, w0) = (state.rotor, state.omega);
                    let stage = |rotor: Rotor, omega: Bivector| {
                        (omega * (k(-0.5) * h), self.omega_rate(rotor, omega) * h)
                    };
                    let (k1, l1) = stage(r0, w0);
                    let (k2, l2) = stage(r0 * (k1 * k(0.5)).exp(), w0 + l1 * k(0.5));
                    let theta3 = k2 * k(0.5) + k1.commutator(k2) * k(0.25);
                    let (k3, l3) = stage(r0 * theta3.exp(), w0 + l2 * k(0.5));
                    let (k4, l4) = stage(r0 * k3.exp(), w0 + l3);
                    let theta = (k1 + (k2 + k3) * k(2.0) + k4) * (k(1.0) / k(6.0))
                        + k1.commutator(k4) * (k(1.0) / k(6.0));
                    State {
                        rotor: unit(r0 * theta.exp()),
                        omega: w0 + (l1 + (l2 + l3) * k(2.0) + l4) * (k(1.0) / k(6.0)),
                    }
                }

                /// `lie-rk4` over `duration` in equal sub-steps of at most `step` (as the
                /// registry's `LieRk4::new(step)` advancing by `duration`).
                pub fn lie_rk4(&self, state: State, step: f64, duration: f64) -> Result<State, Error> {
                    let (n, h) = substeps(step, duration)?;
                    let h = k(h);
                    let mut state = state;
                    for _ in 0..n {
                        state = self.lie_rk4_step(state, h);
                    }
                    Ok(state)
                }

                /// The exact flow of `m_k^2 / (2 i_k)` for `tau`: a turn of the momentum and
                /// the attitude about body axis `k` (as `Splitting::axis_flow`).
                #[inline]
                fn axis_flow(&self, axis: usize, tau: $s, rotor: &mut Rotor, m: &mut [$s; 3]) {
                    let theta = tau * m[axis] / self.moments[axis];
                    let (a, b) = ((axis + 1) % 3, (axis + 2) % 3);
                    let (s, c) = theta.sin_cos();
                    let (ma, mb) = (m[a], m[b]);
                    m[a] = c * ma + s * mb;
                    m[b] = c * mb - s * ma;
                    let (half_s, half_c) = (k(0.5) * theta).sin_cos();
                    let mut w = [<$s as Scalar>::ZERO; 3];
                    w[axis] = -half_s;
                    let plane = Bivector::new(w[2], -w[1], w[0]);
                    *rotor *= Rotor::new(half_c, plane.e12, plane.e13, plane.e23);
                }

                /// The torque-free Strang splitting over `duration` in equal sub-steps of
                /// at most `step`, axes in `order` (outer, middle, centre), as the
                /// registry's `Splitting::new(step)?.with_axis_order(order)`.
                pub fn splitting(
                    &self,
                    state: State,
                    step: f64,
                    duration: f64,
                    order: [usize; 3],
                ) -> Result<State, Error> {
                    let (n, h) = substeps(step, duration)?;
                    crate::integrators::Splitting::new(step)?.with_axis_order(order)?;
                    if self.gravity.is_some() {
                        return Err(Error::invalid(
                            "gravity",
                            "the differentiable splitting is the free body's: use lie_rk4",
                        ));
                    }
                    if n == 0 {
                        return Ok(state);
                    }
                    let h = k(h);
                    let w = [state.omega.e23, -state.omega.e13, state.omega.e12];
                    let mut m: [$s; 3] = ::std::array::from_fn(|i| self.moments[i] * w[i]);
                    let mut rotor = state.rotor;
                    let [outer, middle, centre] = order;
                    let half = k(0.5) * h;
                    self.axis_flow(outer, half, &mut rotor, &mut m);
                    for i in 0..n {
                        self.axis_flow(middle, half, &mut rotor, &mut m);
                        self.axis_flow(centre, h, &mut rotor, &mut m);
                        self.axis_flow(middle, half, &mut rotor, &mut m);
                        let tau = if i + 1 == n { half } else { h };
                        self.axis_flow(outer, tau, &mut rotor, &mut m);
                        rotor = unit(rotor);
                    }
                    let omega = Bivector::new(
                        m[2] / self.moments[2],
                        -(m[1] / self.moments[1]),
                        m[0] / self.moments[0],
                    );
                    Ok(State { rotor, omega })
                }
            }

            /// `R / |R|`.
            #[inline]
            fn unit(rotor: Rotor) -> Rotor {
                rotor / rotor.norm()
            }

            /// The registry's sub-step count and length for `duration`.
            fn substeps(step: f64, duration: f64) -> Result<(u64, f64), Error> {
                crate::integrators::Splitting::new(step)?;
                crate::integrators::substeps(step, duration)
            }
        }
    };
}

free_body_steppers!(
    /// The steppers in `f64`: the registry's arithmetic, the reference the dual runs are
    /// differences of.
    f64,
    ga_core::f64::g3,
    f64
);

#[cfg(feature = "dual")]
free_body_steppers!(
    /// The steppers over `num_dual::Dual64`: a run with one dual input gives the
    /// derivative of the final state along it.
    dual64,
    ga_core::dual64::g3,
    ga_core::num_dual::Dual64
);
