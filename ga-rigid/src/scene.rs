//! Scene files: a rigid body, its initial state, the run length and an optional torque,
//! in TOML.
//!
//! ```toml
//! [body]                      # exactly one of moments, shape, points, mesh
//! moments = [1.0, 2.0, 2.5]
//! # allow_unphysical = true  # with moments only: skip the triangle inequality, for
//! #                          # test bodies such as (2, 1, 2/3) that no mass distribution has
//! # shape = { kind = "box", mass = 2.0, size = [1, 2, 3] }
//! # points = [[1.0, 0, 0, 1], [1.0, 0, 1, 0], [1.0, 1, 0, 0]]   # [m, x, y, z]
//! # mesh = "body.obj"         # relative to this file; needs density = ...
//!
//! [initial]
//! rotor = [1, 0, 0, 0]        # [s, e12, e13, e23], normalised on load
//! # axis = [0, 0, 1]          # or an axis and an angle (rad, right-handed), as glam's
//! # angle = 0.5               # Quat::from_axis_angle
//! omega = [0.45, 0, 1.4]      # body angular velocity w; Omega_B = I w
//!
//! [run]
//! t_end = 10.0
//! samples = 101               # output rows, including t = 0 and t = t_end
//!
//! [torque]                    # optional: uniform gravity
//! g = [0, 0, -9.81]           # space frame
//! com_offset = [0, 0, 0.1]    # body frame, from the fixed point to the centre of mass
//! ```
//!
//! Loading goes in three stages, so that every error names its field: the TOML parser
//! (syntax, duplicated keys: reported with line and column), serde on the parsed value
//! (missing, unknown and mistyped fields: reported with the dotted path serde's value
//! deserializer records), and the checks of this module and of the inertia constructors
//! (non-finite numbers, non-positive moments, ...: named by [`Error::within`]).
//!
//! The whole format follows (also `docs/scenes.md` in the repository).
//!
#![doc = include_str!("../../docs/scenes.md")]

use std::path::{Path, PathBuf};

use ga_core::f64::g3::*;
use serde::Deserialize;

use crate::error::{echo, finite3, positive, Error};
use crate::inertia::{normalize_rotor, Inertia, Mesh, Solid};

/// The most output rows a scene may ask for: ten million rows are about a gigabyte in
/// memory and two and a half as CSV, so more is a typo rather than a plan.
pub const MAX_SAMPLES: i64 = 10_000_000;

/// The largest scene file read: 16 MiB holds some 300,000 point masses; more is not a
/// scene someone wrote, and `/dev/zero` must not be read until memory runs out.
pub const MAX_SCENE_BYTES: u64 = 16 << 20;

/// A parsed and validated scene.
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// How the body was described in the file.
    pub body: BodySpec,
    /// The body's inertia about the point it turns about, computed from `body`: the centre
    /// of mass, or for a heavy top (`torque`) whose body is a shape, points or a mesh, the
    /// fixed point `com_offset` below the centre of mass (parallel-axis theorem, principal
    /// frame found afresh). `moments` are taken as given: about the fixed point when there
    /// is a torque, about the centre of mass otherwise.
    pub inertia: Inertia,
    /// The initial attitude and angular velocity.
    pub initial: Initial,
    /// The length and sampling of the run.
    pub run: Run,
    /// Uniform gravity, when the scene has a `[torque]` section.
    pub torque: Option<GravitySpec>,
}

/// The `[body]` section: one of the four ways to describe a body.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[cfg_attr(feature = "serde", serde(rename_all = "snake_case"))]
#[derive(Clone, Debug, PartialEq)]
pub enum BodySpec {
    /// `moments = [i1, i2, i3]`: principal moments about e1, e2, e3 of the body frame.
    Moments([f64; 3]),
    /// `shape = { kind = ..., mass = ..., ... }`: a standard solid.
    Shape(Solid),
    /// `points = [[m, x, y, z], ...]`: point masses.
    Points(Vec<(f64, [f64; 3])>),
    /// `mesh = "file.obj"` with `density`: a closed triangle mesh.
    Mesh {
        /// The OBJ file, resolved against the scene file's directory.
        path: PathBuf,
        /// The density of the enclosed solid.
        density: f64,
    },
}

