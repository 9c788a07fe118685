//! A polygon may carry vertices on an edge: a run of collinear edges. A
//! ray crossing such a run lies on the line of every edge in it, so the
//! clip may enter by any of them, also one whose segment ends before the
//! crossing. The hit must still be the crossing, not the end of the edge
//! the clip happened to enter by (at a shallow angle that end is far off
//! the ray).
//!
//! Exact geometry: a run from (-1, -1) to (1, -1) in 2 to 32 dyadic
//! pieces, then (3, -0.5) and (0, 2); every vertex order (the run wrapping
//! past vertex 0 too), scaled by powers of two and moved by dyadic
//! offsets, so the polygon is stored exactly. Rays cross the run at its
//! last vertex (1, -1) from directions between the run's line and the next
//! edge's (that edge itself included: the ray then grazes along it), and
//! at an inner vertex of the run, and along the run's line from either
//! side (meeting the boundary at the run's first vertex, or at its last
//! from outside): the exact distance is the origin's distance to that
//! vertex, and the hit must lie within 8 eps L of it, inside the error
//! bound it reports. (Rays along an edge's line in a direction that
//! rounds, whose exact answers need the oracle, are among
//! `tests/properties.rs`'s.) In f32 and f64, for polygons of up
//! to eight vertices (clipped by every edge at once), many-sided ones
//! (searched) and both through `dyn SupportMap` (scanned).

use gjk2d::glam::{DVec2, Vec2};
use gjk2d::{Gjk, Polygon, Ray, RayOutcome, SupportMap, Transform};

type Pt = [f64; 2];

/// The polygon's vertices, counter-clockwise from vertex `first` of the
/// unrotated list, with `pieces` edges along the run.
fn polygon(pieces: usize, first: usize) -> Vec<Pt> {
    let step = 2.0 / pieces as f64;
    let mut vertices: Vec<Pt> = (0..=pieces).map(|i| [-1.0 + step * i as f64, -1.0]).collect();
    vertices.extend([[3.0, -0.5], [0.0, 2.0]]);
    let n = vertices.len();
    (0..n).map(|i| vertices[(first + i) % n]).collect()
}

/// Directions into the polygon at the run's last vertex (1, -1): from
/// nearly along the run back, to along the next edge (grazing it).
const AT_LAST: [Pt; 6] = [[2.0, 0.5], [4.0, 1.5], [8.0, 2.5], [1.0, 1.0], [0.0, 1.0], [-4.0, 1.0]];

/// Directions into the polygon at an inner vertex of the run: any upwards.
const AT_INNER: [Pt; 4] = [[8.0, 1.0], [1.0, 1.0], [-1.0, 4.0], [-8.0, 1.0]];

macro_rules! collinear_suite {
    ($name:ident, $r:ty, $vec:ident) => {
        #[test]
        fn $name() {
            type R = $r;
            let eps = R::EPSILON as f64;
            let v = |p: Pt| $vec::new(p[0] as R, p[1] as R);
            let mut checked = 0;
            for pieces in [2, 4, 32] {
                for first in 0..pieces + 3 {
                    for (scale, offset) in [(1.0, [0.0, 0.0]), (0.0009765625, [0.5, -0.25]), (4096.0, [-8192.0, 1024.0])] {
                        let place = |p: Pt| [p[0] * scale + offset[0], p[1] * scale + offset[1]];
                        let vertices: Vec<$vec> = polygon(pieces, first).into_iter().map(|p| v(place(p))).collect();
                        let small = (vertices.len() <= 8).then(|| Polygon::<R, 8>::new(&vertices).unwrap());
                        let large = Polygon::<R, 64>::new(&vertices).unwrap();
                        let inner = [-1.0 + 2.0 / pieces as f64, -1.0];
                        // Along the run's line, into its first vertex and, from outside, its last.
                        let along = [([-1.0, -1.0], [1.0, 0.0]), ([1.0, -1.0], [-1.0, 0.0])];
                        let rays = AT_LAST
                            .iter()
                            .map(|&u| ([1.0, -1.0], u))
                            .chain(AT_INNER.iter().map(|&u| (inner, u)))
                            .chain(along);
                        for (crossing, u) in rays {
                            for back in [0.25, 1.0, 3.0] {
                                let target = place(crossing);
                                let origin = [target[0] - back * scale * u[0], target[1] - back * scale * u[1]];
                                let exact = back * scale * (u[0] * u[0] + u[1] * u[1]).sqrt();
                                let ray = Ray::new(v(origin), v(u)).unwrap();
                                let gjk = Gjk::<R>::new();
                                let mut casts = vec![("searched", gjk.raycast(&ray, 0.0, &large, &Transform::IDENTITY))];
                                let shapes: [&dyn SupportMap<R>; 1] = [&large];
                                casts.push(("dyn", gjk.raycast(&ray, 0.0, shapes[0], &Transform::IDENTITY)));
                                if let Some(small) = &small {
                                    casts.push(("small", gjk.raycast(&ray, 0.0, small, &Transform::IDENTITY)));
                                }
                                // The size that rounding scales with: the shape's and the origin's.
                                let l = (4.0 * scale).max((origin[0] - offset[0]).abs() + (origin[1] - offset[1]).abs());
                                for (path, cast) in casts {
                                    let what = format!(
                                        "{path}: {pieces} pieces from vertex {first}, scale {scale}, crossing {crossing:?} along {u:?}, back {back}: {cast:?}"
                                    );
                                    let RayOutcome::Hit(hit) = cast.outcome else { panic!("no hit: {what}") };
                                    let err = (hit.distance as f64 - exact).abs();
                                    assert!(err <= 8.0 * eps * l, "distance off by {err:e}: {what}");
                                    assert!(err <= hit.error_bound as f64 + 8.0 * eps * l, "outside its bound: {what}");
                                    let point = [hit.point.x as f64, hit.point.y as f64];
                                    let off = (point[0] - target[0]).hypot(point[1] - target[1]);
                                    assert!(off <= 8.0 * eps * l, "point {off:e} from the crossing: {what}");
                                    checked += 1;
                                }
                            }
                        }
                    }
                }
            }
            assert!(checked > 5000, "{checked}");
        }
    };
}

collinear_suite!(collinear_runs_f32, f32, Vec2);
collinear_suite!(collinear_runs_f64, f64, DVec2);
