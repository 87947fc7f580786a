//! `ga_rs.g3`: the generated G3 types on numpy arrays, and one value at a time.
//!
//! The batched functions take C-contiguous `(m, k)` inputs (`m` is 1 or the output's
//! count; the Python layer broadcasts and reshapes) and a C-contiguous `(n, k)` output,
//! one copy per precision, each computing in its own precision.

use ga_core::f64::g3::{Bivector, Rotor, Sandwich, Vector};
use numpy::{PyArray1, PyArray2};
use pyo3::prelude::*;

macro_rules! batched {
    ($t:ident) => {
        /// The batched functions in this precision.
        pub mod $t {
            use crate::check::{broadcasts, compute, items, items_mut, map1, map2, map3};
            use crate::check::{fast, scalars, scalars_mut, view, view_mut};
            use ga_core::kernels::$t as kernels;
            use ga_core::$t::g3::{Bivector, Rotor, Sandwich, Vector};
            use numpy::{PyReadonlyArray1, PyReadonlyArray2, PyReadwriteArray1, PyReadwriteArray2};
            use pyo3::exceptions::PyValueError;
            use pyo3::prelude::*;

            const NAN: $t = $t::NAN;

            /// `out = a b` on items (each input 1 or `out.len()` of them; the kernel
            /// where both are `out.len()`).
            fn mul_rotors_items(a: &[Rotor], b: &[Rotor], out: &mut [Rotor]) -> PyResult<()> {
                if a.len() == out.len() && b.len() == out.len() {
                    kernels::mul_pairs(a, b, out).map_err(|e| PyValueError::new_err(e.to_string()))
                } else {
                    map2(a, b, out, |x, y| x * y);
                    Ok(())
                }
            }

            /// `out = r v ~r` on items: the matrix kernel for one rotor on many vectors,
            /// the pairs kernel for a rotor per vector.
            fn sandwich_items(r: &[Rotor], v: &[Vector], out: &mut [Vector]) -> PyResult<()> {
                let n = out.len();
                let result = match (r.len() == n, v.len() == n) {
                    (true, true) => kernels::sandwich_pairs(r, v, out),
                    (false, true) => kernels::sandwich_all(r[0], v, out),
                    _ => {
                        map2(r, v, out, |q, x| q.sandwich(x));
                        Ok(())
                    }
                };
                result.map_err(|e| PyValueError::new_err(e.to_string()))
            }

            /// `out = a b` for rotors `a`, `b` (the kernel: bit for bit `a * b`).
            #[pyfunction]
            pub fn mul_rotors(
                py: Python<'_>,
                a: PyReadonlyArray2<'_, $t>,
                b: PyReadonlyArray2<'_, $t>,
                mut out: PyReadwriteArray2<'_, $t>,
            ) -> PyResult<()> {
                let a: &[Rotor] = items(&a, 4, "a")?;
                let b: &[Rotor] = items(&b, 4, "b")?;
                let out: &mut [Rotor] = items_mut(&mut out, 4, "out")?;
                let n = out.len();
                broadcasts(a.len(), n, "a")?;
                broadcasts(b.len(), n, "b")?;
                compute(py, n, || mul_rotors_items(a, b, out))
            }

            /// `out = a b = a.b + a^b` for vectors, a rotor-shaped `[s, e12, e13, e23]`.
            #[pyfunction]
            pub fn mul_vectors(
                py: Python<'_>,
                a: PyReadonlyArray2<'_, $t>,
                b: PyReadonlyArray2<'_, $t>,
                mut out: PyReadwriteArray2<'_, $t>,
            ) -> PyResult<()> {
                let a: &[Vector] = items(&a, 3, "a")?;
                let b: &[Vector] = items(&b, 3, "b")?;
                let out: &mut [Rotor] = items_mut(&mut out, 4, "out")?;
                let n = out.len();
                broadcasts(a.len(), n, "a")?;
                broadcasts(b.len(), n, "b")?;
                compute(py, n, || map2(a, b, out, |x, y| x * y));
                Ok(())
            }

            /// `out = a ^ b` for vectors (a bivector).
            #[pyfunction]
            pub fn outer(
                py: Python<'_>,
                a: PyReadonlyArray2<'_, $t>,
                b: PyReadonlyArray2<'_, $t>,
                mut out: PyReadwriteArray2<'_, $t>,
            ) -> PyResult<()> {
                let a: &[Vector] = items(&a, 3, "a")?;
                let b: &[Vector] = items(&b, 3, "b")?;
                let out: &mut [Bivector] = items_mut(&mut out, 3, "out")?;
                let n = out.len();
                broadcasts(a.len(), n, "a")?;
                broadcasts(b.len(), n, "b")?;
                compute(py, n, || map2(a, b, out, |x, y| x ^ y));
                Ok(())
            }

            /// `out = a | b` for vectors (the scalar product).
            #[pyfunction]
            pub fn inner(
                py: Python<'_>,
                a: PyReadonlyArray2<'_, $t>,
                b: PyReadonlyArray2<'_, $t>,
                mut out: PyReadwriteArray1<'_, $t>,
            ) -> PyResult<()> {
                let a: &[Vector] = items(&a, 3, "a")?;
                let b: &[Vector] = items(&b, 3, "b")?;
                let out = scalars_mut(&mut out, "out")?;
                let n = out.len();
                broadcasts(a.len(), n, "a")?;
                broadcasts(b.len(), n, "b")?;
                compute(py, n, || map2(a, b, out, |x, y| x | y));
                Ok(())
            }

            /// `out = r v ~r`: one rotor on many vectors through the matrix kernel
            /// (`kernels::sandwich_all`, fused multiply-adds where the CPU has them), a
            /// rotor per vector through `kernels::sandwich_pairs` (bit for bit
            /// `r.sandwich(v)`).
            #[pyfunction]
            pub fn sandwich(
                py: Python<'_>,
                r: PyReadonlyArray2<'_, $t>,
                v: PyReadonlyArray2<'_, $t>,
                mut out: PyReadwriteArray2<'_, $t>,
            ) -> PyResult<()> {
                let r: &[Rotor] = items(&r, 4, "rotor")?;
                let v: &[Vector] = items(&v, 3, "vector")?;
                let out: &mut [Vector] = items_mut(&mut out, 3, "out")?;
                let n = out.len();
                broadcasts(r.len(), n, "rotor")?;
                broadcasts(v.len(), n, "vector")?;
                compute(py, n, || sandwich_items(r, v, out))
            }

            /// `out = ~r`.
            #[pyfunction]
            pub fn reverse(
                py: Python<'_>,
                r: PyReadonlyArray2<'_, $t>,
                mut out: PyReadwriteArray2<'_, $t>,
            ) -> PyResult<()> {
                let r: &[Rotor] = items(&r, 4, "rotor")?;
                let out: &mut [Rotor] = items_mut(&mut out, 4, "out")?;
                broadcasts(r.len(), out.len(), "rotor")?;
                compute(py, out.len(), || map1(r, out, Rotor::reverse));
                Ok(())
            }

            /// `out = r / |r|`.
            #[pyfunction]
            pub fn normalize(
                py: Python<'_>,
                r: PyReadonlyArray2<'_, $t>,
                mut out: PyReadwriteArray2<'_, $t>,
            ) -> PyResult<()> {
                let r: &[Rotor] = items(&r, 4, "rotor")?;
                let out: &mut [Rotor] = items_mut(&mut out, 4, "out")?;
                broadcasts(r.len(), out.len(), "rotor")?;
                compute(py, out.len(), || map1(r, out, Rotor::normalized));
                Ok(())
            }

            /// `out = exp(b)`, a rotor.
            #[pyfunction]
            pub fn exp(
                py: Python<'_>,
                b: PyReadonlyArray2<'_, $t>,
                mut out: PyReadwriteArray2<'_, $t>,
            ) -> PyResult<()> {
                let b: &[Bivector] = items(&b, 3, "bivector")?;
                let out: &mut [Rotor] = items_mut(&mut out, 4, "out")?;
                broadcasts(b.len(), out.len(), "bivector")?;
                compute(py, out.len(), || map1(b, out, Bivector::exp));
                Ok(())
            }

            /// `out = log(r)`, NaN where `r` is not unit (within the generated `log`'s
            /// check) or has no logarithm.
            #[pyfunction]
            pub fn log(
                py: Python<'_>,
                r: PyReadonlyArray2<'_, $t>,
                mut out: PyReadwriteArray2<'_, $t>,
            ) -> PyResult<()> {
                let r: &[Rotor] = items(&r, 4, "rotor")?;
                let out: &mut [Bivector] = items_mut(&mut out, 3, "out")?;
                broadcasts(r.len(), out.len(), "rotor")?;
                compute(py, out.len(), || map1(r, out, log_one));
                Ok(())
            }

            /// The logarithm of one rotor, NaN where it has none.
            pub fn log_one(r: Rotor) -> Bivector {
                r.log().unwrap_or(Bivector::new(NAN, NAN, NAN))
            }

            /// `out = Rotor::from_axis_angle(axis, angle)`.
            #[pyfunction]
            pub fn from_axis_angle(
                py: Python<'_>,
                axis: PyReadonlyArray2<'_, $t>,
                angle: PyReadonlyArray1<'_, $t>,
                mut out: PyReadwriteArray2<'_, $t>,
            ) -> PyResult<()> {
                let axis: &[Vector] = items(&axis, 3, "axis")?;
                let angle = scalars(&angle, "angle")?;
                let out: &mut [Rotor] = items_mut(&mut out, 4, "out")?;
                let n = out.len();
                broadcasts(axis.len(), n, "axis")?;
                broadcasts(angle.len(), n, "angle")?;
                compute(py, n, || map2(axis, angle, out, Rotor::from_axis_angle));
                Ok(())
            }

            /// `out` (`(n, 9)`, row-major `3 x 3`) = the rotation matrix of `r`: `M v`
            /// is `r v ~r`.
            #[pyfunction]
            pub fn to_matrix(
                py: Python<'_>,
                r: PyReadonlyArray2<'_, $t>,
                mut out: PyReadwriteArray2<'_, $t>,
            ) -> PyResult<()> {
                let r: &[Rotor] = items(&r, 4, "rotor")?;
                let out: &mut [[[$t; 3]; 3]] = items_mut(&mut out, 9, "out")?;
                broadcasts(r.len(), out.len(), "rotor")?;
                compute(py, out.len(), || map1(r, out, Rotor::sandwich_matrix));
                Ok(())
            }

            /// `out = Rotor::from_matrix(m)` for row-major `m` (`(n, 9)`), NaN where `m`
            /// is not a rotation (within `sqrt(EPSILON)`).
            #[pyfunction]
            pub fn from_matrix(
                py: Python<'_>,
                m: PyReadonlyArray2<'_, $t>,
                mut out: PyReadwriteArray2<'_, $t>,
            ) -> PyResult<()> {
                let m: &[[[$t; 3]; 3]] = items(&m, 9, "matrix")?;
                let out: &mut [Rotor] = items_mut(&mut out, 4, "out")?;
                broadcasts(m.len(), out.len(), "matrix")?;
                compute(py, out.len(), || map1(m, out, from_matrix_one));
                Ok(())
            }

            /// The rotor of one row-major rotation matrix, NaN where it is not one.
            pub fn from_matrix_one(rows: [[$t; 3]; 3]) -> Rotor {
                let columns: [[$t; 3]; 3] =
                    core::array::from_fn(|c| core::array::from_fn(|r| rows[r][c]));
                Rotor::from_matrix(columns).unwrap_or(Rotor::new(NAN, NAN, NAN, NAN))
            }

            /// `out = a.slerp(b, t)`.
            #[pyfunction]
            pub fn slerp(
                py: Python<'_>,
                a: PyReadonlyArray2<'_, $t>,
                b: PyReadonlyArray2<'_, $t>,
                t: PyReadonlyArray1<'_, $t>,
                mut out: PyReadwriteArray2<'_, $t>,
            ) -> PyResult<()> {
                let a: &[Rotor] = items(&a, 4, "a")?;
                let b: &[Rotor] = items(&b, 4, "b")?;
                let t = scalars(&t, "t")?;
                let out: &mut [Rotor] = items_mut(&mut out, 4, "out")?;
                let n = out.len();
                broadcasts(a.len(), n, "a")?;
                broadcasts(b.len(), n, "b")?;
                broadcasts(t.len(), n, "t")?;
                compute(py, n, || map3(a, b, t, out, Rotor::slerp));
                Ok(())
            }

            /// The fast paths in this precision (see [`crate::check::fast`]): each
            /// `Ok(None)` where its inputs are not this precision's common case.
            pub mod quick {
                use super::*;

                /// The result of a fast call, `None` for the general path.
                type Quick<'py> = PyResult<Option<Bound<'py, PyAny>>>;
                /// An argument as the Python layer passes it.
                type Arg<'a, 'py> = &'a Bound<'py, PyAny>;

                /// `geometric`: rotors by rotors, or vectors by vectors.
                pub fn geometric<'py>(
                    py: Python<'py>,
                    a: Arg<'_, 'py>,
                    b: Arg<'_, 'py>,
                    out: Option<Arg<'_, 'py>>,
                ) -> Quick<'py> {
                    let rotors =
                        fast::<$t, 2>(py, [(a, &[4]), (b, &[4])], out, &[4], |[a, b], out| {
                            let (Some(a), Some(b), Some(out)) = (view(a), view(b), view_mut(out))
                            else {
                                return false;
                            };
                            mul_rotors_items(a, b, out).is_ok()
                        })?;
                    if rotors.is_some() {
                        return Ok(rotors);
                    }
                    fast::<$t, 2>(py, [(a, &[3]), (b, &[3])], out, &[4], |[a, b], out| {
                        let (Some(a), Some(b), Some(out)) = (
                            view::<_, Vector>(a),
                            view::<_, Vector>(b),
                            view_mut::<_, Rotor>(out),
                        ) else {
                            return false;
                        };
                        map2(a, b, out, |x, y| x * y);
                        true
                    })
                }

                /// `sandwich`.
                pub fn sandwich<'py>(
                    py: Python<'py>,
                    r: Arg<'_, 'py>,
                    v: Arg<'_, 'py>,
                    out: Option<Arg<'_, 'py>>,
                ) -> Quick<'py> {
                    fast::<$t, 2>(py, [(r, &[4]), (v, &[3])], out, &[3], |[r, v], out| {
                        let (Some(r), Some(v), Some(out)) = (view(r), view(v), view_mut(out))
                        else {
                            return false;
                        };
                        sandwich_items(r, v, out).is_ok()
                    })
                }

                /// `outer`.
                pub fn outer<'py>(
                    py: Python<'py>,
                    a: Arg<'_, 'py>,
                    b: Arg<'_, 'py>,
                    out: Option<Arg<'_, 'py>>,
                ) -> Quick<'py> {
                    fast::<$t, 2>(py, [(a, &[3]), (b, &[3])], out, &[3], |[a, b], out| {
                        let (Some(a), Some(b), Some(out)) = (
                            view::<_, Vector>(a),
                            view::<_, Vector>(b),
                            view_mut::<_, Bivector>(out),
                        ) else {
                            return false;
                        };
                        map2(a, b, out, |x, y| x ^ y);
                        true
                    })
                }

                /// `inner`.
                pub fn inner<'py>(
                    py: Python<'py>,
                    a: Arg<'_, 'py>,
                    b: Arg<'_, 'py>,
                    out: Option<Arg<'_, 'py>>,
                ) -> Quick<'py> {
                    fast::<$t, 2>(py, [(a, &[3]), (b, &[3])], out, &[], |[a, b], out| {
                        let (Some(a), Some(b)) = (view::<_, Vector>(a), view::<_, Vector>(b))
                        else {
                            return false;
                        };
                        map2(a, b, out, |x, y| x | y);
                        true
                    })
                }

                /// A one-input function from items of `A` (`k` components) to items of
                /// `O` (`out_comps`).
                fn unary<'py, A: bytemuck::Pod, O: bytemuck::Pod>(
                    py: Python<'py>,
                    x: Arg<'_, 'py>,
                    k: &[usize],
                    out: Option<Arg<'_, 'py>>,
                    out_comps: &[usize],
                    f: fn(A) -> O,
                ) -> Quick<'py> {
                    fast::<$t, 1>(py, [(x, k)], out, out_comps, |[x], out| {
                        let (Some(x), Some(out)) = (view(x), view_mut(out)) else {
                            return false;
                        };
                        map1(x, out, f);
                        true
                    })
                }

                /// `reverse`.
                pub fn reverse<'py>(
                    py: Python<'py>,
                    r: Arg<'_, 'py>,
                    out: Option<Arg<'_, 'py>>,
                ) -> Quick<'py> {
                    unary(py, r, &[4], out, &[4], Rotor::reverse)
                }

                /// `normalize`.
                pub fn normalize<'py>(
                    py: Python<'py>,
                    r: Arg<'_, 'py>,
                    out: Option<Arg<'_, 'py>>,
                ) -> Quick<'py> {
                    unary(py, r, &[4], out, &[4], Rotor::normalized)
                }

                /// `exp`.
                pub fn exp<'py>(
                    py: Python<'py>,
                    b: Arg<'_, 'py>,
                    out: Option<Arg<'_, 'py>>,
                ) -> Quick<'py> {
                    unary(py, b, &[3], out, &[4], Bivector::exp)
                }

                /// `log`.
                pub fn log<'py>(
                    py: Python<'py>,
                    r: Arg<'_, 'py>,
                    out: Option<Arg<'_, 'py>>,
                ) -> Quick<'py> {
                    unary(py, r, &[4], out, &[3], log_one)
                }

                /// `to_matrix`.
                pub fn to_matrix<'py>(
                    py: Python<'py>,
                    r: Arg<'_, 'py>,
                    out: Option<Arg<'_, 'py>>,
                ) -> Quick<'py> {
                    unary(py, r, &[4], out, &[3, 3], Rotor::sandwich_matrix)
                }

                /// `from_matrix`.
                pub fn from_matrix<'py>(
                    py: Python<'py>,
                    m: Arg<'_, 'py>,
                    out: Option<Arg<'_, 'py>>,
                ) -> Quick<'py> {
                    unary(py, m, &[3, 3], out, &[4], from_matrix_one)
                }

                /// `from_axis_angle`.
                pub fn from_axis_angle<'py>(
                    py: Python<'py>,
                    axis: Arg<'_, 'py>,
                    angle: Arg<'_, 'py>,
                    out: Option<Arg<'_, 'py>>,
                ) -> Quick<'py> {
                    fast::<$t, 2>(
                        py,
                        [(axis, &[3]), (angle, &[])],
                        out,
                        &[4],
                        |[axis, angle], out| {
                            let (Some(axis), Some(out)) = (view(axis), view_mut(out)) else {
                                return false;
                            };
                            map2(axis, angle, out, Rotor::from_axis_angle);
                            true
                        },
                    )
                }

                /// `slerp`.
                pub fn slerp<'py>(
                    py: Python<'py>,
                    a: Arg<'_, 'py>,
                    b: Arg<'_, 'py>,
                    t: Arg<'_, 'py>,
                    out: Option<Arg<'_, 'py>>,
                ) -> Quick<'py> {
                    fast::<$t, 3>(
                        py,
                        [(a, &[4]), (b, &[4]), (t, &[])],
                        out,
                        &[4],
                        |[a, b, t], out| {
                            let (Some(a), Some(b), Some(out)) = (view(a), view(b), view_mut(out))
                            else {
                                return false;
                            };
                            map3(a, b, t, out, Rotor::slerp);
                            true
                        },
                    )
                }
            }

            /// Add this precision's functions to `m`, each name ending in `_f32`/`_f64`.
            pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
                let suffix = concat!("_", stringify!($t));
                for f in [
                    wrap_pyfunction!(mul_rotors, m)?,
                    wrap_pyfunction!(mul_vectors, m)?,
                    wrap_pyfunction!(outer, m)?,
                    wrap_pyfunction!(inner, m)?,
                    wrap_pyfunction!(sandwich, m)?,
                    wrap_pyfunction!(reverse, m)?,
                    wrap_pyfunction!(normalize, m)?,
                    wrap_pyfunction!(exp, m)?,
                    wrap_pyfunction!(log, m)?,
                    wrap_pyfunction!(from_axis_angle, m)?,
                    wrap_pyfunction!(to_matrix, m)?,
                    wrap_pyfunction!(from_matrix, m)?,
                    wrap_pyfunction!(slerp, m)?,
                ] {
                    let name: String = f.getattr("__name__")?.extract()?;
                    m.add(format!("{name}{suffix}"), f)?;
                }
                Ok(())
            }
        }
    };
}

