//! `ga_rs.engine`: `ga_engine`'s step on many bodies in place, in f32 or f64.
//!
//! Orientations are glam quaternions `[x, y, z, w]` (body to world), momenta and torques
//! world vectors. The bodies are stepped by `step_slice` (or `step_slice_order4`) in
//! chunks, which gives the same bits as `ga_engine::{f32, f64}::step` on each alone.

use numpy::{PyArray2, PyReadonlyArray2, PyReadonlyArrayDyn, PyReadwriteArray2};
use pyo3::exceptions::{PyTypeError, PyValueError};
use pyo3::prelude::*;

use crate::check::{broadcasts, compute, items, items_mut};

/// Bodies copied into one stack buffer per `step_slice` call.
const CHUNK: usize = 256;

enum Precision {
    F32(Vec<ga_engine::f32::Body>),
    F64(Vec<ga_engine::f64::Body>),
}

/// Bodies built once from inertia tensors `(n, 3, 3)` (or one `(3, 3)`), float32 or
/// float64; the steps run in the tensors' precision.
#[pyclass(name = "Bodies", module = "ga_rs.engine", frozen)]
pub struct Bodies(Precision);

fn tensors_of<T: numpy::Element + Copy>(
    array: &PyReadonlyArrayDyn<'_, T>,
) -> PyResult<Vec<[[T; 3]; 3]>> {
    let a = array.as_array();
    let shape = a.shape();
    let (n, three) = match shape {
        [3, 3] => (1, true),
        [n, 3, 3] => (*n, true),
        _ => (0, false),
    };
    if !three {
        return Err(PyValueError::new_err(format!(
            "tensors: expected shape (n, 3, 3) or (3, 3), got {shape:?}"
        )));
    }
    let flat: Vec<T> = a.iter().copied().collect();
    Ok((0..n)
        .map(|i| core::array::from_fn(|r| core::array::from_fn(|c| flat[9 * i + 3 * r + c])))
        .collect())
}

macro_rules! bodies_from {
    ($module:ident, $mat:ident, $tensors:expr) => {
        $tensors
            .iter()
            .enumerate()
            .map(|(i, rows)| {
                // Column c of the glam matrix is column c of the row-major tensor.
                let columns = core::array::from_fn(|c| core::array::from_fn(|r| rows[r][c]));
                ga_engine::$module::Body::from_tensor(ga_engine::glam::$mat::from_cols_array_2d(
                    &columns,
                ))
                .map_err(|e| PyValueError::new_err(format!("tensors[{i}]: {e}")))
            })
            .collect::<PyResult<Vec<_>>>()
    };
}

#[pymethods]
impl Bodies {
    #[new]
    fn new(tensors: &Bound<'_, PyAny>) -> PyResult<Self> {
        if let Ok(a) = tensors.extract::<PyReadonlyArrayDyn<'_, f64>>() {
            return Ok(Bodies(Precision::F64(bodies_from!(
                f64,
                DMat3,
                tensors_of(&a)?
            )?)));
        }
        if let Ok(a) = tensors.extract::<PyReadonlyArrayDyn<'_, f32>>() {
            return Ok(Bodies(Precision::F32(bodies_from!(
                f32,
                Mat3,
                tensors_of(&a)?
            )?)));
        }
        Err(PyTypeError::new_err(
            "tensors: expected a float32 or float64 numpy array of shape (n, 3, 3)",
        ))
    }

    fn __len__(&self) -> usize {
        match &self.0 {
            Precision::F32(b) => b.len(),
            Precision::F64(b) => b.len(),
        }
    }

    /// `"float32"` or `"float64"`: the precision the steps run in.
    #[getter]
    fn dtype(&self) -> &'static str {
        match &self.0 {
            Precision::F32(_) => "float32",
            Precision::F64(_) => "float64",
        }
    }

    /// The principal moments `(n, 3)`, float64.
    fn principal_moments<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let rows: Vec<Vec<f64>> = match &self.0 {
            Precision::F32(b) => b
                .iter()
                .map(|b| b.principal_moments().to_array().map(f64::from).to_vec())
                .collect(),
            Precision::F64(b) => b
                .iter()
                .map(|b| b.principal_moments().to_array().to_vec())
                .collect(),
        };
        Ok(PyArray2::from_vec2(py, &rows)?)
    }

    fn __repr__(&self) -> String {
        format!("Bodies(<{} bodies, {}>)", self.__len__(), self.dtype())
    }
}

