//! Shape checks at the boundary: every array is validated here, so that no slice index,
//! cast or length mismatch can panic inside a kernel.

use numpy::{
    PyReadonlyArray1, PyReadonlyArray2, PyReadwriteArray1, PyReadwriteArray2, PyUntypedArrayMethods,
};
use pyo3::exceptions::PyValueError;
use pyo3::{PyErr, PyResult};

/// Above this many items a call releases the GIL while it computes.
pub const DETACH_ITEMS: usize = 4096;

/// The rows of a C-contiguous `(m, k)` array as items of `T` (`k` scalars each).
pub fn items<'a, S: numpy::Element + bytemuck::Pod, T: bytemuck::Pod>(
    array: &'a PyReadonlyArray2<'_, S>,
    k: usize,
    name: &str,
) -> PyResult<&'a [T]> {
    let shape = array.shape();
    if shape[1] != k {
        return Err(PyValueError::new_err(format!(
            "{name}: the last axis has {} components, expected {k}",
            shape[1]
        )));
    }
    // `as_slice` takes Fortran order too, which would read the components wrongly.
    if !array.is_c_contiguous() {
        return Err(not_c_contiguous(name));
    }
    let slice = array.as_slice().map_err(|_| not_c_contiguous(name))?;
    cast(slice, name)
}

/// A C-contiguous one-dimensional array as a slice.
pub fn scalars<'a, S: numpy::Element>(
    array: &'a PyReadonlyArray1<'_, S>,
    name: &str,
) -> PyResult<&'a [S]> {
    array.as_slice().map_err(|_| not_c_contiguous(name))
}

/// The rows of a writable C-contiguous `(n, k)` array as items of `T`.
pub fn items_mut<'a, S: numpy::Element + bytemuck::Pod, T: bytemuck::Pod>(
    array: &'a mut PyReadwriteArray2<'_, S>,
    k: usize,
    name: &str,
) -> PyResult<&'a mut [T]> {
    let shape = array.shape();
    if shape[1] != k {
        return Err(PyValueError::new_err(format!(
            "{name}: the last axis has {} components, expected {k}",
            shape[1]
        )));
    }
    if !array.is_c_contiguous() {
        return Err(not_c_contiguous(name));
    }
    let slice = array.as_slice_mut().map_err(|_| not_c_contiguous(name))?;
    bytemuck::try_cast_slice_mut(slice)
        .map_err(|e| PyValueError::new_err(format!("{name}: cannot view the data ({e})")))
}

/// A writable C-contiguous one-dimensional array as a slice.
pub fn scalars_mut<'a, S: numpy::Element>(
    array: &'a mut PyReadwriteArray1<'_, S>,
    name: &str,
) -> PyResult<&'a mut [S]> {
    array.as_slice_mut().map_err(|_| not_c_contiguous(name))
}

fn not_c_contiguous(name: &str) -> PyErr {
    PyValueError::new_err(format!("{name}: the array is not C-contiguous"))
}

fn cast<'a, S: bytemuck::Pod, T: bytemuck::Pod>(slice: &'a [S], name: &str) -> PyResult<&'a [T]> {
    bytemuck::try_cast_slice(slice)
        .map_err(|e| PyValueError::new_err(format!("{name}: cannot view the data ({e})")))
}

/// An input of `len` items broadcast against `n` outputs: it must have 1 or `n`.
pub fn broadcasts(len: usize, n: usize, name: &str) -> PyResult<()> {
    if len == n || len == 1 {
        Ok(())
    } else {
        Err(PyValueError::new_err(format!(
            "{name}: {len} items cannot broadcast to {n}; give 1 or {n}"
        )))
    }
}

/// `out[i] = f(a[i])`, `a` of 1 or `out.len()` items (checked by the caller).
pub fn map1<A: Copy, O: Copy>(a: &[A], out: &mut [O], f: impl Fn(A) -> O) {
    if a.len() == 1 {
        out.fill(f(a[0]));
    } else {
        for (slot, &x) in out.iter_mut().zip(a) {
            *slot = f(x);
        }
    }
}

/// `out[i] = f(a[i], b[i])`, each input of 1 or `out.len()` items, a single item repeated.
pub fn map2<A: Copy, B: Copy, O: Copy>(a: &[A], b: &[B], out: &mut [O], f: impl Fn(A, B) -> O) {
    match (a.len() == 1, b.len() == 1) {
        (true, true) => out.fill(f(a[0], b[0])),
        (true, false) => {
            for (slot, &y) in out.iter_mut().zip(b) {
                *slot = f(a[0], y);
            }
        }
        (false, true) => {
            for (slot, &x) in out.iter_mut().zip(a) {
                *slot = f(x, b[0]);
            }
        }
        (false, false) => {
            for ((slot, &x), &y) in out.iter_mut().zip(a).zip(b) {
                *slot = f(x, y);
            }
        }
    }
}

/// `out[i] = f(a[i], b[i], c[i])`, each input of 1 or `out.len()` items.
pub fn map3<A: Copy, B: Copy, C: Copy, O: Copy>(
    a: &[A],
    b: &[B],
    c: &[C],
    out: &mut [O],
    f: impl Fn(A, B, C) -> O,
) {
    let at = |s: &[A], i: usize| if s.len() == 1 { s[0] } else { s[i] };
    for (i, slot) in out.iter_mut().enumerate() {
        let y = if b.len() == 1 { b[0] } else { b[i] };
        let z = if c.len() == 1 { c[0] } else { c[i] };
        *slot = f(at(a, i), y, z);
    }
}

/// Run `f`, without the GIL when it covers at least [`DETACH_ITEMS`] items.
pub fn compute<T: Send>(py: pyo3::Python<'_>, n: usize, f: impl FnOnce() -> T + Send) -> T {
    if n >= DETACH_ITEMS {
        py.detach(f)
    } else {
        f()
    }
}
