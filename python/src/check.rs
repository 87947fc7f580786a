//! Shape checks at the boundary: every array is validated here, so that no slice index,
//! cast or length mismatch can panic inside a kernel.

use numpy::{
    PyArrayDyn, PyArrayMethods, PyReadonlyArray1, PyReadonlyArray2, PyReadonlyArrayDyn,
    PyReadwriteArray1, PyReadwriteArray2, PyUntypedArrayMethods,
};
use pyo3::exceptions::PyValueError;
use pyo3::types::{PyAnyMethods, PyFloat};
use pyo3::{Bound, PyAny, PyErr, PyResult, Python};

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

/// A float type the batched functions compute in.
pub trait Float: numpy::Element + bytemuck::Pod + Send + Sync {
    /// A Python float as this type (rounded to nearest, as numpy converts it).
    fn from_f64(x: f64) -> Self;
}

impl Float for f32 {
    fn from_f64(x: f64) -> Self {
        x as f32
    }
}

impl Float for f64 {
    fn from_f64(x: f64) -> Self {
        x
    }
}

/// An input of a fast-path call: an array of the call's dtype, or a Python float in a
/// scalar slot (weak, as numpy's `result_type` takes it).
enum Input<'py, S: Float> {
    Array(PyReadonlyArrayDyn<'py, S>),
    Scalar([S; 1]),
}

impl<S: Float> Input<'_, S> {
    /// The leading axes of an input whose trailing `comps` axes are the components.
    fn lead(&self, comps: usize) -> &[usize] {
        match self {
            Input::Array(a) => &a.shape()[..a.ndim() - comps],
            Input::Scalar(_) => &[],
        }
    }

    fn slice(&self) -> Option<&[S]> {
        match self {
            Input::Array(a) => a.as_slice().ok(),
            Input::Scalar(s) => Some(s),
        }
    }
}

/// `x` as a fast-path input of components `comps`, or `None` where the general path
/// must take it (another dtype or type, other trailing axes, not C-contiguous, borrowed
/// for writing elsewhere).
fn input<'py, S: Float>(x: &Bound<'py, PyAny>, comps: &[usize]) -> Option<Input<'py, S>> {
    if let Ok(a) = x.cast::<PyArrayDyn<S>>() {
        let shape = a.shape();
        let ok = shape.len() >= comps.len()
            && shape[shape.len() - comps.len()..] == *comps
            && a.is_c_contiguous();
        return if ok {
            a.try_readonly().ok().map(Input::Array)
        } else {
            None
        };
    }
    if comps.is_empty() && x.is_exact_instance_of::<PyFloat>() {
        return x
            .extract::<f64>()
            .ok()
            .map(|v| Input::Scalar([S::from_f64(v)]));
    }
    None
}

/// Whether two slices share any byte.
fn overlap<A, B>(a: &[A], b: &[B]) -> bool {
    let (a, b) = (a.as_ptr_range(), b.as_ptr_range());
    let (a, b) = (
        a.start as usize..a.end as usize,
        b.start as usize..b.end as usize,
    );
    !a.is_empty() && !b.is_empty() && a.start < b.end && b.start < a.end
}

/// The common case of a batched call without the Python layer's general checks: every
/// input (`(value, trailing component axes)`) a C-contiguous array of dtype `S` (or a
/// Python float in a scalar slot), the leading shapes all equal except single items
/// (no leading axes), and `out` absent or a C-contiguous writable `S` array of the
/// result's shape sharing no memory with an input. Runs `run` on the inputs' scalars
/// and the output's (without the GIL from [`DETACH_ITEMS`] items) and returns the output.
///
/// `Ok(None)` for anything else, with nothing written: the general path then converts,
/// broadcasts or copies, or raises its error, so both paths give one set of messages.
/// `run` returns `false`, before writing, where it cannot view the scalars as items.
pub fn fast<'py, S: Float, const N: usize>(
    py: Python<'py>,
    values: [(&Bound<'py, PyAny>, &[usize]); N],
    out: Option<&Bound<'py, PyAny>>,
    out_comps: &[usize],
    run: impl FnOnce([&[S]; N], &mut [S]) -> bool + Send,
) -> PyResult<Option<Bound<'py, PyAny>>> {
    let mut inputs = Vec::with_capacity(N);
    for (x, comps) in values {
        match input::<S>(x, comps) {
            Some(i) => inputs.push(i),
            None => return Ok(None),
        }
    }
    let mut lead: &[usize] = &[];
    for (i, (_, comps)) in inputs.iter().zip(values) {
        let l = i.lead(comps.len());
        if l.is_empty() {
            continue;
        }
        if lead.is_empty() {
            lead = l;
        } else if lead != l {
            return Ok(None);
        }
    }
    let shape: Vec<usize> = lead.iter().chain(out_comps).copied().collect();
    let array = match out {
        None => PyArrayDyn::<S>::zeros(py, shape, false),
        Some(o) => match o.cast::<PyArrayDyn<S>>() {
            Ok(a) if a.shape() == shape.as_slice() && a.is_c_contiguous() => a.clone(),
            _ => return Ok(None),
        },
    };
    let Ok(mut writer) = array.try_readwrite() else {
        return Ok(None);
    };
    let Ok(out_slice) = writer.as_slice_mut() else {
        return Ok(None);
    };
    let mut slices: [&[S]; N] = [&[]; N];
    for (slot, i) in slices.iter_mut().zip(&inputs) {
        match i.slice() {
            Some(s) if !overlap(s, out_slice) => *slot = s,
            _ => return Ok(None),
        }
    }
    let items = lead.iter().product::<usize>();
    if !compute(py, items, || run(slices, out_slice)) {
        return Ok(None);
    }
    drop(writer);
    Ok(Some(array.into_any()))
}

/// Scalars viewed as items of `T` (`None` where the length or alignment does not fit).
pub fn view<S: bytemuck::Pod, T: bytemuck::Pod>(s: &[S]) -> Option<&[T]> {
    bytemuck::try_cast_slice(s).ok()
}

/// Writable scalars viewed as items of `T`.
pub fn view_mut<S: bytemuck::Pod, T: bytemuck::Pod>(s: &mut [S]) -> Option<&mut [T]> {
    bytemuck::try_cast_slice_mut(s).ok()
}
