//! Warm starting: the same pairs asked step after step, each moved a little,
//! by the cold queries and by the cached ones (a `PairCache` a pair, kept
//! from step to step), timed in turn; the cached answers against the cold
//! ones, and the mean iterations of each.

use crate::cases::Sh;
use crate::families::frame_pairs;
use crate::judge::median;
use crate::timing::{pass_ratio, time_interleaved, Batch, TIMED_CASES};
use gjk2d::{Gjk, PairCache, Polygon, Real, Transform};
use std::hint::black_box;

/// One query in one precision: cold and cached time per query, mean
/// iterations, and the steps whose cached answer differs from the cold one.
pub(crate) struct WarmRow {
    pub(crate) query: &'static str,
    pub(crate) prec: &'static str,
    pub(crate) cold_ns: f64,
    pub(crate) cached_ns: f64,
    /// Cached over cold, the median of the per-pass ratios.
    pub(crate) ratio: f64,
    pub(crate) cold_iterations: f64,
    pub(crate) cached_iterations: f64,
    pub(crate) differ: usize,
    pub(crate) asked: usize,
}

#[derive(Clone, Copy, PartialEq)]
enum Query {
    Intersect,
    Distance,
    Penetration,
    Manifold,
}

const QUERIES: [(Query, &str); 4] = [
    (Query::Intersect, "intersect"),
    (Query::Distance, "distance"),
    (Query::Penetration, "penetration"),
    (Query::Manifold, "manifold"),
];

/// Steps checked against the cold answers (after the first, which fills
/// the caches).
const CHECKED_STEPS: usize = 8;

/// The pairs in one precision: A as it is, B about its center, and B's
/// placement at every step.
struct Scene<R: Real> {
    a: Vec<Polygon<R, 8>>,
    b: Vec<Polygon<R, 8>>,
    steps: Vec<Vec<Transform<R>>>,
}

fn scene<R: Real>(pairs: &[(Sh, Sh, [f64; 2], f64)], steps: usize) -> Scene<R> {
    let v = |p: [f64; 2]| R::vector(R::from_f64(p[0]), R::from_f64(p[1]));
    let poly = |s: &Sh, c: [f64; 2]| match s {
        Sh::Poly(p) => {
            Polygon::new(&p.iter().map(|q| v([q[0] - c[0], q[1] - c[1]])).collect::<Vec<_>>()).expect("valid")
        }
        _ => unreachable!("frame pairs are polygons"),
    };
    let a = pairs.iter().map(|(a, ..)| poly(a, [0.0, 0.0])).collect();
    let b = pairs.iter().map(|(_, b, ..)| poly(b, b.bounds().0)).collect();
    let steps = (0..steps)
        .map(|k| {
            pairs
                .iter()
                .map(|(_, b, velocity, spin)| {
                    let (c, k) = (b.bounds().0, k as f64);
                    let at = [c[0] + k * velocity[0], c[1] + k * velocity[1]];
                    Transform::new(v(at), R::from_f64(k * spin)).expect("valid")
                })
                .collect()
        })
        .collect();
    Scene { a, b, steps }
}

/// One query of pair `i` at step `k`, as the timed passes ask it: the
/// answer black-boxed, nothing made of it.
#[inline(always)]
fn run<R: Real>(gjk: &Gjk<R>, s: &Scene<R>, q: Query, i: usize, k: usize, cache: Option<&mut PairCache<R>>) {
    let (a, b, tb, ta) = (&s.a[i], &s.b[i], &s.steps[k][i], &Transform::IDENTITY);
    match (q, cache) {
        (Query::Intersect, None) => drop(black_box(gjk.intersects(a, ta, b, tb))),
        (Query::Intersect, Some(c)) => drop(black_box(gjk.intersects_cached(a, ta, b, tb, c))),
        (Query::Distance, None) => drop(black_box(gjk.distance(a, ta, b, tb))),
        (Query::Distance, Some(c)) => drop(black_box(gjk.distance_cached(a, ta, b, tb, c))),
        (Query::Penetration, None) => drop(black_box(gjk.penetration(a, ta, b, tb))),
        (Query::Penetration, Some(c)) => drop(black_box(gjk.penetration_cached(a, ta, b, tb, c))),
        (Query::Manifold, None) => drop(black_box(gjk.manifold(a, ta, b, tb, R::ZERO))),
        (Query::Manifold, Some(c)) => drop(black_box(gjk.manifold_cached(a, ta, b, tb, R::ZERO, c))),
    }
}

