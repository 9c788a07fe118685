//! A circle's rays take one placed cast on every target, static or through
//! `dyn SupportMap`: the normal from the ray's world direction and, on
//! hosts, the outcome picked by selects. Checked here against the circle's
//! own local cast (`cast_local_ray`, placed by hand in f64 from the same
//! local ray): the same verdict wherever the ray is not within rounding of
//! a verdict's edge, the distance within the reported error bound, the
//! normal a unit vector at the local one's rotation. Placed and rotated
//! circles, rays from inside and outside, aimed to hit, graze and miss,
//! bounded short of the hit, past it and not at all.

use gjk2d::glam::{DVec2, Vec2};
use gjk2d::{Circle, Gjk, Ray, RayOutcome, SupportMap, Transform};
use proptest::prelude::*;

macro_rules! disk_ray_suite {
    ($name:ident, $r:ty, $vec:ident) => {
        proptest! {
            #![proptest_config(ProptestConfig::with_cases(4000))]
            #[test]
            fn $name(
                center in (-4.0f64..4.0, -4.0f64..4.0), radius in 0.01f64..10.0,
                place in (-1.0e3f64..1.0e3, -1.0e3f64..1.0e3, 0.0f64..6.3),
                from in (0.0f64..3.0, 0.0f64..6.3), aim in (-1.3f64..1.3),
                bound in prop_oneof![Just(0.0f64), 0.2f64..3.0],
            ) {
                type R = $r;
                let eps = R::EPSILON as f64;
                // The inputs as stored, so the reference below starts from them.
                let round = |x: f64| x as R as f64;
                let (center, radius) = ((round(center.0), round(center.1)), round(radius));
                let place = (round(place.0), round(place.1), round(place.2));
                let circle = Circle::<R>::at($vec::new(center.0 as R, center.1 as R), radius as R).unwrap();
                let t = Transform::<R>::new($vec::new(place.0 as R, place.1 as R), place.2 as R).unwrap();
                // The circle's center in the world, and a ray from `from.0`
                // radii away aimed `aim` radii across the center.
                let (s, c) = place.2.sin_cos();
                let world = |p: (f64, f64)| (place.0 + c * p.0 - s * p.1, place.1 + s * p.0 + c * p.1);
                let cw = world(center);
                let o = (cw.0 + radius * from.0 * from.1.cos(), cw.1 + radius * from.0 * from.1.sin());
                // From the center itself, any direction.
                let (ux, uy) = if o == cw { (1.0, 0.0) } else { (cw.0 - o.0, cw.1 - o.1) };
                let len = ux.hypot(uy).max(radius * 1e-3);
                let d = (ux / len - uy / len * aim, uy / len + ux / len * aim);
                let ray = Ray::<R>::new($vec::new(o.0 as R, o.1 as R), $vec::new(d.0 as R, d.1 as R)).unwrap();
                let max = (bound * len) as R;

                let gjk = Gjk::<R>::new();
                let placed = gjk.raycast(&ray, max, &circle, &t);
                let through_dyn = gjk.raycast(&ray, max, &circle as &dyn SupportMap<R>, &t);
                prop_assert_eq!(format!("{placed:?}"), format!("{through_dyn:?}"));

                // The local cast, from the ray taken into the circle's frame
                // (relative to its center) in f64 from the stored ray.
                let (ro, rd) = (ray.origin(), ray.direction());
                let rel = (ro.x as f64 - place.0, ro.y as f64 - place.1);
                let lo = (c * rel.0 + s * rel.1 - center.0, -s * rel.0 + c * rel.1 - center.1);
                let ld = (c * rd.x as f64 + s * rd.y as f64, -s * rd.x as f64 + c * rd.y as f64);
                let limit = if max > 0.0 { max } else { R::INFINITY };
                let local = circle
                    .cast_local_ray($vec::new(lo.0 as R, lo.1 as R), $vec::new(ld.0 as R, ld.1 as R), limit)
                    .unwrap();
                // Within rounding of a verdict's edge either may be right:
                // the origin on the circle, a tangent ray, a hit at the bound.
                let scale = radius + lo.0.hypot(lo.1) + max as f64;
                let edge = 64.0 * eps * scale;
                let across = (ld.0 * lo.1 - ld.1 * lo.0).abs();
                let on_circle = (lo.0.hypot(lo.1) - radius).abs() <= edge;
                let tangent = (across - radius).abs() <= (edge * scale / radius).sqrt() + edge;
                match (placed.outcome, local.outcome) {
                    (RayOutcome::Hit(h), RayOutcome::Hit(l)) => {
                        prop_assert!((h.distance as f64 - l.distance as f64).abs() <= h.error_bound as f64 + edge,
                            "distance {} against the local {} (bound {})", h.distance, l.distance, h.error_bound);
                        let n = (h.normal.x as f64, h.normal.y as f64);
                        let ln = (c * l.normal.x as f64 - s * l.normal.y as f64, s * l.normal.x as f64 + c * l.normal.y as f64);
                        prop_assert!((n.0.hypot(n.1) - 1.0).abs() <= 8.0 * eps, "normal {:?} not unit", n);
                        prop_assert!((n.0 - ln.0).hypot(n.1 - ln.1) <= 1e3 * eps + h.error_bound as f64 / radius,
                            "normal {:?} against the local {:?}", n, ln);
                    }
                    (p, l) => {
                        let hit = match (p, l) {
                            (RayOutcome::Hit(h), _) | (_, RayOutcome::Hit(h)) => Some(h.distance as f64),
                            _ => None,
                        };
                        let near_max = hit.is_some_and(|t| max > 0.0 && (t - max as f64).abs() <= edge);
                        prop_assert!(format!("{p:?}") == format!("{l:?}") || on_circle || tangent || near_max,
                            "{:?} against the local {:?}", p, l);
                    }
                }
            }
        }
    };
}

disk_ray_suite!(f32_disk_rays_match_the_local_cast, f32, Vec2);
disk_ray_suite!(f64_disk_rays_match_the_local_cast, f64, DVec2);
