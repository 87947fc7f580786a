//! Scene files for bodies in two and four dimensions: the 3D format of `crate::scene`
//! with `[body] dimension = 2` or `4`, bivectors in canonical order and rotors with all
//! their components (the format is in `docs/scenes.md`).
//!
//! Loading goes through the same three stages as the 3D loader, with its messages: the
//! TOML parser, serde on the parsed value (unknown, missing and mistyped fields), then
//! the checks here and of [`RigidBody`]'s constructors, each error naming its field.

use std::path::Path;

use serde::Deserialize;

use super::algebra::{Algebra, G2, G4};
use super::body::{PrincipalFrame, RigidBody};
use super::state::State;
use super::torque::{BodyTorque, SpaceTorque};
use crate::error::{self, Error};
use crate::scene::{
    declared_dimension, field_error, sections_are_tables, syntax_error, Run, MAX_SAMPLES,
};

/// The dimension a scene file declares in `[body] dimension`: 2 or 4 where it says so, 3
/// otherwise, also where the file cannot be read or parsed (the 3D loader then says why,
/// in the order the 3D command checks its input).
#[must_use]
pub fn dimension_of(path: &Path) -> usize {
    let Ok(text) = crate::input::read_text("SCENE", path, crate::scene::MAX_SCENE_BYTES) else {
        return 3;
    };
    let Ok(table) = toml::from_str::<toml::Table>(&text) else {
        return 3;
    };
    match declared_dimension(&table) {
        Some(2) => 2,
        Some(4) => 4,
        _ => 3,
    }
}

/// A validated 2D or 4D scene.
// One scene is loaded per run: a boxed variant would save nothing worth the indirection.
#[allow(clippy::large_enum_variant)]
#[derive(Clone, Debug)]
pub enum NdScene {
    /// A body turning in the plane.
    Planar(BodyScene<G2>),
    /// A body in four dimensions.
    Four(BodyScene<G4>),
}

/// How the body was given, for what the `inertia` command can say about it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BodySource {
    /// `second_moments`: the principal frame is the scene's, the mass unknown.
    SecondMoments,
    /// `points`: mass, centre and principal frame computed.
    Points,
    /// `shape`: a box or ball of known mass, centred, in its principal frame.
    Shape,
}

/// A constant applied torque.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum TorqueSpec<A: Algebra> {
    /// `[torque] body = [...]`: fixed in the body, in the scene's body frame.
    Body(A::Bivector),
    /// `[torque] space = [...]`: fixed in space.
    Space(A::Bivector),
}

/// A scene of one body in `A`: the body in its principal frame, where that frame lies in
/// the scene's, the initial state as the file gives it (in the scene's frame) and the run.
#[derive(Clone, Debug)]
pub struct BodyScene<A: Algebra> {
    /// The body in its principal frame, with the scene's torque.
    pub body: RigidBody<A>,
    /// How the body was given.
    pub source: BodySource,
    /// The mass, where the scene gives one (points, shape).
    pub mass: Option<f64>,
    /// The centre of mass in the points' frame (zero otherwise).
    pub centre: [f64; super::MAX_DIMENSION],
    /// The principal rotor `P`: `P e_k ~P` is the `k`-th principal axis in the scene's
    /// body frame (the identity unless the body is given by points).
    pub principal: A::Rotor,
    /// The initial state in the scene's frame: the rotor normalised.
    pub initial: State<A>,
    /// The applied torque, if any.
    pub torque: Option<TorqueSpec<A>>,
    /// The run length and sampling.
    pub run: Run,
}

impl<A: Algebra> BodyScene<A> {
    /// The initial state in the principal frame: attitude `R P`, velocity `~P Omega P`.
    #[must_use]
    pub fn principal_state(&self) -> State<A> {
        let p = self.principal;
        State {
            rotor: self.initial.rotor * p,
            omega: A::sandwich(A::reverse(p), self.initial.omega),
        }
    }

