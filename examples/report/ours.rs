//! gjk2d's side: the families' shapes built as gjk2d's, each query answered and
//! judged, and the batch that times it.

use crate::cases::{Cases, Family, RayVerdict, Sh};
use crate::judge::{judge_manifold, judge_pair, judge_ray, Acc, Out, Query};
use crate::timing::{time_batches, Batch, Meas, TIMED_CASES};
use gjk2d::{Capsule, CastOutcome, Circle, Ellipse, Gjk, Motion, Polygon, Ray, RayOutcome, Real, Status, Transform};
use std::hint::black_box;

/// The polygon boxed, as parry's shapes are (`Box<dyn Shape>`): a scene's
/// enum of shapes then costs a circle its own size, not a polygon's.
enum G<R: Real, const N: usize> {
    P(Box<Polygon<R, N>>),
    C(Circle<R>),
    K(Capsule<R>),
    E(Ellipse<R>),
}

pub(crate) struct GS<R: Real, const N: usize> {
    s: G<R, N>,
    t: Transform<R>,
}

pub(crate) fn build_g<R: Real, const N: usize>(sh: &Sh) -> Option<GS<R, N>> {
    let v = |p: &[f64; 2]| R::vector(R::from_f64(p[0]), R::from_f64(p[1]));
    let id = Transform::IDENTITY;
    Some(match sh {
        Sh::Poly(p) => GS { s: G::P(Box::new(Polygon::new(&p.iter().map(v).collect::<Vec<_>>()).ok()?)), t: id },
        Sh::Circle(c, r) => GS { s: G::C(Circle::at(v(c), R::from_f64(*r)).ok()?), t: id },
        Sh::Capsule(a, b, r) => GS { s: G::K(Capsule::new(v(a), v(b), R::from_f64(*r)).ok()?), t: id },
        Sh::Ellipse(c, a, b) => GS {
            s: G::E(Ellipse::new(R::from_f64(2.0 * a), R::from_f64(2.0 * b)).ok()?),
            t: Transform::from_translation(v(c)).ok()?,
        },
    })
}

/// Calls `$body` with `$x`, `$y` bound to the concrete shapes of a pair (static
/// dispatch: every combination the families use is its own monomorphised call).
macro_rules! with_pair {
    ($a:expr, $b:expr, |$x:ident, $y:ident| $body:expr) => {
        match (&$a.s, &$b.s) {
            (G::P(p), G::P(q)) => {
                let ($x, $y) = (&**p, &**q);
                $body
            }
            (G::C($x), G::P(q)) => {
                let $y = &**q;
                $body
            }
            (G::K($x), G::P(q)) => {
                let $y = &**q;
                $body
            }
            (G::C($x), G::C($y)) => $body,
            (G::E($x), G::C($y)) => $body,
            _ => unreachable!("pair kind not used by the report"),
        }
    };
}

macro_rules! with_shape {
    ($a:expr, |$x:ident| $body:expr) => {
        match &$a.s {
            G::P(p) => {
                let $x = &**p;
                $body
            }
            G::C($x) => $body,
            G::K($x) => $body,
            G::E($x) => $body,
        }
    };
}

fn v2<R: Real>(v: R::Vector) -> [f64; 2] {
    let (x, y) = R::components(v);
    [x.to_f64(), y.to_f64()]
}

fn g_pair_query<R: Real, const N: usize>(
    gjk: &Gjk<R>,
    q: Query,
    a: &GS<R, N>,
    b: &GS<R, N>,
) -> (Out, (Status, Option<u32>)) {
    match q {
        Query::Intersect => {
            let d = with_pair!(a, b, |x, y| gjk.intersects(x, &a.t, y, &b.t));
            (Out::Verdict(d.intersecting), (d.status, Some(d.iterations)))
        }
        Query::Distance => {
            let d = with_pair!(a, b, |x, y| gjk.distance(x, &a.t, y, &b.t));
            (
                Out::Value(d.map(|s| (s.distance.to_f64(), v2::<R>(s.normal)))),
                d.map_or((Status::Converged, None), |s| (s.status, Some(s.iterations))),
            )
        }
        Query::Penetration => {
            let p = with_pair!(a, b, |x, y| gjk.penetration(x, &a.t, y, &b.t));
            (
                Out::Value(p.map(|s| (s.depth.to_f64(), v2::<R>(s.normal)))),
                p.map_or((Status::Converged, None), |s| (s.status, Some(s.iterations))),
            )
        }
        Query::Manifold => {
            let m = with_pair!(a, b, |x, y| gjk.manifold(x, &a.t, y, &b.t, R::ZERO)).expect("a valid margin");
            let n = v2::<R>(m.normal);
            let points = m
                .points()
                .iter()
                .map(|c| {
                    let (p, s) = (v2::<R>(c.point), c.separation.to_f64());
                    (p, [p[0] + s * n[0], p[1] + s * n[1]], s)
                })
                .collect();
            (Out::Manifold(n, points), (m.status, Some(m.iterations)))
        }
        Query::Ray | Query::Cast => unreachable!(),
    }
}