impl BodySpec {
    /// The inertia the description gives, about the centre of mass; errors name the
    /// scene field (`body.moments`, `body.shape.mass`, `body.points[2]`, `body.mesh`).
    /// Moments must satisfy the triangle inequality (for those that do not, build the
    /// inertia with [`Inertia::from_principal_unphysical`] and use
    /// [`Scene::with_inertia`]); a mesh path is read as given.
    pub fn inertia(&self) -> Result<Inertia, Error> {
        match self {
            BodySpec::Moments(moments) => {
                Inertia::from_principal(*moments).map_err(|e| e.within("body"))
            }
            BodySpec::Shape(solid) => solid.inertia().map_err(|e| e.within("body.shape")),
            BodySpec::Points(points) => {
                Inertia::from_point_masses(points).map_err(|e| e.within("body"))
            }
            BodySpec::Mesh { path, density } => {
                positive("body.density", "density", *density)?;
                let mesh = Mesh::read_obj(path).map_err(|e| e.within("body"))?;
                Inertia::from_mesh(&mesh, *density).map_err(|e| e.within("body"))
            }
        }
    }
}

/// The `[initial]` section.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Initial {
    /// The initial attitude (body to space: `y = R x ~R`), normalised.
    #[cfg_attr(feature = "serde", serde(with = "serde_arrays::rotor"))]
    pub rotor: Rotor,
    /// The initial body angular velocity `[w1, w2, w3]`.
    pub omega: [f64; 3],
}

impl Initial {
    /// The body angular velocity as a bivector: `Omega_B = I w = w1 e23 - w2 e13 + w3 e12`.
    #[must_use]
    pub fn omega_bivector(&self) -> Bivector {
        crate::dynamics::omega_from_vector(self.omega)
    }
}

/// The `[run]` section.
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Run {
    /// The end time (positive); the run starts at t = 0.
    pub t_end: f64,
    /// The number of output rows, evenly spaced from 0 to `t_end` inclusive (at least 2,
    /// at most [`MAX_SAMPLES`]).
    pub samples: usize,
}

impl Run {
    /// The sample times `k t_end / (samples - 1)`, the last one exactly `t_end`.
    #[must_use]
    pub fn times(&self) -> Vec<f64> {
        // `samples >= 2` after loading; stay panic-free for a hand-built `Run` too.
        let last = self.samples.saturating_sub(1).max(1);
        (0..self.samples)
            .map(|k| {
                if k == last {
                    self.t_end
                } else {
                    // As in `Simulation::samples`: the fraction first only where
                    // `t_end * k` would overflow.
                    let scaled = self.t_end * k as f64;
                    if scaled.is_finite() {
                        scaled / last as f64
                    } else {
                        self.t_end * (k as f64 / last as f64)
                    }
                }
            })
            .collect()
    }
}

/// The `[torque]` section: uniform gravity acting at the centre of mass, as the scene file
/// writes it (no mass: that comes from the body); the dynamics' torque is
/// [`crate::dynamics::Gravity`].
#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct GravitySpec {
    /// The gravitational acceleration in the space frame.
    #[cfg_attr(feature = "serde", serde(with = "serde_arrays::vector"))]
    pub g: Vector,
    /// The centre of mass relative to the fixed point, in the body frame.
    #[cfg_attr(feature = "serde", serde(with = "serde_arrays::vector"))]
    pub com_offset: Vector,
}

/// The scene's parts as plain arrays for serde: ga-core's types have no serde support,
/// and arrays in the TOML file's own component order (`[s, e12, e13, e23]`, `[x, y, z]`)
/// read the same in any format.
#[cfg(feature = "serde")]
mod serde_arrays {
    /// A rotor as `[s, e12, e13, e23]`.
    pub mod rotor {
        use ga_core::f64::g3::Rotor;
        use serde::{Deserialize, Deserializer, Serialize, Serializer};

        pub fn serialize<S: Serializer>(r: &Rotor, s: S) -> Result<S::Ok, S::Error> {
            r.to_array().serialize(s)
        }

        pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Rotor, D::Error> {
            let [s, e12, e13, e23] = <[f64; 4]>::deserialize(d)?;
            Ok(Rotor::new(s, e12, e13, e23))
        }
    }