/// The iterations of one query of pair `i` at step `k`, and a summary of its
/// answer to compare cold with cached (the verdict and the bits of its
/// value; a distance only to within its error bounds, checked apart).
fn ask<R: Real>(
    gjk: &Gjk<R>,
    s: &Scene<R>,
    q: Query,
    i: usize,
    k: usize,
    cache: Option<&mut PairCache<R>>,
) -> (u32, Option<f64>, f64) {
    let (a, b, tb, ta) = (&s.a[i], &s.b[i], &s.steps[k][i], &Transform::IDENTITY);
    match (q, cache) {
        (Query::Intersect, None) => {
            let d = gjk.intersects(a, ta, b, tb);
            (d.iterations, Some(d.intersecting as u8 as f64), 0.0)
        }
        (Query::Intersect, Some(c)) => {
            let d = gjk.intersects_cached(a, ta, b, tb, c);
            (d.iterations, Some(d.intersecting as u8 as f64), 0.0)
        }
        (Query::Distance, None) => gjk
            .distance(a, ta, b, tb)
            .map_or((0, None, 0.0), |d| (d.iterations, Some(d.distance.to_f64()), d.error_bound.to_f64())),
        (Query::Distance, Some(c)) => gjk
            .distance_cached(a, ta, b, tb, c)
            .map_or((0, None, 0.0), |d| (d.iterations, Some(d.distance.to_f64()), d.error_bound.to_f64())),
        (Query::Penetration, None) => {
            gjk.penetration(a, ta, b, tb).map_or((0, None, 0.0), |p| (p.iterations, Some(p.depth.to_f64()), 0.0))
        }
        (Query::Penetration, Some(c)) => gjk
            .penetration_cached(a, ta, b, tb, c)
            .map_or((0, None, 0.0), |p| (p.iterations, Some(p.depth.to_f64()), 0.0)),
        (Query::Manifold, None) => {
            let m = gjk.manifold(a, ta, b, tb, R::ZERO).expect("margin 0");
            (m.iterations, Some(m.points().iter().map(|p| p.separation.to_f64()).fold(0.0, f64::min)), 0.0)
        }
        (Query::Manifold, Some(c)) => {
            let m = gjk.manifold_cached(a, ta, b, tb, R::ZERO, c).expect("margin 0");
            (m.iterations, Some(m.points().iter().map(|p| p.separation.to_f64()).fold(0.0, f64::min)), 0.0)
        }
    }
}

fn measure<R: Real>(prec: &'static str, pairs: &[(Sh, Sh, [f64; 2], f64)], reps: usize, rows: &mut Vec<WarmRow>) {
    let n = pairs.len();
    // One step for the check, then one a timed pass (and the warm-up's).
    let s = scene::<R>(pairs, CHECKED_STEPS + reps + 3);
    let gjk = Gjk::<R>::new();
    let eps = R::EPSILON.to_f64();
    for (q, query) in QUERIES {
        // The check: every pair at the first steps, cached against cold.
        let mut caches = vec![PairCache::<R>::default(); n];
        let (mut cold_it, mut cached_it, mut differ, mut asked, mut answered) = (0u64, 0u64, 0, 0, 0usize);
        for k in 0..=CHECKED_STEPS {
            for (i, cache) in caches.iter_mut().enumerate() {
                let (ic, cold, bound_c) = ask(&gjk, &s, q, i, k, None);
                let (iw, warm, bound_w) = ask(&gjk, &s, q, i, k, Some(cache));
                if k == 0 {
                    continue;
                }
                // Iterations where both answered (a distance of shapes that
                // overlap has none to report).
                if cold.is_some() && warm.is_some() {
                    cold_it += ic as u64;
                    cached_it += iw as u64;
                    answered += 1;
                }
                asked += 1;
                let same = match (cold, warm) {
                    (Some(x), Some(y)) if q == Query::Distance => (x - y).abs() <= bound_c + bound_w + 16.0 * eps * 4.0,
                    (x, y) => x == y,
                };
                differ += !same as usize;
            }
        }
        // The timing: a step a pass, the caches carried from pass to pass.
        let first = CHECKED_STEPS + 1;
        let (mut cold_step, mut cached_step) = (first, first);
        let s = &s;
        let gjk = &gjk;
        let mut batches: Vec<Batch<'_>> = vec![
            Box::new(move || {
                for i in 0..n {
                    run(gjk, s, q, black_box(i), cold_step, None);
                }
                cold_step += 1;
            }),
            Box::new(move || {
                for (i, cache) in caches.iter_mut().enumerate() {
                    run(gjk, s, q, black_box(i), cached_step, Some(cache));
                }
                cached_step += 1;
            }),
        ];
        let times = time_interleaved(n, reps, &mut batches);
        rows.push(WarmRow {
            query,
            prec,
            cold_ns: median(times[0].clone()),
            cached_ns: median(times[1].clone()),
            ratio: pass_ratio(&times[1], &times[0]),
            cold_iterations: cold_it as f64 / answered.max(1) as f64,
            cached_iterations: cached_it as f64 / answered.max(1) as f64,
            differ,
            asked,
        });
    }
}

/// Every query, f32 and f64, over [`TIMED_CASES`] pairs of 8-gons.
pub(crate) fn warm_rows(reps: usize) -> Vec<WarmRow> {
    let pairs = frame_pairs(TIMED_CASES);
    let mut rows = Vec::new();
    measure::<f32>("f32", &pairs, reps, &mut rows);
    measure::<f64>("f64", &pairs, reps, &mut rows);
    rows
}

/// The rows as a markdown table, with the median ratio in its own column.
pub(crate) fn warm_table(rows: &[WarmRow]) -> String {
    let mut t = String::from(
        "| query | precision | cold ns | cached ns | cached / cold | mean iterations, cold | cached | cached answers differing |\n|---|---|---:|---:|---:|---:|---:|---:|\n",
    );
    for r in rows {
        t += &format!(
            "| {} | {} | {:.0} | {:.0} | {:.2} | {:.2} | {:.2} | {} of {} |\n",
            r.query, r.prec, r.cold_ns, r.cached_ns, r.ratio, r.cold_iterations, r.cached_iterations, r.differ, r.asked
        );
    }
    t
}