batched!(f32);
batched!(f64);

/// The fast paths the Python layer tries first (`ga_rs.g3`'s functions): float64 or
/// float32 arrays that need no conversion, broadcasting or copy. Each returns the result,
/// or `None` where the Python layer's general path must take the call; none raises for
/// bad input (the general path raises, with its messages).
mod quick {
    use super::{f32, f64};
    use pyo3::prelude::*;

    type Quick<'py> = PyResult<Option<Bound<'py, PyAny>>>;
    type Arg<'a, 'py> = &'a Bound<'py, PyAny>;

    /// Defines a `#[pyfunction]` that tries float64, then float32.
    macro_rules! both {
        ($(#[$doc:meta])* $name:ident($($arg:ident),*)) => {
            $(#[$doc])*
            #[pyfunction]
            pub fn $name<'py>(py: Python<'py>, $($arg: Arg<'_, 'py>,)* out: Option<Arg<'_, 'py>>) -> Quick<'py> {
                match f64::quick::$name(py, $($arg,)* out)? {
                    Some(result) => Ok(Some(result)),
                    None => f32::quick::$name(py, $($arg,)* out),
                }
            }
        };
    }

    both!(/// `geometric(a, b, out)`.
        geometric(a, b));
    both!(/// `sandwich(r, v, out)`.
        sandwich(r, v));
    both!(/// `outer(a, b, out)`.
        outer(a, b));
    both!(/// `inner(a, b, out)`.
        inner(a, b));
    both!(/// `reverse(r, out)`.
        reverse(r));
    both!(/// `normalize(r, out)`.
        normalize(r));
    both!(/// `exp(b, out)`.
        exp(b));
    both!(/// `log(r, out)`.
        log(r));
    both!(/// `to_matrix(r, out)`.
        to_matrix(r));
    both!(/// `from_matrix(m, out)`.
        from_matrix(m));
    both!(/// `from_axis_angle(axis, angle, out)`.
        from_axis_angle(axis, angle));
    both!(/// `slerp(a, b, t, out)`.
        slerp(a, b, t));