macro_rules! step_in {
    ($module:ident, $t:ident, $quat:ident, $vec:ident) => {
        fn $module(
            py: Python<'_>,
            bodies: &[ga_engine::$module::Body],
            q: &Bound<'_, PyAny>,
            l: &Bound<'_, PyAny>,
            torque: &Bound<'_, PyAny>,
            dt: f64,
            order: u32,
        ) -> PyResult<()> {
            use ga_engine::$module::{step_slice, step_slice_order4, BodyState};
            use ga_engine::glam::{$quat, $vec};
            let wrong = |name: &str, shape: &str| {
                PyTypeError::new_err(format!(
                    "{name}: expected a writable C-contiguous {} array of shape {shape} (the bodies' precision)",
                    dtype_name(stringify!($t))
                ))
            };
            let mut q: PyReadwriteArray2<'_, $t> = q.extract().map_err(|_| wrong("q", "(n, 4)"))?;
            let mut l: PyReadwriteArray2<'_, $t> = l.extract().map_err(|_| wrong("l", "(n, 3)"))?;
            let torque: PyReadonlyArray2<'_, $t> =
                torque.extract().map_err(|_| wrong("torque", "(n, 3) or (3,)"))?;
            let q: &mut [[$t; 4]] = items_mut(&mut q, 4, "q")?;
            let l: &mut [[$t; 3]] = items_mut(&mut l, 3, "l")?;
            let torque: &[[$t; 3]] = items(&torque, 3, "torque")?;
            let n = q.len();
            if l.len() != n {
                return Err(PyValueError::new_err(format!(
                    "l: {} momenta for {n} orientations",
                    l.len()
                )));
            }
            broadcasts(bodies.len(), n, "bodies")?;
            broadcasts(torque.len(), n, "torque")?;
            let dt = dt as $t;
            let step: fn(&mut [BodyState], $t) = match order {
                2 => step_slice,
                4 => step_slice_order4,
                _ => {
                    return Err(PyValueError::new_err(format!(
                        "order: 2 or 4, got {order}"
                    )))
                }
            };
            let at = |len: usize, i: usize| if len == 1 { 0 } else { i };
            compute(py, n, || {
                let mut states = Vec::with_capacity(CHUNK.min(n));
                for start in (0..n).step_by(CHUNK) {
                    let end = (start + CHUNK).min(n);
                    states.clear();
                    states.extend((start..end).map(|i| BodyState {
                        body: bodies[at(bodies.len(), i)],
                        orientation: $quat::from_array(q[i]),
                        angular_momentum: $vec::from_array(l[i]),
                        torque: $vec::from_array(torque[at(torque.len(), i)]),
                    }));
                    step(&mut states, dt);
                    for (i, s) in (start..end).zip(&states) {
                        q[i] = s.orientation.to_array();
                        l[i] = s.angular_momentum.to_array();
                    }
                }
            });
            Ok(())
        }
    };
}

fn dtype_name(t: &str) -> &'static str {
    if t == "f32" {
        "float32"
    } else {
        "float64"
    }
}

step_in!(f32, f32, Quat, Vec3);
step_in!(f64, f64, DQuat, DVec3);

/// Step every body once in place: `q` `(n, 4)` and `l` `(n, 3)` in the bodies' dtype,
/// `torque` `(n, 3)` or `(1, 3)`, `order` 2 (`step`) or 4 (`step_order4`).
#[pyfunction]
#[pyo3(signature = (bodies, q, l, torque, dt, order=2))]
fn step(
    py: Python<'_>,
    bodies: &Bodies,
    q: &Bound<'_, PyAny>,
    l: &Bound<'_, PyAny>,
    torque: &Bound<'_, PyAny>,
    dt: f64,
    order: u32,
) -> PyResult<()> {
    match &bodies.0 {
        Precision::F32(b) => f32(py, b, q, l, torque, dt, order),
        Precision::F64(b) => f64(py, b, q, l, torque, dt, order),
    }
}

/// The `engine` submodule.
pub fn module(py: Python<'_>) -> PyResult<Bound<'_, PyModule>> {
    let m = PyModule::new(py, "engine")?;
    m.add_class::<Bodies>()?;
    m.add_function(wrap_pyfunction!(step, &m)?)?;
    Ok(m)
}
