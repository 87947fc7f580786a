//! `ga_rs.rigid`: a scene run by a registry method through the command's checks, the
//! exact free-body flow, a scene's inertia and the report.
//!
//! Every library error becomes `ValueError` with the line `ga-rigid simulate` prints:
//! the same checks (`Method::given_step`, `limits::plan` with the default `Limits`, the
//! run), renamed by the command's own table (`ga_rigid_cli::FLAG_NAMES`).

use std::path::{Path, PathBuf};

use ga_rigid::error::Error;
use ga_rigid::limits::{plan, Limits};
use ga_rigid::registry::Method;
use ga_rigid::run::run_simulation_with_progress;
use ga_rigid::scene::Scene;
use numpy::{PyArray1, PyArrayMethods, PyReadonlyArray1, PyReadwriteArray2};
use pyo3::exceptions::{PyOSError, PyTypeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};

use crate::check::{compute, items_mut, scalars};

/// The path a scene given as a dict is parsed as (messages name it; a relative mesh
/// path resolves against the working directory).
const DICT_PATH: &str = "<dict>";

/// A library error in the command's words, as `ValueError`.
fn value_error(e: Error) -> PyErr {
    PyValueError::new_err(e.renamed(&ga_rigid_cli::FLAG_NAMES).to_string())
}

/// A Python value of a scene dict as TOML; `key` names it in errors.
fn to_toml(value: &Bound<'_, PyAny>, key: &str) -> PyResult<toml::Value> {
    if value.is_instance_of::<PyBool>() {
        return Ok(toml::Value::Boolean(value.extract()?));
    }
    if value.is_instance_of::<PyInt>() {
        let i: i64 = value.extract().map_err(|_| {
            PyValueError::new_err(format!("{key}: the integer does not fit in 64 bits"))
        })?;
        return Ok(toml::Value::Integer(i));
    }
    if value.is_instance_of::<PyFloat>() {
        return Ok(toml::Value::Float(value.extract()?));
    }
    if value.is_instance_of::<PyString>() {
        return Ok(toml::Value::String(value.extract()?));
    }
    if let Ok(dict) = value.cast::<PyDict>() {
        let mut table = toml::Table::new();
        for (k, v) in dict.iter() {
            let name: String = k.extract().map_err(|_| {
                PyTypeError::new_err(format!("{key}: the keys of a scene dict must be str"))
            })?;
            let path = if key.is_empty() {
                name.clone()
            } else {
                format!("{key}.{name}")
            };
            table.insert(name, to_toml(&v, &path)?);
        }
        return Ok(toml::Value::Table(table));
    }
    if value.is_instance_of::<PyList>() || value.is_instance_of::<PyTuple>() {
        let items: Vec<Bound<'_, PyAny>> = value.extract()?;
        let values = items
            .iter()
            .enumerate()
            .map(|(i, v)| to_toml(v, &format!("{key}[{i}]")))
            .collect::<PyResult<Vec<_>>>()?;
        return Ok(toml::Value::Array(values));
    }
    // numpy arrays and scalars: their Python values.
    if value.hasattr("tolist")? {
        let plain = value.call_method0("tolist")?;
        if !plain.is(value) {
            return to_toml(&plain, key);
        }
    }
    Err(PyTypeError::new_err(format!(
        "{key}: a scene value must be a bool, int, float, str, list, tuple or dict, got {}",
        value.get_type().name()?
    )))
}

/// `run.t_end` and `run.samples` replaced where given.
fn with_run(table: &mut toml::Table, t_end: Option<f64>, samples: Option<i64>) {
    if t_end.is_none() && samples.is_none() {
        return;
    }
    let run = table
        .entry("run")
        .or_insert_with(|| toml::Value::Table(toml::Table::new()));
    if let toml::Value::Table(run) = run {
        if let Some(t) = t_end {
            run.insert("t_end".into(), toml::Value::Float(t));
        }
        if let Some(n) = samples {
            run.insert("samples".into(), toml::Value::Integer(n));
        }
    }
}