    /// Add the fast paths to `m`, each name ending in `_quick`.
    pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
        for f in [
            wrap_pyfunction!(geometric, m)?,
            wrap_pyfunction!(sandwich, m)?,
            wrap_pyfunction!(outer, m)?,
            wrap_pyfunction!(inner, m)?,
            wrap_pyfunction!(reverse, m)?,
            wrap_pyfunction!(normalize, m)?,
            wrap_pyfunction!(exp, m)?,
            wrap_pyfunction!(log, m)?,
            wrap_pyfunction!(to_matrix, m)?,
            wrap_pyfunction!(from_matrix, m)?,
            wrap_pyfunction!(from_axis_angle, m)?,
            wrap_pyfunction!(slerp, m)?,
        ] {
            let name: String = f.getattr("__name__")?.extract()?;
            m.add(format!("{name}_quick"), f)?;
        }
        Ok(())
    }
}

fn array<'py>(py: Python<'py>, values: &[f64]) -> Bound<'py, PyArray1<f64>> {
    PyArray1::from_slice(py, values)
}

/// `repr` of a float as Python writes it (shortest round trip).
fn float_repr(x: f64) -> String {
    if x.is_nan() {
        "nan".to_string()
    } else if x.is_infinite() {
        if x > 0.0 { "inf" } else { "-inf" }.to_string()
    } else if x == x.trunc() && x.abs() < 1e16 {
        format!("{x:.1}")
    } else {
        format!("{x:?}")
    }
}

