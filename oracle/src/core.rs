//! Exact relation between two cores (point / segment / strictly convex polygon):
//! separation verdict, squared distance with closest points, or penetration depth.
//!
//! All exact work happens on integers: both shapes are put over a common denominator
//! `l`, so coordinates, edge normals, dot products and squared distances are big
//! integers. Floats are used only as a *prefilter* choosing which candidates to
//! evaluate exactly; they never decide an answer (see [`Frame`] for the safety argument).

use crate::exact::{big_to_f64_shifted, Q};
use crate::shape::ExactShape;
use num_bigint::BigInt;
use num_traits::{One, Signed, Zero};
use std::cmp::Ordering;

type V = [BigInt; 2];

/// Both cores over a common denominator, plus float images for prefiltering.
///
/// Prefilter safety: the float image of each coordinate is the correctly rounded value of
/// `X * 2^-shift`, where `shift` makes every |coordinate| < 1, so each float coordinate is
/// within 2^-53 (+ 2^-1074) of the exact scaled one. Float normals are correctly rounded
/// images of the exact integer normals (relative error 2^-53 per component). Hence a
/// float dot product `p·n` is within about 5e-16 * |n|_1 of the exact scaled value, and a
/// float point-segment distance within about 1e-14 (each distance is 1-Lipschitz in each
/// point and the formula has a handful of roundings on values <= 4). The prefilters keep
/// every candidate whose float value lies within `2 * bound` of the float optimum, with
/// bounds taken 10^4 times larger than these estimates (1e-11 |n|_1 for dots, 1e-10 for
/// distances, 4e-11 for depths). The exact optimum's float value is at most `bound`
/// above its exact value, which is at most the exact value of the float optimum, which
/// is at most the float optimum plus `bound`; so the exact optimum is always kept. Directions whose float image could
/// underflow (|n|_1 < 1e-250 after scaling) or overflow are always evaluated exactly.
pub(crate) struct Frame {
    pub a: Vec<V>,
    pub b: Vec<V>,
    pub fa: Vec<[f64; 2]>,
    pub fb: Vec<[f64; 2]>,
    pub shift: u64,
    pub l: BigInt,
}

impl Frame {
    pub fn new(sa: &ExactShape, sb: &ExactShape) -> Frame {
        let l = crate::exact::lcm_fast(&sa.den, &sb.den);
        let scale = |pts: &[V], k: BigInt| -> Vec<V> {
            if k.is_one() {
                pts.to_vec()
            } else {
                pts.iter().map(|p| [&p[0] * &k, &p[1] * &k]).collect()
            }
        };
        let a = scale(&sa.ints, &l / &sa.den);
        let b = scale(&sb.ints, &l / &sb.den);
        let shift = a.iter().chain(b.iter()).flat_map(|p| p.iter()).map(|c| c.bits()).max().unwrap_or(0);
        let f = |pts: &[V]| -> Vec<[f64; 2]> {
            pts.iter().map(|p| [big_to_f64_shifted(&p[0], shift), big_to_f64_shifted(&p[1], shift)]).collect()
        };
        let fa = f(&a);
        let fb = f(&b);
        Frame { a, b, fa, fb, shift, l }
    }
}

/// Relation between two cores, in real (not frame) units.
pub(crate) enum CoreRel {
    /// Disjoint: squared distance and a pair of closest points (core A, core B).
    Apart { d2: Q, ca: [Q; 2], cb: [Q; 2] },
    /// Touching (distance exactly 0, depth 0). `n`: a direction achieving zero overlap
    /// (from A to B), `unique` when every such direction is the same.
    Touching { n: Option<V>, unique: bool },
    /// Overlapping: squared depth, direction in which B moves (from A to B), uniqueness.
    Overlap { depth2: Q, n: V, unique: bool },
}

fn dot(p: &V, n: &V) -> BigInt {
    &p[0] * &n[0] + &p[1] * &n[1]
}

fn fdot(p: &[f64; 2], n: &[f64; 2]) -> f64 {
    p[0] * n[0] + p[1] * n[1]
}

fn sub(p: &V, q: &V) -> V {
    [&p[0] - &q[0], &p[1] - &q[1]]
}

fn same_direction(u: &V, v: &V) -> bool {
    (&u[0] * &v[1] - &u[1] * &v[0]).is_zero() && dot(u, v).is_positive()
}