/// Parse `table` as scene text from `path`; `in_file` names the file in its errors (a
/// scene file whose run was overridden), as `Scene::load` does.
fn parse_table(table: &toml::Table, path: &Path, in_file: bool) -> PyResult<Scene> {
    let text = toml::to_string(table)
        .map_err(|e| PyValueError::new_err(format!("the scene cannot be written as TOML: {e}")))?;
    Scene::parse(&text, path)
        .map_err(|e| if in_file { e.in_file(path) } else { e })
        .map_err(value_error)
}

/// The scene a dict or a path describes, with the run overridden where given.
fn scene_of(scene: &Bound<'_, PyAny>, t_end: Option<f64>, samples: Option<i64>) -> PyResult<Scene> {
    if scene.cast::<PyDict>().is_ok() {
        let toml::Value::Table(mut table) = to_toml(scene, "")? else {
            unreachable!("a dict converts to a table")
        };
        with_run(&mut table, t_end, samples);
        return parse_table(&table, Path::new(DICT_PATH), false);
    }
    let path: PathBuf = scene.extract().map_err(|_| {
        PyTypeError::new_err(format!(
            "scene: expected a dict or a path (str or os.PathLike), got {}",
            scene
                .get_type()
                .name()
                .map_or_else(|_| "?".into(), |n| n.to_string())
        ))
    })?;
    let loaded = Scene::load(&path).map_err(value_error)?;
    if t_end.is_none() && samples.is_none() {
        return Ok(loaded);
    }
    // Loaded once with every check of the file; read again to change its run.
    let text = std::fs::read_to_string(&path).map_err(|e| {
        PyValueError::new_err(format!("SCENE: cannot read {}: {e}", path.display()))
    })?;
    let mut table: toml::Table =
        toml::from_str(&text).map_err(|e| PyValueError::new_err(format!("SCENE: {e}")))?;
    with_run(&mut table, t_end, samples);
    parse_table(&table, &path, true)
}

/// The method of a name, or the error naming the choices.
fn method_of(name: &str) -> PyResult<Method> {
    Method::from_name(name).ok_or_else(|| {
        let names: Vec<&str> = Method::ALL.iter().map(|m| m.name()).collect();
        PyValueError::new_err(format!(
            "method: unknown method '{}'; one of {}",
            ga_rigid::error::echo(name),
            names.join(", ")
        ))
    })
}

/// Run `scene` by `method` as `ga-rigid simulate` does and return its rows as arrays.
#[pyfunction]
#[pyo3(signature = (scene, method, dt=None, tol=None, t_end=None, samples=None))]
fn simulate<'py>(
    py: Python<'py>,
    scene: &Bound<'py, PyAny>,
    method: &str,
    dt: Option<f64>,
    tol: Option<f64>,
    t_end: Option<f64>,
    samples: Option<i64>,
) -> PyResult<Bound<'py, PyDict>> {
    let method = method_of(method)?;
    // As the command: the step control is checked before the scene is read.
    let given = method.given_step(dt, tol).map_err(value_error)?;
    let scene = scene_of(scene, t_end, samples)?;
    let rows = py
        .detach(|| {
            let limits = Limits::default();
            let run = plan(&scene, method, given, &limits)?;
            run_simulation_with_progress(&scene, method, run.step, limits.max_steps, &mut |_| {})
        })
        .map_err(value_error)?;
    let n = rows.len();
    let mut time = Vec::with_capacity(n);
    let mut rotor = Vec::with_capacity(4 * n);
    let mut omega = Vec::with_capacity(3 * n);
    let mut energy = Vec::with_capacity(n);
    let mut momentum = Vec::with_capacity(3 * n);
    for row in &rows {
        time.push(row.t);
        rotor.extend(row.rotor.to_array());
        omega.extend(row.omega);
        energy.push(row.energy);
        momentum.extend(row.momentum);
    }
    let out = PyDict::new(py);
    out.set_item("time", PyArray1::from_vec(py, time))?;
    out.set_item("rotor", PyArray1::from_vec(py, rotor).reshape([n, 4])?)?;
    out.set_item("omega", PyArray1::from_vec(py, omega).reshape([n, 3])?)?;
    out.set_item("energy", PyArray1::from_vec(py, energy))?;
    out.set_item(
        "momentum",
        PyArray1::from_vec(py, momentum).reshape([n, 3])?,
    )?;
    Ok(out)
}