fn g_ray<R: Real, const N: usize>(gjk: &Gjk<R>, ray: &Ray<R>, max: R, s: &GS<R, N>) -> (Out, (Status, Option<u32>)) {
    let r = with_shape!(s, |x| gjk.raycast(ray, max, x, &s.t));
    let out = match r.outcome {
        RayOutcome::Hit(h) => Out::Ray(RayVerdict::Hit, h.distance.to_f64(), v2::<R>(h.normal)),
        RayOutcome::Miss => Out::Ray(RayVerdict::Miss, 0.0, [0.0; 2]),
        RayOutcome::Inside => Out::Ray(RayVerdict::Inside, 0.0, [0.0; 2]),
    };
    (out, (r.status, Some(r.iterations)))
}

/// The cast's answer as the ray against the pair's difference: a hit's
/// distance travelled and normal, a miss, or `Inside` for overlapping at
/// the start.
fn g_cast<R: Real, const N: usize>(
    gjk: &Gjk<R>,
    a: &GS<R, N>,
    b: &GS<R, N>,
    m: &Motion<R>,
) -> (Out, (Status, Option<u32>)) {
    let c = with_pair!(a, b, |x, y| gjk.cast(x, &a.t, y, &b.t, m));
    let out = match c.outcome {
        CastOutcome::Hit(h) => Out::Ray(RayVerdict::Hit, h.distance.to_f64(), v2::<R>(h.normal)),
        CastOutcome::Miss => Out::Ray(RayVerdict::Miss, 0.0, [0.0; 2]),
        CastOutcome::Start(_) => Out::Ray(RayVerdict::Inside, 0.0, [0.0; 2]),
    };
    (out, (c.status, Some(c.iterations)))
}

pub(crate) struct GFamily<R: Real, const N: usize> {
    pairs: Vec<(GS<R, N>, GS<R, N>)>,
    rays: Vec<(Ray<R>, R, GS<R, N>)>,
    casts: Vec<(GS<R, N>, GS<R, N>, Motion<R>)>,
}

pub(crate) fn build_family<R: Real, const N: usize>(f: &Family) -> GFamily<R, N> {
    let v = |p: &[f64; 2]| R::vector(R::from_f64(p[0]), R::from_f64(p[1]));
    match &f.cases {
        Cases::Pairs(c) => GFamily {
            pairs: c
                .iter()
                .map(|c| (&c.a, &c.b))
                .chain(f.extra_pairs().iter().map(|(a, b)| (a, b)))
                .map(|(a, b)| (build_g(a).expect("valid shape"), build_g(b).expect("valid shape")))
                .collect(),
            rays: Vec::new(),
            casts: Vec::new(),
        },
        Cases::Rays(c) => GFamily {
            pairs: Vec::new(),
            rays: c
                .iter()
                .map(|c| (&c.o, &c.d, c.max_len, &c.s))
                .chain(f.extra_rays().iter().map(|(o, d, m, s)| (o, d, *m, s)))
                .map(|(o, d, max_len, s)| {
                    (Ray::new(v(o), v(d)).expect("valid ray"), R::from_f64(max_len), build_g(s).expect("valid shape"))
                })
                .collect(),
            casts: Vec::new(),
        },
        Cases::Casts(c) => GFamily {
            pairs: Vec::new(),
            rays: Vec::new(),
            casts: c
                .iter()
                .map(|c| (&c.a, &c.b, &c.m))
                .chain(f.extra_casts().iter().map(|(a, b, m)| (a, b, m)))
                .map(|(a, b, m)| {
                    let (a, b) = (build_g(a).expect("valid shape"), build_g(b).expect("valid shape"));
                    (a, b, Motion::new(v(m)).expect("valid motion"))
                })
                .collect(),
        },
    }
}

