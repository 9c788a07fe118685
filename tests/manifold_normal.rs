//! A manifold's normal, least separation, iterations and status are the
//! distance query's when the shapes are apart and the penetration query's
//! when they overlap, to the bit, though it runs GJK once where the two
//! queries asked in turn would run it twice. Checked on shapes whose types
//! are known when the program is compiled (every host fast path: point
//! cores, a point against a small polygon, separating axes of small
//! polygons and of a segment core) and through `dyn SupportMap` (GJK, EPA),
//! in f32 and f64, at random placements, about half of them overlapping.

#[path = "common/rng.rs"]
mod rng;
use gjk2d::glam::{DVec2, Vec2};
use gjk2d::*;
use rng::{cases, Rng};

macro_rules! suite {
    ($name:ident, $r:ty, $vec:ident) => {
        #[test]
        fn $name() {
            type R = $r;
            /// A near the origin, B within a few sizes of it, both turned.
            fn placements(rng: &mut Rng) -> (Transform<R>, Transform<R>) {
                let mut at = |reach: f64| {
                    let t = $vec::new(rng.range(-reach, reach) as R, rng.range(-reach, reach) as R);
                    Transform::<R>::new(t, rng.range(-4.0, 4.0) as R).unwrap()
                };
                (at(1.0), at(3.0))
            }
            fn check<A: SupportMap<R> + ?Sized, B: SupportMap<R> + ?Sized>(
                gjk: &Gjk<R>,
                a: &A,
                b: &B,
                rng: &mut Rng,
            ) -> bool {
                let (ta, tb) = placements(rng);
                check_at(gjk, a, &ta, b, &tb)
            }
            fn check_at<A: SupportMap<R> + ?Sized, B: SupportMap<R> + ?Sized>(
                gjk: &Gjk<R>,
                a: &A,
                ta: &Transform<R>,
                b: &B,
                tb: &Transform<R>,
            ) -> bool {
                let (ta, tb) = (*ta, *tb);
                let m = gjk.manifold(a, &ta, b, &tb, 0.25).unwrap();
                let want = match gjk.distance(a, &ta, b, &tb) {
                    Some(s) => Some((s.normal, s.distance, s.iterations, s.status)),
                    None => gjk.penetration(a, &ta, b, &tb).map(|p| (p.normal, -p.depth, p.iterations, p.status)),
                };
                let Some((normal, separation, iterations, status)) = want else {
                    assert!(m.is_empty(), "{m:?}: the queries disagree, the manifold must be empty");
                    return false;
                };
                assert_eq!((m.normal, m.iterations, m.status), (normal, iterations, status), "{ta:?} {tb:?}");
                if let Some(least) = m.points().iter().map(|p| p.separation).reduce(R::min) {
                    // The least point is the query's within rounding of the
                    // clip (and, on curves, the tolerance of its support).
                    let size = 8.0 + (ta.translation() - tb.translation()).length();
                    let tol = (4.0 * gjk.config.distance_epsilon() + 64.0 * R::EPSILON) * size;
                    assert!((least - separation).abs() <= tol, "{m:?}: least {least}, the query's {separation}");
                }
                separation <= 0.0
            }
            /// The same pair through concrete types (their vertices at hand
            /// on hosts) and through `dyn` (the support function asked
            /// round each vertex): where the two normals agree, the same
            /// manifold to the bit. Whether they agreed.
            fn same_faces<A: SupportMap<R>, B: SupportMap<R>>(gjk: &Gjk<R>, a: &A, b: &B, rng: &mut Rng) -> bool {
                let (ta, tb) = placements(rng);
                let (da, db): (&dyn SupportMap<R>, &dyn SupportMap<R>) = (a, b);
                let (lent, asked) =
                    (gjk.manifold(a, &ta, b, &tb, 0.5).unwrap(), gjk.manifold(da, &ta, db, &tb, 0.5).unwrap());
                if lent.normal != asked.normal {
                    return false;
                }
                assert_eq!(lent.points(), asked.points(), "{ta:?} {tb:?}");
                true
            }
            let v = |x: f64, y: f64| $vec::new(x as R, y as R);
            let octagon: Vec<_> = (0..8)
                .map(|i| (i as f64 * 0.785 + 0.1, 1.0 + 0.1 * (i % 3) as f64))
                .map(|(t, r)| v(r * t.cos(), r * t.sin()))
                .collect();
            let many: Vec<_> = (0..64).map(|i| i as f64 * 0.0982).map(|t| v(1.5 * t.cos(), 0.8 * t.sin())).collect();
            let p8 = Polygon::<R, 8>::new(&octagon).unwrap();
            let p64 = Polygon::<R, 64>::new(&many).unwrap();
            let circle = Circle::<R>::new(0.75).unwrap();
            let capsule = Capsule::<R>::new(v(-1.0, 0.2), v(1.0, -0.1), 0.3).unwrap();
            let segment = Segment::<R>::new(v(-1.0, 0.2), v(1.0, -0.1)).unwrap();
            let ellipse = Ellipse::<R>::new(2.0, 1.0).unwrap();
            let rounded = Rounded::new(Rectangle::<R>::new(1.0, 1.5).unwrap(), 0.2).unwrap();
            let gjk = Gjk::<R>::new();
            let mut rng = Rng(0x6d61_6e69);
            let mut overlapping = 0;
            let n = cases(200);
            for _ in 0..n {
                overlapping += check(&gjk, &p8, &p8, &mut rng) as u32;
                overlapping += check(&gjk, &p64, &p8, &mut rng) as u32;
                overlapping += check(&gjk, &circle, &p8, &mut rng) as u32;
                overlapping += check(&gjk, &p8, &circle, &mut rng) as u32;
                overlapping += check(&gjk, &circle, &circle, &mut rng) as u32;
                overlapping += check(&gjk, &capsule, &p8, &mut rng) as u32;
                overlapping += check(&gjk, &p8, &segment, &mut rng) as u32;
                overlapping += check(&gjk, &ellipse, &p64, &mut rng) as u32;
                overlapping += check(&gjk, &rounded, &capsule, &mut rng) as u32;
                let (da, db): (&dyn SupportMap<R>, &dyn SupportMap<R>) = (&p8, &capsule);
                overlapping += check(&gjk, da, db, &mut rng) as u32;
            }
            assert!(
                overlapping > 10 * n / 5 && overlapping < 10 * n * 4 / 5,
                "{overlapping} of {} overlapping",
                10 * n
            );
            // Capsules resting on the octagon's edges, their cores the
            // radius away to within rounding, turned to the edge: where the
            // closed-form verdict and GJK part by rounding, the manifold
            // still follows the distance query, and else the penetration's.
            for k in 0..n as usize {
                let (u, w) = (octagon[k % 8], octagon[(k + 1) % 8]);
                let (u, w) = ([u.x as f64, u.y as f64], [w.x as f64, w.y as f64]);
                let (dx, dy) = (w[0] - u[0], w[1] - u[1]);
                let length = dx.hypot(dy);
                let (along, half) = (rng.range(0.1, 0.9), rng.range(0.05, 0.6));
                let lift = 0.3 * (1.0 + rng.range(-8.0, 8.0) * R::EPSILON as f64);
                let centre = v(u[0] + dx * along + dy / length * lift, u[1] + dy * along - dx / length * lift);
                let resting = Capsule::<R>::new(v(-half, 0.0), v(half, 0.0), 0.3).unwrap();
                let on_edge = Transform::<R>::new(centre, dy.atan2(dx) as R).unwrap();
                check_at(&gjk, &p8, &Transform::IDENTITY, &resting, &on_edge);
                check_at(&gjk, &resting, &on_edge, &p8, &Transform::IDENTITY);
            }
            let mut agreed = 0;
            for _ in 0..n {
                agreed += same_faces(&gjk, &p8, &p8, &mut rng) as u32;
                agreed += same_faces(&gjk, &capsule, &p8, &mut rng) as u32;
                agreed += same_faces(&gjk, &p8, &segment, &mut rng) as u32;
                agreed += same_faces(
                    &gjk,
                    &Triangle::<R>::new(v(-1.0, -0.5), v(1.0, -0.4), v(0.1, 1.0)).unwrap(),
                    &p8,
                    &mut rng,
                ) as u32;
            }
            assert!(agreed > n, "{agreed} of {} pairs with the same normal both ways", 4 * n);
            // Faces resting on faces, where both ends of the overlap come
            // from the faces' far vertices and name them.
            let square =
                Polygon::<R, 8>::new(&[v(-1.0, -1.0), v(0.0, -1.0), v(1.0, -1.0), v(1.0, 1.0), v(-1.0, 1.0)]).unwrap();
            for k in 0..64 {
                let tb =
                    Transform::<R>::new(v(k as f64 / 24.0 - 1.3, 1.99 - k as f64 * 1e-4), 1e-4 * (k % 5) as R).unwrap();
                let (da, db): (&dyn SupportMap<R>, &dyn SupportMap<R>) = (&square, &square);
                let lent = gjk.manifold(&square, &Transform::IDENTITY, &square, &tb, 0.1).unwrap();
                let asked = gjk.manifold(da, &Transform::IDENTITY, db, &tb, 0.1).unwrap();
                assert_eq!(lent.points().len(), 2, "{lent:?}");
                if lent.normal == asked.normal {
                    assert_eq!(lent.points(), asked.points(), "{tb:?}");
                }
            }
        }
    };
}

suite!(manifold_normal_is_the_queries_f32, f32, Vec2);
suite!(manifold_normal_is_the_queries_f64, f64, DVec2);