/// A candidate separating direction n (pointing from A towards B):
/// overlap(n) = max_{a in A} a·n - min_{b in B} b·n.
struct Dir {
    n: V,
    nf: [f64; 2],
    /// Vertex of A known to maximise a·n (n is the outward normal of A's edge there).
    ka: Option<usize>,
    /// Vertex of B known to minimise b·n (-n is the outward normal of B's edge there).
    kb: Option<usize>,
}

fn edges(k: usize) -> usize {
    match k {
        1 => 0,
        2 => 1,
        n => n,
    }
}

/// Candidate directions: the facet normals of the Minkowski difference B - A, i.e. A's
/// outward edge normals and B's inward ones. A segment core contributes both normals
/// and both axis directions (its normal cone at an endpoint contains the axis); this
/// makes the separating-axis test complete when B - A is degenerate (collinear
/// segments, point on a segment's line). Extra directions never lower the depth: for
/// the origin inside a convex D, h_D(u)/|u| >= distance to the boundary for every u.
fn directions(fr: &Frame) -> Vec<Dir> {
    let mut out = Vec::new();
    let mk = |n: V, ka, kb, shift| Dir {
        nf: [big_to_f64_shifted(&n[0], shift), big_to_f64_shifted(&n[1], shift)],
        n,
        ka,
        kb,
    };
    for (pts, is_a) in [(&fr.a, true), (&fr.b, false)] {
        let k = pts.len();
        if k == 2 {
            let e = sub(&pts[1], &pts[0]);
            let perp = [e[1].clone(), -&e[0]];
            for n in [perp.clone(), [-&perp[0], -&perp[1]], e.clone(), [-&e[0], -&e[1]]] {
                out.push(mk(n, None, None, fr.shift));
            }
        } else if k >= 3 {
            for i in 0..k {
                let e = sub(&pts[(i + 1) % k], &pts[i]);
                if is_a {
                    out.push(mk([e[1].clone(), -&e[0]], Some(i), None, fr.shift));
                } else {
                    out.push(mk([-&e[1], e[0].clone()], None, Some(i), fr.shift));
                }
            }
        }
    }
    out
}

/// Exact extreme of p·n over `pts` (max if `want_max`), evaluating exactly only the
/// vertices whose float value is within `2*err` of the float extreme.
fn exact_extreme(pts: &[V], fp: &[[f64; 2]], d: &Dir, err: f64, exact_all: bool, want_max: bool) -> BigInt {
    let vals: Vec<f64> = fp.iter().map(|p| fdot(p, &d.nf)).collect();
    let best = if want_max {
        vals.iter().cloned().fold(f64::NEG_INFINITY, f64::max)
    } else {
        vals.iter().cloned().fold(f64::INFINITY, f64::min)
    };
    let mut res: Option<BigInt> = None;
    for (i, &v) in vals.iter().enumerate() {
        let keep = exact_all || if want_max { v >= best - 2.0 * err } else { v <= best + 2.0 * err };
        if !keep {
            continue;
        }
        let x = dot(&pts[i], &d.n);
        res = Some(match res {
            None => x,
            Some(r) => {
                if (want_max && x > r) || (!want_max && x < r) {
                    x
                } else {
                    r
                }
            }
        });
    }
    res.expect("empty core")
}

struct FloatDir {
    fo: f64,
    err: f64,
    exact_only: bool,
}

fn float_overlap(fr: &Frame, d: &Dir) -> FloatDir {
    let maxa = match d.ka {
        Some(k) => fdot(&fr.fa[k], &d.nf),
        None => fr.fa.iter().map(|p| fdot(p, &d.nf)).fold(f64::NEG_INFINITY, f64::max),
    };
    let minb = match d.kb {
        Some(k) => fdot(&fr.fb[k], &d.nf),
        None => fr.fb.iter().map(|p| fdot(p, &d.nf)).fold(f64::INFINITY, f64::min),
    };
    let n1 = d.nf[0].abs() + d.nf[1].abs();
    let fo = maxa - minb;
    let exact_only = !(n1.is_finite() && n1 >= 1e-250 && fo.is_finite());
    FloatDir { fo, err: 1e-11 * n1, exact_only }
}

