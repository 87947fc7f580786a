//! Closed triangle meshes: a Wavefront OBJ reader, a closedness check, and exact mass
//! properties of the enclosed homogeneous solid.
//!
//! The mass properties follow the signed-tetrahedron form of the divergence theorem
//! (Mirtich, "Fast and Accurate Computation of Polyhedral Mass Properties", J. Graphics
//! Tools 1(2), 1996; Eberly, "Polyhedral Mass Properties (Revisited)", Geometric Tools,
//! 2002): each triangle (a, b, c), with a reference point at the origin, spans a
//! tetrahedron of signed volume `a . (b x c) / 6`, and the tetrahedron's second moment is
//! `integral of x x^T dV = V/20 (a a^T + b b^T + c c^T + s s^T)` with `s = a + b + c`
//! (the origin, as a fourth vertex, adds nothing). Summed over a closed, outward-wound
//! surface the signed tetrahedra add up to the solid exactly.

use std::collections::HashMap;
use std::path::Path;

use ga_core::f64::g3::*;

use super::eigen::Matrix3;
use super::inertia::Inertia;
use crate::error::{positive, Error};

/// The largest OBJ file read: 256 MiB is some five million triangles.
pub const MAX_MESH_BYTES: u64 = 256 << 20;

/// A triangle mesh: vertex positions and triangles as 0-based vertex indices, wound
/// counter-clockwise when seen from outside.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    /// Vertex positions.
    pub vertices: Vec<[f64; 3]>,
    /// Triangles as 0-based indices into `vertices`.
    pub triangles: Vec<[usize; 3]>,
}

/// Volume, centre and second moment of the solid a closed mesh encloses (unit density).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MeshMoments {
    /// The signed enclosed volume: positive for outward-wound faces.
    pub volume: f64,
    /// The centroid of the enclosed solid.
    pub centroid: [f64; 3],
    /// `integral of d d^T dV` with `d = x - centroid`.
    pub covariance: Matrix3,
}

impl Mesh {
    /// Parse the `v` and `f` lines of a Wavefront OBJ text; `path` is used in messages.
    ///
    /// `v x y z` takes an optional fourth homogeneous weight `w` (the position is divided
    /// by it) or three colour components (ignored). `f` takes three or more vertex
    /// references `i`, `i/t`, `i//n` or `i/t/n`, 1-based or negative (relative to the
    /// vertices read so far); polygons are fan-triangulated from their first vertex.
    /// Other statements (`vt`, `vn`, `g`, `o`, `s`, `usemtl`, ...) are ignored. Errors
    /// ([`Error::Obj`], field `mesh`) give the line.
    pub fn parse_obj(text: &str, path: &Path) -> Result<Mesh, Error> {
        let err = |line: usize, message: String| Error::Obj {
            field: "mesh".to_string(),
            path: path.to_path_buf(),
            line,
            message,
        };
        let mut mesh = Mesh::default();
        // Positive indices may point at vertices defined further down, so they are
        // checked against the final count; keep the line of each face for that message.
        let mut face_lines = Vec::new();
        for (number, raw) in text.lines().enumerate() {
            let line_no = number + 1;
            let line = raw.split('#').next().unwrap_or("");
            let mut tokens = line.split_whitespace();
            match tokens.next() {
                Some("v") => {
                    let numbers = tokens
                        .map(|t| {
                            t.parse::<f64>()
                                .map_err(|_| err(line_no, format!("`{t}` is not a number")))
                        })
                        .collect::<Result<Vec<f64>, Error>>()?;
                    let position = match numbers.len() {
                        3 | 6 => [numbers[0], numbers[1], numbers[2]],
                        4 => {
                            let w = numbers[3];
                            if !(w.is_finite() && w > 0.0) {
                                return Err(err(
                                    line_no,
                                    format!("the vertex weight must be positive, got {w}"),
                                ));
                            }
                            [numbers[0] / w, numbers[1] / w, numbers[2] / w]
                        }
                        n => {
                            return Err(err(
                                line_no,
                                format!("a vertex needs 3 coordinates, got {n} numbers"),
                            ))
                        }
                    };
                    if let Some(x) = position.iter().find(|x| !x.is_finite()) {
                        return Err(err(
                            line_no,
                            format!("vertex coordinates must be finite, got {x}"),
                        ));
                    }
                    mesh.vertices.push(position);
                }
                Some("f") => {
                    let count = mesh.vertices.len();
                    let polygon = tokens
                        .map(|t| resolve_index(t, count).map_err(|m| err(line_no, m)))
                        .collect::<Result<Vec<usize>, Error>>()?;
                    if polygon.len() < 3 {
                        return Err(err(
                            line_no,
                            format!("a face needs at least 3 vertices, got {}", polygon.len()),
                        ));
                    }
                    for k in 1..polygon.len() - 1 {
                        mesh.triangles
                            .push([polygon[0], polygon[k], polygon[k + 1]]);
                        face_lines.push(line_no);
                    }
                }
                _ => {}
            }
        }
        let count = mesh.vertices.len();
        for (triangle, &line) in mesh.triangles.iter().zip(&face_lines) {
            if let Some(&i) = triangle.iter().find(|&&i| i >= count) {
                return Err(err(
                    line,
                    format!(
                        "vertex index {} is out of range: the file has {count} vertices",
                        i + 1
                    ),
                ));
            }
        }
        if mesh.triangles.is_empty() {
            return Err(err(
                text.lines().count(),
                "the file has no faces".to_string(),
            ));
        }
        Ok(mesh)
    }

