//! Nothing to link: the cases are under `tests/ui/` (one mistake each, with the error it
//! gets) and `tests/ui-pass/` (expansions that must compile and run); `tests/ui.rs` drives
//! them with trybuild.
