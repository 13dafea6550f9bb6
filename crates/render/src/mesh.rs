//! Triangle meshes: the STL format (binary and ASCII, read and written),
//! the closed-and-manifold check and the enclosed volume.

use std::collections::HashMap;

use crate::RenderError;

/// A triangle soup with outward (counter-clockwise seen from outside)
/// triangles, in millimetres.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    triangles: Vec<[[f64; 3]; 3]>,
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn cross(u: [f64; 3], v: [f64; 3]) -> [f64; 3] {
    [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ]
}

/// The unit normal of a triangle (zero for a degenerate one).
pub fn normal(t: &[[f64; 3]; 3]) -> [f64; 3] {
    let n = cross(sub(t[1], t[0]), sub(t[2], t[0]));
    let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    if len == 0.0 {
        [0.0; 3]
    } else {
        [n[0] / len, n[1] / len, n[2] / len]
    }
}

impl Mesh {
    /// A mesh of these triangles.
    pub fn new(triangles: Vec<[[f64; 3]; 3]>) -> Mesh {
        Mesh { triangles }
    }

    /// The triangles.
    pub fn triangles(&self) -> &[[[f64; 3]; 3]] {
        &self.triangles
    }

    /// The enclosed volume (positive when the triangles face outward).
    pub fn volume(&self) -> f64 {
        self.triangles
            .iter()
            .map(|[a, b, c]| {
                (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0])
                    + a[2] * (b[0] * c[1] - b[1] * c[0]))
                    / 6.0
            })
            .sum()
    }

    /// The number of edges that are not shared by exactly two triangles
    /// running them in opposite directions (vertices are compared after
    /// rounding to the 32-bit floats STL stores). 0 for a closed, manifold,
    /// consistently oriented mesh.
    pub fn bad_edges(&self) -> usize {
        let key = |p: [f64; 3]| p.map(|v| (v as f32).to_bits());
        let mut directed: HashMap<([u32; 3], [u32; 3]), i32> = HashMap::new();
        for t in &self.triangles {
            for i in 0..3 {
                let (a, b) = (key(t[i]), key(t[(i + 1) % 3]));
                *directed.entry((a, b)).or_insert(0) += 1;
            }
        }
        let mut bad = 0;
        for (&(a, b), &n) in &directed {
            let back = directed.get(&(b, a)).copied().unwrap_or(0);
            if n != 1 || back != 1 {
                bad += 1;
            }
        }
        bad
    }

    /// The number of edges not shared by exactly two triangles, whatever
    /// their direction (0 for a closed mesh).
    ///
    /// Vertices closer than a millionth of the mesh's size count as one, so
    /// rounding noise of the program that wrote the file does not open it.
    pub fn open_edges(&self) -> usize {
        let mut lo = [f64::MAX; 3];
        let mut hi = [f64::MIN; 3];
        for p in self.triangles.iter().flatten() {
            for k in 0..3 {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
        }
        let size = (0..3).map(|k| hi[k] - lo[k]).fold(0.0, f64::max);
        let eps = if size > 0.0 { size * 1e-6 } else { 1.0 };
        let key = |p: [f64; 3]| p.map(|v| (v / eps).round() as i64);
        let mut count: HashMap<([i64; 3], [i64; 3]), i32> = HashMap::new();
        for t in &self.triangles {
            for i in 0..3 {
                let (a, b) = (key(t[i]), key(t[(i + 1) % 3]));
                *count
                    .entry(if a < b { (a, b) } else { (b, a) })
                    .or_insert(0) += 1;
            }
        }
        count.values().filter(|n| **n != 2).count()
    }

    /// Binary STL.
    pub fn to_binary_stl(&self, name: &str) -> Vec<u8> {
        let mut out = Vec::with_capacity(84 + 50 * self.triangles.len());
        let mut header = [b' '; 80];
        let h = format!("dissect {name}");
        for (d, s) in header.iter_mut().zip(h.bytes()) {
            *d = s;
        }
        out.extend_from_slice(&header);
        out.extend_from_slice(&(self.triangles.len() as u32).to_le_bytes());
        for t in &self.triangles {
            for v in normal(t) {
                out.extend_from_slice(&(v as f32).to_le_bytes());
            }
            for p in t {
                for v in p {
                    out.extend_from_slice(&(*v as f32).to_le_bytes());
                }
            }
            out.extend_from_slice(&[0, 0]);
        }
        out
    }

    /// ASCII STL.
    pub fn to_ascii_stl(&self, name: &str) -> String {
        let mut s = format!("solid {name}\n");
        for t in &self.triangles {
            let n = normal(t);
            s += &format!(
                "  facet normal {} {} {}\n    outer loop\n",
                n[0], n[1], n[2]
            );
            for p in t {
                s += &format!(
                    "      vertex {} {} {}\n",
                    p[0] as f32, p[1] as f32, p[2] as f32
                );
            }
            s += "    endloop\n  endfacet\n";
        }
        s += &format!("endsolid {name}\n");
        s
    }

    /// Reads a binary or ASCII STL.
    pub fn from_stl(bytes: &[u8]) -> Result<Mesh, RenderError> {
        let bad = |m: String| RenderError::BadMesh(m);
        let text_start = bytes.iter().skip_while(|b| b.is_ascii_whitespace()).take(5);
        let looks_ascii = text_start.eq(b"solid".iter());
        if bytes.len() >= 84 {
            let n = u32::from_le_bytes([bytes[80], bytes[81], bytes[82], bytes[83]]) as usize;
            if n.checked_mul(50).and_then(|v| v.checked_add(84)) == Some(bytes.len()) {
                if n > crate::bounds::MAX_TRIANGLES {
                    return Err(too_many(n));
                }
                let mut triangles = Vec::with_capacity(n);
                for k in 0..n {
                    let base = 84 + 50 * k + 12;
                    let f = |i: usize| {
                        let o = base + 4 * i;
                        f32::from_le_bytes([bytes[o], bytes[o + 1], bytes[o + 2], bytes[o + 3]])
                            as f64
                    };
                    let t = [[f(0), f(1), f(2)], [f(3), f(4), f(5)], [f(6), f(7), f(8)]];
                    if t.iter().flatten().any(|v| !v.is_finite()) {
                        return Err(bad(format!(
                            "triangle {} has a coordinate that is not a number",
                            k + 1
                        )));
                    }
                    triangles.push(t);
                }
                return Ok(Mesh { triangles });
            }
        }
        if !looks_ascii {
            return Err(bad(
                "neither binary STL (the triangle count does not match the size) nor ASCII STL (no \"solid\" at the start)".into(),
            ));
        }
        let text = std::str::from_utf8(bytes).map_err(|e| {
            bad(format!(
                "ASCII STL that is not UTF-8 text (byte {})",
                e.valid_up_to()
            ))
        })?;
        let mut triangles = Vec::new();
        let mut current: Vec<[f64; 3]> = Vec::new();
        for (ln, line) in text.lines().enumerate() {
            let mut words = line.split_whitespace();
            match words.next() {
                Some("vertex") => {
                    let v: Vec<f64> = words
                        .map(|w| w.parse::<f64>())
                        .collect::<Result<_, _>>()
                        .map_err(|_| bad(format!("line {}: bad vertex coordinates", ln + 1)))?;
                    if v.len() != 3 || v.iter().any(|x| !x.is_finite()) {
                        return Err(bad(format!("line {}: a vertex needs 3 numbers", ln + 1)));
                    }
                    if current.len() == 3 {
                        return Err(bad(format!(
                            "line {}: a facet has more than 3 vertices",
                            ln + 1
                        )));
                    }
                    current.push([v[0], v[1], v[2]]);
                }
                Some("endloop") => {
                    if current.len() != 3 {
                        return Err(bad(format!(
                            "line {}: a facet has {} vertices, expected 3",
                            ln + 1,
                            current.len()
                        )));
                    }
                    triangles.push([current[0], current[1], current[2]]);
                    current.clear();
                    if triangles.len() > crate::bounds::MAX_TRIANGLES {
                        return Err(too_many(triangles.len()));
                    }
                }
                Some("solid" | "facet" | "outer" | "endfacet" | "endsolid") | None => {}
                Some(w) => return Err(bad(format!("line {}: unexpected word {w:?}", ln + 1))),
            }
        }
        if triangles.is_empty() {
            return Err(bad("no triangle".into()));
        }
        Ok(Mesh { triangles })
    }
}