fn exact_overlap(fr: &Frame, d: &Dir, f: &FloatDir) -> BigInt {
    let maxa = match d.ka {
        Some(k) => dot(&fr.a[k], &d.n),
        None => exact_extreme(&fr.a, &fr.fa, d, f.err, f.exact_only, true),
    };
    let minb = match d.kb {
        Some(k) => dot(&fr.b[k], &d.n),
        None => exact_extreme(&fr.b, &fr.fb, d, f.err, f.exact_only, false),
    };
    maxa - minb
}

/// Exact relation between the cores of `fr`.
pub(crate) fn core_relation(fr: &Frame) -> CoreRel {
    if fr.a.len() == 1 && fr.b.len() == 1 {
        if fr.a[0] == fr.b[0] {
            return CoreRel::Touching { n: None, unique: false };
        }
        return apart(fr);
    }
    let dirs = directions(fr);
    let fl: Vec<FloatDir> = dirs.iter().map(|d| float_overlap(fr, d)).collect();
    // A direction whose float overlap is clearly negative separates the cores.
    if fl.iter().any(|f| !f.exact_only && f.fo < -f.err) {
        return apart(fr);
    }
    let mut exact: Vec<Option<BigInt>> = vec![None; dirs.len()];
    let mut zeros: Vec<usize> = Vec::new();
    for i in 0..dirs.len() {
        if fl[i].exact_only || fl[i].fo <= fl[i].err {
            let o = exact_overlap(fr, &dirs[i], &fl[i]);
            if o.is_negative() {
                return apart(fr);
            }
            if o.is_zero() {
                zeros.push(i);
            }
            exact[i] = Some(o);
        }
    }
    if !zeros.is_empty() {
        let first = &dirs[zeros[0]].n;
        let unique = zeros.iter().all(|&i| same_direction(first, &dirs[i].n));
        return CoreRel::Touching { n: Some(first.clone()), unique };
    }
    // Penetration depth: min over directions of overlap(n)/|n|.
    let fv: Vec<Option<f64>> = dirs
        .iter()
        .zip(&fl)
        .map(|(d, f)| {
            if f.exact_only {
                None
            } else {
                let v = f.fo / d.nf[0].hypot(d.nf[1]);
                v.is_finite().then_some(v)
            }
        })
        .collect();
    let vmin = fv.iter().flatten().cloned().fold(f64::INFINITY, f64::min);
    let mut best: Vec<usize> = Vec::new();
    let mut best_o = BigInt::zero();
    let mut best_nn = BigInt::one();
    for i in 0..dirs.len() {
        let keep = match fv[i] {
            None => true,
            Some(v) => v <= vmin + 4e-11 + 1e-12 * vmin.abs(),
        };
        if !keep {
            continue;
        }
        let o = match exact[i].take() {
            Some(o) => o,
            None => exact_overlap(fr, &dirs[i], &fl[i]),
        };
        let nn = dot(&dirs[i].n, &dirs[i].n);
        if best.is_empty() {
            best.push(i);
            best_o = o;
            best_nn = nn;
            continue;
        }
        // o/sqrt(nn) vs best_o/sqrt(best_nn), both non-negative: compare squares.
        let lhs = &o * &o * &best_nn;
        let rhs = &best_o * &best_o * &nn;
        match lhs.cmp(&rhs) {
            Ordering::Less => {
                best.clear();
                best.push(i);
                best_o = o;
                best_nn = nn;
            }
            Ordering::Equal => best.push(i),
            Ordering::Greater => {}
        }
    }
    let n = dirs[best[0]].n.clone();
    let unique = best.iter().all(|&i| same_direction(&n, &dirs[i].n));
    let l2 = &fr.l * &fr.l;
    CoreRel::Overlap { depth2: Q::new(&best_o * &best_o, best_nn * l2), n, unique }
}

/// Float distance from p to segment [a, b] (prefilter only).
fn fdist_ps(p: &[f64; 2], a: &[f64; 2], b: &[f64; 2]) -> f64 {
    let (ex, ey) = (b[0] - a[0], b[1] - a[1]);
    let (wx, wy) = (p[0] - a[0], p[1] - a[1]);
    let ee = ex * ex + ey * ey;
    let t = if ee > 0.0 { ((wx * ex + wy * ey) / ee).clamp(0.0, 1.0) } else { 0.0 };
    let (dx, dy) = (wx - t * ex, wy - t * ey);
    dx.hypot(dy)
}

