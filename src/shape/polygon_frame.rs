//! A polygon's validation and framing, written once as `const fn`s and
//! generated for f32 and f64. Its points get the checks every shape's
//! inputs get (`checks.rs`).
//!
//! `const` because a firmware's shapes are usually fixed: a shape declared
//! as a constant (its `*_const` constructor, or
//! [`Polygon::from_array`](super::Polygon::from_array)) is checked by the
//! compiler, an invalid one fails the build, and the program carries neither
//! this code nor a copy of the shape in RAM. Generated
//! per type because a `const fn` cannot do arithmetic through the [`Real`]
//! trait. [`Polygon::new`](super::Polygon::new) runs the same functions at
//! run time (through [`Framing`]), so a polygon built either way is bit for
//! bit the same.
//!
//! [`Real`]: crate::Real

use crate::error::Error;
use crate::real::{PerType, Real, V2};

/// Where a validated polygon's vertices are stored relative to, and the
/// bounding circle GJK scales its tolerances by.
#[derive(Clone, Copy, Debug)]
pub struct Frame<R> {
    pub reference: V2<R>,
    pub center: V2<R>,
    /// Squared, so a firmware that only tests polygons for overlap links no
    /// square root.
    pub bounding_radius_squared: R,
    /// Squared as well: see [`SupportMap::inner_radius_squared`](crate::SupportMap).
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    pub inner_radius_squared: R,
}

