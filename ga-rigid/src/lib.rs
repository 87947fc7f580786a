//! Rigid-body dynamics in geometric algebra.
