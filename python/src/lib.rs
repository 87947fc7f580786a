//! The native part of the `ga_rs` Python package: `ga_rs._native.{g3, rigid, engine}`,
//! wrapped by the package's Python modules (which broadcast, pick the precision and
//! allocate outputs). Every array is validated before any kernel runs.

mod check;
mod engine;
mod g3;
mod rigid;

use pyo3::prelude::*;

/// The extension module `ga_rs._native`.
#[pymodule]
fn _native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add_submodule(&g3::module(py)?)?;
    m.add_submodule(&rigid::module(py)?)?;
    m.add_submodule(&engine::module(py)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
