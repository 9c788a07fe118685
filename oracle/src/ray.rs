//! Exact ray cast.

use crate::core::core_distance2;
use crate::exact::{q_from_f64, round_iv, sqrt_bounds, unit_q, QSqrt, Q};
use crate::pair::pair;
use crate::shape::{ExactShape, Pt};
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;

/// Verdict of a ray cast.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RayStatus {
    /// The ray reaches the shape's boundary within its allowed length.
    Hit,
    /// It does not.
    Miss,
    /// The origin is inside the shape or on its boundary.
    Inside,
}

/// Exact ray-cast answer.
#[derive(Clone, Debug)]
pub struct RayAnswer {
    pub status: RayStatus,
    /// Hit: distance `|hit - o|` in length units. Inside: 0. Miss: +inf.
    pub t: f64,
    /// Hit: outward unit normal at the hit point. Inside/Miss: `[0, 0]`.
    ///
    /// Vertex hits of a plain polygon: of the two faces meeting there, the one the ray
    /// meets most head-on (largest `-n̂·d̂`), and on an exact tie the one with the
    /// smaller index in the core's counter-clockwise vertex order. Plain segments: the
    /// side facing the ray; a ray running along the segment (or hitting a plain point)
    /// gets `-d̂`. Rounded shapes have a unique normal everywhere.
    pub normal: Pt,
    /// False when the normal is not unique at the hit point (polygon vertex, segment
    /// endpoint, ray along a segment, point core, or not a hit).
    pub normal_unique: bool,
    /// How far the verdict is from flipping, in length units (always >= 0):
    /// - Inside: distance from the origin to the shape's boundary (0 if on it);
    /// - Hit: `max_len - t` when bounded, `+inf` when unbounded;
    /// - Miss: distance between the shape and the ray's segment `[o, o + max_len d̂]`
    ///   (the whole ray when unbounded). A miss that the unbounded ray would hit beyond
    ///   `max_len` therefore gets the distance from the far end region to the shape.
    pub margin: f64,
}

fn dot(p: &[Q; 2], q: &[Q; 2]) -> Q {
    &p[0] * &q[0] + &p[1] * &q[1]
}

fn sub(p: &[Q; 2], q: &[Q; 2]) -> [Q; 2] {
    [&p[0] - &q[0], &p[1] - &q[1]]
}

fn cross(p: &[Q; 2], q: &[Q; 2]) -> Q {
    &p[0] * &q[1] - &p[1] * &q[0]
}

/// How the normal at the hit is obtained.
enum NormalKind {
    /// Outward (unnormalised) face normal.
    Face([Q; 2]),
    /// Disk of the given center (radius = shape radius): normal = (hit - c) / r.
    Disk([Q; 2]),
}

struct HitInfo {
    /// Hit parameter in units of `d`.
    t: QSqrt,
    normal: NormalKind,
    unique: bool,
}

/// First hit of the unbounded ray on a plain (radius 0) core, in exact rationals.
fn hit_plain(o: &[Q; 2], d: &[Q; 2], v: &[[Q; 2]]) -> Option<HitInfo> {
    let dd = dot(d, d);
    let minus_d = [-&d[0], -&d[1]];
    match v.len() {
        1 => {
            let w = sub(&v[0], o);
            if cross(d, &w).is_zero() && dot(&w, d).is_positive() {
                Some(HitInfo { t: QSqrt::rational(dot(&w, d) / &dd), normal: NormalKind::Face(minus_d), unique: false })
            } else {
                None
            }
        }
        2 => {
            let e = sub(&v[1], &v[0]);
            let w = sub(&v[0], o);
            let den = cross(d, &e);
            if den.is_zero() {
                if !cross(d, &w).is_zero() {
                    return None;
                }
                let ta = dot(&w, d) / &dd;
                let tb = dot(&sub(&v[1], o), d) / &dd;
                let t = if ta < tb { ta } else { tb };
                if !t.is_positive() {
                    return None;
                }
                return Some(HitInfo { t: QSqrt::rational(t), normal: NormalKind::Face(minus_d), unique: false });
            }
            let t = cross(&w, &e) / &den;
            let u = cross(&w, d) / &den;
            if t.is_negative() || u.is_negative() || u > Q::one() {
                return None;
            }
            let mut n = [e[1].clone(), -&e[0]];
            if dot(&n, d).is_positive() {
                n = [-&n[0], -&n[1]];
            }
            let unique = u.is_positive() && u < Q::one();
            Some(HitInfo { t: QSqrt::rational(t), normal: NormalKind::Face(n), unique })
        }
        k => {
            // Cyrus-Beck clipping against the edges' half-planes (origin is outside).
            let mut t_enter = Q::zero();
            let mut enter: Vec<usize> = Vec::new();
            let mut t_exit: Option<Q> = None;
            let mut normals = Vec::with_capacity(k);
            for i in 0..k {
                let e = sub(&v[(i + 1) % k], &v[i]);
                let n = [e[1].clone(), -&e[0]];
                let num = dot(&n, &sub(&v[i], o));
                let den = dot(&n, d);
                normals.push(n);
                if den.is_zero() {
                    if num.is_negative() {
                        return None;
                    }
                    continue;
                }
                let t = num / &den;
                if den.is_negative() {
                    match t.cmp(&t_enter) {
                        Ordering::Greater => {
                            t_enter = t;
                            enter.clear();
                            enter.push(i);
                        }
                        Ordering::Equal if !enter.is_empty() => enter.push(i),
                        _ => {}
                    }
                } else if t_exit.as_ref().is_none_or(|x| &t < x) {
                    t_exit = Some(t);
                }
            }
            if enter.is_empty() || t_exit.as_ref().is_some_and(|x| &t_enter > x) {
                return None;
            }
            // Tie-break at vertices: most head-on face, then lowest index.
            let mut best = enter[0];
            let score = |i: usize| {
                let n = &normals[i];
                let nd = dot(n, d);
                &nd * &nd / dot(n, n)
            };
            for &i in &enter[1..] {
                if score(i) > score(best) {
                    best = i;
                }
            }
            Some(HitInfo {
                t: QSqrt::rational(t_enter),
                normal: NormalKind::Face(normals[best].clone()),
                unique: enter.len() == 1,
            })
        }
    }
}

