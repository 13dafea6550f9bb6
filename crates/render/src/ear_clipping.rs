//! Triangulation of a polygon with holes by ear clipping, after joining
//! every hole to the outer boundary by a bridge. It keeps every vertex
//! (also those where the boundary goes straight on), so triangles meet the
//! neighbouring faces of a mesh without T-junctions.

/// `(b - a) × (c - a)`.
fn area(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

fn cross(u: [f64; 2], v: [f64; 2]) -> f64 {
    u[0] * v[1] - u[1] * v[0]
}

fn sub(a: [f64; 2], b: [f64; 2]) -> [f64; 2] {
    [a[0] - b[0], a[1] - b[1]]
}

/// Whether the closed segments `p1 q1` and `p2 q2` share a point other than
/// a shared endpoint position.
fn segments_meet(p1: [f64; 2], q1: [f64; 2], p2: [f64; 2], q2: [f64; 2]) -> bool {
    let shares = |a: [f64; 2]| a == p2 || a == q2;
    let o1 = area(p1, q1, p2);
    let o2 = area(p1, q1, q2);
    let o3 = area(p2, q2, p1);
    let o4 = area(p2, q2, q1);
    let on = |a: [f64; 2], b: [f64; 2], c: [f64; 2]| {
        c[0] >= a[0].min(b[0])
            && c[0] <= a[0].max(b[0])
            && c[1] >= a[1].min(b[1])
            && c[1] <= a[1].max(b[1])
    };
    if o1 * o2 < 0.0 && o3 * o4 < 0.0 {
        return true;
    }
    // Touching or collinear cases, ignoring shared endpoints.
    (o1 == 0.0 && on(p1, q1, p2) && !(p2 == p1 || p2 == q1))
        || (o2 == 0.0 && on(p1, q1, q2) && !(q2 == p1 || q2 == q1))
        || (o3 == 0.0 && on(p2, q2, p1) && !shares(p1))
        || (o4 == 0.0 && on(p2, q2, q1) && !shares(q1))
        || (o1 == 0.0 && o2 == 0.0 && on(p1, q1, p2) && on(p1, q1, q2) && p2 != q2 && {
            // Collinear overlap of positive length.
            let key = |a: [f64; 2]| (a[0], a[1]);
            let lo = |a: [f64; 2], b: [f64; 2]| if key(a) < key(b) { key(a) } else { key(b) };
            let hi = |a: [f64; 2], b: [f64; 2]| if key(a) < key(b) { key(b) } else { key(a) };
            let (l1, l2, h1, h2) = (lo(p1, q1), lo(p2, q2), hi(p1, q1), hi(p2, q2));
            (if l1 > l2 { l1 } else { l2 }) < (if h1 < h2 { h1 } else { h2 })
        })
}

/// Whether direction `w` from vertex `o` (between `prev` and `next`, polygon
/// counter-clockwise) points strictly into the polygon.
fn points_inside(prev: [f64; 2], o: [f64; 2], next: [f64; 2], w: [f64; 2]) -> bool {
    let a = sub(next, o);
    let b = sub(prev, o);
    if cross(sub(o, prev), sub(next, o)) > 0.0 {
        cross(a, w) > 0.0 && cross(w, b) > 0.0
    } else {
        !(cross(b, w) >= 0.0 && cross(w, a) >= 0.0)
    }
}

/// Triangulates the polygon whose outer boundary is `outer` (indices into
/// `pts`, counter-clockwise) with holes `holes` (clockwise). Returns
/// counter-clockwise triangles, or `None` when the input is not a valid
/// polygon.
pub fn triangulate(
    pts: &[[f64; 2]],
    outer: &[usize],
    holes: &[Vec<usize>],
) -> Option<Vec<[usize; 3]>> {
    let mut poly: Vec<usize> = outer.to_vec();
    let mut holes: Vec<&Vec<usize>> = holes.iter().filter(|h| !h.is_empty()).collect();
    // Right-most holes first, so that bridges never cross later holes' bridges.
    let max_x = |h: &Vec<usize>| h.iter().map(|&i| pts[i][0]).fold(f64::MIN, f64::max);
    holes.sort_by(|a, b| max_x(b).total_cmp(&max_x(a)));
    for (k, hole) in holes.iter().enumerate() {
        // The hole vertex of largest x (then smallest y).
        let (ih, &h) = hole.iter().enumerate().max_by(|a, b| {
            let (pa, pb) = (pts[*a.1], pts[*b.1]);
            pa[0].total_cmp(&pb[0]).then(pb[1].total_cmp(&pa[1]))
        })?;
        let hp = pts[h];
        let hprev = pts[hole[(ih + hole.len() - 1) % hole.len()]];
        let hnext = pts[hole[(ih + 1) % hole.len()]];
        let mut best: Option<(f64, usize)> = None;
        let n = poly.len();
        for io in 0..n {
            let o = pts[poly[io]];
            let d2 = (o[0] - hp[0]).powi(2) + (o[1] - hp[1]).powi(2);
            if best.is_some_and(|(bd, _)| d2 >= bd) || o == hp {
                continue;
            }
            let prev = pts[poly[(io + n - 1) % n]];
            let next = pts[poly[(io + 1) % n]];
            if !points_inside(prev, o, next, sub(hp, o)) {
                continue;
            }
            // The hole runs clockwise, so the material is on its left too.
            if !points_inside(hprev, hp, hnext, sub(o, hp)) {
                continue;
            }
            let blocked = (0..n).any(|j| {
                let (a, b) = (pts[poly[j]], pts[poly[(j + 1) % n]]);
                segments_meet(hp, o, a, b)
            }) || holes[k..].iter().any(|hh| {
                (0..hh.len()).any(|j| {
                    let (a, b) = (pts[hh[j]], pts[hh[(j + 1) % hh.len()]]);
                    segments_meet(hp, o, a, b)
                })
            });
            if !blocked {
                best = Some((d2, io));
            }
        }
        let (_, io) = best?;
        let mut merged = Vec::with_capacity(poly.len() + hole.len() + 2);
        merged.extend_from_slice(&poly[..=io]);
        for j in 0..=hole.len() {
            merged.push(hole[(ih + j) % hole.len()]);
        }
        merged.push(poly[io]);
        merged.extend_from_slice(&poly[io + 1..]);
        poly = merged;
    }
    clip(pts, poly)
}

fn clip(pts: &[[f64; 2]], mut poly: Vec<usize>) -> Option<Vec<[usize; 3]>> {
    let mut out = Vec::with_capacity(poly.len().saturating_sub(2));
    while poly.len() > 3 {
        let n = poly.len();
        let mut found = None;
        for i in 0..n {
            let (ia, ib, ic) = (poly[(i + n - 1) % n], poly[i], poly[(i + 1) % n]);
            let (a, b, c) = (pts[ia], pts[ib], pts[ic]);
            if area(a, b, c) <= 0.0 {
                continue;
            }
            let blocked = poly.iter().any(|&j| {
                let p = pts[j];
                if p == a || p == b || p == c {
                    return false;
                }
                area(a, b, p) >= 0.0 && area(b, c, p) >= 0.0 && area(c, a, p) >= 0.0
            });
            // A bridge or pinch vertex equal to `b` elsewhere must not lie
            // inside the diagonal's cone either.
            let diagonal_crosses = (0..n).any(|j| {
                let (p, q) = (pts[poly[j]], pts[poly[(j + 1) % n]]);
                segments_meet(a, c, p, q)
            });
            if !blocked && !diagonal_crosses {
                found = Some(i);
                break;
            }
        }
        let i = found?;
        let n = poly.len();
        out.push([poly[(i + n - 1) % n], poly[i], poly[(i + 1) % n]]);
        poly.remove(i);
    }
    if poly.len() == 3 {
        let (a, b, c) = (pts[poly[0]], pts[poly[1]], pts[poly[2]]);
        if area(a, b, c) <= 0.0 {
            return None;
        }
        out.push([poly[0], poly[1], poly[2]]);
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn total_area(pts: &[[f64; 2]], tris: &[[usize; 3]]) -> f64 {
        tris.iter()
            .map(|t| area(pts[t[0]], pts[t[1]], pts[t[2]]) / 2.0)
            .sum()
    }

    #[test]
    fn square_with_a_point_on_an_edge_keeps_it() {
        let pts = [[0., 0.], [1., 0.], [2., 0.], [2., 2.], [0., 2.]];
        let t = triangulate(&pts, &[0, 1, 2, 3, 4], &[]).unwrap();
        assert_eq!(t.len(), 3);
        assert!(t.iter().any(|t| t.contains(&1)));
        assert_eq!(total_area(&pts, &t), 4.0);
    }

    #[test]
    fn square_with_a_square_hole() {
        let pts = [
            [0., 0.],
            [3., 0.],
            [3., 3.],
            [0., 3.],
            [1., 1.],
            [1., 2.],
            [2., 2.],
            [2., 1.],
        ];
        let t = triangulate(&pts, &[0, 1, 2, 3], &[vec![4, 5, 6, 7]]).unwrap();
        assert_eq!(t.len(), 8);
        assert_eq!(total_area(&pts, &t), 8.0);
    }
}