    /// Read and parse an OBJ file (see [`Mesh::parse_obj`]): only a regular file (or a
    /// link to one) of at most [`MAX_MESH_BYTES`].
    pub fn read_obj(path: &Path) -> Result<Mesh, Error> {
        let text = crate::input::read_text("mesh", path, MAX_MESH_BYTES)?;
        Mesh::parse_obj(&text, path)
    }

    /// Check that the mesh is a closed, consistently oriented surface: every edge is
    /// shared by exactly two triangles that traverse it in opposite directions, and no
    /// triangle repeats a vertex. Errors ([`Error::OpenMesh`], field `mesh`) name the
    /// first offending edge with 1-based vertex numbers, as in the OBJ file.
    pub fn check_closed(&self) -> Result<(), Error> {
        let open = |reason: String| Error::OpenMesh {
            field: "mesh".to_string(),
            reason,
        };
        let count = self.vertices.len();
        let mut edges: HashMap<(usize, usize), usize> = HashMap::new();
        for (t, tri) in self.triangles.iter().enumerate() {
            if let Some(&i) = tri.iter().find(|&&i| i >= count) {
                return Err(open(format!(
                    "triangle {} uses vertex {} but there are {count} vertices",
                    t + 1,
                    i + 1
                )));
            }
            if tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2] {
                return Err(open(format!(
                    "triangle {} repeats a vertex ({} {} {})",
                    t + 1,
                    tri[0] + 1,
                    tri[1] + 1,
                    tri[2] + 1
                )));
            }
            for (a, b) in [(tri[0], tri[1]), (tri[1], tri[2]), (tri[2], tri[0])] {
                if let Some(&first) = edges.get(&(a, b)) {
                    return Err(open(format!(
                        "edge {}->{} is traversed in the same direction by triangles {} and {} \
                         (inconsistent orientation or more than two faces on an edge)",
                        a + 1,
                        b + 1,
                        first + 1,
                        t + 1
                    )));
                }
                edges.insert((a, b), t);
            }
        }
        // Report the first edge in input order, so the message is deterministic.
        for (t, tri) in self.triangles.iter().enumerate() {
            for (a, b) in [(tri[0], tri[1]), (tri[1], tri[2]), (tri[2], tri[0])] {
                if !edges.contains_key(&(b, a)) {
                    return Err(open(format!(
                        "edge {}-{} of triangle {} belongs to no other triangle",
                        a + 1,
                        b + 1,
                        t + 1
                    )));
                }
            }
        }
        Ok(())
    }

    /// Volume, centroid and central second moment of the enclosed solid at unit density.
    ///
    /// Exact for a closed mesh (see the module docs); meaningless for an open one, so call
    /// [`Mesh::check_closed`] first. The volume is negative for inward-wound faces.
    #[must_use]
    pub fn moments(&self) -> MeshMoments {
        // Sum relative to the mean vertex: the signed tetrahedra then stay small even for a
        // mesh far from the origin, which keeps the cancellation between them harmless.
        let n = self.vertices.len().max(1) as f64;
        let mut origin = [0.0; 3];
        for v in &self.vertices {
            for i in 0..3 {
                origin[i] += v[i] / n;
            }
        }
        let rel = |k: usize| {
            let v = self.vertices[k];
            [v[0] - origin[0], v[1] - origin[1], v[2] - origin[2]]
        };
        let mut six_volume = 0.0;
        let mut first = [0.0; 3]; // 24 * integral of x dV
        let mut second = [[0.0; 3]; 3]; // 120 * integral of x x^T dV
        for tri in &self.triangles {
            let (a, b, c) = (rel(tri[0]), rel(tri[1]), rel(tri[2]));
            let det = a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                + a[2] * (b[0] * c[1] - b[1] * c[0]);
            let s = [a[0] + b[0] + c[0], a[1] + b[1] + c[1], a[2] + b[2] + c[2]];
            six_volume += det;
            for i in 0..3 {
                first[i] += det * s[i];
                for j in 0..3 {
                    second[i][j] += det * (a[i] * a[j] + b[i] * b[j] + c[i] * c[j] + s[i] * s[j]);
                }
            }
        }
        let volume = six_volume / 6.0;
        let centre_rel = first.map(|f| f / 24.0 / volume);
        let mut covariance = [[0.0; 3]; 3];
        for i in 0..3 {
            for j in 0..3 {
                covariance[i][j] = second[i][j] / 120.0 - volume * centre_rel[i] * centre_rel[j];
            }
        }
        MeshMoments {
            volume,
            centroid: [
                origin[0] + centre_rel[0],
                origin[1] + centre_rel[1],
                origin[2] + centre_rel[2],
            ],
            covariance,
        }
    }
}