fn too_many(n: usize) -> RenderError {
    RenderError::TooLarge(format!(
        "the mesh has {n} triangles or more; at most {} are read",
        crate::bounds::MAX_TRIANGLES
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tetra() -> Mesh {
        let (o, x, y, z) = (
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [0.0, 1.0, 0.0],
            [0.0, 0.0, 1.0],
        );
        Mesh::new(vec![[o, y, x], [o, x, z], [o, z, y], [x, y, z]])
    }

    #[test]
    fn tetrahedron_is_closed_with_volume_a_sixth() {
        let m = tetra();
        assert_eq!(m.bad_edges(), 0);
        assert!((m.volume() - 1.0 / 6.0).abs() < 1e-12);
    }

    #[test]
    fn binary_and_ascii_stl_read_back() {
        let m = tetra();
        assert_eq!(Mesh::from_stl(&m.to_binary_stl("t")).unwrap(), m);
        assert_eq!(Mesh::from_stl(m.to_ascii_stl("t").as_bytes()).unwrap(), m);
    }

    #[test]
    fn open_mesh_has_bad_edges_and_garbage_is_refused() {
        let mut t = tetra().triangles().to_vec();
        t.pop();
        assert_eq!(Mesh::new(t).bad_edges(), 3);
        let e = Mesh::from_stl(b"hello").unwrap_err();
        assert!(e.to_string().contains("not an STL mesh"), "{e}");
        let e =
            Mesh::from_stl(b"solid x\nfacet normal 0 0 1\nouter loop\nvertex 1 2\n").unwrap_err();
        assert!(e.to_string().contains("line 4"), "{e}");
    }
}
