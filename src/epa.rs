//! Penetration depth of overlapping cores: the pluggable solver trait and
//! EPA, the default, on a fixed-capacity polytope.
//!
//! The polytope is a convex polygon inside the Minkowski difference that
//! contains the origin. Its closest edge gives a *lower* bound of the depth;
//! the support along that edge's normal an *upper* bound. EPA pushes the
//! closest edge out until the bounds meet: exactly when a support vertex
//! repeats (polytopes), or within `epsilon * size` (curved cores).

use crate::config::EpaConfig;
use crate::minkowski::{MinkowskiDifference, SupportPoint, NO_ID};
use crate::real::{Real, V2};
use crate::result::Status;

/// The depth and direction of the overlap of two cores, as a penetration
/// solver reports it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PenetrationEstimate<R: Real> {
    /// Unit vector from A towards B: moving B by `depth` along it separates
    /// the cores.
    pub normal: R::Vector,
    pub depth: R,
    /// Gap between the solver's upper and lower bounds of the depth.
    pub error_bound: R,
    pub iterations: u32,
    pub status: Status,
}

/// A penetration solver (dyn4j's `MinkowskiPenetrationSolver`): given the
/// Minkowski difference of two overlapping cores and GJK's final simplex
/// (1 to 3 points enclosing or touching the origin), find the depth.
pub trait PenetrationSolver<R: Real> {
    fn solve<M: MinkowskiDifference<R>>(
        &self,
        difference: &M,
        simplex: &[SupportPoint<R>],
    ) -> PenetrationEstimate<R>;
}

/// The expanding polytope algorithm with room for `N` polytope vertices on
/// the stack (default 32: 640 bytes in f32, 1 KB in f64).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Epa<R: Real, const N: usize = 32> {
    pub config: EpaConfig<R>,
}

impl<R: Real, const N: usize> Epa<R, N> {
    pub fn new(config: EpaConfig<R>) -> Self {
        Self { config }
    }
}

impl<R: Real, const N: usize> PenetrationSolver<R> for Epa<R, N> {
    fn solve<M: MinkowskiDifference<R>>(
        &self,
        difference: &M,
        simplex: &[SupportPoint<R>],
    ) -> PenetrationEstimate<R> {
        let mut polytope = heapless::Vec::<Corner<R>, N>::new();
        expand(&mut polytope, &self.config, difference, simplex)
    }
}

/// A polytope vertex and the distance of the edge that starts at it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Corner<R> {
    w: V2<R>,
    id: u64,
    /// Distance from the origin to the line of the edge to the next corner.
    edge_distance: R,
}

/// Growable storage for the polytope: inline (heapless) or, with `std`, a
/// `Vec` without a cap.
pub(crate) trait Storage<R> {
    fn items(&self) -> &[Corner<R>];
    fn items_mut(&mut self) -> &mut [Corner<R>];
    /// Inserts at `index`; false when full.
    fn insert_at(&mut self, index: usize, c: Corner<R>) -> bool;
    fn clear_all(&mut self);
}

impl<R: Copy, const N: usize> Storage<R> for heapless::Vec<Corner<R>, N> {
    fn items(&self) -> &[Corner<R>] {
        self
    }
    fn items_mut(&mut self) -> &mut [Corner<R>] {
        self
    }
    fn insert_at(&mut self, index: usize, c: Corner<R>) -> bool {
        self.insert(index, c).is_ok()
    }
    fn clear_all(&mut self) {
        self.clear()
    }
}

#[cfg(feature = "std")]
impl<R: Copy> Storage<R> for std::vec::Vec<Corner<R>> {
    fn items(&self) -> &[Corner<R>] {
        self
    }
    fn items_mut(&mut self) -> &mut [Corner<R>] {
        self
    }
    fn insert_at(&mut self, index: usize, c: Corner<R>) -> bool {
        self.insert(index, c);
        true
    }
    fn clear_all(&mut self) {
        self.clear()
    }
}

/// Distance from the origin to the line through `p`, `q` (a counter-clockwise
/// edge of a polytope around the origin), and its outward unit normal.
fn edge<R: Real>(p: V2<R>, q: V2<R>) -> (R, V2<R>) {
    let n = (q - p).perp_cw();
    let len = n.length();
    if len > R::ZERO {
        let unit = n * (R::ONE / len);
        ((p.dot(n) / len).max(R::ZERO), unit)
    } else {
        (
            R::ZERO,
            p.try_normalize().unwrap_or(V2::new(R::ONE, R::ZERO)),
        )
    }
}

fn corner<R: Real>(s: &SupportPoint<R>) -> Corner<R> {
    Corner {
        w: V2::from_glam(s.point),
        id: s.id,
        edge_distance: R::ZERO,
    }
}

