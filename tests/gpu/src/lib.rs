//! GPU tests only; see tests/.
