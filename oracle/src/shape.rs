//! Input shapes and their exact (rational) counterparts.

use crate::exact::{q_from_f64, Q};
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;

/// A 2D point or vector in `f64`.
pub type Pt = [f64; 2];

/// The float shapes of the library, as the oracle receives them.
#[derive(Clone, Debug)]
pub enum Shape {
    /// Convex polygon, counter-clockwise, >= 3 vertices (may contain collinear vertices;
    /// treated as the convex hull of the points).
    Polygon(Vec<Pt>),
    /// Disk.
    Circle { center: Pt, radius: f64 },
    /// Segment a-b swept by a disk of radius r (r may be 0: a plain segment).
    Capsule { a: Pt, b: Pt, radius: f64 },
    /// Convex polygon swept by a disk of radius r.
    RoundedPolygon { vertices: Vec<Pt>, radius: f64 },
}

/// A shape with exact rational coordinates: a *core* (a point, a segment or a strictly
/// convex counter-clockwise polygon) swept by a disk of exact radius `radius`.
///
/// Polygons are reduced to their exact convex hull (collinear and duplicate vertices
/// dropped), so every query can rely on strict convexity; a hull that degenerates to a
/// segment or a point becomes that core. The coordinates are also kept as integers over
/// a common denominator, which is what the queries compute with (no gcd per operation).
#[derive(Clone, Debug)]
pub struct ExactShape {
    verts: Vec<[Q; 2]>,
    pub(crate) ints: Vec<[BigInt; 2]>,
    pub(crate) den: BigInt,
    radius: Q,
}

impl ExactShape {
    /// Builds a shape from an exact core and radius. `verts` must be one point, two
    /// distinct points, or >= 3 vertices of a strictly convex counter-clockwise polygon.
    pub fn from_core(verts: Vec<[Q; 2]>, radius: Q) -> Self {
        assert!(!verts.is_empty(), "empty core");
        assert!(!radius.is_negative(), "negative radius");
        let mut den = BigInt::one();
        for v in &verts {
            for c in v {
                if !(&den % c.denom()).is_zero() {
                    den = crate::exact::lcm_fast(&den, c.denom());
                }
            }
        }
        let ints = verts
            .iter()
            .map(|v| {
                let f = |c: &Q| c.numer() * (&den / c.denom());
                [f(&v[0]), f(&v[1])]
            })
            .collect();
        ExactShape { verts, ints, den, radius }
    }

    /// A single exact point (radius 0).
    pub fn point(p: Pt) -> Self {
        Self::from_core(vec![[q_from_f64(p[0]), q_from_f64(p[1])]], Q::zero())
    }

    /// The core's vertices: 1 (point), 2 (segment) or >= 3 (strictly convex, CCW).
    pub fn core_vertices(&self) -> &[[Q; 2]] {
        &self.verts
    }

    /// The exact sweep radius (0 for plain polygons and segments).
    pub fn radius(&self) -> &Q {
        &self.radius
    }
}

impl From<&Shape> for ExactShape {
    fn from(s: &Shape) -> Self {
        transform_shape(s, 1.0, 0.0, 0.0, 0.0)
    }
}

/// Exact sign of the orientation of (a, b, c): > 0 counter-clockwise.
///
/// Shewchuk's static filter (ccwerrboundA) decides the sign from the float determinant
/// when that is provably right (no overflow/underflow); otherwise exact rationals decide.
fn orient(a: Pt, b: Pt, c: Pt) -> Ordering {
    let l = (a[0] - c[0]) * (b[1] - c[1]);
    let r = (a[1] - c[1]) * (b[0] - c[0]);
    let det = l - r;
    let sum = l.abs() + r.abs();
    let bound = 3.330_669_073_875_471_6e-16 * sum;
    if sum.is_finite() && sum > 1e-280 && det.abs() > bound {
        return det.partial_cmp(&0.0).unwrap();
    }
    let q = |x: f64| q_from_f64(x);
    let (ax, ay, bx, by, cx, cy) = (q(a[0]), q(a[1]), q(b[0]), q(b[1]), q(c[0]), q(c[1]));
    let d = (&ax - &cx) * (&by - &cy) - (&ay - &cy) * (&bx - &cx);
    d.cmp(&Q::zero())
}

