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

use std::collections::{HashMap, HashSet};
use std::io::{BufRead, Read as _};
use std::path::Path;

use ga_core::f64::g3::*;

use ga_core::glam::DMat3;

use super::eigen::{from_rows, to_rows};
use super::inertia::Inertia;
use crate::error::{positive, Error};

/// The largest OBJ file read: 256 MiB is some five million triangles.
pub const MAX_MESH_BYTES: u64 = 256 << 20;

/// The most triangles a mesh may have, counted (after fan triangulation) before any is
/// built: with [`MAX_MESH_VERTICES`] it keeps a mesh's memory, the closedness check's edge
/// table included, under about 600 MB (24 bytes a triangle and a vertex, 13 bytes and
/// slack an edge).
pub const MAX_MESH_TRIANGLES: usize = 4_000_000;

/// The most vertices a mesh may have (see [`MAX_MESH_TRIANGLES`]).
pub const MAX_MESH_VERTICES: usize = 4_000_000;

/// The most separate shells (connected pieces of surface) a mesh may have: each pair is
/// checked for overlap, so this bounds that check to some 5e7 box comparisons.
pub const MAX_MESH_SHELLS: usize = 10_000;

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
    pub covariance: DMat3,
}

impl Mesh {
    /// Parse the `v` and `f` lines of a Wavefront OBJ text; `path` is used in messages.
    ///
    /// `v x y z` takes an optional fourth homogeneous weight `w` (the position is divided
    /// by it) or three colour components (ignored). `f` takes three or more distinct vertex
    /// references `i`, `i/t`, `i//n` or `i/t/n`, 1-based or negative (relative to the
    /// vertices read so far); polygons are fan-triangulated from their first vertex.
    /// Other statements (`vt`, `vn`, `g`, `o`, `s`, `usemtl`, ...) are ignored. Errors
    /// ([`Error::Obj`], field `mesh`) give the line; more than [`MAX_MESH_TRIANGLES`]
    /// triangles or [`MAX_MESH_VERTICES`] vertices are refused as they are counted.
    pub fn parse_obj(text: &str, path: &Path) -> Result<Mesh, Error> {
        parse_lines(text.as_bytes(), path, u64::MAX, MAX_MESH_TRIANGLES)
    }