/// `ga_rigid::exact_flow::exact_free_body` at each time of `t`, into `rotor` `(n, 4)` and
/// `momentum` `(n, 3)`.
#[pyfunction]
fn exact_free_body(
    py: Python<'_>,
    moments: [f64; 3],
    m0: [f64; 3],
    r0: [f64; 4],
    t: PyReadonlyArray1<'_, f64>,
    mut rotor: PyReadwriteArray2<'_, f64>,
    mut momentum: PyReadwriteArray2<'_, f64>,
) -> PyResult<()> {
    let t = scalars(&t, "t")?;
    let rotor: &mut [[f64; 4]] = items_mut(&mut rotor, 4, "rotor")?;
    let momentum: &mut [[f64; 3]] = items_mut(&mut momentum, 3, "momentum")?;
    if rotor.len() != t.len() || momentum.len() != t.len() {
        return Err(PyValueError::new_err(format!(
            "the outputs must have one row per time ({}), got {} and {}",
            t.len(),
            rotor.len(),
            momentum.len()
        )));
    }
    compute(py, t.len(), || {
        for ((&ti, r), m) in t.iter().zip(rotor.iter_mut()).zip(momentum.iter_mut()) {
            (*r, *m) = ga_rigid::exact_flow::exact_free_body(moments, m0, r0, ti);
        }
    });
    Ok(())
}

/// The mass properties of a scene's body, as `ga-rigid inertia` prints them.
#[pyfunction]
fn inertia<'py>(py: Python<'py>, scene: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyDict>> {
    let scene = scene_of(scene, None, None)?;
    let inertia = &scene.inertia;
    let out = PyDict::new(py);
    out.set_item("mass", inertia.mass())?;
    let c = inertia.centre_of_mass();
    out.set_item("centre", PyArray1::from_slice(py, &[c.e1, c.e2, c.e3]))?;
    out.set_item("moments", PyArray1::from_slice(py, &inertia.moments()))?;
    out.set_item(
        "rotor",
        PyArray1::from_slice(py, &inertia.rotor().to_array()),
    )?;
    Ok(out)
}

/// `ga-rigid report --out=OUT_DIR [--quick]` through the command's library entry; its
/// summary and progress go to standard output and error as the command prints them. An
/// error is raised with the line the command would print: `ValueError` where the command
/// exits with status 2 (bad input), `OSError` where it exits with 1 (a failed write).
#[pyfunction]
#[pyo3(signature = (out_dir, quick=false))]
fn report(py: Python<'_>, out_dir: PathBuf, quick: bool) -> PyResult<()> {
    // `--out=DIR` in one argument, so that a directory named like a flag ("-x") is taken
    // as the value, not parsed as an option.
    let mut out = std::ffi::OsString::from("--out=");
    out.push(out_dir.into_os_string());
    let mut args = vec!["ga-rigid".into(), "report".into(), out];
    if quick {
        args.push("--quick".into());
    }
    py.detach(|| ga_rigid_cli::try_run(args))
        .map_err(|failure| match failure.status {
            2 => PyValueError::new_err(failure.message),
            _ => PyOSError::new_err(failure.message),
        })
}

/// The method names, in the registry's order.
#[pyfunction]
fn methods() -> Vec<&'static str> {
    Method::ALL.iter().map(|m| m.name()).collect()
}

/// The `rigid` submodule.
pub fn module(py: Python<'_>) -> PyResult<Bound<'_, PyModule>> {
    let m = PyModule::new(py, "rigid")?;
    m.add_function(wrap_pyfunction!(simulate, &m)?)?;
    m.add_function(wrap_pyfunction!(exact_free_body, &m)?)?;
    m.add_function(wrap_pyfunction!(inertia, &m)?)?;
    m.add_function(wrap_pyfunction!(report, &m)?)?;
    m.add_function(wrap_pyfunction!(methods, &m)?)?;
    Ok(m)
}