/// Exact convex hull (Andrew's monotone chain), counter-clockwise, without collinear or
/// duplicate points. Returns 1 point or 2 points for degenerate inputs.
fn hull(pts: &[Pt]) -> Vec<Pt> {
    assert!(!pts.is_empty(), "polygon without vertices");
    for p in pts {
        assert!(p[0].is_finite() && p[1].is_finite(), "gjk2d-oracle: non-finite vertex");
    }
    let mut p: Vec<Pt> = pts.iter().map(|v| [v[0] + 0.0, v[1] + 0.0]).collect();
    p.sort_by(|a, b| a.partial_cmp(b).unwrap());
    p.dedup();
    if p.len() < 3 {
        return p;
    }
    let mut lower: Vec<Pt> = Vec::new();
    for &v in &p {
        while lower.len() >= 2 && orient(lower[lower.len() - 2], lower[lower.len() - 1], v) != Ordering::Greater {
            lower.pop();
        }
        lower.push(v);
    }
    let mut upper: Vec<Pt> = Vec::new();
    for &v in p.iter().rev() {
        while upper.len() >= 2 && orient(upper[upper.len() - 2], upper[upper.len() - 1], v) != Ordering::Greater {
            upper.pop();
        }
        upper.push(v);
    }
    lower.pop();
    upper.pop();
    lower.extend(upper);
    lower
}

/// A dyadic number `m * 2^e`.
type Dy = (BigInt, i64);

/// A finite float as `m * 2^e`.
fn dy_of(x: f64) -> Dy {
    let bits = x.to_bits();
    let exp = ((bits >> 52) & 0x7ff) as i64;
    let frac = bits & ((1u64 << 52) - 1);
    let (m, e) = if exp == 0 { (frac, -1074) } else { (frac | (1u64 << 52), exp - 1075) };
    let m = BigInt::from(m);
    (if bits >> 63 == 1 { -m } else { m }, e)
}

/// Exact `sum(sign * a * b) + t` of dyadic numbers, as a reduced rational.
fn dy_sum(terms: &[(i32, &Dy, &Dy)], t: &Dy) -> Q {
    let mut parts: Vec<Dy> = terms
        .iter()
        .map(|(sg, a, b)| {
            let m = &a.0 * &b.0;
            (if *sg < 0 { -m } else { m }, a.1 + b.1)
        })
        .collect();
    parts.push(t.clone());
    let e0 = parts.iter().map(|p| p.1).min().unwrap();
    let mut m = BigInt::zero();
    for (pm, pe) in parts {
        m += pm << ((pe - e0) as usize);
    }
    if m.is_zero() {
        return Q::zero();
    }
    let tz = m.trailing_zeros().unwrap_or(0) as i64;
    let k = tz.min((-e0).max(0));
    let m = m >> (k as usize);
    let e = e0 + k;
    if e >= 0 {
        Q::from_integer(m << (e as usize))
    } else {
        Q::new_raw(m, BigInt::one() << ((-e) as usize))
    }
}

/// Exact rigid (or similarity) transform of a shape: `x' = cos*x - sin*y + tx`,
/// `y' = sin*x + cos*y + ty`, evaluated in rationals. `cos`/`sin` are used as given
/// (not normalised): the oracle answers for exactly the map the float code was given.
/// The radius is kept exact and is not scaled.
pub fn transform_shape(s: &Shape, cos: f64, sin: f64, tx: f64, ty: f64) -> ExactShape {
    let (core, radius): (Vec<Pt>, f64) = match s {
        Shape::Polygon(v) => (hull(v), 0.0),
        Shape::Circle { center, radius } => (vec![*center], *radius),
        Shape::Capsule { a, b, radius } => (hull(&[*a, *b]), *radius),
        Shape::RoundedPolygon { vertices, radius } => (hull(vertices), *radius),
    };
    let r = q_from_f64(radius);
    assert!(!r.is_negative(), "gjk2d-oracle: negative radius");
    let (c, sn, x, y) = (q_from_f64(cos), q_from_f64(sin), q_from_f64(tx), q_from_f64(ty));
    if c.is_zero() && sn.is_zero() {
        // Degenerate map: everything collapses onto the translation.
        return ExactShape::from_core(vec![[x, y]], r);
    }
    // The map has determinant cos^2 + sin^2 > 0: it preserves orientation, strict
    // convexity and distinctness, so the transformed hull is still a valid core.
    // Evaluated on dyadic integers (mantissa, exponent): exact, and no gcd per operation.
    let (dc, ds, dx, dy) = (dy_of(cos), dy_of(sin), dy_of(tx), dy_of(ty));
    let verts = core
        .iter()
        .map(|p| {
            let (px, py) = (dy_of(p[0]), dy_of(p[1]));
            [dy_sum(&[(1, &dc, &px), (-1, &ds, &py)], &dx), dy_sum(&[(1, &ds, &px), (1, &dc, &py)], &dy)]
        })
        .collect();
    ExactShape::from_core(verts, r)
}
