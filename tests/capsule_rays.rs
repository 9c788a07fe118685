//! Capsule rays on exact dyadic geometry, at every scale from tiny to the
//! largest coordinates: a capsule of core length `s` and radius `5 s / 64`
//! along either axis (either end first), rays that start inside it or on
//! its side, hit a side, hit an end's cap head on, across it and along the
//! side line's tangent, pass it by, point away, or stop short. Every answer
//! here is a power-of-two multiple of small integers (the cap's chord is a
//! 3-4-5 triangle), so the distances are checked exactly, and the normals
//! to a few ulps where they are fifths.

use gjk2d::glam::{DVec2, Vec2};
use gjk2d::{Capsule, Gjk, Ray, RayOutcome, SupportMap, Transform};

#[derive(Clone, Copy, Debug)]
enum Expect {
    Inside,
    Miss,
    /// Distance and normal, in units of `s` (the normal as is).
    Hit(f64, (f64, f64)),
}

/// A ray in units of `s`: origin, direction, maximum length (0: unbounded),
/// and the exact answer.
type Case = ((f64, f64), (f64, f64), f64, Expect);

/// Rays in a capsule's frame, along x from `(-s/2, 0)` to `(s/2, 0)` with
/// radius `5 s / 64`.
fn cases() -> Vec<Case> {
    let r = 5.0 / 64.0;
    vec![
        // Inside: over the core, in a cap, on the side line.
        ((0.0, 1.0 / 32.0), (1.0, 0.0), 0.0, Expect::Inside),
        ((-0.5 - 1.0 / 32.0, 0.0), (0.0, 1.0), 0.0, Expect::Inside),
        ((0.25, r), (0.0, 1.0), 0.0, Expect::Inside),
        // A side, from above and from below.
        ((0.0, 1.0), (0.0, -1.0), 0.0, Expect::Hit(1.0 - r, (0.0, 1.0))),
        ((0.25, -1.0), (0.0, 1.0), 0.0, Expect::Hit(1.0 - r, (0.0, -1.0))),
        // Bounded: short of the hit, and exactly at it.
        ((0.0, 1.0), (0.0, -1.0), 0.5, Expect::Miss),
        ((0.0, 1.0), (0.0, -1.0), 1.0 - r, Expect::Hit(1.0 - r, (0.0, 1.0))),
        // A cap head on, from either end.
        ((-2.0, 0.0), (1.0, 0.0), 0.0, Expect::Hit(2.0 - 0.5 - r, (-1.0, 0.0))),
        ((2.0, 0.0), (-1.0, 0.0), 0.0, Expect::Hit(2.0 - 0.5 - r, (1.0, 0.0))),
        // Down past an end: it crosses the side line beyond the core and
        // meets the cap 3 r / 5 from its center, 4 r / 5 up.
        ((-0.5 - 3.0 / 64.0, 1.0), (0.0, -1.0), 0.0, Expect::Hit(15.0 / 16.0, (-0.6, 0.8))),
        ((0.5 + 3.0 / 64.0, -1.0), (0.0, 1.0), 0.0, Expect::Hit(15.0 / 16.0, (0.6, -0.8))),
        // Along the side line from beyond an end: it touches the cap's top.
        ((-2.0, r), (1.0, 0.0), 0.0, Expect::Hit(1.5, (0.0, 1.0))),
        // Away, parallel above, and past an end.
        ((0.0, 1.0), (0.0, 1.0), 0.0, Expect::Miss),
        ((-2.0, 0.5), (1.0, 0.0), 0.0, Expect::Miss),
        ((-1.0, 1.0), (0.0, -1.0), 0.0, Expect::Miss),
    ]
}

macro_rules! capsule_ray_suite {
    ($name:ident, $r:ty, $vec:ident, $scales:expr) => {
        #[test]
        fn $name() {
            type R = $r;
            let gjk = Gjk::<R>::new();
            let mut checked = 0;
            for k in $scales {
                let s = (2.0f64).powi(k);
                // Along x, or turned a quarter (exactly: cos 0, sin 1), and
                // with its ends either way round.
                for (quarter, reversed) in [(false, false), (false, true), (true, false), (true, true)] {
                    let turn = |p: (f64, f64)| if quarter { (-p.1, p.0) } else { p };
                    let v = |p: (f64, f64)| $vec::new((p.0 * s) as R, (p.1 * s) as R);
                    let (mut a, mut b) = (v((-0.5, 0.0)), v((0.5, 0.0)));
                    if reversed {
                        core::mem::swap(&mut a, &mut b);
                    }
                    let capsule = Capsule::<R>::new(a, b, (5.0 / 64.0 * s) as R).unwrap();
                    let t = if quarter {
                        Transform::<R>::from_cos_sin($vec::ZERO, 0.0, 1.0).unwrap()
                    } else {
                        Transform::<R>::IDENTITY
                    };
                    for (o, d, max, expect) in cases() {
                        let ray = Ray::<R>::new(v(turn(o)), v(turn(d)) / (s as R)).unwrap();
                        let label = format!("s = 2^{k}, quarter {quarter}, reversed {reversed}, {o:?} {d:?}");
                        for cast in [
                            gjk.raycast(&ray, (max * s) as R, &capsule, &t),
                            gjk.raycast(&ray, (max * s) as R, &capsule as &dyn SupportMap<R>, &t),
                        ] {
                            match (expect, cast.outcome) {
                                (Expect::Inside, RayOutcome::Inside) | (Expect::Miss, RayOutcome::Miss) => {}
                                (Expect::Hit(distance, normal), RayOutcome::Hit(hit)) => {
                                    assert_eq!(hit.distance, (distance * s) as R, "{label}: distance");
                                    let n = turn(normal);
                                    let ulps = 4.0 * R::EPSILON as f64;
                                    assert!(
                                        (hit.normal.x as f64 - n.0).abs() <= ulps
                                            && (hit.normal.y as f64 - n.1).abs() <= ulps,
                                        "{label}: normal {:?}, exact {n:?}",
                                        hit.normal
                                    );
                                }
                                (expect, outcome) => panic!("{label}: {outcome:?}, exact {expect:?}"),
                            }
                            checked += 1;
                        }
                    }
                }
            }
            assert!(checked > 1000, "{checked} casts checked");
        }
    };
}

// Up to the largest coordinates each type allows (the rays start 2 s out).
capsule_ray_suite!(f32_capsule_rays, f32, Vec2, -40..=48);
capsule_ray_suite!(f64_capsule_rays, f64, DVec2, -300..=480);
