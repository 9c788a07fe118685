//! Timing: every timed pass asks each of a family's cases once, the contenders in
//! turn, and the figure is the median over the passes.

use crate::judge::{median, Acc};
use std::time::Instant;

/// Distinct cases per timed pass: a family's judged cases and as many more of the
/// same kind, each asked once per pass. Repeating a small batch would let the
/// branch predictor learn the answers, which flatters branchy code by 2x or more;
/// a physics step or a game frame asks each pair once.
pub(crate) const TIMED_CASES: usize = 16_384;

/// Median over `reps` passes of the time per query; each pass asks every timed
/// case (`n` queries) once.
pub(crate) fn time_batches(n: usize, reps: usize, mut batch: impl FnMut()) -> f64 {
    if n == 0 {
        return f64::NAN;
    }
    batch();
    let v = (0..reps)
        .map(|_| {
            let t = Instant::now();
            batch();
            t.elapsed().as_nanos() as f64 / n as f64
        })
        .collect();
    median(v)
}

/// Like [`time_batches`] for several contenders over the same `n` cases, one pass
/// each in turn within every repeat, in an order that rotates from repeat to
/// repeat: each contender's time per query, pass by pass.
pub(crate) fn time_interleaved(n: usize, reps: usize, batches: &mut [Batch<'_>]) -> Vec<Vec<f64>> {
    if n == 0 {
        return vec![vec![f64::NAN]; batches.len()];
    }
    for b in batches.iter_mut() {
        b();
    }
    let k = batches.len();
    let mut times = vec![Vec::new(); k];
    for rep in 0..reps {
        for j in 0..k {
            let i = (rep + j) % k;
            let t = Instant::now();
            (batches[i])();
            times[i].push(t.elapsed().as_nanos() as f64 / n as f64);
        }
    }
    times
}

/// `a / b` pass by pass, then the median: the ratio of two runs taken side by
/// side, which a change in machine load moves less than either time (as
/// `cargo bench --bench queries` takes it).
pub(crate) fn pass_ratio(a: &[f64], b: &[f64]) -> f64 {
    median(a.iter().zip(b).map(|(x, y)| x / y).collect())
}

#[derive(Clone, Debug)]
pub(crate) struct Meas {
    pub(crate) acc: Acc,
    pub(crate) ns: f64,
}

pub(crate) type Batch<'a> = Box<dyn FnMut() + 'a>;
