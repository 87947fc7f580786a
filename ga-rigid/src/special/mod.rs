//! Special functions for the exact rigid-body flow: Jacobi elliptic functions, the
//! elliptic integrals of the first and third kinds and Carlson's symmetric integrals.

pub mod elliptic;
