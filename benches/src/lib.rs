//! Shared bench support: seeded inputs and a table-driven reference algebra.