macro_rules! polygon_frame {
    ($module:ident, $R:ty) => {
        pub(crate) mod $module {
            use super::Frame;
            use crate::checks::$module::{check_length, check_point, max};
            use crate::error::Error;
            use crate::real::{Real, V2};

            /// Checks the vertices and frames them in place: each finite and
            /// within range, no empty edge, convex, wound once; then put
            /// counter-clockwise and made relative to the reference point.
            /// The checks come in the order the errors are documented in.
            pub(crate) const fn frame(v: &mut [V2<$R>]) -> Result<Frame<$R>, Error> {
                if v.len() < 3 {
                    return Err(Error::TooFewVertices);
                }
                let mut i = 0;
                while i < v.len() {
                    if let Err(e) = check_point(v[i]) {
                        return Err(e);
                    }
                    i += 1;
                }
                match convex_winding(v) {
                    Err(e) => return Err(e),
                    Ok(winding) if winding < 0 => reverse(v),
                    Ok(_) => {}
                }
                let reference = choose_reference(v);
                let mut i = 0;
                while i < v.len() {
                    v[i] = sub(v[i], reference);
                    i += 1;
                }
                let center = area_centroid(v);
                let mut r2 = 0.0;
                let mut i = 0;
                while i < v.len() {
                    let d = sub(v[i], center);
                    r2 = max(r2, d.x * d.x + d.y * d.y);
                    i += 1;
                }
                Ok(Frame {
                    reference,
                    center,
                    bounding_radius_squared: r2,
                    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
                    inner_radius_squared: inner_radius_squared(v, center, r2),
                })
            }

            /// The square of the least distance from `center` to an edge's
            /// line, rounded down past its rounding: each distance is within
            /// 16 eps R of the true one (R the bounding radius, which bounds
            /// it), so its square within 32 eps R^2, and twice that is taken
            /// off. Zero where the center is not inside by more, or where a
            /// product could leave the normal range and round by more.
            #[cfg(not(any(target_os = "none", target_family = "wasm")))]
            const fn inner_radius_squared(v: &[V2<$R>], center: V2<$R>, r2: $R) -> $R {
                let eps = <$R>::EPSILON;
                let normal = <$R>::MIN_POSITIVE / eps;
                if !(r2 > normal && r2 < <$R>::MAX * eps) {
                    return 0.0;
                }
                let mut least = r2;
                let mut i = 0;
                while i < v.len() {
                    let e = sub(at(v, i + 1), v[i]);
                    let length2 = e.x * e.x + e.y * e.y;
                    let c = cross(e, sub(center, v[i]));
                    if !(c > 0.0 && length2 > normal) {
                        return 0.0;
                    }
                    let h2 = c / length2 * c;
                    if h2 < least {
                        least = h2;
                    }
                    i += 1;
                }
                let bound = least * (1.0 - 8.0 * eps) - 64.0 * eps * r2;
                if bound > 0.0 {
                    bound
                } else {
                    0.0
                }
            }

            /// Half of a `width` by `height` box, both checked as lengths:
            /// what a rectangle and an ellipse keep.
            pub(crate) const fn half_extents(width: $R, height: $R) -> Result<V2<$R>, Error> {
                let width = const_try!(check_length(width));
                let height = const_try!(check_length(height));
                Ok(V2 { x: width * 0.5, y: height * 0.5 })
            }

            const fn sub(a: V2<$R>, b: V2<$R>) -> V2<$R> {
                V2 { x: a.x - b.x, y: a.y - b.y }
            }

            const fn cross(a: V2<$R>, b: V2<$R>) -> $R {
                a.x * b.y - a.y * b.x
            }

            /// `v[i % n]` for `i < 2 n`, without a division (software on
            /// Cortex-M0) or a bounds check that could panic.
            const fn at(v: &[V2<$R>], i: usize) -> V2<$R> {
                let n = v.len();
                let j = if i >= n { i - n } else { i };
                if j < n {
                    v[j]
                } else {
                    V2 { x: 0.0, y: 0.0 }
                }
            }

            const fn opposite(a: $R, b: $R) -> bool {
                (a > 0.0 && b < 0.0) || (a < 0.0 && b > 0.0)
            }

            const fn reverse(v: &mut [V2<$R>]) {
                let n = v.len();
                let mut i = 0;
                while i < n / 2 {
                    let t = v[i];
                    v[i] = v[n - 1 - i];
                    v[n - 1 - i] = t;
                    i += 1;
                }
            }

            /// +1 for a counter-clockwise convex polygon, -1 for a clockwise
            /// one, in one pass over the edges. No edge may be empty, every
            /// turn must go the same way (collinear turns allowed, but not
            /// back along the edge: a spike) and the edge directions must wind
            /// once: a convex polygon's edge x- and y-components change sign
            /// at most twice around the loop, a pentagram's more often.
            const fn convex_winding(p: &[V2<$R>]) -> Result<i32, Error> {
                let n = p.len();
                let (mut left, mut right, mut spike) = (false, false, false);
                let mut changes = 0u32;
                let mut last = [0.0 as $R; 2];
                let mut previous = V2 { x: 0.0, y: 0.0 };
                // Edge n is edge 0 again: the sign changes close the loop.
                let mut i = 0;
                while i <= n {
                    let e = sub(at(p, i + 1), at(p, i));
                    if e.x == 0.0 && e.y == 0.0 {
                        return Err(Error::DuplicateVertex);
                    }
                    let components = [e.x, e.y];
                    let mut k = 0;
                    while k < 2 {
                        let c = components[k];
                        if c != 0.0 {
                            if last[k] != 0.0 && (c > 0.0) != (last[k] > 0.0) {
                                changes += 1;
                            }
                            last[k] = c;
                        }
                        k += 1;
                    }
                    // The turn at vertex i, from edge i - 1 to edge i.
                    if i > 0 {
                        let turn = orientation(at(p, i - 1), at(p, i), at(p, i + 1));
                        left |= turn > 0.0;
                        right |= turn < 0.0;
                        // Collinear edges (the turn is exact) that point
                        // opposite ways have a component of opposite signs,
                        // and differences of floats keep their signs.
                        if turn == 0.0 {
                            spike |= opposite(previous.x, e.x) || opposite(previous.y, e.y);
                        }
                    }
                    previous = e;
                    i += 1;
                }
                if left && right {
                    return Err(Error::NotConvex);
                }
                if !left && !right {
                    return Err(Error::Degenerate);
                }
                // The sign changes below miss a spike: its edges' signs change
                // and change back, as a convex polygon's do.
                if spike {
                    return Err(Error::NotConvex);
                }
                // Each component of a closed loop's edges changes sign at
                // least twice, and every one of them 2k times when the edges
                // wind k times: more than four changes in all is a second
                // winding.
                if changes > 4 {
                    return Err(Error::NotConvex);
                }
                Ok(if left { 1 } else { -1 })
            }

            /// The point vertices are stored relative to. Far from the origin
            /// (or wherever the shift is exact), the first vertex: differences
            /// of nearby floats are exact, and the shape keeps its own
            /// precision, not its position's. Near the origin, the origin
            /// itself: the coordinates as given are exact already, and a shift
            /// would round them.
            const fn choose_reference(p: &[V2<$R>]) -> V2<$R> {
                let first = p[0];
                let mut exact = true;
                let mut extent = 0.0;
                let mut i = 0;
                while i < p.len() {
                    exact = exact && two_diff(p[i].x, first.x).1 == 0.0 && two_diff(p[i].y, first.y).1 == 0.0;
                    let d = sub(p[i], first);
                    extent = max(extent, max(d.x.abs(), d.y.abs()));
                    i += 1;
                }
                if exact || max(first.x.abs(), first.y.abs()) > extent * 4.0 {
                    first
                } else {
                    V2 { x: 0.0, y: 0.0 }
                }
            }

            /// Area centroid of a counter-clockwise polygon: a fan from vertex
            /// 0, on coordinates relative to it, so the triangles' areas and
            /// centers lose nothing to a far-away origin. Two passes (total
            /// area, then each triangle's share of it) so no intermediate grows
            /// like size cubed: at f32's coordinate limit that would overflow.
            const fn area_centroid(v: &[V2<$R>]) -> V2<$R> {
                let n = v.len();
                let origin = v[0];
                let mut area2 = 0.0;
                let mut i = 1;
                while i + 1 < n {
                    area2 += cross(sub(v[i], origin), sub(v[i + 1], origin));
                    i += 1;
                }
                let mut acc = V2 { x: 0.0, y: 0.0 };
                if area2 > 0.0 && area2.is_finite() {
                    let mut i = 1;
                    while i + 1 < n {
                        let (p, q) = (sub(v[i], origin), sub(v[i + 1], origin));
                        let share = cross(p, q) / area2;
                        acc = V2 { x: acc.x + (p.x + q.x) * share, y: acc.y + (p.y + q.y) * share };
                        i += 1;
                    }
                    let third = 1.0 / 3.0;
                    V2 { x: origin.x + acc.x * third, y: origin.y + acc.y * third }
                } else {
                    // Unreachable for validated polygons; the vertex mean is a
                    // safe center.
                    let weight = 1.0 / n as $R;
                    let mut i = 0;
                    while i < n {
                        let d = sub(v[i], origin);
                        acc = V2 { x: acc.x + d.x * weight, y: acc.y + d.y * weight };
                        i += 1;
                    }
                    V2 { x: origin.x + acc.x, y: origin.y + acc.y }
                }
            }

            /// `cross(b - a, c - a)` with its sign right far beyond what the
            /// plain formula gives: positive when `a, b, c` turn
            /// counter-clockwise. The differences and products are expanded
            /// error-free (TwoDiff, Dekker's TwoProduct), so only the final
            /// sums round, and those are tiny next to any value they could
            /// flip.
            const fn orientation(a: V2<$R>, b: V2<$R>, c: V2<$R>) -> $R {
                let (abx, abx_e) = two_diff(b.x, a.x);
                let (aby, aby_e) = two_diff(b.y, a.y);
                let (acx, acx_e) = two_diff(c.x, a.x);
                let (acy, acy_e) = two_diff(c.y, a.y);
                let (p, p_e) = two_product(abx, acy);
                let (q, q_e) = two_product(aby, acx);
                // Main term and its error, then the cross terms from the
                // difference errors.
                let main = p - q;
                let tail = (p_e - q_e) + (abx * acy_e + abx_e * acy) - (aby * acx_e + aby_e * acx)
                    + (abx_e * acy_e - aby_e * acx_e);
                // When p and q nearly cancel, p - q is exact (Sterbenz) and
                // the sign comes from the tail of rounding errors, which is
                // itself computed almost exactly.
                main + tail
            }

            /// Knuth's TwoSum applied to `a - b`: `hi + lo == a - b` exactly.
            const fn two_diff(a: $R, b: $R) -> ($R, $R) {
                let hi = a - b;
                let bv = a - hi;
                let av = hi + bv;
                let lo = (a - av) + (bv - b);
                (hi, lo)
            }

            /// Dekker's TwoProduct: `hi + lo == a * b` exactly (no overflow:
            /// coordinates are bounded by `MAX_COORDINATE`).
            const fn two_product(a: $R, b: $R) -> ($R, $R) {
                let hi = a * b;
                let (ah, al) = split(a);
                let (bh, bl) = split(b);
                let lo = ((ah * bh - hi) + ah * bl + al * bh) + al * bl;
                (hi, lo)
            }

            /// Veltkamp's split: `a == hi + lo` with both halves of at most
            /// half the significand's bits, so their products are exact. No
            /// fma: on a Cortex-M4F an f32 fma is software (through soft f64).
            const fn split(a: $R) -> ($R, $R) {
                let c = <$R as Real>::SPLITTER * a;
                let hi = c - (c - a);
                (hi, a - hi)
            }
        }
    };
}

polygon_frame!(single, f32);
polygon_frame!(double, f64);

/// A polygon's framing, as generic code ([`Polygon::new`](super::Polygon::new))
/// reaches the per-type `const fn`s above: one definition of it, at compile
/// time and at run time.
pub(crate) enum Framing {}

impl PerType for Framing {
    type Input<'a, R: Real> = &'a mut [V2<R>];
    type Output<R: Real> = Result<Frame<R>, Error>;
    #[inline]
    fn f32(vertices: &mut [V2<f32>]) -> Result<Frame<f32>, Error> {
        single::frame(vertices)
    }
    #[inline]
    fn f64(vertices: &mut [V2<f64>]) -> Result<Frame<f64>, Error> {
        double::frame(vertices)
    }
}
