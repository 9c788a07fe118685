//! The GJK simplex (at most a triangle in 2D) and the closest point of it
//! to the origin.
//!
//! Closest points are computed in the form that keeps the most precision: on
//! an edge, `v = n (n . w1) / (n . n)` with `n` perpendicular to the edge, so
//! `v` is exactly normal to the edge's direction and no `w1 + t (w2 - w1)`
//! cancellation is spent on it.

use crate::minkowski::MinkowskiVertex;
use crate::real::{Real, V2};

#[derive(Clone, Copy, Debug)]
pub(crate) struct Simplex<R: Real> {
    pub verts: [MinkowskiVertex<R>; 3],
    /// Barycentric weights of the closest point.
    pub weights: [R; 3],
    pub len: usize,
}

/// Where the origin is relative to the simplex.
pub(crate) enum Closest<R> {
    /// The closest point of the simplex (the simplex reduced to its support).
    Point(V2<R>),
    /// The origin lies inside the triangle or on its boundary.
    Enclosed,
}

impl<R: Real> Simplex<R> {
    pub fn new(first: MinkowskiVertex<R>) -> Self {
        Self { verts: [first; 3], weights: [R::ONE, R::ZERO, R::ZERO], len: 1 }
    }

    pub fn vertices(&self) -> &[MinkowskiVertex<R>] {
        &self.verts[..self.len]
    }

    /// Appends a vertex; the caller keeps `len < 3` before it.
    pub fn push(&mut self, v: MinkowskiVertex<R>) {
        self.verts[self.len] = v;
        self.len += 1;
    }

    /// Whether a vertex with this (non-curve) id is in the simplex.
    pub fn contains_id(&self, id: u64) -> bool {
        id != crate::minkowski::NO_ID && self.vertices().iter().any(|v| v.id == id)
    }

    /// Reduces the simplex to the smallest face holding the closest point to
    /// the origin, and returns that point.
    pub fn solve(&mut self) -> Closest<R> {
        match self.len {
            1 => {
                self.weights[0] = R::ONE;
                Closest::Point(self.verts[0].w)
            }
            2 => {
                let (s, v) = solve_segment(self.verts[0], self.verts[1]);
                *self = s;
                Closest::Point(v)
            }
            _ => self.solve_triangle(),
        }
    }

    fn solve_triangle(&mut self) -> Closest<R> {
        let [a, b, c] = self.verts;
        let (wa, wb, wc) = (a.w, b.w, c.w);
        let area = (wb - wa).cross(wc - wa);
        // The origin is on the inner side of edge i->j when cross(wi, wj)
        // has the sign of the area (zero counts as inside: touching).
        let edges = [(a, b, wa.cross(wb)), (b, c, wb.cross(wc)), (c, a, wc.cross(wa))];
        let outside = |side: R| {
            if area > R::ZERO {
                side < R::ZERO
            } else if area < R::ZERO {
                side > R::ZERO
            } else {
                true
            }
        };
        if area != R::ZERO && !edges.iter().any(|e| outside(e.2)) {
            return Closest::Enclosed;
        }
        // The closest point lies on an edge the origin is outside of; a
        // degenerate (flat) triangle tries all three.
        let mut best: Option<(Simplex<R>, V2<R>, R)> = None;
        for &(p, q, side) in edges.iter() {
            if !outside(side) {
                continue;
            }
            let (s, v) = solve_segment(p, q);
            let vv = v.length_squared();
            if best.as_ref().is_none_or(|b| vv < b.2) {
                best = Some((s, v, vv));
            }
        }
        match best {
            Some((s, v, _)) => {
                *self = s;
                Closest::Point(v)
            }
            None => Closest::Enclosed,
        }
    }

    /// The closest point's pre-images on A and B (pair frame).
    pub fn witness_points(&self) -> (V2<R>, V2<R>) {
        let mut pa = V2::zero();
        let mut pb = V2::zero();
        for (v, &w) in self.vertices().iter().zip(self.weights.iter()) {
            pa = pa + v.a * w;
            pb = pb + v.b * w;
        }
        (pa, pb)
    }

    /// Distance from the origin to the simplex's closest point and the unit
    /// normal towards it, in the most precise form for the face it lies on.
    /// `toward` (B's center minus A's) orients the normal when the distance
    /// rounds to exactly zero and the edge alone cannot tell its side.
    pub fn distance_and_normal(&self, v: V2<R>, toward: V2<R>) -> Option<(R, V2<R>)> {
        if self.len == 2 {
            let (w1, w2) = (self.verts[0].w, self.verts[1].w);
            let n = (w2 - w1).perp();
            let len = n.length();
            if len > R::ZERO {
                // Divided componentwise, an axis-aligned normal comes out as
                // exactly (0, +-1) or (+-1, 0), so axis-aligned contacts give
                // exact distances (a touching pair gives exactly 0).
                let unit = V2::new(n.x / len, n.y / len);
                let signed = unit.dot(w1);
                let outward = signed > R::ZERO || (signed == R::ZERO && unit.dot(toward) >= R::ZERO);
                return if outward { Some((signed, unit)) } else { Some((-signed, -unit)) };
            }
        }
        let len = v.length();
        if len > R::ZERO {
            Some((len, v * (R::ONE / len)))
        } else {
            None
        }
    }
}

/// Closest point of segment `p`-`q` to the origin, with the segment reduced
/// to the vertex or edge holding it.
fn solve_segment<R: Real>(p: MinkowskiVertex<R>, q: MinkowskiVertex<R>) -> (Simplex<R>, V2<R>) {
    let e = q.w - p.w;
    let toward_q = -p.w.dot(e);
    let toward_p = q.w.dot(e);
    if toward_q <= R::ZERO {
        return (Simplex::new(p), p.w);
    }
    if toward_p <= R::ZERO {
        return (Simplex::new(q), q.w);
    }
    let n = e.perp();
    let nn = n.length_squared();
    if nn <= R::ZERO {
        // An edge so short its squared length underflows: keep the nearer end.
        let nearer = if p.w.length_squared() <= q.w.length_squared() { p } else { q };
        return (Simplex::new(nearer), nearer.w);
    }
    let inv = R::ONE / (toward_q + toward_p);
    let v = n * (n.dot(p.w) / nn);
    let s = Simplex { verts: [p, q, q], weights: [toward_p * inv, toward_q * inv, R::ZERO], len: 2 };
    (s, v)
}
