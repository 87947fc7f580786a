//! The public `BodyColumns`: many bodies stored column-wise (`blocks.rs`), for engines that
//! keep their bodies' rotation in the engine's own store and step them all each frame.
//! Written once and stamped out inside each precision's module by `precision_api!`
//! (`api.rs`), whose `Body`, `BodyState` and glam conversions it uses.

/// `BodyColumns` and `BodyMut` of one precision on one glam: `$glam` that glam (its module
/// name, as in `precision_api!`), `$t` the float, `$width` the lanes of a block,
/// `$blocks_all` the stepper of a slice of blocks (`dispatch.rs`).
macro_rules! columns_api {
    ($glam:ident, $t:ident, $quat:ident, $vec3:ident, $width:literal, $blocks_all:path) => {
        /// Lanes in one block of [`BodyColumns`].
        const WIDTH: usize = $width;

        /// Many bodies, stored component by component in blocks of eight (`f32`) or
        /// four (`f64`) bodies, the lanes the slice step runs in: stepping them
        /// ([`BodyColumns::step`]) loads each component of a block with one instruction,
        /// where [`step_slice`] gathers it from each [`BodyState`] and scatters the
        /// results back. Each body gets the bits [`step`] gives it alone.
        ///
        /// An engine keeps its bodies' rotation here for their life (index `i` is the
        /// `i`-th body pushed; [`BodyColumns::swap_remove`] moves the last into a hole, as
        /// `Vec::swap_remove`), reads and changes one through [`BodyColumns::get_mut`], and
        /// steps all of them once a frame. Indices out of range give `None`, never a
        /// panic.
        ///
        /// ```
        // The module of this glam and this precision, and that glam as the user's crate
        // names it (`glam`; here ga-engine's renamed dependency, in a hidden line).
        #[doc = concat!("# use ", stringify!($glam), " as glam;")]
        #[doc = concat!("use ga_engine::", stringify!($glam), "::", stringify!($t), "::{BodyColumns, Body, BodyState};")]
        #[doc = concat!("use glam::{", stringify!($quat), ", ", stringify!($vec3), "};")]
        ///
        #[doc = concat!("let body = Body::from_principal(", stringify!($vec3), "::new(1.0, 2.0, 3.0), ", stringify!($quat), "::IDENTITY).unwrap();")]
        /// let mut bodies = BodyColumns::new();
        /// for k in 0..10 {
        #[doc = concat!("    let momentum = ", stringify!($vec3), "::new(0.01, 2.0, 0.1 * k as ", stringify!($t), ");")]
        #[doc = concat!("    bodies.push(BodyState::new(body, ", stringify!($quat), "::IDENTITY, momentum));")]
        /// }
        #[doc = concat!("bodies.get_mut(3).unwrap().set_torque(", stringify!($vec3), "::new(0.0, 0.0, 0.5));")]
        /// for _ in 0..60 {
        ///     bodies.step(1.0 / 60.0);
        /// }
        /// let third = bodies.get(3).unwrap();
        /// assert!((third.angular_momentum.z - 0.8).abs() < 1e-5); // 0.3 + 0.5 * 1 s
        /// assert!(bodies.get(10).is_none());
        /// ```
        #[derive(Clone, Debug, Default)]
        pub struct BodyColumns {
            /// The blocks; lanes at and after `len` in the last are copies, never read.
            blocks: alloc::vec::Vec<crate::blocks::Block<$t, WIDTH>>,
            /// BodyColumns held.
            len: usize,
        }

        impl BodyColumns {
            /// No bodies.
            #[must_use]
            pub fn new() -> Self {
                BodyColumns::default()
            }

            /// No bodies, room for `n` without reallocating.
            #[must_use]
            pub fn with_capacity(n: usize) -> Self {
                BodyColumns {
                    blocks: alloc::vec::Vec::with_capacity(n.div_ceil(WIDTH)),
                    len: 0,
                }
            }

            /// How many bodies.
            #[must_use]
            pub fn len(&self) -> usize {
                self.len
            }

            /// Whether there are none.
            #[must_use]
            pub fn is_empty(&self) -> bool {
                self.len == 0
            }

            /// Adds a body at index [`BodyColumns::len`].
            pub fn push(&mut self, state: BodyState) {
                let lane = lane_of(&state);
                let i = self.len % WIDTH;
                if i == 0 {
                    // The empty lanes of a new block copy its first body.
                    self.blocks.push(crate::blocks::Block::filled(&lane));
                } else if let Some(block) = self.blocks.last_mut() {
                    block.set(i, &lane);
                }
                self.len += 1;
            }

            /// Body `i`, or `None` past the end.
            #[must_use]
            pub fn get(&self, i: usize) -> Option<BodyState> {
                (i < self.len).then(|| state_of(&self.blocks[i / WIDTH].get(i % WIDTH)))
            }

            /// Body `i` to read and change in place, or `None` past the end.
            #[must_use]
            pub fn get_mut(&mut self, i: usize) -> Option<BodyMut<'_>> {
                (i < self.len).then(|| BodyMut {
                    block: &mut self.blocks[i / WIDTH],
                    lane: i % WIDTH,
                })
            }

            /// Removes body `i` and returns it, moving the last body into its place
            /// (`Vec::swap_remove`); `None` past the end.
            pub fn swap_remove(&mut self, i: usize) -> Option<BodyState> {
                let removed = self.get(i)?;
                let last = self.len - 1;
                if i != last {
                    let moved = self.blocks[last / WIDTH].get(last % WIDTH);
                    self.blocks[i / WIDTH].set(i % WIDTH, &moved);
                }
                if last % WIDTH == 0 {
                    self.blocks.pop();
                }
                self.len = last;
                Some(removed)
            }

            /// The bodies in index order.
            pub fn iter(&self) -> impl ExactSizeIterator<Item = BodyState> + '_ {
                (0..self.len).map(|i| state_of(&self.blocks[i / WIDTH].get(i % WIDTH)))
            }

            /// Every body by [`step`], a block at a time: the same bits as stepping
            /// each alone, the torque of each held over the step.
            pub fn step(&mut self, dt: $t) {
                $blocks_all(&mut self.blocks, dt, Order::Two);
            }

            /// Every body by [`step_order4`], likewise.
            pub fn step_order4(&mut self, dt: $t) {
                $blocks_all(&mut self.blocks, dt, Order::Four);
            }

            /// [`BodyColumns::step`] on rayon's current pool, in fixed chunks: the results
            /// do not depend on the number of threads.
            #[cfg(feature = "rayon")]
            pub fn par_step(&mut self, dt: $t) {
                crate::parallel::for_chunks(&mut self.blocks, |chunk| {
                    $blocks_all(chunk, dt, Order::Two)
                });
            }

            /// [`BodyColumns::step_order4`] on rayon's current pool, likewise.
            #[cfg(feature = "rayon")]
            pub fn par_step_order4(&mut self, dt: $t) {
                crate::parallel::for_chunks(&mut self.blocks, |chunk| {
                    $blocks_all(chunk, dt, Order::Four)
                });
            }
        }

        impl FromIterator<BodyState> for BodyColumns {
            fn from_iter<I: IntoIterator<Item = BodyState>>(states: I) -> Self {
                let mut bodies = BodyColumns::new();
                bodies.extend(states);
                bodies
            }
        }

        impl Extend<BodyState> for BodyColumns {
            fn extend<I: IntoIterator<Item = BodyState>>(&mut self, states: I) {
                for state in states {
                    self.push(state);
                }
            }
        }

        /// One body of [`BodyColumns`], to read and change in place.
        #[derive(Debug)]
        pub struct BodyMut<'a> {
            /// Its block.
            block: &'a mut crate::blocks::Block<$t, WIDTH>,
            /// Its lane.
            lane: usize,
        }

        impl BodyMut<'_> {
            /// The whole body.
            #[must_use]
            pub fn state(&self) -> BodyState {
                state_of(&self.block.get(self.lane))
            }

            /// Replaces the whole body.
            pub fn set(&mut self, state: BodyState) {
                self.block.set(self.lane, &lane_of(&state));
            }

            /// Body to world.
            #[must_use]
            pub fn orientation(&self) -> $quat {
                q_out(self.block.motion(self.lane).0)
            }

            /// The world angular momentum.
            #[must_use]
            pub fn angular_momentum(&self) -> $vec3 {
                v_out(self.block.motion(self.lane).1)
            }

            /// The world angular velocity.
            #[must_use]
            pub fn angular_velocity(&self) -> $vec3 {
                self.state().angular_velocity()
            }

            /// The world torque held over the next steps.
            #[must_use]
            pub fn torque(&self) -> $vec3 {
                v_out(self.block.torque(self.lane))
            }

            /// Sets the world torque held over the next steps.
            pub fn set_torque(&mut self, torque: $vec3) {
                self.block.set_torque(self.lane, v_in(torque));
            }

            /// As [`BodyState::apply_angular_impulse`]: exact.
            pub fn apply_angular_impulse(&mut self, impulse: $vec3) {
                let l = self.angular_momentum() + impulse;
                self.block.set_momentum(self.lane, v_in(l));
            }

            /// As [`BodyState::set_angular_velocity`]: rounds once; call it only where
            /// the velocity really changed.
            pub fn set_angular_velocity(&mut self, velocity: $vec3) {
                let mut state = self.state();
                state.set_angular_velocity(velocity);
                self.block
                    .set_momentum(self.lane, v_in(state.angular_momentum));
            }
        }

        /// A body as a block's lane holds it.
        fn lane_of(state: &BodyState) -> crate::blocks::Lane<$t> {
            (
                state.body.inertia,
                q_in(state.orientation),
                v_in(state.angular_momentum),
                v_in(state.torque),
            )
        }

        /// A block's lane as a body.
        fn state_of(lane: &crate::blocks::Lane<$t>) -> BodyState {
            let (inertia, q, l, t) = *lane;
            BodyState {
                body: Body { inertia },
                orientation: q_out(q),
                angular_momentum: v_out(l),
                torque: v_out(t),
            }
        }
    };
}