/// A rotor `s + e12 + e13 + e23` in float64 (the even part of G3).
#[pyclass(name = "Rotor", module = "ga_rs.g3", frozen, eq, from_py_object)]
#[derive(Clone, Copy, PartialEq)]
pub struct PyRotor(pub Rotor);

/// A vector `e1, e2, e3` in float64.
#[pyclass(name = "Vector", module = "ga_rs.g3", frozen, eq, from_py_object)]
#[derive(Clone, Copy, PartialEq)]
pub struct PyVector(pub Vector);

/// A bivector `e12, e13, e23` in float64.
#[pyclass(name = "Bivector", module = "ga_rs.g3", frozen, eq, from_py_object)]
#[derive(Clone, Copy, PartialEq)]
pub struct PyBivector(pub Bivector);

#[pymethods]
impl PyRotor {
    #[new]
    #[pyo3(signature = (s=1.0, e12=0.0, e13=0.0, e23=0.0))]
    fn new(s: f64, e12: f64, e13: f64, e23: f64) -> Self {
        PyRotor(Rotor::new(s, e12, e13, e23))
    }

    /// The rotor turning by `angle` about `axis` (a unit vector): `exp(-I axis angle / 2)`.
    #[staticmethod]
    fn from_axis_angle(axis: PyVector, angle: f64) -> Self {
        PyRotor(Rotor::from_axis_angle(axis.0, angle))
    }