    /// A principal-frame state in the scene's frame: attitude `R ~P`, velocity
    /// `P Omega ~P`.
    #[must_use]
    pub fn scene_state(&self, state: &State<A>) -> State<A> {
        let p = self.principal;
        State {
            rotor: state.rotor * A::reverse(p),
            omega: A::sandwich(p, state.omega),
        }
    }
}

impl NdScene {
    /// Read and validate a 2D or 4D scene file (at most
    /// [`crate::scene::MAX_SCENE_BYTES`], a regular file or a link to one); every
    /// error's message starts with the path, as [`crate::scene::Scene::load`]'s.
    pub fn load(path: &Path) -> Result<NdScene, Error> {
        let text = crate::input::read_text("SCENE", path, crate::scene::MAX_SCENE_BYTES)?;
        NdScene::parse(&text, path).map_err(|e| e.in_file(path))
    }

    /// Parse and validate scene text; `path` is the file it came from, for messages.
    pub fn parse(text: &str, path: &Path) -> Result<NdScene, Error> {
        let table: toml::Table = toml::from_str(text).map_err(|e| syntax_error(&e, text, path))?;
        sections_are_tables(&table)?;
        let file: SceneFile = toml::Value::Table(table)
            .try_into()
            .map_err(|e: toml::de::Error| field_error(&e))?;
        match file.body.dimension {
            2 => Ok(NdScene::Planar(build::<G2>(file)?)),
            4 => Ok(NdScene::Four(build::<G4>(file)?)),
            d => Err(Error::invalid(
                "body.dimension",
                format!(
                    "this loader reads 2D and 4D scenes, got {d}; 3D scenes are scene::Scene's"
                ),
            )),
        }
    }

    /// The dimension, 2 or 4.
    #[must_use]
    pub fn dimension(&self) -> usize {
        match self {
            NdScene::Planar(_) => 2,
            NdScene::Four(_) => 4,
        }
    }