    /// Read and parse an OBJ file (see [`Mesh::parse_obj`]) line by line, so that only
    /// the mesh is held, never the text: only a regular file (or a link to one) of at
    /// most [`MAX_MESH_BYTES`].
    pub fn read_obj(path: &Path) -> Result<Mesh, Error> {
        let file = crate::input::open_regular("mesh", path, MAX_MESH_BYTES)?;
        // One byte past the limit tells a file that grew after the check from one that fits.
        let reader = std::io::BufReader::new(file.take(MAX_MESH_BYTES + 1));
        parse_lines(reader, path, MAX_MESH_BYTES, MAX_MESH_TRIANGLES)
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
        if count > MAX_MESH_VERTICES || self.triangles.len() > MAX_MESH_TRIANGLES {
            return Err(Error::invalid(
                "mesh",
                format!(
                    "{count} vertices and {} triangles: the limits are {MAX_MESH_VERTICES} \
                     and {MAX_MESH_TRIANGLES}",
                    self.triangles.len()
                ),
            ));
        }
        // 32-bit indices (the limits fit) and the table reserved once: some 200 MB at the
        // triangle limit, and a clear refusal rather than an abort when memory is short.
        let mut edges: HashMap<(u32, u32), u32> = HashMap::new();
        edges.try_reserve(3 * self.triangles.len()).map_err(|_| {
            Error::invalid(
                "mesh",
                format!(
                    "not enough memory to check the {} triangles' edges",
                    self.triangles.len()
                ),
            )
        })?;
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
            // Within the limits checked above, so the casts are exact.
            let [a0, b0, c0] = tri.map(|i| i as u32);
            for (a, b) in [(a0, b0), (b0, c0), (c0, a0)] {
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
                edges.insert((a, b), t as u32);
            }
        }
        // Report the first edge in input order, so the message is deterministic.
        for (t, tri) in self.triangles.iter().enumerate() {
            let [a0, b0, c0] = tri.map(|i| i as u32);
            for (a, b) in [(a0, b0), (b0, c0), (c0, a0)] {
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

    /// Check that the mesh's shells (its connected pieces of surface) do not overlap: a
    /// shell inside another, or two that intersect, would count the shared volume twice
    /// (a cube inside a cube weighs nine, not eight). The test is conservative: two shells
    /// whose axis-aligned bounding boxes overlap (with positive volume; touching is fine)
    /// are refused, which also refuses a hollow body written as an outer and an inner
    /// shell, and interlocking rings. At most [`MAX_MESH_SHELLS`] shells. Errors
    /// (field `mesh`) name a triangle of each shell, 1-based. Call
    /// [`Mesh::check_closed`] first.
    pub fn check_shells(&self) -> Result<(), Error> {
        let count = self.vertices.len();
        // Union-find over the vertices, joined along each triangle.
        let mut parent: Vec<usize> = Vec::new();
        parent
            .try_reserve_exact(count)
            .map_err(|_| Error::invalid("mesh", "not enough memory to find the mesh's shells"))?;
        parent.extend(0..count);
        fn root(parent: &mut [usize], mut i: usize) -> usize {
            while parent[i] != i {
                parent[i] = parent[parent[i]];
                i = parent[i];
            }
            i
        }
        for tri in &self.triangles {
            if tri.iter().any(|&i| i >= count) {
                continue; // check_closed refuses these.
            }
            for &other in &tri[1..] {
                let (a, b) = (root(&mut parent, tri[0]), root(&mut parent, other));
                if a != b {
                    parent[a.max(b)] = a.min(b);
                }
            }
        }
        // One box per shell, with the first triangle that names it.
        let mut shell_of: HashMap<usize, usize> = HashMap::new();
        let mut shells: Vec<(usize, [f64; 3], [f64; 3])> = Vec::new();
        for (t, tri) in self.triangles.iter().enumerate() {
            if tri.iter().any(|&i| i >= count) {
                continue;
            }
            let r = root(&mut parent, tri[0]);
            let k = *shell_of.entry(r).or_insert_with(|| {
                shells.push((t, [f64::INFINITY; 3], [f64::NEG_INFINITY; 3]));
                shells.len() - 1
            });
            if shells.len() > MAX_MESH_SHELLS {
                return Err(Error::invalid(
                    "mesh",
                    format!("more than {MAX_MESH_SHELLS} separate shells, the limit"),
                ));
            }
            let shell = &mut shells[k];
            for &i in tri {
                for axis in 0..3 {
                    shell.1[axis] = shell.1[axis].min(self.vertices[i][axis]);
                    shell.2[axis] = shell.2[axis].max(self.vertices[i][axis]);
                }
            }
        }
        // Sweep along x: only shells whose x ranges overlap are compared.
        shells.sort_by(|a, b| a.1[0].total_cmp(&b.1[0]));
        for (k, a) in shells.iter().enumerate() {
            for b in &shells[k + 1..] {
                if b.1[0] >= a.2[0] {
                    break;
                }
                if (1..3).all(|axis| a.1[axis] < b.2[axis] && b.1[axis] < a.2[axis]) {
                    let (first, second) = (a.0.min(b.0), a.0.max(b.0));
                    return Err(Error::invalid(
                        "mesh",
                        format!(
                            "the shells of triangles {} and {} overlap (nested or \
                             intersecting): their volume would count twice",
                            first + 1,
                            second + 1
                        ),
                    ));
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
            covariance: from_rows(&covariance),
        }
    }
}

/// Resolve one OBJ vertex reference (`i`, `i/t`, `i//n`, `i/t/n`) to a 0-based index.
/// Negative indices count back from the `count` vertices read so far.
fn resolve_index(token: &str, count: usize) -> Result<usize, String> {
    let first = token.split('/').next().unwrap_or("");
    let index: i64 = first
        .parse()
        .map_err(|_| format!("`{}` is not a vertex index", crate::error::echo(token)))?;
    match index {
        0 => Err("vertex index 0 is invalid: OBJ indices start at 1".to_string()),
        i if i > 0 => usize::try_from(i - 1)
            .ok()
            .filter(|&k| k < MAX_MESH_VERTICES)
            .ok_or_else(|| {
                format!("vertex index {i} is above the limit of {MAX_MESH_VERTICES} vertices")
            }),
        i => {
            let back = usize::try_from(i.unsigned_abs())
                .map_err(|_| format!("vertex index {i} is too small"))?;
            count.checked_sub(back).ok_or_else(|| {
                format!("relative vertex index {i} points before the first vertex ({count} read so far)")
            })
        }
    }
}

/// The streaming OBJ parser behind [`Mesh::parse_obj`] and [`Mesh::read_obj`]: each line is
/// checked as it is read, each face's triangles counted against [`MAX_MESH_TRIANGLES`]
/// vertex by vertex before any is stored, and a face that repeats a vertex refused at its
/// line. `limit` bounds the bytes read, `max_triangles` the triangles (a parameter so
/// that a test can reach it with a small file).
fn parse_lines<R: BufRead>(
    mut reader: R,
    path: &Path,
    limit: u64,
    max_triangles: usize,
) -> Result<Mesh, Error> {
    let err = |line: usize, message: String| Error::Obj {
        field: "mesh".to_string(),
        path: path.to_path_buf(),
        line,
        message,
    };
    let memory = |line: usize, what: &str| {
        err(
            line,
            format!("not enough memory for the mesh's {what}; the file is refused"),
        )
    };
    let mut mesh = Mesh::default();
    // Positive indices may point at vertices defined further down; such faces are checked
    // against the final count, by their line and largest index.
    let mut forward: Vec<(usize, usize)> = Vec::new();
    let mut polygon: Vec<usize> = Vec::new();
    let mut seen: HashSet<usize> = HashSet::new();
    let mut buffer: Vec<u8> = Vec::new();
    let mut bytes: u64 = 0;
    let mut line_no = 0;
    loop {
        buffer.clear();
        let read = reader
            .read_until(b'\n', &mut buffer)
            .map_err(|source| Error::Read {
                field: "mesh".to_string(),
                path: path.to_path_buf(),
                source,
            })?;
        if read == 0 {
            break;
        }
        bytes += read as u64;
        if bytes > limit {
            return Err(Error::invalid(
                "mesh",
                format!(
                    "{} is more than the limit of {limit} bytes",
                    crate::error::echo_path(path)
                ),
            ));
        }
        line_no += 1;
        let raw = std::str::from_utf8(&buffer)
            .map_err(|_| err(line_no, "the line is not UTF-8 text".to_string()))?;
        let line = raw.split('#').next().unwrap_or("");
        let mut tokens = line.split_whitespace();
        match tokens.next() {
            Some("v") => {
                let mut numbers = [0.0; 6];
                let mut n = 0;
                for t in tokens {
                    let x = t.parse::<f64>().map_err(|_| {
                        err(
                            line_no,
                            format!("`{}` is not a number", crate::error::echo(t)),
                        )
                    })?;
                    if n < numbers.len() {
                        numbers[n] = x;
                    }
                    n += 1;
                }
                let position = match n {
                    3 | 6 => [numbers[0], numbers[1], numbers[2]],
                    4 => {
                        let w = numbers[3];
                        if !(w.is_finite() && w > 0.0) {
                            return Err(err(
                                line_no,
                                format!(
                                    "the vertex weight must be positive, got {}",
                                    crate::error::num(w)
                                ),
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
                        format!(
                            "vertex coordinates must be finite, got {}",
                            crate::error::num(*x)
                        ),
                    ));
                }
                if mesh.vertices.len() >= MAX_MESH_VERTICES {
                    return Err(err(
                        line_no,
                        format!("more than {MAX_MESH_VERTICES} vertices, the limit"),
                    ));
                }
                mesh.vertices
                    .try_reserve(1)
                    .map_err(|_| memory(line_no, "vertices"))?;
                mesh.vertices.push(position);
            }
            Some("f") => {
                let count = mesh.vertices.len();
                polygon.clear();
                seen.clear();
                for t in tokens {
                    let i = resolve_index(t, count).map_err(|m| err(line_no, m))?;
                    // The triangles this face adds, counted before any is built.
                    if mesh.triangles.len() + polygon.len().saturating_sub(1) > max_triangles {
                        return Err(err(
                            line_no,
                            format!(
                                "more than {max_triangles} triangles (polygons count as their fans), \
                                 the limit"
                            ),
                        ));
                    }
                    // A short face is searched directly, a long one through a set.
                    let repeated = if polygon.len() < 16 {
                        polygon.contains(&i)
                    } else {
                        if seen.is_empty() {
                            seen.extend(polygon.iter().copied());
                        }
                        !seen.insert(i)
                    };
                    if repeated {
                        return Err(err(
                            line_no,
                            format!(
                                "the face repeats vertex {} (vertex {} of the face)",
                                i + 1,
                                polygon.len() + 1
                            ),
                        ));
                    }
                    polygon
                        .try_reserve(1)
                        .map_err(|_| memory(line_no, "faces"))?;
                    polygon.push(i);
                }
                if polygon.len() < 3 {
                    return Err(err(
                        line_no,
                        format!("a face needs at least 3 vertices, got {}", polygon.len()),
                    ));
                }
                mesh.triangles
                    .try_reserve(polygon.len() - 2)
                    .map_err(|_| memory(line_no, "triangles"))?;
                for k in 1..polygon.len() - 1 {
                    mesh.triangles
                        .push([polygon[0], polygon[k], polygon[k + 1]]);
                }
                let largest = polygon.iter().copied().max().unwrap_or(0);
                if largest >= count {
                    forward.push((line_no, largest));
                }
            }
            _ => {}
        }
    }
    let count = mesh.vertices.len();
    if let Some(&(line, i)) = forward.iter().find(|&&(_, i)| i >= count) {
        return Err(err(
            line,
            format!(
                "vertex index {} is out of range: the file has {count} vertices",
                i + 1
            ),
        ));
    }
    if mesh.triangles.is_empty() {
        return Err(err(line_no, "the file has no faces".to_string()));
    }
    Ok(mesh)
}

impl Inertia {
    /// The inertia of the homogeneous solid a closed triangle mesh encloses, about its
    /// centre of mass, at the given `density`.
    ///
    /// Errors: a non-positive or non-finite `density`; an open or inconsistently wound
    /// mesh ([`Mesh::check_closed`]); shells that overlap ([`Mesh::check_shells`]); a
    /// non-positive enclosed volume (inward-wound faces, or a flat mesh); a singular
    /// inertia (`mesh`).
    pub fn from_mesh(mesh: &Mesh, density: f64) -> Result<Self, Error> {
        let rho = positive("density", "density", density)?;
        mesh.check_closed()?;
        mesh.check_shells()?;
        let moments = mesh.moments();
        if moments.volume.is_nan() || moments.volume <= 0.0 {
            return Err(Error::invalid(
                "mesh",
                format!(
                    "the enclosed volume must be positive, got {} (faces must wind \
                     counter-clockwise seen from outside)",
                    crate::error::num_short(moments.volume)
                ),
            ));
        }
        let c = to_rows(&moments.covariance);
        let trace = c[0][0] + c[1][1] + c[2][2];
        let mut j = [[0.0; 3]; 3];
        for (a, row) in j.iter_mut().enumerate() {
            for (b, entry) in row.iter_mut().enumerate() {
                let delta = if a == b { trace } else { 0.0 };
                *entry = rho * (delta - c[a][b]);
            }
        }
        let [x, y, z] = moments.centroid;
        Inertia::from_rows(&j, Some(rho * moments.volume), Vector::new(x, y, z))
            .map_err(|e| e.at("mesh"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The fuzz run's find: a vertex at 1e308 made the volume -1.7e307, printed in full as
    /// a 310-digit number; a message stays one short line.
    #[test]
    fn a_huge_negative_volume_is_reported_in_a_short_number() {
        let obj = "v 0 0 0\nv 0 0 1\nv 0 1 1e308\nv 0 1 1\nv 1 0 0\nv 1 0 1\nv 1 1 0\n\
                   v 1 1 1\nf 1 2 4 3\nf 5 7 8 6\nf 1 5 6 2\nf 3 4 8 7\nf 1 3 7 5\nf 2 6 8 4\n";
        let mesh = Mesh::parse_obj(obj, Path::new("body.obj")).unwrap();
        let e = Inertia::from_mesh(&mesh, 1.0).unwrap_err().to_string();
        assert!(
            e.starts_with("mesh: the enclosed volume must be positive, got -1.66667e307 "),
            "{e}"
        );
        assert!(e.len() < 200, "{e}");
    }

    #[test]
    fn a_polygon_past_the_triangle_limit_is_refused_before_it_is_built() {
        // Ten distinct vertices make an 8-triangle fan; the limit of 5 stops it at the
        // seventh vertex, naming the line.
        let mut text = String::new();
        for k in 0..10 {
            text.push_str(&format!("v {k} {} 0\n", k * k));
        }
        text.push_str("f 1 2 3 4 5 6 7 8 9 10\n");
        let e = parse_lines(text.as_bytes(), Path::new("m.obj"), u64::MAX, 5)
            .unwrap_err()
            .to_string();
        assert_eq!(
            e,
            "mesh: m.obj:11: more than 5 triangles (polygons count as their fans), the limit"
        );
        // At the limit it is accepted.
        let mesh = parse_lines(text.as_bytes(), Path::new("m.obj"), u64::MAX, 8).unwrap();
        assert_eq!(mesh.triangles.len(), 8);
    }

    #[test]
    fn triangles_of_many_faces_count_toward_the_limit() {
        let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\nf 1 3 4\n";
        let e = parse_lines(text.as_bytes(), Path::new("m.obj"), u64::MAX, 2)
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("mesh: m.obj:7: more than 2 triangles"), "{e}");
    }

    #[test]
    fn a_long_face_that_repeats_a_vertex_is_refused_at_the_repeat() {
        // `f 1 2 3 1 2 3 ...`, the shape of issue 22's 250 MiB file, and a long face
        // (past the direct search) whose repeat comes late.
        let mut text = String::from("v 0 0 0\nv 1 0 0\nv 0 1 0\nf");
        for _ in 0..1000 {
            text.push_str(" 1 2 3");
        }
        let e = Mesh::parse_obj(&text, Path::new("m.obj"))
            .unwrap_err()
            .to_string();
        assert_eq!(
            e,
            "mesh: m.obj:4: the face repeats vertex 1 (vertex 4 of the face)"
        );
        let mut text = String::new();
        for k in 0..40 {
            text.push_str(&format!("v {k} {} 0\n", k * k));
        }
        text.push('f');
        for k in 1..=40 {
            text.push_str(&format!(" {k}"));
        }
        text.push_str(" 17\n");
        let e = Mesh::parse_obj(&text, Path::new("m.obj"))
            .unwrap_err()
            .to_string();
        assert!(
            e.ends_with("the face repeats vertex 17 (vertex 41 of the face)"),
            "{e}"
        );
    }

    #[test]
    fn an_index_past_the_vertex_limit_is_refused_as_it_is_read() {
        let text = "v 0 0 0\nf 1 2 99999999999\n";
        let e = Mesh::parse_obj(text, Path::new("m.obj"))
            .unwrap_err()
            .to_string();
        assert!(e.contains("above the limit of 4000000 vertices"), "{e}");
        let text = "v 0 0 0\nf 1 2 -9223372036854775808\n";
        let e = Mesh::parse_obj(text, Path::new("m.obj"))
            .unwrap_err()
            .to_string();
        assert!(e.contains("points before the first vertex"), "{e}");
    }
}
