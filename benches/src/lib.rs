//! Shared bench support: seeded inputs and a table-driven reference algebra.
//!
//! - [`inputs`]: batches of random rotors, vectors, bivectors and multivectors of G3 and G4,
//!   as plain arrays in canonical blade order (`s, e1, e2, ..., e12, e13, ...`), converted
//!   to each library's types by the benches; seeded (the workspace's one generator,
//!   `ga_test_rng::Rng`), so that every run measures the same data.
//! - [`table`]: what a generic multivector library does: dense `[S; 2^n]` multivectors and a
//!   geometric product that loops over blade pairs with a sign table built at run time.
//! - [`peers`]: conversions from canonical arrays to glam, nalgebra and ultraviolet types,
//!   and exp and log for ultraviolet's rotors (written with its own API).
//! - [`rigid`]: the rigid-body test models, Euler's equations in matrix form for
//!   ode_solvers' Dop853, and the searches for each method's cheapest setting.
//! - [`summary`]: reads criterion's estimates and writes the markdown table of medians.
#![deny(missing_docs)]

pub mod inputs;
pub mod peers;
pub mod rigid;
pub mod summary;
pub mod table;