    /// The rotor of a row-major 3 x 3 rotation matrix; `None` if it is not one.
    #[staticmethod]
    fn from_matrix(rows: [[f64; 3]; 3]) -> Option<Self> {
        let r = f64::from_matrix_one(rows);
        (!r.s.is_nan()).then_some(PyRotor(r))
    }

    #[getter]
    fn s(&self) -> f64 {
        self.0.s
    }
    #[getter]
    fn e12(&self) -> f64 {
        self.0.e12
    }
    #[getter]
    fn e13(&self) -> f64 {
        self.0.e13
    }
    #[getter]
    fn e23(&self) -> f64 {
        self.0.e23
    }

    /// The geometric product of two rotors.
    fn __mul__(&self, other: PyRotor) -> PyRotor {
        PyRotor(self.0 * other.0)
    }

    /// `R v ~R`.
    fn sandwich(&self, v: PyVector) -> PyVector {
        PyVector(self.0.sandwich(v.0))
    }

    /// `~R`.
    fn reverse(&self) -> PyRotor {
        PyRotor(self.0.reverse())
    }

    /// `R / |R|`.
    fn normalize(&self) -> PyRotor {
        PyRotor(self.0.normalized())
    }

    /// The bivector `B` with `exp(B) = R` (NaN components where `R` is not unit).
    fn log(&self) -> PyBivector {
        PyBivector(f64::log_one(self.0))
    }