/// Exact squared distance from p to segment [a, b] as num/den, and the parameter of the
/// closest point as tn/td.
fn exact_ps(p: &V, a: &V, b: &V) -> (BigInt, BigInt, BigInt, BigInt) {
    let e = sub(b, a);
    let w = sub(p, a);
    let tn = dot(&w, &e);
    let ee = dot(&e, &e);
    if !tn.is_positive() {
        (dot(&w, &w), BigInt::one(), BigInt::zero(), BigInt::one())
    } else if tn >= ee {
        let w2 = sub(p, b);
        (dot(&w2, &w2), BigInt::one(), BigInt::one(), BigInt::one())
    } else {
        let c = &e[0] * &w[1] - &e[1] * &w[0];
        (&c * &c, ee.clone(), tn, ee)
    }
}

/// Squared distance between disjoint cores: for disjoint convex sets a closest pair
/// always involves a vertex of one set, so it is the minimum over vertex-of-one vs
/// edge-of-other (vertex vs vertex for two points).
fn apart(fr: &Frame) -> CoreRel {
    let to_real = |p: &V| [Q::new(p[0].clone(), fr.l.clone()), Q::new(p[1].clone(), fr.l.clone())];
    let l2 = &fr.l * &fr.l;
    if fr.a.len() == 1 && fr.b.len() == 1 {
        let w = sub(&fr.b[0], &fr.a[0]);
        return CoreRel::Apart { d2: Q::new(dot(&w, &w), l2), ca: to_real(&fr.a[0]), cb: to_real(&fr.b[0]) };
    }
    // (vertex owner is A?, vertex index, edge index in the other core, float distance)
    let mut cands: Vec<(bool, usize, usize, f64)> = Vec::new();
    for (vert_a, fp, ofp) in [(true, &fr.fa, &fr.fb), (false, &fr.fb, &fr.fa)] {
        let k = ofp.len();
        for j in 0..edges(k) {
            let (e0, e1) = (&ofp[j], &ofp[(j + 1) % k]);
            for (i, p) in fp.iter().enumerate() {
                cands.push((vert_a, i, j, fdist_ps(p, e0, e1)));
            }
        }
    }
    let finite = cands.iter().all(|c| c.3.is_finite());
    let dmin = cands.iter().map(|c| c.3).fold(f64::INFINITY, f64::min);
    let mut best: Option<(BigInt, BigInt, bool, usize, usize, BigInt, BigInt)> = None;
    for &(vert_a, i, j, fd) in &cands {
        if finite && fd > dmin + 1e-10 {
            continue;
        }
        let (pts, opts) = if vert_a { (&fr.a, &fr.b) } else { (&fr.b, &fr.a) };
        let k = opts.len();
        let (num, den, tn, td) = exact_ps(&pts[i], &opts[j], &opts[(j + 1) % k]);
        let better = match &best {
            None => true,
            Some(b) => &num * &b.1 < &b.0 * &den,
        };
        if better {
            best = Some((num, den, vert_a, i, j, tn, td));
        }
    }
    let (num, den, vert_a, i, j, tn, td) = best.expect("no distance candidates");
    let (pts, opts) = if vert_a { (&fr.a, &fr.b) } else { (&fr.b, &fr.a) };
    let k = opts.len();
    let (e0, e1) = (&opts[j], &opts[(j + 1) % k]);
    let t = Q::new(tn, td);
    let lq = Q::from_integer(fr.l.clone());
    let proj = [
        (Q::from_integer(e0[0].clone()) + &t * Q::from_integer(&e1[0] - &e0[0])) / &lq,
        (Q::from_integer(e0[1].clone()) + &t * Q::from_integer(&e1[1] - &e0[1])) / &lq,
    ];
    let vtx = to_real(&pts[i]);
    let (ca, cb) = if vert_a { (vtx, proj) } else { (proj, vtx) };
    CoreRel::Apart { d2: Q::new(num, den * l2), ca, cb }
}

/// Exact squared distance between the cores of two shapes (0 if they touch or overlap).
pub(crate) fn core_distance2(a: &ExactShape, b: &ExactShape) -> Q {
    let fr = Frame::new(a, b);
    match core_relation(&fr) {
        CoreRel::Apart { d2, .. } => d2,
        _ => Q::zero(),
    }
}