/// Resolve one OBJ vertex reference (`i`, `i/t`, `i//n`, `i/t/n`) to a 0-based index.
/// Negative indices count back from the `count` vertices read so far.
fn resolve_index(token: &str, count: usize) -> Result<usize, String> {
    let first = token.split('/').next().unwrap_or("");
    let index: i64 = first
        .parse()
        .map_err(|_| format!("`{token}` is not a vertex index"))?;
    match index {
        0 => Err("vertex index 0 is invalid: OBJ indices start at 1".to_string()),
        i if i > 0 => usize::try_from(i - 1).map_err(|_| format!("vertex index {i} is too large")),
        i => {
            let back = usize::try_from(-i).map_err(|_| format!("vertex index {i} is too small"))?;
            count.checked_sub(back).ok_or_else(|| {
                format!("relative vertex index {i} points before the first vertex ({count} read so far)")
            })
        }
    }
}

impl Inertia {
    /// The inertia of the homogeneous solid a closed triangle mesh encloses, about its
    /// centre of mass, at the given `density`.
    ///
    /// Errors: a non-positive or non-finite `density`; an open or inconsistently wound
    /// mesh ([`Mesh::check_closed`]); a non-positive enclosed volume (inward-wound faces,
    /// or a flat mesh); a singular inertia (`mesh`).
    pub fn from_mesh(mesh: &Mesh, density: f64) -> Result<Self, Error> {
        let rho = positive("density", "density", density)?;
        mesh.check_closed()?;
        let moments = mesh.moments();
        if moments.volume.is_nan() || moments.volume <= 0.0 {
            return Err(Error::invalid(
                "mesh",
                format!(
                    "the enclosed volume must be positive, got {} (faces must wind \
                     counter-clockwise seen from outside)",
                    moments.volume
                ),
            ));
        }
        let c = moments.covariance;
        let trace = c[0][0] + c[1][1] + c[2][2];
        let mut j = [[0.0; 3]; 3];
        for (a, row) in j.iter_mut().enumerate() {
            for (b, entry) in row.iter_mut().enumerate() {
                let delta = if a == b { trace } else { 0.0 };
                *entry = rho * (delta - c[a][b]);
            }
        }
        let [x, y, z] = moments.centroid;
        Inertia::from_matrix(&j, Some(rho * moments.volume), Vector::new(x, y, z))
            .map_err(|e| e.at("mesh"))
    }
}