    /// The run length and sampling.
    #[must_use]
    pub fn run(&self) -> Run {
        match self {
            NdScene::Planar(s) => s.run,
            NdScene::Four(s) => s.run,
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
    dimension: i64,
    second_moments: Option<Vec<f64>>,
    points: Option<Vec<Vec<f64>>>,
    shape: Option<ShapeFile>,
}

/// A homogeneous solid centred at the origin, axes along the scene's.
#[derive(Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
enum ShapeFile {
    /// A box with edge lengths `size` along e1 .. en: `l_k = m s_k^2 / 12`.
    Box { mass: f64, size: Vec<f64> },
    /// A solid n-ball: `l_k = m r^2 / (n + 2)`.
    Ball { mass: f64, radius: f64 },
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct InitialFile {
    rotor: Vec<f64>,
    omega: Vec<f64>,
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
    body: Option<Vec<f64>>,
    space: Option<Vec<f64>>,
}

/// What a scene needs of its algebra beyond [`Algebra`]: rotors from their components,
/// and the component names for messages.
trait SceneAlgebra: Algebra {
    /// The rotor components in canonical order, for messages.
    const ROTOR_NAMES: &'static str;
    /// The bivector components in canonical order, for messages.
    const PLANE_NAMES: &'static str;
    /// The rotor with components `c` (`c.len() == ROTOR_LEN`).
    fn rotor_from(c: &[f64]) -> Self::Rotor;
    /// The unit rotor nearest `r`, or why `r` is not (a multiple of) one.
    fn normalised(r: Self::Rotor) -> Result<Self::Rotor, String>;
}

impl SceneAlgebra for G2 {
    const ROTOR_NAMES: &'static str = "s, e12";
    const PLANE_NAMES: &'static str = "e12";
    fn rotor_from(c: &[f64]) -> Self::Rotor {
        ga_core::f64::g2::Rotor::from_array([c[0], c[1]])
    }
    fn normalised(r: Self::Rotor) -> Result<Self::Rotor, String> {
        scaled::<G2>(r)
    }
}

impl SceneAlgebra for G4 {
    const ROTOR_NAMES: &'static str = "s, e12, e13, e14, e23, e24, e34, e1234";
    const PLANE_NAMES: &'static str = "e12, e13, e14, e23, e24, e34";
    fn rotor_from(c: &[f64]) -> Self::Rotor {
        let mut a = [0.0; 8];
        a.copy_from_slice(&c[..8]);
        ga_core::f64::g4::Rotor::from_array(a)
    }
    /// An even element `r` of G4 is a multiple of a rotor when `r ~r = alpha + beta I` has
    /// `beta = 0`. Typed digits leave a small `beta`: `r (r ~r)^(-1/2)` is then the rotor
    /// (`alpha + beta I` commutes with every even element, and with `I^2 = 1` its inverse
    /// square root is `(p + q)/2 + (p - q)/2 I`, `p, q = (alpha +- beta)^(-1/2)`).
    fn normalised(r: Self::Rotor) -> Result<Self::Rotor, String> {
        let square = r * G4::reverse(r);
        let (alpha, beta) = (square.s, square.e1234);
        if !(alpha > 0.0 && alpha.is_finite()) {
            return Err("the rotor must not be zero".to_string());
        }
        if beta.abs() > 1e-6 * alpha {
            return Err(format!(
                "not a rotor: R ~R has the e1234 part {} (relative to |R|^2; a 4D rotor \
                 needs s e1234 - e12 e34 + e13 e24 - e14 e23 = 0)",
                error::num_short(beta / alpha)
            ));
        }
        let (p, q) = ((alpha + beta).sqrt().recip(), (alpha - beta).sqrt().recip());
        let root = ga_core::f64::g4::Rotor::new(
            0.5 * (p + q),
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.5 * (p - q),
        );
        Ok(r * root)
    }
}

/// `r / |r|`, or an error for a zero `r`.
fn scaled<A: Algebra>(r: A::Rotor) -> Result<A::Rotor, String> {
    let norm = A::rotor_norm(r);
    if norm > 0.0 && norm.is_finite() {
        Ok(r * (1.0 / norm))
    } else {
        Err("the rotor must not be zero".to_string())
    }
}

/// The finite numbers of `values`, `expected` of them, or an error naming `field`.
fn components(
    field: &str,
    what: &str,
    names: &str,
    expected: usize,
    values: &[f64],
) -> Result<(), Error> {
    if values.len() != expected {
        return Err(Error::invalid(
            field,
            format!(
                "{what} have {expected} components ({names}), got {}",
                values.len()
            ),
        ));
    }
    for (k, &v) in values.iter().enumerate() {
        error::finite(&format!("{field}[{k}]"), "component", v)?;
    }
    Ok(())
}

fn build<A: SceneAlgebra>(file: SceneFile) -> Result<BodyScene<A>, Error> {
    let n = A::DIMENSION;
    let planes = A::PLANES.len();
    let (body, source, mass, frame) = load_body::<A>(file.body)?;

    let rotor = &file.initial.rotor;
    components(
        "initial.rotor",
        &format!("{n}D rotors"),
        A::ROTOR_NAMES,
        A::ROTOR_LEN,
        rotor,
    )?;
    let rotor = A::normalised(A::rotor_from(rotor))
        .map_err(|rule| Error::invalid("initial.rotor", rule))?;
    let omega = &file.initial.omega;
    components(
        "initial.omega",
        &format!("{n}D angular velocities"),
        A::PLANE_NAMES,
        planes,
        omega,
    )?;
    let omega = A::bivector(omega);

    let t_end = error::positive("run.t_end", "t_end", file.run.t_end)?;
    let samples = file.run.samples;
    if samples < 2 {
        return Err(Error::invalid(
            "run.samples",
            format!("samples must be at least 2, got {samples}"),
        ));
    }
    if samples > MAX_SAMPLES {
        return Err(Error::invalid(
            "run.samples",
            format!("samples must be at most {MAX_SAMPLES}, got {samples}"),
        ));
    }
    let run = Run {
        t_end,
        samples: usize::try_from(samples).unwrap_or(usize::MAX),
    };

    let principal = frame.map_or(A::ONE, |f| f.rotor);
    let torque = match file.torque {
        None => None,
        Some(TorqueFile {
            body: Some(t),
            space: None,
        }) => {
            components(
                "torque.body",
                &format!("{n}D torques"),
                A::PLANE_NAMES,
                planes,
                &t,
            )?;
            Some(TorqueSpec::Body(A::bivector(&t)))
        }
        Some(TorqueFile {
            body: None,
            space: Some(t),
        }) => {
            components(
                "torque.space",
                &format!("{n}D torques"),
                A::PLANE_NAMES,
                planes,
                &t,
            )?;
            Some(TorqueSpec::Space(A::bivector(&t)))
        }
        Some(_) => return Err(Error::invalid(
            "torque",
            "give exactly one of `body` (a torque fixed in the body) and `space` (fixed in space)",
        )),
    };
    let body = match torque {
        None => body,
        // The equations run in the principal frame.
        Some(TorqueSpec::Body(t)) => {
            body.with_torque(BodyTorque::<A>(A::sandwich(A::reverse(principal), t)))
        }
        Some(TorqueSpec::Space(t)) => body.with_torque(SpaceTorque::<A>(t)),
    };
    Ok(BodyScene {
        body,
        source,
        mass,
        centre: frame.map_or([0.0; super::MAX_DIMENSION], |f| f.centre),
        principal,
        initial: State { rotor, omega },
        torque,
        run,
    })
}

/// The body of `[body]`: exactly one of `second_moments`, `points`, `shape`.
type Loaded<A> = (
    RigidBody<A>,
    BodySource,
    Option<f64>,
    Option<PrincipalFrame<A>>,
);

fn load_body<A: SceneAlgebra>(body: BodyFile) -> Result<Loaded<A>, Error> {
    let n = A::DIMENSION;
    match (body.second_moments, body.points, body.shape) {
        (Some(l), None, None) => {
            let b = RigidBody::<A>::new(&l).map_err(|e| e.within("body"))?;
            Ok((b, BodySource::SecondMoments, None, None))
        }
        (None, Some(points), None) => {
            let mut masses = Vec::with_capacity(points.len());
            for (k, p) in points.iter().enumerate() {
                if p.len() != n + 1 {
                    let coordinates: Vec<String> = (1..=n).map(|i| format!("x{i}")).collect();
                    return Err(Error::invalid(
                        format!("body.points[{k}]"),
                        format!(
                            "a point in {n}D is [m, {}], got {} numbers",
                            coordinates.join(", "),
                            p.len()
                        ),
                    ));
                }
                masses.push((p[0], &p[1..]));
            }
            let (b, frame) =
                RigidBody::<A>::from_point_masses(&masses).map_err(|e| e.within("body"))?;
            Ok((b, BodySource::Points, Some(frame.mass), Some(frame)))
        }
        (None, None, Some(ShapeFile::Box { mass, size })) => {
            error::positive("body.shape.mass", "mass", mass)?;
            if size.len() != n {
                return Err(Error::invalid(
                    "body.shape.size",
                    format!("a {n}D box has {n} edge lengths, got {}", size.len()),
                ));
            }
            for (k, &s) in size.iter().enumerate() {
                error::positive(&format!("body.shape.size[{k}]"), "edge length", s)?;
            }
            let b = RigidBody::<A>::from_box(mass, &size).map_err(|e| e.within("body.shape"))?;
            Ok((b, BodySource::Shape, Some(mass), None))
        }
        (None, None, Some(ShapeFile::Ball { mass, radius })) => {
            let b = RigidBody::<A>::from_ball(mass, radius).map_err(|e| e.within("body.shape"))?;
            Ok((b, BodySource::Shape, Some(mass), None))
        }
        (l, p, s) => {
            let given: Vec<&str> = [
                ("second_moments", l.is_some()),
                ("points", p.is_some()),
                ("shape", s.is_some()),
            ]
            .into_iter()
            .filter_map(|(name, present)| present.then_some(name))
            .collect();
            Err(Error::invalid(
                "body",
                format!(
                    "give exactly one of second_moments, points, shape; got {}",
                    if given.is_empty() {
                        "none".to_string()
                    } else {
                        given.join(", ")
                    }
                ),
            ))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(text: &str) -> Result<NdScene, Error> {
        NdScene::parse(text, Path::new("scene.toml"))
    }

    const FOUR: &str = "[body]\ndimension = 4\nsecond_moments = [0.5, 0.9, 1.4, 2.0]\n\
        [initial]\nrotor = [2, 0, 0, 0, 0, 0, 0, 0]\nomega = [1.0, 0, 0.4, -0.6, 0.2, 0.8]\n\
        [run]\nt_end = 10\nsamples = 3\n";

    #[test]
    fn a_4d_scene_loads_with_its_rotor_normalised() {
        let NdScene::Four(scene) = parse(FOUR).unwrap() else {
            panic!("not 4D");
        };
        assert_eq!(scene.initial.rotor, G4::ONE);
        assert_eq!(scene.body.second_moments(), &[0.5, 0.9, 1.4, 2.0]);
        assert_eq!(scene.initial.omega[5], 0.8);
    }

    #[test]
    fn errors_name_the_field_at_fault() {
        let cases = [
            (
                FOUR.replace("rotor = [2, 0, 0, 0, 0, 0, 0, 0]", "rotor = [1, 0, 0, 0]"),
                "initial.rotor: 4D rotors have 8 components",
            ),
            (
                FOUR.replace("[0.5, 0.9, 1.4, 2.0]", "[0.5, 0.9, 1.4]"),
                "body.second_moments: ",
            ),
            (
                FOUR.replace("second_moments", "moments"),
                "body.moments: unknown field",
            ),
            (
                FOUR.replace(
                    "rotor = [2, 0, 0, 0, 0, 0, 0, 0]",
                    "rotor = [1, 0, 0, 0, 0, 0, 0, 1]",
                ),
                "initial.rotor: not a rotor",
            ),
            (
                FOUR.replace(
                    "omega = [1.0, 0, 0.4, -0.6, 0.2, 0.8]",
                    "omega = [1.0, 0, 0.4]",
                ),
                "initial.omega: 4D angular velocities have 6 components",
            ),
        ];
        for (text, start) in cases {
            let message = parse(&text).unwrap_err().to_string();
            assert!(message.starts_with(start), "{message}");
            assert!(!message.contains('\n'), "{message}");
        }
    }

    /// A rotor typed to six digits is made exactly unit (its e1234 part of `R ~R` too).
    #[test]
    fn a_rounded_4d_rotor_is_projected_onto_the_rotors() {
        let exact = G4::exp(G4::bivector(&[0.3, -1.2, 0.8, 0.4, -0.9, 1.3]));
        let typed: Vec<f64> = exact
            .to_array()
            .iter()
            .map(|x| (x * 1e6).round() / 1e6)
            .collect();
        let r = G4::normalised(G4::rotor_from(&typed)).unwrap();
        let square = r * G4::reverse(r);
        assert!(
            (square.s - 1.0).abs() < 1e-15 && square.e1234.abs() < 1e-15,
            "{square:?}"
        );
        assert!(G4::rotor_norm(r - exact) < 1e-5);
    }

    #[test]
    fn points_give_the_principal_frame_and_the_3d_loader_refuses_4d() {
        let text = "[body]\ndimension = 2\npoints = [[1, 1, 0.5], [1, -1, -0.5], [2, 0, 0]]\n\
            [initial]\nrotor = [1, 0]\nomega = [2]\n[run]\nt_end = 1\nsamples = 2\n";
        let NdScene::Planar(scene) = parse(text).unwrap() else {
            panic!("not 2D");
        };
        assert_eq!(scene.mass, Some(4.0));
        // The principal state turned back is the state as given.
        let back = scene.scene_state(&scene.principal_state());
        assert!(G2::rotor_norm(back.rotor - scene.initial.rotor) < 1e-15);
        let err = crate::scene::Scene::parse(text, Path::new("s.toml")).unwrap_err();
        assert!(
            err.to_string().starts_with("body.dimension: a 2D scene"),
            "{err}"
        );
    }
}