pub(crate) fn expand<R: Real, S: Storage<R>, M: MinkowskiDifference<R>>(
    polytope: &mut S,
    config: &EpaConfig<R>,
    difference: &M,
    simplex: &[SupportPoint<R>],
) -> PenetrationEstimate<R> {
    let support = |d: V2<R>| corner(&difference.support(d.to_glam()));
    let tolerance = config.epsilon() * difference.scale();
    let mut iterations = 0;

    // A counter-clockwise polygon around the origin from GJK's simplex. A
    // simplex that only touches the origin (a point or an edge) is widened
    // with supports along its normals.
    polytope.clear_all();
    match simplex {
        [a, b, c] => {
            let (a, b, c) = (corner(a), corner(b), corner(c));
            let ccw = (b.w - a.w).cross(c.w - a.w) >= R::ZERO;
            let order = if ccw { [a, b, c] } else { [a, c, b] };
            for (i, c) in order.into_iter().enumerate() {
                polytope.insert_at(i, c);
            }
        }
        [a, b] => seed_from_edge(polytope, corner(a), corner(b), &support, &mut iterations),
        [a] => {
            let a = corner(a);
            let b = support(V2::new(R::ONE, R::ZERO));
            let b = if b.w == a.w {
                support(V2::new(-R::ONE, R::ZERO))
            } else {
                b
            };
            iterations += 1;
            seed_from_edge(polytope, a, b, &support, &mut iterations)
        }
        _ => {}
    }
    if polytope.items().len() < 3 {
        // The Minkowski difference is flat (e.g. parallel segments): it has
        // no interior, the depth is zero along the normal of its line.
        let normal = match polytope.items() {
            [a, b, ..] => (b.w - a.w).perp().try_normalize(),
            _ => None,
        }
        .unwrap_or(V2::new(R::ONE, R::ZERO));
        return estimate(normal, R::ZERO, R::ZERO, iterations, Status::Converged);
    }
    let n = polytope.items().len();
    for i in 0..n {
        let q = polytope.items()[(i + 1) % n].w;
        let c = &mut polytope.items_mut()[i];
        c.edge_distance = edge(c.w, q).0;
    }

    let mut upper = R::INFINITY;
    loop {
        let items = polytope.items();
        let n = items.len();
        let (mut i, mut lower) = (0, items[0].edge_distance);
        for (k, c) in items.iter().enumerate().skip(1) {
            if c.edge_distance < lower {
                i = k;
                lower = c.edge_distance;
            }
        }
        let j = (i + 1) % n;
        let (p, q) = (items[i], items[j]);
        let (_, normal) = edge(p.w, q.w);
        if iterations >= config.max_iterations() {
            return estimate(
                normal,
                lower,
                upper - lower,
                iterations,
                Status::IterationLimit,
            );
        }
        let w = support(normal);
        iterations += 1;
        let reach = w.w.dot(normal);
        upper = upper.min(reach);
        let repeated = w.id != NO_ID && (w.id == p.id || w.id == q.id);
        if repeated || reach - lower <= tolerance {
            return estimate(
                normal,
                lower,
                (upper - lower).max(R::ZERO),
                iterations,
                Status::Converged,
            );
        }
        let new = Corner {
            w: w.w,
            id: w.id,
            edge_distance: edge(w.w, q.w).0,
        };
        if !polytope.insert_at(j.max(i + 1), new) {
            return estimate(
                normal,
                lower,
                upper - lower,
                iterations,
                Status::CapacityLimit,
            );
        }
        polytope.items_mut()[i].edge_distance = edge(p.w, w.w).0;
    }
}

/// A triangle or quadrilateral around the origin from an edge `a`-`b` that
/// holds it, with the supports on both sides of the edge.
fn seed_from_edge<R: Real, S: Storage<R>>(
    polytope: &mut S,
    a: Corner<R>,
    b: Corner<R>,
    support: &impl Fn(V2<R>) -> Corner<R>,
    iterations: &mut u32,
) {
    let side = (b.w - a.w).perp();
    let right = support(-side);
    let left = support(side);
    *iterations += 2;
    // Counter-clockwise: a, the right-hand support, b, the left-hand one.
    // Supports that add no area (on the edge's line) are left out.
    let mut k = 0;
    for c in [a, right, b, left] {
        if !polytope.items().iter().any(|p| p.w == c.w) {
            polytope.insert_at(k, c);
            k += 1;
        }
    }
    let items = polytope.items();
    if items.len() == 4 {
        // Drop a side support that lies on the edge's line (zero area side).
        let area_right = (b.w - a.w).cross(items[1].w - a.w);
        let area_left = (b.w - a.w).cross(items[3].w - a.w);
        if area_left <= R::ZERO {
            remove(polytope, 3);
        }
        if area_right >= R::ZERO {
            remove(polytope, 1);
        }
    } else if items.len() == 3 {
        let area = (items[1].w - items[0].w).cross(items[2].w - items[0].w);
        if area == R::ZERO {
            remove(polytope, 2);
        } else if area < R::ZERO {
            let (x, y) = (items[1], items[2]);
            polytope.items_mut()[1] = y;
            polytope.items_mut()[2] = x;
        }
    }
}

fn remove<R: Copy, S: Storage<R>>(polytope: &mut S, index: usize) {
    let kept: heapless::Vec<Corner<R>, 4> = polytope
        .items()
        .iter()
        .enumerate()
        .filter(|&(i, _)| i != index)
        .map(|(_, c)| *c)
        .collect();
    polytope.clear_all();
    for (i, c) in kept.into_iter().enumerate() {
        polytope.insert_at(i, c);
    }
}

fn estimate<R: Real>(
    outward: V2<R>,
    depth: R,
    error_bound: R,
    iterations: u32,
    status: Status,
) -> PenetrationEstimate<R> {
    PenetrationEstimate {
        // The polytope's outward normal points from B into A's side; B moves
        // the other way.
        normal: (-outward).to_glam(),
        depth,
        error_bound,
        iterations,
        status,
    }
}
