//! Ray casts against half-ellipses and slices (GJK's ray cast: they have no
//! closed form), judged by the certified branch-and-bound oracle
//! (`gjk2d_oracle::curved`) as `tests/curved.rs` judges their distances. A ray
//! is the cast of a point: at a reported hit the point on the ray lies on the
//! boundary (within README's curved guarantee, plus rounding at the ray's
//! scale and the hit's own `error_bound`), and the ray enters nowhere before
//! it (checked at 64 points); a miss enters nowhere up to the ray's length;
//! `Inside` starts inside. Converged hits must lie within the guarantee
//! alone; one at the iteration limit within it plus its error bound. In f32 and f64, at sizes 1e-2 to 1e2, slices of
//! 1e-3 rad to pi, rays aimed at the shape, past its corners and tangent to
//! it, from near and from 1e3 sizes away.
//!
//! `cargo test --test curved_rays -- --nocapture` prints each precision's
//! worst distance from the boundary at a converged hit, in units of L (the shape's
//! bounding radius or the ray origin's distance from its centre, if larger).

// `!(err <= allowed)`: a NaN error must fail the check.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

use gjk2d::glam::{DVec2, Vec2};
use gjk2d::*;
use gjk2d_oracle::curved::{curved_pair, Local, Placed};
use std::f64::consts::{PI, TAU};

#[path = "common/rng.rs"]
mod rng;
use rng::{cases, Rng};

fn r32(x: f64) -> f64 {
    x as f32 as f64
}

macro_rules! suite {
    ($name:ident, $r:ty, $vec:ident) => {
        #[test]
        fn $name() {
            type R = $r;
            let eps = <R>::EPSILON as f64;
            let curved_tol = if eps > 1e-10 { 1e-6 } else { 1e-12 };
            let v = |p: [f64; 2]| $vec::new(p[0] as R, p[1] as R);
            let pt = |p: $vec| [p.x as f64, p.y as f64];
            let gjk = Gjk::<R>::new();
            let mut rng = Rng(0x6375_7276_6564 ^ eps.to_bits());
            let (mut worst, mut hits, mut misses, mut inside, mut limited) = (0.0f64, 0, 0, 0, 0u32);
            for i in 0..cases(4000) {
                let size = 10f64.powf(rng.range(-2.0, 2.0));
                let (w, h) = (r32(size * rng.range(0.2, 2.0)), r32(size * rng.range(0.02, 2.0)));
                let (shape, local): (Box<dyn SupportMap<R>>, Local) = if i % 2 == 0 {
                    (Box::new(HalfEllipse::<R>::new(w as R, h as R).unwrap()), Local::HalfEllipse { a: w / 2.0, h })
                } else {
                    let theta = r32(rng.range(-7.0, 0.0).exp().max(1e-3) * PI);
                    let slice = Slice::<R>::new(w as R, theta as R).unwrap();
                    // The end gjk2d computed: its support straight up (the
                    // slice spans at most pi, so that is an end).
                    let end = pt(slice.support(v([0.0, 1.0])));
                    (Box::new(slice), Local::Slice { radius: w, end })
                };
                let at = [r32(size * rng.range(-3.0, 3.0)), r32(size * rng.range(-3.0, 3.0))];
                let tf = Transform::<R>::new(v(at), rng.range(-4.0, 4.0) as R).unwrap();
                let placed = Placed::new(local.clone(), tf.cos() as f64, tf.sin() as f64, pt(tf.translation()));
                // Aim at a point of the shape (a support, so corners and
                // tangents are common) nudged by up to a tenth of the size.
                let aim_dir = rng.range(0.0, TAU);
                let target =
                    pt(tf.transform_point(shape.reference_point() + shape.support(v([aim_dir.cos(), aim_dir.sin()]))));
                let nudge = size * 0.1 * rng.range(-1.0, 1.0) * if rng.next() % 4 == 0 { 1e-5 } else { 1.0 };
                let from_dir = rng.range(0.0, TAU);
                let far = if rng.next() % 4 == 0 { 1e3 } else { rng.range(1.5, 6.0) };
                let origin =
                    [r32(target[0] + far * size * from_dir.cos()), r32(target[1] + far * size * from_dir.sin())];
                let to =
                    [target[0] - from_dir.sin() * nudge - origin[0], target[1] + from_dir.cos() * nudge - origin[1]];
                let Ok(ray) = Ray::new(v(origin), v(to)) else { continue };
                let dir = pt(ray.direction());
                let max = r32((far + 3.0) * size);
                let c = gjk.raycast(&ray, max as R, &*shape, &tf);
                let center = pt(tf.transform_point(shape.reference_point() + shape.center()));
                let l = (shape.bounding_radius() as f64).max((origin[0] - center[0]).hypot(origin[1] - center[1]));
                let tol = curved_tol * l + 16.0 * eps * l;
                let point_at = |t: f64| {
                    let p = [origin[0] + dir[0] * t, origin[1] + dir[1] * t];
                    curved_pair(&placed, &Placed::new(Local::Polygon(vec![[0.0, 0.0]]), 1.0, 0.0, p), 1e-15)
                };
                let ctx = || format!("{local:?} at {tf:?}, ray from {origin:?} along {dir:?} up to {max}: {c:?}");
                // At its iteration limit (a ray from 1e3 sizes away in f32,
                // whose point rounds by more than the tolerance) an answer
                // is judged with its error bound, as everywhere.
                limited += u32::from(!c.status.is_converged());
                match c.outcome {
                    RayOutcome::Inside => {
                        inside += 1;
                        assert!(point_at(0.0).signed <= tol, "{}", ctx());
                    }
                    RayOutcome::Miss => {
                        misses += 1;
                        for k in 0..=64 {
                            let s = point_at(max * k as f64 / 64.0);
                            assert!(s.signed > -tol, "missed an entry at {k}/64 ({:e}): {}", s.signed, ctx());
                        }
                    }
                    RayOutcome::Hit(hit) => {
                        hits += 1;
                        let t = hit.distance as f64;
                        let s = point_at(t);
                        if c.status.is_converged() {
                            worst = worst.max(s.signed.abs() / l);
                        }
                        let allowed = tol + s.error + hit.error_bound as f64;
                        assert!(s.signed.abs() <= allowed, "hit {:e} off the boundary: {}", s.signed, ctx());
                        for k in 0..64 {
                            let s = point_at(t * k as f64 / 64.0);
                            assert!(s.signed > -tol, "entered before the hit at {k}/64 ({:e}): {}", s.signed, ctx());
                        }
                    }
                }
            }
            println!(
                "{}: {hits} hits, {misses} misses, {inside} inside, {limited} at the iteration limit; worst converged hit {worst:.1e} L off the boundary",
                stringify!($name)
            );
            assert!(worst <= curved_tol + 8.0 * eps, "worst converged hit {worst:e} L off the boundary");
            assert!(hits > cases(4000) / 4 && misses > cases(4000) / 20, "too few hits or misses to judge");
        }
    };
}

suite!(single, f32, Vec2);
suite!(double, f64, DVec2);