    /// A vector as `[x, y, z]`.
    pub mod vector {
        use ga_core::f64::g3::Vector;
        use serde::{Deserialize, Deserializer, Serialize, Serializer};

        pub fn serialize<S: Serializer>(v: &Vector, s: S) -> Result<S::Ok, S::Error> {
            v.to_array().serialize(s)
        }

        pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<Vector, D::Error> {
            let [x, y, z] = <[f64; 3]>::deserialize(d)?;
            Ok(Vector::new(x, y, z))
        }
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct SceneFile {
    body: BodyFile,
    initial: InitialFile,
    run: RunFile,
    torque: Option<TorqueFile>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct BodyFile {
    moments: Option<[f64; 3]>,
    shape: Option<Solid>,
    points: Option<Vec<[f64; 4]>>,
    mesh: Option<PathBuf>,
    density: Option<f64>,
    allow_unphysical: Option<bool>,
    /// 3 when given, checked on the table before serde (`only_3d`).
    #[allow(dead_code)]
    dimension: Option<i64>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct InitialFile {
    rotor: Option<[f64; 4]>,
    axis: Option<[f64; 3]>,
    angle: Option<f64>,
    omega: [f64; 3],
}

/// The initial attitude: `rotor = [s, e12, e13, e23]`, or `axis = [x, y, z]` with `angle`
/// (rad, right-handed about the axis: the rotor `exp(-I a angle / 2)` for the unit axis `a`,
/// as glam's `Quat::from_axis_angle`).
fn initial_rotor(file: &InitialFile) -> Result<Rotor, Error> {
    match (file.rotor, file.axis, file.angle) {
        (Some([s, e12, e13, e23]), None, None) => Ok(Rotor::new(s, e12, e13, e23)),
        (None, Some(axis), Some(angle)) => {
            let [x, y, z] = finite3("initial.axis", "axis", axis)?;
            crate::error::finite("initial.angle", "angle", angle)?;
            let largest = x.abs().max(y.abs()).max(z.abs());
            if largest == 0.0 {
                return Err(Error::invalid("initial.axis", "the axis must not be zero"));
            }
            let a = Vector::new(x / largest, y / largest, z / largest);
            Ok(Rotor::from_axis_angle(a / a.norm(), angle))
        }
        (None, Some(_), None) => Err(Error::invalid(
            "initial.angle",
            "missing field: `axis` needs an `angle` (rad)",
        )),
        (None, None, Some(_)) => Err(Error::invalid(
            "initial.axis",
            "missing field: `angle` needs an `axis`",
        )),
        (None, None, None) => Err(Error::invalid(
            "initial.rotor",
            "missing field: give `rotor = [s, e12, e13, e23]` or `axis` and `angle`",
        )),
        (Some(_), _, _) => Err(Error::invalid(
            "initial.rotor",
            "give either `rotor` or `axis` and `angle`, not both",
        )),
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RunFile {
    t_end: f64,
    // Signed, so that a negative count gets this module's message rather than serde's.
    samples: i64,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct TorqueFile {
    g: [f64; 3],
    com_offset: [f64; 3],
}

impl Scene {
    /// Read and validate a scene file; errors naming the file's own problems use the
    /// field `SCENE`, and every error's message starts with the path
    /// ([`Error::in_file`]). Only a regular file (or a link to one) of at most
    /// [`MAX_SCENE_BYTES`] is read.
    pub fn load(path: &Path) -> Result<Scene, Error> {
        let text = crate::input::read_text("SCENE", path, MAX_SCENE_BYTES)?;
        Scene::parse(&text, path).map_err(|e| e.in_file(path))
    }

    /// Parse and validate scene text; `path` is the file it came from (for messages and
    /// to resolve a relative `mesh` path).
    pub fn parse(text: &str, path: &Path) -> Result<Scene, Error> {
        let table: toml::Table = toml::from_str(text).map_err(|e| syntax_error(&e, text, path))?;
        sections_are_tables(&table)?;
        only_3d(&table)?;
        let file: SceneFile = toml::Value::Table(table)
            .try_into()
            .map_err(|e: toml::de::Error| field_error(&e))?;

        let (body, inertia) = load_body(file.body, path)?;
        let initial = Initial {
            rotor: initial_rotor(&file.initial)?,
            omega: file.initial.omega,
        };
        let samples = file.run.samples;
        if samples < 2 {
            return Err(Error::invalid(
                "run.samples",
                format!("samples must be at least 2, got {samples}"),
            ));
        }
        let run = Run {
            t_end: file.run.t_end,
            // Out of range only above usize::MAX, which `with_inertia` then refuses.
            samples: usize::try_from(samples).unwrap_or(usize::MAX),
        };
        let torque = file.torque.map(|t| GravitySpec {
            g: Vector::new(t.g[0], t.g[1], t.g[2]),
            com_offset: Vector::new(t.com_offset[0], t.com_offset[1], t.com_offset[2]),
        });
        Scene::with_inertia(body, inertia, initial, run, torque)
    }

    /// A scene built in code rather than read from TOML: the inertia is computed from
    /// `body` (see [`BodySpec::inertia`]), and every part checked as the loader checks a
    /// file, with errors naming the scene field (`initial.omega`, `run.samples`, ...).
    ///
    /// ```
    /// use ga_core::f64::g3::Rotor;
    /// use ga_rigid::scene::{BodySpec, Initial, Run, Scene};
    ///
    /// let scene = Scene::new(
    ///     BodySpec::Moments([2.0, 2.0, 1.0]),
    ///     Initial { rotor: Rotor::ONE, omega: [0.3, 0.0, 5.0] },
    ///     Run { t_end: 10.0, samples: 101 },
    ///     None,
    /// )?;
    /// assert_eq!(scene.inertia.moments(), [2.0, 2.0, 1.0]);
    /// # Ok::<(), ga_rigid::error::Error>(())
    /// ```
    pub fn new(
        body: BodySpec,
        initial: Initial,
        run: Run,
        torque: Option<GravitySpec>,
    ) -> Result<Scene, Error> {
        let inertia = body.inertia()?;
        Scene::with_inertia(body, inertia, initial, run, torque)
    }

    /// [`Scene::new`] with an inertia computed by the caller (for instance
    /// [`Inertia::from_principal_unphysical`] for the literature's test bodies); `body`
    /// only records how it was described. The rotor is normalised. As in a file, the
    /// inertia of a body other than `Moments` is taken about its centre of mass and, with a
    /// torque, shifted to the fixed point ([`Inertia::about_point`]).
    pub fn with_inertia(
        body: BodySpec,
        inertia: Inertia,
        initial: Initial,
        run: Run,
        torque: Option<GravitySpec>,
    ) -> Result<Scene, Error> {
        let rotor = normalize_rotor("initial.rotor", initial.rotor.to_array())?;
        let omega = finite3("initial.omega", "angular velocity", initial.omega)?;

        let t_end = positive("run.t_end", "t_end", run.t_end)?;
        let samples = run.samples;
        if samples < 2 {
            return Err(Error::invalid(
                "run.samples",
                format!("samples must be at least 2, got {samples}"),
            ));
        }
        if samples as u64 > MAX_SAMPLES as u64 {
            return Err(Error::invalid(
                "run.samples",
                format!("samples must be at most {MAX_SAMPLES}, got {samples}"),
            ));
        }

        let torque = match torque {
            None => None,
            Some(t) => {
                let [gx, gy, gz] = finite3("torque.g", "gravity", t.g.to_array())?;
                let [cx, cy, cz] = finite3("torque.com_offset", "offset", t.com_offset.to_array())?;
                Some(GravitySpec {
                    g: Vector::new(gx, gy, gz),
                    com_offset: Vector::new(cx, cy, cz),
                })
            }
        };

        // A solid's inertia is about its centre of mass; a heavy top turns about its
        // fixed point, `com_offset` away from it.
        let inertia = match (&body, torque) {
            (BodySpec::Moments(_), _) | (_, None) => inertia,
            (_, Some(gravity)) => inertia.about_point(gravity.com_offset).map_err(|e| {
                Error::invalid(
                    "torque.com_offset",
                    format!("the inertia about the fixed point: {e}"),
                )
            })?,
        };
        let scene = Scene {
            body,
            inertia,
            initial: Initial { rotor, omega },
            run: Run { t_end, samples },
            torque,
        };
        scene.check_magnitudes()?;
        Ok(scene)
    }

    /// The field the user wrote the body in (`body.moments`, `body.shape`, ...).
    #[must_use]
    pub fn body_field(&self) -> &'static str {
        match self.body {
            BodySpec::Moments(_) => "body.moments",
            BodySpec::Shape(_) => "body.shape",
            BodySpec::Points(_) => "body.points",
            BodySpec::Mesh { .. } => "body.mesh",
        }
    }

    /// Refuse scenes whose numbers overflow or underflow before any step is taken: the
    /// principal moments outside [`MOMENT_RANGE`], or an initial kinetic energy, squared
    /// angular momentum or weight that is not finite. A method would otherwise write
    /// `inf` rows, or fail later with a message about its own internals.
    fn check_magnitudes(&self) -> Result<(), Error> {
        let (low, high) = MOMENT_RANGE;
        let moments = self.inertia.moments();
        if let Some(&i) = moments.iter().find(|&&i| !(low..=high).contains(&i)) {
            return Err(Error::invalid(
                self.body_field(),
                format!(
                    "the principal moments must lie between {low:e} and {high:e} \
                     (rescale the units), got {i:e}"
                ),
            ));
        }
        let omega = self
            .inertia
            .rotor()
            .reverse()
            .sandwich(self.initial.omega_bivector());
        let w = crate::dynamics::omega_to_vector(omega);
        let momentum = [0, 1, 2].map(|k| moments[k] * w[k]);
        let energy: f64 = (0..3).map(|k| 0.5 * momentum[k] * w[k]).sum();
        let squared_momentum: f64 = momentum.iter().map(|l| l * l).sum();
        if !(energy.is_finite() && squared_momentum.is_finite()) {
            return Err(Error::invalid(
                "initial.omega",
                format!(
                    "the kinetic energy ({energy:e}) and squared angular momentum \
                     ({squared_momentum:e}) overflow with these moments; slow the body down"
                ),
            ));
        }
        if let Some(gravity) = self.torque {
            let mass = self.inertia.mass().unwrap_or(1.0);
            let weight = mass * gravity.g.norm() * gravity.com_offset.norm();
            if !weight.is_finite() {
                return Err(Error::invalid(
                    "torque.g",
                    "the potential energy m |g| |com_offset| overflows; rescale the units",
                ));
            }
        }
        Ok(())
    }
}

/// The range the principal moments must lie in: wide enough for any unit system, narrow
/// enough that products of up to three moments and squared energies stay normal numbers.
pub const MOMENT_RANGE: (f64, f64) = (1e-100, 1e100);
/// The scene's body and start in its principal frame, where the equations run. A scene's
/// `rotor` and `omega` describe its own (mesh or point-cloud) frame, related by the
/// principal rotor `P` (principal to scene frame): the principal attitude is `R P`, the
/// principal angular velocity `~P Omega P`.
impl Scene {
    /// The body in its principal frame, with gravity when the scene has it.
    pub fn principal_body(&self) -> Result<crate::dynamics::RigidBody, Error> {
        let body = crate::dynamics::RigidBody::new_unphysical(self.inertia.moments())?;
        Ok(match self.torque {
            None => body,
            Some(gravity) => {
                let principal = self.inertia.rotor();
                body.with_torque(crate::dynamics::Gravity {
                    // A `moments` body has no mass: its `g` is the weight m g.
                    mass: self.inertia.mass().unwrap_or(1.0),
                    g: gravity.g,
                    com_offset: principal.reverse().sandwich(gravity.com_offset),
                })
            }
        })
    }

    /// The initial state in the principal frame.
    #[must_use]
    pub fn principal_state(&self) -> crate::dynamics::State {
        let principal = self.inertia.rotor();
        crate::dynamics::State {
            rotor: self.initial.rotor * principal,
            omega: principal.reverse().sandwich(self.initial.omega_bivector()),
        }
    }
}

/// Pick the one body description and compute its inertia.
fn load_body(body: BodyFile, scene_path: &Path) -> Result<(BodySpec, Inertia), Error> {
    let given: Vec<&str> = [
        ("moments", body.moments.is_some()),
        ("shape", body.shape.is_some()),
        ("points", body.points.is_some()),
        ("mesh", body.mesh.is_some()),
    ]
    .into_iter()
    .filter_map(|(name, present)| present.then_some(name))
    .collect();
    if given.len() != 1 {
        let got = if given.is_empty() {
            "none".to_string()
        } else {
            given
                .iter()
                .map(|g| format!("`{g}`"))
                .collect::<Vec<_>>()
                .join(" and ")
        };
        return Err(Error::invalid(
            "body",
            format!("exactly one of `moments`, `shape`, `points`, `mesh` must be given, got {got}"),
        ));
    }
    if body.density.is_some() && body.mesh.is_none() {
        return Err(Error::invalid(
            "body.density",
            "density is only used with `mesh`",
        ));
    }

    if body.allow_unphysical.is_some() && body.moments.is_none() {
        return Err(Error::invalid(
            "body.allow_unphysical",
            "allow_unphysical is only used with `moments`",
        ));
    }

    if let Some(moments) = body.moments {
        let inertia = if body.allow_unphysical == Some(true) {
            Inertia::from_principal_unphysical(moments)
        } else {
            Inertia::from_principal(moments)
        }
        .map_err(|e| e.within("body"))?;
        return Ok((BodySpec::Moments(moments), inertia));
    }
    if let Some(solid) = body.shape {
        let inertia = solid.inertia().map_err(|e| e.within("body.shape"))?;
        return Ok((BodySpec::Shape(solid), inertia));
    }
    if let Some(points) = body.points {
        let points: Vec<(f64, [f64; 3])> = points
            .into_iter()
            .map(|[m, x, y, z]| (m, [x, y, z]))
            .collect();
        let inertia = Inertia::from_point_masses(&points).map_err(|e| e.within("body"))?;
        return Ok((BodySpec::Points(points), inertia));
    }
    // Exactly one description was given and it is not one of the three above.
    let mesh_path = body.mesh.unwrap_or_default();
    let density = body
        .density
        .ok_or_else(|| Error::invalid("body.density", "missing field: `mesh` needs a `density`"))?;
    positive("body.density", "density", density)?;
    let path = match scene_path.parent() {
        Some(dir) if mesh_path.is_relative() => dir.join(&mesh_path),
        _ => mesh_path,
    };
    let mesh = Mesh::read_obj(&path).map_err(|e| e.within("body"))?;
    let inertia = Inertia::from_mesh(&mesh, density).map_err(|e| e.within("body"))?;
    Ok((BodySpec::Mesh { path, density }, inertia))
}

/// Refuse a section written as something other than one table: serde would read
/// `[[run]]` (an array of tables) as a sequence of the section's fields in order, and
/// complain that `t_end` got a table ("invalid type: map, expected f64").
pub(crate) fn sections_are_tables(table: &toml::Table) -> Result<(), Error> {
    // Unknown names are left to serde, which names them as unknown fields.
    for name in ["body", "initial", "run", "torque"] {
        let got = match table.get(name) {
            None | Some(toml::Value::Table(_)) => continue,
            Some(toml::Value::Array(items)) if items.iter().all(toml::Value::is_table) => {
                format!("an array of tables [[{name}]]")
            }
            Some(other) => format!("a value of type {}", other.type_str()),
        };
        return Err(Error::invalid(
            name,
            format!("a section must be one table [{name}], got {got}"),
        ));
    }
    Ok(())
}

/// A TOML syntax error as one line with its position; a duplicated key (which the
/// parser reports as "duplicate key `k` in table `t`") is named as the field `t.k`.
pub(crate) fn syntax_error(e: &toml::de::Error, text: &str, path: &Path) -> Error {
    let (line, column) = match e.span() {
        Some(span) => {
            // Bytes, not chars: a span need not fall on a char boundary of `text`.
            let before = &text.as_bytes()[..span.start.min(text.len())];
            let line = before.iter().filter(|&&b| b == b'\n').count() + 1;
            let start = before
                .iter()
                .rposition(|&b| b == b'\n')
                .map_or(0, |i| i + 1);
            (line, before.len() - start + 1)
        }
        None => (0, 0),
    };
    let mut message = one_line(e.message());
    if message.is_empty() {
        // The parser gives no message when the text ends where a value should be.
        message = if e.span().is_some_and(|s| s.start >= text.trim_end().len()) {
            "the file ends where a value was expected".to_string()
        } else {
            "invalid TOML".to_string()
        };
    }
    if let Some(field) = duplicated_key(e.message(), text, e.span().map_or(0, |s| s.start)) {
        return Error::invalid(
            echo(&field),
            format!(
                "duplicated key (again at {}:{line}); each field may appear once",
                crate::error::echo_path(path)
            ),
        );
    }
    Error::Toml {
        path: path.to_path_buf(),
        line,
        column,
        message,
    }
}

/// The dotted field of a "duplicate key `k` in table `t`" or "... in document root"
/// message. Inside an inline table the parser names neither, so the table is found from
/// the text: the last `[header]` before `offset` and the key that starts its line.
fn duplicated_key(message: &str, text: &str, offset: usize) -> Option<String> {
    let rest = &message[message.find("duplicate key `")? + "duplicate key `".len()..];
    let (key, rest) = rest.split_once('`')?;
    if let Some(table) = rest
        .strip_prefix(" in table `")
        .and_then(|t| t.split_once('`'))
        .map(|(t, _)| t)
    {
        return Some(format!("{table}.{key}"));
    }
    if rest.starts_with(" in document root") {
        return Some(key.to_string());
    }
    let before = text.get(..offset.min(text.len()))?;
    let line = before.rsplit('\n').next().unwrap_or("");
    let outer = line.split_once('=').map(|(k, _)| k.trim()).unwrap_or("");
    let header = before
        .lines()
        .rev()
        .map(str::trim)
        .find(|l| l.starts_with('[') && l.ends_with(']'))
        .map(|l| l.trim_matches(|c| c == '[' || c == ']').trim())
        .unwrap_or("");
    let path: Vec<&str> = [header, outer, key]
        .into_iter()
        .filter(|p| !p.is_empty())
        .collect();
    Some(path.join("."))
}

/// A serde error on the parsed document, turned into `section.field: rule`.
///
/// toml's value deserializer appends the dotted key path as a final line "in `a.b`";
/// serde's own messages name the field for unknown and missing fields. Combining the
/// two gives the full path of the offending field.
pub(crate) fn field_error(e: &toml::de::Error) -> Error {
    let message = e.message();
    let display = e.to_string();
    let path = display
        .lines()
        .rev()
        .find_map(|l| l.strip_prefix("in `").and_then(|l| l.strip_suffix('`')))
        .unwrap_or("")
        .to_string();
    let join = |name: &str| {
        if path.is_empty() {
            echo(name)
        } else {
            echo(&format!("{path}.{name}"))
        }
    };
    if let Some(rest) = message.strip_prefix("unknown field `") {
        if let Some((name, expected)) = rest.split_once('`') {
            let expected = expected.trim_start_matches(", ");
            let what = if path.is_empty() { "section" } else { "field" };
            return Error::invalid(join(name), format!("unknown {what}, {expected}"));
        }
    }
    if let Some(rest) = message.strip_prefix("missing field `") {
        if let Some((name, _)) = rest.split_once('`') {
            let what = if path.is_empty() { "section" } else { "field" };
            return Error::invalid(join(name), format!("missing {what}"));
        }
    }
    let field = if path.is_empty() {
        "SCENE".to_string()
    } else {
        echo(&path)
    };
    Error::invalid(field, in_words(&one_line(message)))
}

/// serde's Rust type names in a message (`expected i64`) in the words of a scene file.
fn in_words(message: &str) -> String {
    let mut out = message.to_string();
    for (rust, words) in [
        ("expected f64", "expected a number"),
        ("expected i64", "expected a whole number"),
        ("expected u64", "expected a whole number"),
        ("expected usize", "expected a whole number"),
        ("expected u32", "expected a whole number"),
        ("expected a boolean", "expected true or false"),
    ] {
        if out.ends_with(rust)
            || out.contains(&format!("{rust} "))
            || out.contains(&format!("{rust};"))
        {
            out = out.replace(rust, words);
        }
    }
    out
}

/// A parser or serde message on one line, with every quoted piece of the user's text
/// (`...` or "...") cut by [`echo`], and the whole at most 180 characters.
fn one_line(message: &str) -> String {
    let joined = message
        .lines()
        .map(str::trim)
        .filter(|l| !l.is_empty())
        .collect::<Vec<_>>()
        .join("; ");
    let mut out = String::new();
    let mut rest = joined.as_str();
    while let Some(open) = rest.find(['`', '"']) {
        let quote = rest[open..].chars().next().unwrap_or('`');
        out.push_str(&rest[..=open]);
        let after = &rest[open + 1..];
        match after.find(quote) {
            Some(close) => {
                out.push_str(&echo(&after[..close]));
                out.push(quote);
                rest = &after[close + 1..];
            }
            None => {
                out.push_str(&echo(after));
                rest = "";
            }
        }
    }
    out.push_str(rest);
    if out.chars().count() > 180 {
        let head: String = out.chars().take(170).collect();
        return format!("{head}...");
    }
    out
}

/// `body.dimension` where it is an integer.
pub(crate) fn declared_dimension(table: &toml::Table) -> Option<i64> {
    table
        .get("body")
        .and_then(toml::Value::as_table)
        .and_then(|body| body.get("dimension"))
        .and_then(toml::Value::as_integer)
}

/// The 3D loader's check of `body.dimension`, before serde reads the other fields for 3D:
/// absent or 3 (a value of another type is left to serde's message).
pub(crate) fn only_3d(table: &toml::Table) -> Result<(), Error> {
    match declared_dimension(table) {
        None | Some(3) => Ok(()),
        Some(d @ (2 | 4)) => Err(Error::invalid(
            "body.dimension",
            format!("a {d}D scene: load it with nd::scene::NdScene, not the 3D Scene"),
        )),
        Some(d) => Err(Error::invalid(
            "body.dimension",
            format!("the dimension must be 2, 3 or 4, got {d}"),
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A value of the wrong type is named in words, not by the Rust type serde wanted.
    #[test]
    fn a_wrong_type_says_what_the_field_expects_in_words() {
        let scene = |moments: &str, samples: &str| {
            format!(
                "[body]\nmoments = {moments}\n[initial]\nrotor = [1, 0, 0, 0]\n\
                 omega = [0.1, 1.0, 0.2]\n[run]\nt_end = 10.0\nsamples = {samples}\n"
            )
        };
        let path = Path::new("s.toml");
        let e = Scene::parse(&scene("[1.0, 2.0, 2.5]", "1.5"), path).unwrap_err();
        assert_eq!(
            e.to_string(),
            "run.samples: invalid type: floating point `1.5`, expected a whole number"
        );
        let e = Scene::parse(&scene("[1.0, 2.0, \"x\"]", "3"), path).unwrap_err();
        assert_eq!(
            e.to_string(),
            "body.moments: invalid type: string \"x\", expected a number"
        );
    }

    fn parse(text: &str) -> Result<Scene, Error> {
        Scene::parse(text, Path::new("scene.toml"))
    }

    const RUN: &str =
        "[initial]\nrotor = [1, 0, 0, 0]\nomega = [1, 0, 0]\n[run]\nt_end = 1\nsamples = 3\n";

    #[test]
    fn minimal_scene_loads_and_normalises_the_rotor() {
        let s = parse(&format!(
            "[body]\nmoments = [1, 2, 2.5]\n{}",
            RUN.replace("[1, 0, 0, 0]", "[2, 0, 0, 0]")
        ))
        .unwrap();
        assert_eq!(s.initial.rotor, Rotor::ONE);
        assert_eq!(s.inertia.moments(), [1.0, 2.0, 2.5]);
        assert_eq!(s.run.times(), vec![0.0, 0.5, 1.0]);
    }

    #[test]
    fn nested_unknown_field_names_its_full_path() {
        let e = parse(&format!(
            "[body]\nshape = {{ kind = \"box\", mass = 1, size = [1, 1, 1], colour = 3 }}\n{RUN}"
        ))
        .unwrap_err();
        assert!(
            e.to_string()
                .starts_with("body.shape.colour: unknown field"),
            "{e}"
        );
    }
}