pub(crate) fn measure_g<R: Real, const N: usize>(
    f: &Family,
    gf: &GFamily<R, N>,
    gjk: &Gjk<R>,
    q: Query,
    reps: usize,
) -> Meas {
    let (acc, n, batch) = accuracy_and_batch_g(f, gf, gjk, q);
    Meas { acc, ns: time_batches(n, reps, batch) }
}

/// A batch: every case of a family once, results black-boxed.
/// The accuracy of every case, and the batch that times them.
pub(crate) fn accuracy_and_batch_g<'a, R: Real, const N: usize>(
    f: &'a Family,
    gf: &'a GFamily<R, N>,
    gjk: &'a Gjk<R>,
    q: Query,
) -> (Acc, usize, Batch<'a>) {
    let eps = R::EPSILON.to_f64();
    let mut acc = Acc::default();
    match &f.cases {
        Cases::Pairs(cases) => {
            for (c, (a, b)) in cases.iter().zip(&gf.pairs) {
                let (out, lim) = g_pair_query(gjk, q, a, b);
                match q {
                    Query::Manifold => judge_manifold(&mut acc, c, eps, out, lim),
                    _ => judge_pair(&mut acc, q, c, eps, out, lim),
                }
            }
            // One loop a query kind, as a scene asks one kind of many pairs
            // in turn: the kind is not chosen again for every pair.
            let pairs = || gf.pairs.iter().take(TIMED_CASES).map(|(a, b)| (black_box(a), black_box(b)));
            let batch: Batch<'a> = match q {
                Query::Intersect => Box::new(move || {
                    for (a, b) in pairs() {
                        black_box(with_pair!(a, b, |x, y| gjk.intersects(x, &a.t, y, &b.t)));
                    }
                }),
                Query::Distance => Box::new(move || {
                    for (a, b) in pairs() {
                        black_box(with_pair!(a, b, |x, y| gjk.distance(x, &a.t, y, &b.t)));
                    }
                }),
                Query::Penetration => Box::new(move || {
                    for (a, b) in pairs() {
                        black_box(with_pair!(a, b, |x, y| gjk.penetration(x, &a.t, y, &b.t)));
                    }
                }),
                Query::Manifold => Box::new(move || {
                    for (a, b) in pairs() {
                        black_box(with_pair!(a, b, |x, y| gjk.manifold(x, &a.t, y, &b.t, R::ZERO)).ok());
                    }
                }),
                Query::Ray | Query::Cast => unreachable!(),
            };
            (acc, gf.pairs.len().min(TIMED_CASES), batch)
        }
        Cases::Casts(cases) => {
            for (c, (a, b, m)) in cases.iter().zip(&gf.casts) {
                let (out, lim) = g_cast(gjk, a, b, m);
                judge_ray(&mut acc, &c.truth, c.l, eps, out, lim);
            }
            let batch: Batch<'a> = Box::new(move || {
                for (a, b, m) in gf.casts.iter().take(TIMED_CASES) {
                    let (a, b) = (black_box(a), black_box(b));
                    black_box(with_pair!(a, b, |x, y| gjk.cast(x, &a.t, y, &b.t, black_box(m))));
                }
            });
            (acc, gf.casts.len().min(TIMED_CASES), batch)
        }
        Cases::Rays(cases) => {
            for (c, (ray, max, s)) in cases.iter().zip(&gf.rays) {
                let (out, lim) = g_ray(gjk, ray, *max, s);
                judge_ray(&mut acc, &c.truth, c.l, eps, out, lim);
            }
            let batch: Batch<'a> = Box::new(move || {
                for (ray, max, s) in gf.rays.iter().take(TIMED_CASES) {
                    let s = black_box(s);
                    black_box(with_shape!(s, |x| gjk.raycast(black_box(ray), *max, x, &s.t)));
                }
            });
            (acc, gf.rays.len().min(TIMED_CASES), batch)
        }
    }
}
