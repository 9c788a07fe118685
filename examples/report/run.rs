//! One family: every query, both precisions, both libraries, timed in turn.

use crate::cases::{Cases, Family};
use crate::judge::{median, Acc, Query};
use crate::ours::{accuracy_and_batch_g, build_family};
use crate::parry::{parry32, parry64};
use crate::timing::{pass_ratio, time_interleaved, Meas};
use gjk2d::Gjk;

pub(crate) struct Row {
    pub(crate) family: String,
    pub(crate) stiff: bool,
    pub(crate) query: Query,
    pub(crate) prec: &'static str,
    pub(crate) ours: Meas,
    pub(crate) parry: Option<Meas>,
    /// Our time over parry's, the median of the per-pass ratios.
    pub(crate) ratio: Option<f64>,
    pub(crate) eps: f64,
}

/// The families whose contact manifolds are measured: polygons, and a
/// circle or a capsule against one, as parry's `contact_manifolds` has them.
const MANIFOLD_FAMILIES: [&str; 4] = ["poly8", "poly64", "circle_poly", "capsule_poly"];

fn queries_of(f: &Family) -> &'static [Query] {
    match f.cases {
        Cases::Pairs(_) if MANIFOLD_FAMILIES.contains(&f.name.as_str()) => {
            &[Query::Intersect, Query::Penetration, Query::Distance, Query::Manifold]
        }
        Cases::Pairs(_) => &[Query::Intersect, Query::Penetration, Query::Distance],
        Cases::Rays(_) => &[Query::Ray],
        Cases::Casts(_) => &[Query::Cast],
    }
}

pub(crate) fn max_vertices(f: &Family) -> usize {
    match &f.cases {
        Cases::Pairs(c) => c.iter().map(|c| c.a.vertex_count().max(c.b.vertex_count())).max().unwrap_or(0),
        Cases::Rays(c) => c.iter().map(|c| c.s.vertex_count()).max().unwrap_or(0),
        Cases::Casts(c) => c.iter().map(|c| c.a.vertex_count().max(c.b.vertex_count())).max().unwrap_or(0),
    }
}

pub(crate) fn run_family<const N: usize>(f: &Family, reps: usize, rows: &mut Vec<Row>) {
    let g32 = build_family::<f32, N>(f);
    let g64 = build_family::<f64, N>(f);
    let p32 = parry32::build_family(f);
    let p64 = parry64::build_family(f);
    let (gjk32, gjk64) = (Gjk::<f32>::new(), Gjk::<f64>::new());
    for &q in queries_of(f) {
        // The four contenders' batches run in turn within every repeat, so a change
        // in machine load falls on all of them alike.
        let (a32, n, b32) = accuracy_and_batch_g(f, &g32, &gjk32, q);
        let (a64, _, b64) = accuracy_and_batch_g(f, &g64, &gjk64, q);
        let mut batches = vec![b32, b64];
        let mut parry_acc = Vec::new();
        for pr in [parry32::accuracy_and_batch(f, &p32, q), parry64::accuracy_and_batch(f, &p64, q)] {
            match pr {
                Some((acc, _, b)) => {
                    parry_acc.push(Some(acc));
                    batches.push(b);
                }
                None => parry_acc.push(None),
            }
        }
        let times = time_interleaved(n, reps, &mut batches);
        let mut k = 2;
        let mut parry = |acc: Option<Acc>| {
            acc.map(|acc| {
                k += 1;
                (Meas { acc, ns: median(times[k - 1].clone()) }, k - 1)
            })
        };
        let (p32m, p64m) = (parry(parry_acc[0].take()), parry(parry_acc[1].take()));
        for (prec, acc, ours, parry, eps) in
            [("f32", a32, 0, p32m, f32::EPSILON as f64), ("f64", a64, 1, p64m, f64::EPSILON)]
        {
            rows.push(Row {
                family: f.name.clone(),
                stiff: f.stiff,
                query: q,
                prec,
                ours: Meas { acc, ns: median(times[ours].clone()) },
                ratio: parry.as_ref().map(|&(_, theirs)| pass_ratio(&times[ours], &times[theirs])),
                parry: parry.map(|(m, _)| m),
                eps,
            });
        }
    }
}
