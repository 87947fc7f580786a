//! The `algebra!` generator.