/// First hit of the unbounded ray on a rounded core (radius r > 0).
///
/// The shape is the union of the disks at the core vertices and of the rectangles
/// swept outwards from each edge (plus the core itself, which is interior). The first
/// entry into a union is the least first entry into its parts; entering a rectangle
/// through one of its short sides is preceded by entering the adjacent disk, so the
/// candidates are: each disk's smaller root and each facing edge's offset line (when the
/// crossing projects onto the edge). Validity is decided exactly (signs of
/// `a + b sqrt(g)`); the least candidate is chosen by intervals refined until it is
/// separated from the others (ties have the same point, hence the same normal).
fn hit_round(o: &[Q; 2], d: &[Q; 2], v: &[[Q; 2]], r: &Q) -> Option<HitInfo> {
    let dd = dot(d, d);
    let r2 = r * r;
    let mut cands: Vec<(QSqrt, NormalKind)> = Vec::new();
    for c in v {
        let w = sub(o, c);
        let bq = dot(d, &w);
        let cq = dot(&w, &w) - &r2;
        let disc = &bq * &bq - &dd * &cq;
        if disc.is_negative() || !bq.is_negative() {
            continue;
        }
        cands.push((QSqrt { a: -&bq / &dd, b: -Q::one() / &dd, g: disc }, NormalKind::Disk(c.clone())));
    }
    let k = v.len();
    let edge_list: Vec<(usize, usize)> = match k {
        1 => vec![],
        2 => vec![(0, 1)],
        _ => (0..k).map(|i| (i, (i + 1) % k)).collect(),
    };
    for (i, j) in edge_list {
        let e = sub(&v[j], &v[i]);
        let mut n = [e[1].clone(), -&e[0]];
        let mut nd = dot(&n, d);
        if k == 2 && nd.is_positive() {
            n = [-&n[0], -&n[1]];
            nd = -nd;
        }
        if !nd.is_negative() {
            continue;
        }
        // n·(o + t d - v_i) = r |n|  =>  t = (r sqrt(nn) - n·(o - v_i)) / (n·d)
        let w = sub(o, &v[i]);
        let nn = dot(&n, &n);
        let t = QSqrt { a: -dot(&n, &w) / &nd, b: r / &nd, g: nn };
        if t.sign() < 0 {
            continue;
        }
        let u = t.mul_q(&dot(&e, d)).add_q(&dot(&e, &w));
        if u.sign() < 0 || u.add_q(&-dot(&e, &e)).sign() > 0 {
            continue;
        }
        cands.push((t, NormalKind::Face(n)));
    }
    if cands.is_empty() {
        return None;
    }
    let mut bits = 128;
    let best = loop {
        let ivs: Vec<(Q, Q)> = cands.iter().map(|c| c.0.bounds(bits)).collect();
        let mut best = 0;
        for i in 1..ivs.len() {
            if ivs[i].0 < ivs[best].0 {
                best = i;
            }
        }
        let separated = ivs.iter().enumerate().all(|(i, iv)| i == best || iv.0 > ivs[best].1);
        if separated || bits >= 4096 {
            break best;
        }
        bits *= 2;
    };
    let (t, normal) = cands.swap_remove(best);
    Some(HitInfo { t, normal, unique: true })
}

