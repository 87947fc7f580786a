//! The public, glam-typed face of the engine, written once and stamped out for each
//! enabled glam version and both precisions.

/// The items of one precision on one glam: `$glam` is that glam (the dependency renamed
/// `glam_0_NN`), `$t` the float, `$step2`, `$step2_with` and `$step4` the one-body steps
/// for it (second order, with a torque read at both ends, fourth order), `$slice_all` the
/// slice form's stepper.
macro_rules! precision_api {
    (
        $glam:ident,
        $t:ident,
        $quat:ident,
        $vec3:ident,
        $mat3:ident,
        $step2:path,
        $step2_with:path,
        $step4:path,
        $slice_all:path,
        $width:literal,
        $blocks_all:path
    ) => {
        use crate::error::BodyError;
        use crate::inertia::Inertia;
        use crate::parts::{Order, Parts};
        use crate::rotation::{Q, V};
        use ::$glam::{$mat3, $quat, $vec3};

        #[inline(always)]
        fn q_in(q: $quat) -> Q<$t> {
            Q {
                x: q.x,
                y: q.y,
                z: q.z,
                w: q.w,
            }
        }

        #[inline(always)]
        fn q_out(q: Q<$t>) -> $quat {
            $quat::from_xyzw(q.x, q.y, q.z, q.w)
        }

        #[inline(always)]
        fn v_in(v: $vec3) -> V<$t> {
            V {
                x: v.x,
                y: v.y,
                z: v.z,
            }
        }

        #[inline(always)]
        fn v_out(v: V<$t>) -> $vec3 {
            $vec3::new(v.x, v.y, v.z)
        }

        /// A body's inertia, diagonalised once: principal moments, the principal frame
        /// and the free flow's constants (56 bytes in f32). Cheap to copy; build it when
        /// the shape changes, not per step.
        #[derive(Clone, Copy, Debug)]
        pub struct Body {
            inertia: Inertia<$t>,
        }

        impl Body {
            /// From the inertia tensor in the body frame (symmetric; its symmetric part
            /// is used), diagonalised here in f64 by Jacobi rotations. A diagonal tensor
            /// keeps its axes in the given order. The step works on the principal axes
            /// ordered from the smallest moment to the largest: where the moments do
            /// not decrease from x to z (`diag(1, 2, 3)`, a sphere, a flat top spinning
            /// about z) this costs the steps nothing extra; in another order
            /// (`diag(3, 2, 1)`, a rod along z)
            /// each step turns the orientation into that order and back, two quaternion
            /// products (the engine bench's `step_framed`). Giving the axes in ascending
            /// order, where a body's frame is free to choose, avoids them.
            ///
            /// # Errors
            /// A non-finite entry ([`BodyError::NotFinite`]), a principal moment that is
            /// not positive ([`BodyError::NotPositive`]) or outside the range the
            /// precision steps ([`BodyError::OutOfRange`], which says the range).
            pub fn from_tensor(tensor: $mat3) -> Result<Self, BodyError> {
                let c = [tensor.x_axis, tensor.y_axis, tensor.z_axis];
                Inertia::from_tensor(c.map(|a| [a.x, a.y, a.z])).map(|inertia| Body { inertia })
            }

            /// From principal moments and the principal frame: `frame` turns the
            /// principal axes into the body frame (so the tensor is
            /// `R diag(moments) R^T`, `R` the rotation of `frame`; any non-zero finite
            /// quaternion, of any size, normalised here). The cost of the axes' order is
            /// as in [`Body::from_tensor`].
            ///
            /// # Errors
            /// As [`Body::from_tensor`], and a zero `frame` ([`BodyError::ZeroFrame`]).
            pub fn from_principal(moments: $vec3, frame: $quat) -> Result<Self, BodyError> {
                Inertia::from_principal([moments.x, moments.y, moments.z], q_in(frame))
                    .map(|inertia| Body { inertia })
            }

            /// The principal moments, in the order of [`Body::principal_frame`]'s axes.
            #[must_use]
            pub fn principal_moments(&self) -> $vec3 {
                v_out(self.inertia.given().0)
            }

            /// The rotation from the principal axes to the body frame.
            #[must_use]
            pub fn principal_frame(&self) -> $quat {
                q_out(self.inertia.given().1)
            }

            /// The world angular velocity of a body with `orientation` (body to world)
            /// and world angular momentum `momentum`.
            #[must_use]
            pub fn angular_velocity(&self, orientation: $quat, momentum: $vec3) -> $vec3 {
                let q_p = self.inertia.principal_orientation(q_in(orientation).unit());
                v_out(self.inertia.velocity(q_p, v_in(momentum)))
            }

            /// The world angular momentum of a body with `orientation` turning at the
            /// world angular velocity `velocity`.
            #[must_use]
            pub fn angular_momentum(&self, orientation: $quat, velocity: $vec3) -> $vec3 {
                let q_p = self.inertia.principal_orientation(q_in(orientation).unit());
                v_out(self.inertia.momentum(q_p, v_in(velocity)))
            }

            /// The rotational kinetic energy `L . w / 2`.
            #[must_use]
            pub fn kinetic_energy(&self, orientation: $quat, momentum: $vec3) -> $t {
                let q_p = self.inertia.principal_orientation(q_in(orientation).unit());
                self.inertia.energy(q_p, v_in(momentum))
            }
        }

        /// The recommended step: free flow plus kick, second order (see the module
        /// docs). `orientation` body to world, `momentum` and `torque` in the world
        /// frame (the torque held over the step); returns the new orientation
        /// (normalised, in the hemisphere of the old one) and momentum. Without torque
        /// `|momentum|` is returned unchanged, bit for bit. `orientation` may be any
        /// non-zero finite quaternion: it is stepped as the unit one (see "Orientations"
        /// in the crate docs; zero or NaN gives a NaN orientation).
        #[must_use]
        // Inlined into the caller's loop when optimised (about 2.5 KB of code): called
        // out of line, its arguments and results went through memory and the step cost
        // about a tenth more (BENCHMARKS.md, "The one-body step inline"); `#[inline]`
        // alone left it out of line. Unoptimised, an ordinary call (see "Unoptimised
        // builds" in `splitting.rs`).
        #[cfg_attr(not(debug_assertions), inline(always))]
        #[cfg_attr(debug_assertions, inline)]
        pub fn step(
            body: &Body,
            orientation: $quat,
            momentum: $vec3,
            torque: $vec3,
            dt: $t,
        ) -> ($quat, $vec3) {
            let (q, l) = $step2(
                &body.inertia,
                q_in(orientation),
                v_in(momentum),
                v_in(torque),
                dt,
            );
            (q_out(q), v_out(l))
        }

        /// As [`step`] for a torque that depends on the orientation (gravity on a body
        /// turning about a pivot, a spring to a fixed direction): the arguments in
        /// [`step`]'s order, the torque given as `torque(q)`, read at the start and at
        /// the end of the step, half a kick each (Strang's splitting), which keeps the
        /// energy of a torque from a potential from drifting. Holding the start's torque
        /// over the step, as [`step`] with `torque(q)` would, lets it drift (the
        /// repository's `examples/t_handle.rs` shows both on a heavy top).
        #[must_use]
        #[inline]
        pub fn step_with(
            body: &Body,
            orientation: $quat,
            momentum: $vec3,
            mut torque: impl FnMut($quat) -> $vec3,
            dt: $t,
        ) -> ($quat, $vec3) {
            let (q, l) = $step2_with(&body.inertia, q_in(orientation), v_in(momentum), dt, |q| {
                v_in(torque(q_out(q)))
            });
            (q_out(q), v_out(l))
        }

        /// As [`step`], fourth order, three times the work. The better choice where
        /// each step turns the body a little (`dt |w|` up to about half a radian: at
        /// 60 Hz, up to 30 rad/s), where its error falls much faster with `dt`; about
        /// even with [`step`] near one radian a step, and worse beyond: at two radians
        /// a step its energy error is many times [`step`]'s (its substeps of 1.35 `dt`
        /// and -1.7 `dt` are larger than the step). For large steps use [`step`].
        /// For a body whose moments span decades, what counts for both steps is not
        /// `dt |w|` but about `dt |L| / sqrt(I_1 I_2)` (`I_1`, `I_2` the two smaller
        /// moments), which is far larger: moments (1e-3, 1, 1e3) spun about the middle
        /// axis with a twentieth of the rate about the largest have it near
        /// `1600 dt |w|`, and neither step keeps their energy above `dt |w|` of about
        /// 1e-4. `cargo run --release -p ga-engine --example step_sizes`
        /// measures both, and the test `step_order4_is_the_better_choice_only_for_small_steps`
        /// holds the comparison.
        #[must_use]
        #[inline]
        pub fn step_order4(
            body: &Body,
            orientation: $quat,
            momentum: $vec3,
            torque: $vec3,
            dt: $t,
        ) -> ($quat, $vec3) {
            let (q, l) = $step4(
                &body.inertia,
                q_in(orientation),
                v_in(momentum),
                v_in(torque),
                dt,
            );
            (q_out(q), v_out(l))
        }

        /// Baseline: explicit gyroscopic Euler on the world angular velocity
        /// (`w += dt J^-1 (T - w x J w)`, then the orientation by the new `w`).
        #[must_use]
        #[inline]
        pub fn explicit_gyroscopic_euler(
            body: &Body,
            orientation: $quat,
            velocity: $vec3,
            torque: $vec3,
            dt: $t,
        ) -> ($quat, $vec3) {
            let (q, w) = crate::euler::explicit(
                &body.inertia,
                q_in(orientation),
                v_in(velocity),
                v_in(torque),
                dt,
            );
            (q_out(q), v_out(w))
        }

        /// Baseline: implicit gyroscopic Euler with one Newton iteration, as in Bullet
        /// (Catto, GDC 2015), on the world angular velocity. It does not keep the
        /// energy: at small steps it damps the rotation (the energy falls), and at large
        /// ones (two radians a step) the energy can grow several times over.
        #[must_use]
        #[inline]
        pub fn implicit_gyroscopic_euler(
            body: &Body,
            orientation: $quat,
            velocity: $vec3,
            torque: $vec3,
            dt: $t,
        ) -> ($quat, $vec3) {
            let (q, w) = crate::euler::implicit(
                &body.inertia,
                q_in(orientation),
                v_in(velocity),
                v_in(torque),
                dt,
            );
            (q_out(q), v_out(w))
        }

        /// One body of a slice: its inertia, orientation (body to world), world angular
        /// momentum and the world torque held over the next step.
        #[derive(Clone, Copy, Debug)]
        pub struct BodyState {
            /// The body's inertia.
            pub body: Body,
            /// Body to world.
            pub orientation: $quat,
            /// World angular momentum.
            pub angular_momentum: $vec3,
            /// World torque, held over a step.
            pub torque: $vec3,
        }

        impl BodyState {
            /// From the world angular momentum, no torque.
            #[must_use]
            pub fn new(body: Body, orientation: $quat, angular_momentum: $vec3) -> Self {
                BodyState {
                    body,
                    orientation,
                    angular_momentum,
                    torque: $vec3::ZERO,
                }
            }

            /// From the world angular velocity, for an engine that stores the velocity:
            /// converted to the momentum once, here, and kept as the momentum from then
            /// on (see "Engines that store the angular velocity" in the crate docs).
            #[must_use]
            pub fn from_angular_velocity(body: Body, orientation: $quat, velocity: $vec3) -> Self {
                let angular_momentum = body.angular_momentum(orientation, velocity);
                BodyState::new(body, orientation, angular_momentum)
            }

            /// Adds a world angular impulse (a contact's `r x J`, a solver's correction
            /// times the inertia) to the momentum: exact, with no conversion through the
            /// velocity.
            #[inline]
            pub fn apply_angular_impulse(&mut self, impulse: $vec3) {
                self.angular_momentum += impulse;
            }

            /// Sets the world angular velocity, for a solver that writes velocities: the
            /// momentum becomes `I(q) w`, which rounds once. Call it only where the engine
            /// really changed the velocity; a momentum read back from an unchanged
            /// velocity each frame would round every frame and lose the free body's
            /// `|L|`.
            #[inline]
            pub fn set_angular_velocity(&mut self, velocity: $vec3) {
                self.angular_momentum = self.body.angular_momentum(self.orientation, velocity);
            }

            /// [`step`] in place (the same call, inlined as it is).
            #[cfg_attr(not(debug_assertions), inline(always))]
            #[cfg_attr(debug_assertions, inline)]
            pub fn step(&mut self, dt: $t) {
                (self.orientation, self.angular_momentum) = step(
                    &self.body,
                    self.orientation,
                    self.angular_momentum,
                    self.torque,
                    dt,
                );
            }

            /// [`step_order4`] in place (the same call).
            #[inline]
            pub fn step_order4(&mut self, dt: $t) {
                (self.orientation, self.angular_momentum) = step_order4(
                    &self.body,
                    self.orientation,
                    self.angular_momentum,
                    self.torque,
                    dt,
                );
            }

            /// The world angular velocity.
            #[must_use]
            pub fn angular_velocity(&self) -> $vec3 {
                self.body
                    .angular_velocity(self.orientation, self.angular_momentum)
            }

            /// The rotational kinetic energy.
            #[must_use]
            pub fn kinetic_energy(&self) -> $t {
                self.body
                    .kinetic_energy(self.orientation, self.angular_momentum)
            }
        }

        impl Parts<$t> for BodyState {
            #[inline(always)]
            fn parts(&self) -> (&Inertia<$t>, Q<$t>, V<$t>, V<$t>) {
                (
                    &self.body.inertia,
                    q_in(self.orientation),
                    v_in(self.angular_momentum),
                    v_in(self.torque),
                )
            }
            #[inline(always)]
            fn store(&mut self, q: Q<$t>, l: V<$t>) {
                self.orientation = q_out(q);
                self.angular_momentum = v_out(l);
            }
        }

        /// Every body by [`step`], several at a time in lanes: the same bits as
        /// stepping each alone. Gathering each body's components into the lanes and
        /// scattering the results back takes about half of its time; where the bodies
        /// can stay in a `BodyColumns` (feature `columns`), its `step` skips both.
        pub fn step_slice(states: &mut [BodyState], dt: $t) {
            $slice_all(states, dt, Order::Two);
        }

        /// Every body by [`step_order4`], likewise.
        pub fn step_slice_order4(states: &mut [BodyState], dt: $t) {
            $slice_all(states, dt, Order::Four);
        }

        /// [`step_slice`] on rayon's current pool, in fixed chunks: the results do not
        /// depend on the number of threads.
        #[cfg(feature = "rayon")]
        pub fn par_step_slice(states: &mut [BodyState], dt: $t) {
            crate::parallel::for_chunks(states, |chunk| step_slice(chunk, dt));
        }

        /// [`step_slice_order4`] on rayon's current pool, likewise.
        #[cfg(feature = "rayon")]
        pub fn par_step_slice_order4(states: &mut [BodyState], dt: $t) {
            crate::parallel::for_chunks(states, |chunk| step_slice_order4(chunk, dt));
        }

        #[cfg(feature = "columns")]
        columns_api!($glam, $t, $quat, $vec3, $width, $blocks_all);
    };
}

/// `f32` and `f64` modules on one glam.
macro_rules! engine_api {
    ($glam:ident) => {
        /// The engine in `f32` (`Quat`, `Vec3`, `Mat3`).
        // Slices in groups of 8, one AVX register a component, where the CPU has AVX;
        // else 4, one SSE register (8 in two SSE registers spilled to the stack and were
        // slower per body).
        pub mod f32 {
            precision_api!(
                $glam,
                f32,
                Quat,
                Vec3,
                Mat3,
                crate::splitting::step2_f32,
                crate::splitting::step2_with_f32,
                crate::splitting::step4_f32,
                crate::dispatch::step_all_f32,
                8,
                crate::dispatch::step_blocks_f32
            );
        }
        /// The engine in `f64` (`DQuat`, `DVec3`, `DMat3`).
        pub mod f64 {
            precision_api!(
                $glam,
                f64,
                DQuat,
                DVec3,
                DMat3,
                crate::splitting::step2,
                crate::splitting::step2_with,
                crate::splitting::step4,
                crate::dispatch::step_all_f64,
                4,
                crate::dispatch::step_blocks_f64
            );
        }
    };
}