    /// Spherical interpolation to `end` (t = 0 gives self).
    fn slerp(&self, end: PyRotor, t: f64) -> PyRotor {
        PyRotor(self.0.slerp(end.0, t))
    }

    /// The row-major rotation matrix: `M @ v` is `R v ~R`.
    #[pyo3(name = "to_matrix")]
    fn matrix<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<f64>>> {
        let rows = self.0.sandwich_matrix();
        Ok(PyArray2::from_vec2(py, &rows.map(|r| r.to_vec()))?)
    }

    /// `[s, e12, e13, e23]` as a float64 array.
    #[pyo3(name = "to_array")]
    fn components<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        array(py, &self.0.to_array())
    }

    fn __repr__(&self) -> String {
        let r = self.0;
        format!(
            "Rotor({}, {}, {}, {})",
            float_repr(r.s),
            float_repr(r.e12),
            float_repr(r.e13),
            float_repr(r.e23)
        )
    }
}

#[pymethods]
impl PyVector {
    #[new]
    #[pyo3(signature = (e1=0.0, e2=0.0, e3=0.0))]
    fn new(e1: f64, e2: f64, e3: f64) -> Self {
        PyVector(Vector::new(e1, e2, e3))
    }

    #[getter]
    fn e1(&self) -> f64 {
        self.0.e1
    }
    #[getter]
    fn e2(&self) -> f64 {
        self.0.e2
    }
    #[getter]
    fn e3(&self) -> f64 {
        self.0.e3
    }

