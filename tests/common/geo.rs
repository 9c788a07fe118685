//! Shapes as plain numbers for the oracle-backed suites (properties, stiff):
//! what gjk2d is given and the oracle is given, from one description.
// Each suite uses its own subset.
#![allow(dead_code)]

use gjk2d_oracle::Shape;

pub type Pt = [f64; 2];

pub fn norm(p: Pt) -> f64 {
    p[0].hypot(p[1])
}
pub fn sub(p: Pt, q: Pt) -> Pt {
    [p[0] - q[0], p[1] - q[1]]
}

/// Andrew's monotone chain on integers, strictly convex, counter-clockwise.
pub fn integer_hull(mut p: Vec<(i64, i64)>) -> Vec<(i64, i64)> {
    p.sort();
    p.dedup();
    if p.len() < 3 {
        return p;
    }
    let cross = |o: (i64, i64), a: (i64, i64), b: (i64, i64)| (a.0 - o.0) * (b.1 - o.1) - (a.1 - o.1) * (b.0 - o.0);
    let mut h: Vec<(i64, i64)> = Vec::new();
    for pass in 0..2 {
        let start = h.len();
        let iter: Box<dyn Iterator<Item = &(i64, i64)>> =
            if pass == 0 { Box::new(p.iter()) } else { Box::new(p.iter().rev()) };
        for &q in iter {
            while h.len() >= start + 2 && cross(h[h.len() - 2], h[h.len() - 1], q) <= 0 {
                h.pop();
            }
            h.push(q);
        }
        h.pop();
    }
    h
}

/// A shape as plain numbers, exactly representable in the suite's precision.
#[derive(Clone, Debug)]
pub enum Geo {
    Poly(Vec<Pt>),
    Circle(Pt, f64),
    Capsule(Pt, Pt, f64),
    Segment(Pt, Pt),
    /// A polygon swept by a radius.
    Rounded(Vec<Pt>, f64),
}

impl Geo {
    pub fn oracle(&self) -> Shape {
        match self {
            Geo::Poly(v) => Shape::Polygon(v.clone()),
            Geo::Circle(c, r) => Shape::Circle { center: *c, radius: *r },
            Geo::Capsule(a, b, r) => Shape::Capsule { a: *a, b: *b, radius: *r },
            Geo::Segment(a, b) => Shape::Capsule { a: *a, b: *b, radius: 0.0 },
            Geo::Rounded(v, r) => Shape::RoundedPolygon { vertices: v.clone(), radius: *r },
        }
    }
    pub fn core(&self) -> Vec<Pt> {
        match self {
            Geo::Poly(v) | Geo::Rounded(v, _) => v.clone(),
            Geo::Circle(c, _) => vec![*c],
            Geo::Capsule(a, b, _) | Geo::Segment(a, b) => vec![*a, *b],
        }
    }
    pub fn radius(&self) -> f64 {
        match self {
            Geo::Poly(_) | Geo::Segment(..) => 0.0,
            Geo::Circle(_, r) | Geo::Capsule(_, _, r) | Geo::Rounded(_, r) => *r,
        }
    }
    /// Largest local coordinate magnitude, radius included.
    pub fn extent(&self) -> f64 {
        self.core().iter().map(|&p| norm(p)).fold(0.0, f64::max) + self.radius()
    }
    pub fn is_circle(&self) -> bool {
        matches!(self, Geo::Circle(..))
    }
    /// Support value `h(n)` (any `n`, not unit) of the shape mapped by
    /// `x -> M x + t`, `M = [[c, -s], [s, c]]`, in f64.
    pub fn support(&self, cs: (f64, f64), t: Pt, n: Pt) -> f64 {
        let m = [cs.0 * n[0] + cs.1 * n[1], -cs.1 * n[0] + cs.0 * n[1]];
        let core = self.core().iter().map(|p| p[0] * m[0] + p[1] * m[1]).fold(f64::NEG_INFINITY, f64::max);
        core + self.radius() * norm(n) + t[0] * n[0] + t[1] * n[1]
    }
    /// Short description (big polygons are not printed in full).
    pub fn describe(&self) -> String {
        match self {
            Geo::Poly(v) if v.len() > 12 => format!("Poly({} vertices, first {:?})", v.len(), v[0]),
            other => format!("{other:?}"),
        }
    }
}
