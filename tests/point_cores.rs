//! Two circles whose types are known when the program is compiled skip GJK's
//! loop: the queries finish from what the loop would end with. Through
//! `dyn SupportMap` the loop still runs, so the two must agree to the bit,
//! iterations and status included, for placed and rotated pairs, touching,
//! coincident and far apart, with and without a detection margin.

use gjk2d::glam::{DVec2, Vec2};
use gjk2d::{Circle, Gjk, SupportMap, Transform};
use proptest::prelude::*;

macro_rules! point_core_suite {
    ($name:ident, $r:ty, $vec:ident) => {
        proptest! {
            #![proptest_config(ProptestConfig::with_cases(2000))]
            #[test]
            fn $name(
                ca in (-3i32..=3, -3i32..=3), cb in (-3i32..=3, -3i32..=3),
                ra in 1u32..=4, rb in 1u32..=4,
                ta in (-1.0e3f64..1.0e3, -1.0e3f64..1.0e3, 0.0f64..6.3),
                tb in (-1.0e3f64..1.0e3, -1.0e3f64..1.0e3, 0.0f64..6.3),
                nudge in -2.0f64..2.0, margin in prop::bool::ANY,
            ) {
                // Small integer centers and radii make touching and coincident
                // pairs common; the nudge moves B off them by a little.
                let a = Circle::<$r>::at($vec::new(ca.0 as $r, ca.1 as $r), ra as $r).unwrap();
                let b = Circle::<$r>::at($vec::new(cb.0 as $r + (nudge * 1e-6) as $r, cb.1 as $r), rb as $r).unwrap();
                let place = |t: (f64, f64, f64), same: bool| {
                    let angle = if same { ta.2 } else { t.2 };
                    Transform::<$r>::new($vec::new(t.0 as $r, t.1 as $r), angle as $r).unwrap()
                };
                // Half the pairs share A's placement exactly.
                let (pa, pb) = (place(ta, false), place(tb, nudge > 0.0));
                let pb = if nudge.abs() < 0.5 { pa } else { pb };
                let mut gjk = Gjk::<$r>::new();
                if margin {
                    gjk.config.set_detect_epsilon(1e-3).unwrap();
                }
                let (da, db): (&dyn SupportMap<$r>, &dyn SupportMap<$r>) = (&a, &b);
                // Compared as printed: `{:?}` tells -0.0 from 0.0, `==` would not.
                macro_rules! same {
                    ($x:expr, $y:expr) => {
                        prop_assert_eq!(format!("{:?}", $x), format!("{:?}", $y))
                    };
                }
                same!(gjk.intersects(&a, &pa, &b, &pb), gjk.intersects(da, &pa, db, &pb));
                same!(gjk.distance(&a, &pa, &b, &pb), gjk.distance(da, &pa, db, &pb));
                same!(gjk.penetration(&a, &pa, &b, &pb), gjk.penetration(da, &pa, db, &pb));
                same!(gjk.distance(&a, &pa, &a, &pa), gjk.distance(da, &pa, da, &pa));
                same!(gjk.penetration(&b, &pb, &b, &pb), gjk.penetration(db, &pb, db, &pb));
            }
        }
    };
}

point_core_suite!(point_cores_match_the_loop_f32, f32, Vec2);
point_core_suite!(point_cores_match_the_loop_f64, f64, DVec2);