    /// The geometric product `a b = a.b + a^b`, a rotor-shaped even element.
    fn __mul__(&self, other: PyVector) -> PyRotor {
        PyRotor(self.0 * other.0)
    }

    /// `a ^ b`.
    fn outer(&self, other: PyVector) -> PyBivector {
        PyBivector(self.0 ^ other.0)
    }

    /// `a . b`.
    fn inner(&self, other: PyVector) -> f64 {
        self.0 | other.0
    }

    /// `[e1, e2, e3]` as a float64 array.
    #[pyo3(name = "to_array")]
    fn components<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        array(py, &self.0.to_array())
    }

    fn __repr__(&self) -> String {
        let v = self.0;
        format!(
            "Vector({}, {}, {})",
            float_repr(v.e1),
            float_repr(v.e2),
            float_repr(v.e3)
        )
    }
}

#[pymethods]
impl PyBivector {
    #[new]
    #[pyo3(signature = (e12=0.0, e13=0.0, e23=0.0))]
    fn new(e12: f64, e13: f64, e23: f64) -> Self {
        PyBivector(Bivector::new(e12, e13, e23))
    }

    #[getter]
    fn e12(&self) -> f64 {
        self.0.e12
    }
    #[getter]
    fn e13(&self) -> f64 {
        self.0.e13
    }
    #[getter]
    fn e23(&self) -> f64 {
        self.0.e23
    }

    /// `exp(B)`, a rotor.
    fn exp(&self) -> PyRotor {
        PyRotor(self.0.exp())
    }

    /// `[e12, e13, e23]` as a float64 array.
    #[pyo3(name = "to_array")]
    fn components<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<f64>> {
        array(py, &self.0.to_array())
    }

    fn __repr__(&self) -> String {
        let b = self.0;
        format!(
            "Bivector({}, {}, {})",
            float_repr(b.e12),
            float_repr(b.e13),
            float_repr(b.e23)
        )
    }
}

/// The `g3` submodule.
pub fn module(py: Python<'_>) -> PyResult<Bound<'_, PyModule>> {
    let m = PyModule::new(py, "g3")?;
    f32::register(&m)?;
    f64::register(&m)?;
    quick::register(&m)?;
    m.add_class::<PyRotor>()?;
    m.add_class::<PyVector>()?;
    m.add_class::<PyBivector>()?;
    m.add("instruction_set", ga_core::kernels::instruction_set())?;
    Ok(m)
}
