//! The workspace integration-test support: a slow reference algebra.
