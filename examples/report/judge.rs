//! Accuracy bookkeeping, shared by gjk2d and parry: each answer judged against the
//! exact one.

use crate::cases::{PairCase, RayTruth, RayVerdict};
use gjk2d::Status;
use gjk2d_oracle as oracle;

#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Query {
    Intersect,
    Distance,
    Penetration,
    Ray,
    Cast,
    Manifold,
}

impl Query {
    pub(crate) fn name(self) -> &'static str {
        match self {
            Query::Intersect => "intersect",
            Query::Distance => "distance",
            Query::Penetration => "penetration",
            Query::Ray => "ray",
            Query::Cast => "cast",
            Query::Manifold => "manifold",
        }
    }
}

/// What a query returned, in f64.
pub(crate) enum Out {
    Verdict(bool),
    /// Distance (apart) or depth (overlapping) with its normal; None: the other verdict.
    Value(Option<(f64, [f64; 2])>),
    Ray(RayVerdict, f64, [f64; 2]),
    /// A manifold: its normal and each point on A, on B, and their separation.
    Manifold([f64; 2], Vec<([f64; 2], [f64; 2], f64)>),
}

#[derive(Clone, Default, Debug)]
pub(crate) struct Acc {
    pub(crate) cases: usize,
    judged: usize,
    pub(crate) wrong: usize,
    errs: Vec<f64>,
    nerrs: Vec<f64>,
    pub(crate) limit: usize,
    pub(crate) capacity: usize,
    pub(crate) nonfinite: usize,
    pub(crate) iters: u64,
    pub(crate) answered: usize,
}

impl Acc {
    fn count_status(&mut self, (s, it): (Status, Option<u32>)) {
        if let Some(it) = it {
            self.iters += it as u64;
            self.answered += 1;
        }
        self.limit += (s == Status::IterationLimit) as usize;
        self.capacity += (s == Status::CapacityLimit) as usize;
    }
    pub(crate) fn max_err(&self) -> f64 {
        self.errs.iter().copied().fold(0.0, f64::max)
    }
    pub(crate) fn med_err(&self) -> f64 {
        median(self.errs.clone())
    }
    pub(crate) fn max_nerr(&self) -> f64 {
        self.nerrs.iter().copied().fold(0.0, f64::max)
    }
}

pub(crate) fn median(mut v: Vec<f64>) -> f64 {
    if v.is_empty() {
        return 0.0;
    }
    v.sort_by(|a, b| a.partial_cmp(b).unwrap());
    v[v.len() / 2]
}

fn angle(a: [f64; 2], b: [f64; 2]) -> f64 {
    let cross = a[0] * b[1] - a[1] * b[0];
    let dot = a[0] * b[0] + a[1] * b[1];
    cross.abs().atan2(dot)
}

fn finite2(v: [f64; 2]) -> bool {
    v[0].is_finite() && v[1].is_finite()
}

pub(crate) fn judge_pair(acc: &mut Acc, q: Query, c: &PairCase, eps: f64, out: Out, status: (Status, Option<u32>)) {
    acc.cases += 1;
    acc.count_status(status);
    let tol = 8.0 * eps * c.l;
    let judged = c.truth.signed.abs() > tol;
    acc.judged += judged as usize;
    let overlap = c.truth.signed <= 0.0;
    match out {
        Out::Verdict(v) => acc.wrong += (judged && v != overlap) as usize,
        Out::Value(v) => {
            let says = v.is_some();
            let want = if q == Query::Distance { !overlap } else { overlap };
            acc.wrong += (judged && says != want) as usize;
            if let Some((x, n)) = v {
                if !x.is_finite() || !finite2(n) {
                    acc.nonfinite += 1;
                    return;
                }
                let truth = if q == Query::Distance { c.truth.distance } else { c.truth.depth };
                if says == want {
                    acc.errs.push((x - truth).abs() / c.l);
                    if judged && c.truth.normal_unique {
                        acc.nerrs.push(angle(n, c.truth.normal));
                    }
                }
            }
        }
        Out::Ray(..) | Out::Manifold(..) => unreachable!(),
    }
}

/// A contact manifold (speculative margin zero) against the exact pair:
/// points only where the shapes overlap or touch; its error is the farthest
/// a point lies off its shape's boundary (exact distances of the points as
/// given), or the least separation off the exact signed distance, over
/// `L`; the normal against the exact one.
pub(crate) fn judge_manifold(acc: &mut Acc, c: &PairCase, eps: f64, out: Out, status: (Status, Option<u32>)) {
    let Out::Manifold(n, points) = out else { unreachable!() };
    acc.cases += 1;
    acc.count_status(status);
    let judged = c.truth.signed.abs() > 8.0 * eps * c.l;
    acc.judged += judged as usize;
    let overlap = c.truth.signed <= 0.0;
    let says = !points.is_empty();
    acc.wrong += (judged && says != overlap) as usize;
    if !says {
        return;
    }
    if !finite2(n) || points.iter().any(|(p, q, s)| !finite2(*p) || !finite2(*q) || !s.is_finite()) {
        acc.nonfinite += 1;
        return;
    }
    if !overlap {
        return;
    }
    let (ea, eb) = (oracle::ExactShape::from(&c.a.oracle()), oracle::ExactShape::from(&c.b.oracle()));
    let off = |p: [f64; 2], shape: &oracle::ExactShape| {
        oracle::pair(&oracle::ExactShape::point(p), shape).signed_distance.abs()
    };
    let on_boundaries = points.iter().map(|(p, q, _)| off(*p, &ea).max(off(*q, &eb))).fold(0.0, f64::max);
    let least = points.iter().map(|p| p.2).fold(f64::INFINITY, f64::min);
    acc.errs.push(on_boundaries.max((least - c.truth.signed).abs()) / c.l);
    if judged && c.truth.normal_unique {
        acc.nerrs.push(angle(n, c.truth.normal));
    }
}

/// A ray's answer (or a cast's, as the ray against the pair's difference:
/// `Inside` for overlapping at the start) against the exact one; errors
/// over the case's scale `l`.
pub(crate) fn judge_ray(acc: &mut Acc, truth: &RayTruth, l: f64, eps: f64, out: Out, status: (Status, Option<u32>)) {
    let Out::Ray(v, t, n) = out else { unreachable!() };
    acc.cases += 1;
    acc.count_status(status);
    let judged = truth.margin > 8.0 * eps * l;
    acc.judged += judged as usize;
    acc.wrong += (judged && v != truth.verdict) as usize;
    if v == RayVerdict::Hit {
        if !t.is_finite() || !finite2(n) {
            acc.nonfinite += 1;
            return;
        }
        if truth.verdict == RayVerdict::Hit {
            acc.errs.push((t - truth.t).abs() / l);
            if judged && truth.normal_unique {
                acc.nerrs.push(angle(n, truth.normal));
            }
        }
    }
}
