//! Exact pair query: distance, penetration depth, normal and closest points.

use crate::core::{core_relation, CoreRel, Frame};
use crate::exact::{q_to_f64, round_iv, sqrt_bounds, unit_int, unit_q, Q};
use crate::shape::{ExactShape, Pt};
use num_traits::Zero;
use std::cmp::Ordering;

/// Exact answer for a pair of shapes, every field rounded once from the exact value.
#[derive(Clone, Debug)]
pub struct PairAnswer {
    /// Minimum distance between the shapes; 0 if they overlap or touch.
    pub distance: f64,
    /// Penetration depth: length of the shortest translation of B separating it from A
    /// (leaving them touching); 0 if apart or touching.
    pub depth: f64,
    /// `distance` if apart, `-depth` if overlapping, 0 if touching: the margin by which
    /// the intersection verdict is decided.
    pub signed_distance: f64,
    /// Exact verdict: the exact distance is 0.
    pub touching_or_overlapping: bool,
    /// Unit vector from A towards B. Apart: direction closest point on A -> closest
    /// point on B. Overlapping: the direction in which B must move by `depth`. Touching:
    /// the contact direction when a single one exists (edge contact, or rounded shapes
    /// whose cores are apart), else `[0, 0]`. Also `[0, 0]` for two coincident point
    /// cores (concentric disks): every direction is then equally valid.
    pub normal: Pt,
    /// False when several directions achieve the same depth (ties), and always false
    /// when the shapes exactly touch.
    pub normal_unique: bool,
    /// Closest point on A (apart only; `[0, 0]` when touching or overlapping). For ties
    /// any closest pair is returned.
    pub point_a: Pt,
    /// Closest point on B (apart only; `[0, 0]` when touching or overlapping).
    pub point_b: Pt,
}

/// `c + sign * r * w / sqrt(ww)`, correctly rounded per component.
fn offset_point(c: &[Q; 2], r: &Q, w: &[Q; 2], ww: &Q, sign: i32) -> Pt {
    if r.is_zero() {
        return [q_to_f64(&c[0]), q_to_f64(&c[1])];
    }
    let comp = |k: usize| {
        let rw = if sign > 0 { r * &w[k] } else { -(r * &w[k]) };
        round_iv(|bits| {
            let (sl, sh) = sqrt_bounds(ww, bits);
            let x = &rw / &sh;
            let y = &rw / &sl;
            let (lo, hi) = if x <= y { (x, y) } else { (y, x) };
            (&c[k] + lo, &c[k] + hi)
        })
    };
    [comp(0), comp(1)]
}

/// Distance, depth, normal and closest points of two exact shapes.
///
/// The cores (point / segment / polygon) are related exactly (see `core_relation`);
/// radii are then added: with `R = rA + rB` and core distance `dc`, the shapes are apart
/// iff `dc^2 > R^2` (distance `dc - R`), touch iff `dc^2 == R^2`, and otherwise overlap
/// with depth `R - dc` (cores apart, normal = core separation direction) or
/// `core depth + R` (cores touching/overlapping, normal = core penetration normal).
pub fn pair(a: &ExactShape, b: &ExactShape) -> PairAnswer {
    let fr = Frame::new(a, b);
    let ra = a.radius();
    let rb = b.radius();
    let r: Q = ra + rb;
    let touching = |normal: Pt| PairAnswer {
        distance: 0.0,
        depth: 0.0,
        signed_distance: 0.0,
        touching_or_overlapping: true,
        normal,
        normal_unique: false,
        point_a: [0.0, 0.0],
        point_b: [0.0, 0.0],
    };
    let overlapping = |depth: f64, normal: Pt, unique: bool| PairAnswer {
        distance: 0.0,
        depth,
        signed_distance: -depth,
        touching_or_overlapping: true,
        normal,
        normal_unique: unique,
        point_a: [0.0, 0.0],
        point_b: [0.0, 0.0],
    };
    match core_relation(&fr) {
        CoreRel::Apart { d2, ca, cb } => {
            let w = [&cb[0] - &ca[0], &cb[1] - &ca[1]];
            let normal = unit_q(&w, &d2);
            let r2 = &r * &r;
            match d2.cmp(&r2) {
                Ordering::Greater => {
                    let distance = round_iv(|bits| {
                        let (lo, hi) = sqrt_bounds(&d2, bits);
                        (lo - &r, hi - &r)
                    });
                    PairAnswer {
                        distance,
                        depth: 0.0,
                        signed_distance: distance,
                        touching_or_overlapping: false,
                        normal,
                        normal_unique: true,
                        point_a: offset_point(&ca, ra, &w, &d2, 1),
                        point_b: offset_point(&cb, rb, &w, &d2, -1),
                    }
                }
                Ordering::Equal => touching(normal),
                Ordering::Less => {
                    let depth = round_iv(|bits| {
                        let (lo, hi) = sqrt_bounds(&d2, bits);
                        (&r - hi, &r - lo)
                    });
                    overlapping(depth, normal, true)
                }
            }
        }
        CoreRel::Touching { n, unique } => {
            let normal = match (&n, unique) {
                (Some(v), true) => unit_int(v),
                _ => [0.0, 0.0],
            };
            if r.is_zero() {
                touching(normal)
            } else {
                // Depth is exactly R; the normal is one of the zero-overlap directions.
                let normal = match &n {
                    Some(v) => unit_int(v),
                    None => [0.0, 0.0],
                };
                overlapping(q_to_f64(&r), normal, unique)
            }
        }
        CoreRel::Overlap { depth2, n, unique } => {
            let depth = round_iv(|bits| {
                let (lo, hi) = sqrt_bounds(&depth2, bits);
                (lo + &r, hi + &r)
            });
            overlapping(depth, unit_int(&n), unique)
        }
    }
}