/// Ray cast of origin `o`, direction `d` (any non-zero length; `t` is reported in length
/// units, `|hit - o|`), allowed length `max_len` (`<= 0` or infinite: unbounded) against
/// an exact shape. See [`RayAnswer`] for the meaning of every field.
pub fn ray(o: Pt, d: Pt, max_len: f64, s: &ExactShape) -> RayAnswer {
    assert!(d[0] != 0.0 || d[1] != 0.0, "gjk2d-oracle: zero ray direction");
    let oq = [q_from_f64(o[0]), q_from_f64(o[1])];
    let dq = [q_from_f64(d[0]), q_from_f64(d[1])];
    let bounded = max_len.is_finite() && max_len > 0.0;
    let ml = if bounded { q_from_f64(max_len) } else { Q::zero() };
    let ml2 = &ml * &ml;
    let dd = dot(&dq, &dq);
    let r = s.radius().clone();

    let origin = ExactShape::from_core(vec![oq.clone()], Q::zero());
    let inside = pair(s, &origin);
    if inside.touching_or_overlapping {
        return RayAnswer {
            status: RayStatus::Inside,
            t: 0.0,
            normal: [0.0, 0.0],
            normal_unique: false,
            margin: inside.depth,
        };
    }

    let hit =
        if r.is_zero() { hit_plain(&oq, &dq, s.core_vertices()) } else { hit_round(&oq, &dq, s.core_vertices(), &r) };
    if let Some(h) = hit {
        // Within the allowed length iff t^2 |d|^2 <= max_len^2 (t >= 0).
        let within = !bounded || h.t.square().mul_q(&dd).add_q(&-&ml2).sign() <= 0;
        if within {
            let t_bounds = |bits: u64| {
                let (tl, th) = h.t.bounds(bits);
                let (dl, dh) = sqrt_bounds(&dd, bits);
                (tl * dl, th * dh)
            };
            let t_len = round_iv(t_bounds);
            let margin = if bounded {
                round_iv(|bits| {
                    let (lo, hi) = t_bounds(bits);
                    (&ml - hi, &ml - lo)
                })
            } else {
                f64::INFINITY
            };
            let (normal, unique) = match &h.normal {
                NormalKind::Face(n) => (unit_q(n, &dot(n, n)), h.unique),
                NormalKind::Disk(c) => {
                    let comp = |k: usize| {
                        let p = h.t.mul_q(&dq[k]).add_q(&(&oq[k] - &c[k])).mul_q(&(Q::one() / &r));
                        round_iv(|bits| p.bounds(bits))
                    };
                    ([comp(0), comp(1)], true)
                }
            };
            return RayAnswer { status: RayStatus::Hit, t: t_len, normal, normal_unique: unique, margin };
        }
    }

    // Miss: distance between the ray's segment and the shape. Along the ray the distance
    // to the (convex) core is convex and increasing beyond every core vertex's
    // projection T0, so for the unbounded ray the segment up to T0 + 1 is equivalent.
    let t0 = s
        .core_vertices()
        .iter()
        .map(|v| dot(&sub(v, &oq), &dq) / &dd)
        .fold(Q::zero(), |m, x| if x > m { x } else { m });
    let t_far = t0 + Q::one();
    let seg = |t: &Q| {
        let e = [&oq[0] + &dq[0] * t, &oq[1] + &dq[1] * t];
        ExactShape::from_core(vec![oq.clone(), e], Q::zero())
    };
    let margin = if !bounded || &t_far * &t_far * &dd <= ml2 {
        let d2 = core_distance2(&seg(&t_far), s);
        round_iv(|bits| {
            let (lo, hi) = sqrt_bounds(&d2, bits);
            (lo - &r, hi - &r)
        })
    } else {
        // The segment ends at o + (max_len/|d|) d, an irrational point: bracket it. The
        // distance is non-increasing in the segment's length.
        let s2 = &ml2 / &dd;
        round_iv(|bits| {
            let (sl, sh) = sqrt_bounds(&s2, bits);
            let d2_small = core_distance2(&seg(&sh), s);
            let d2_big = core_distance2(&seg(&sl), s);
            let (lo, _) = sqrt_bounds(&d2_small, bits);
            let (_, hi) = sqrt_bounds(&d2_big, bits);
            (lo - &r, hi - &r)
        })
    };
    RayAnswer { status: RayStatus::Miss, t: f64::INFINITY, normal: [0.0, 0.0], normal_unique: false, margin }
}
