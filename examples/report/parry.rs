//! parry's side: the same measurement for parry2d (f32) and parry2d-f64, through its
//! public dyn-Shape API (identity poses, shapes given in world coordinates).

macro_rules! parry_side {
    ($m:ident, $p:ident, $R:ty) => {
        pub(crate) mod $m {
            use crate::cases::{Cases, Family, RayVerdict, Sh};
            use crate::judge::{judge_manifold, judge_pair, judge_ray, Acc, Out, Query};
            use crate::timing::{Batch, TIMED_CASES};
            use gjk2d::Status;
            use std::hint::black_box;
            use $p::math::{Pose, Vector};
            use $p::query::{self, ContactManifold, DefaultQueryDispatcher, PersistentQueryDispatcher, Ray};
            use $p::shape::{Ball, Capsule, ConvexPolygon, Shape};

            pub struct PS {
                s: Box<dyn Shape>,
                pos: Pose,
            }

            fn v(p: &[f64; 2]) -> Vector {
                Vector::new(p[0] as $R, p[1] as $R)
            }

            /// `None` for ellipses (parry has none). Polygons keep every vertex
            /// (`from_convex_polyline_unmodified`; `from_convex_polyline` would drop
            /// vertices whose edges turn by less than sqrt(eps), changing the shape).
            pub fn build(sh: &Sh) -> Option<PS> {
                Some(match sh {
                    Sh::Poly(p) => PS {
                        s: Box::new(ConvexPolygon::from_convex_polyline_unmodified(p.iter().map(v).collect())?),
                        pos: Pose::identity(),
                    },
                    Sh::Circle(c, r) => PS { s: Box::new(Ball::new(*r as $R)), pos: Pose::from_translation(v(c)) },
                    Sh::Capsule(a, b, r) => {
                        PS { s: Box::new(Capsule::new(v(a), v(b), *r as $R)), pos: Pose::identity() }
                    }
                    Sh::Ellipse(..) => return None,
                })
            }

            fn w(x: Vector) -> [f64; 2] {
                [x.x as f64, x.y as f64]
            }

            fn pair_query(q: Query, a: &PS, b: &PS) -> Out {
                match q {
                    Query::Intersect => Out::Verdict(
                        query::intersection_test(&a.pos, &*a.s, &b.pos, &*b.s).map_or(false, |i| i.intersecting),
                    ),
                    Query::Distance => {
                        // parry reports 0 for overlap; its normal comes from closest points.
                        match query::distance(&a.pos, &*a.s, &b.pos, &*b.s) {
                            Ok(d) if d.distance > 0.0 => {
                                let n = match query::closest_points(&a.pos, &*a.s, &b.pos, &*b.s, <$R>::MAX) {
                                    Ok(query::ClosestPoints::WithinMargin(p1, p2)) => {
                                        let d = p2 - p1;
                                        w(d / d.length())
                                    }
                                    _ => [f64::NAN; 2],
                                };
                                Out::Value(Some((d.distance as f64, n)))
                            }
                            _ => Out::Value(None),
                        }
                    }
                    Query::Penetration => match query::contact(&a.pos, &*a.s, &b.pos, &*b.s, 0.0) {
                        Ok(Some(c)) if c.dist <= 0.0 => Out::Value(Some((-(c.dist as f64), w(c.normal1)))),
                        _ => Out::Value(None),
                    },
                    Query::Manifold => {
                        let mut manifolds = Vec::new();
                        manifold(a, b, &mut manifolds);
                        let Some(m) = manifolds.iter().find(|m| !m.points.is_empty()) else {
                            return Out::Manifold([1.0, 0.0], Vec::new());
                        };
                        let points = m
                            .points
                            .iter()
                            .filter(|p| p.dist <= 0.0)
                            .map(|p| (w(a.pos * p.local_p1), w(b.pos * p.local_p2), p.dist as f64))
                            .collect();
                        Out::Manifold(w(a.pos.rotation * m.local_n1), points)
                    }
                    Query::Ray | Query::Cast => unreachable!(),
                }
            }

            /// parry's contact manifolds of A and B (margin zero), computed
            /// cold: `manifolds` cleared, no workspace kept.
            fn manifold(a: &PS, b: &PS, manifolds: &mut Vec<ContactManifold<(), ()>>) {
                manifolds.clear();
                let pos12 = a.pos.inv_mul(&b.pos);
                let _ = DefaultQueryDispatcher.contact_manifolds(&pos12, &*a.s, &*b.s, 0.0, manifolds, &mut None);
            }

            /// B moving by `m` against A: parry's shape cast, its time of
            /// impact scaled to the distance travelled; a penetration at
            /// the start is `Inside`.
            fn cast_query(a: &PS, b: &PS, m: Vector) -> Out {
                let options = query::ShapeCastOptions::with_max_time_of_impact(1.0);
                match query::cast_shapes(&a.pos, Vector::ZERO, &*a.s, &b.pos, m, &*b.s, options) {
                    Ok(Some(h)) if h.status == query::ShapeCastStatus::PenetratingOrWithinTargetDist => {
                        Out::Ray(RayVerdict::Inside, 0.0, [0.0; 2])
                    }
                    Ok(Some(h)) => Out::Ray(RayVerdict::Hit, h.time_of_impact as f64 * m.length() as f64, w(h.normal1)),
                    _ => Out::Ray(RayVerdict::Miss, 0.0, [0.0; 2]),
                }
            }

            fn ray_query(ray: &Ray, max: $R, s: &PS) -> Out {
                match s.s.cast_ray_and_get_normal(&s.pos, ray, max, true) {
                    Some(h) if h.time_of_impact == 0.0 => Out::Ray(RayVerdict::Inside, 0.0, [0.0; 2]),
                    Some(h) => Out::Ray(RayVerdict::Hit, h.time_of_impact as f64, w(h.normal)),
                    None => Out::Ray(RayVerdict::Miss, 0.0, [0.0; 2]),
                }
            }

            pub enum PFamily {
                Pairs(Vec<(PS, PS)>),
                Rays(Vec<(Ray, $R, PS)>),
                Casts(Vec<(PS, PS, Vector)>),
                Unsupported,
            }

            pub fn build_family(f: &Family) -> PFamily {
                match &f.cases {
                    Cases::Pairs(c) => {
                        let v: Option<Vec<(PS, PS)>> = c
                            .iter()
                            .map(|c| (&c.a, &c.b))
                            .chain(f.extra_pairs().iter().map(|(a, b)| (a, b)))
                            .map(|(a, b)| Some((build(a)?, build(b)?)))
                            .collect();
                        v.map_or(PFamily::Unsupported, PFamily::Pairs)
                    }
                    Cases::Rays(c) => {
                        let v: Option<Vec<(Ray, $R, PS)>> = c
                            .iter()
                            .map(|c| (&c.o, &c.d, c.max_len, &c.s))
                            .chain(f.extra_rays().iter().map(|(o, d, m, s)| (o, d, *m, s)))
                            .map(|(o, d, max_len, s)| {
                                let d = v(d);
                                let max = if max_len > 0.0 { max_len as $R } else { <$R>::MAX };
                                Some((Ray::new(v(o), d / d.length()), max, build(s)?))
                            })
                            .collect();
                        v.map_or(PFamily::Unsupported, PFamily::Rays)
                    }
                    Cases::Casts(c) => {
                        let v: Option<Vec<(PS, PS, Vector)>> = c
                            .iter()
                            .map(|c| (&c.a, &c.b, &c.m))
                            .chain(f.extra_casts().iter().map(|(a, b, m)| (a, b, m)))
                            .map(|(a, b, m)| Some((build(a)?, build(b)?, v(m))))
                            .collect();
                        v.map_or(PFamily::Unsupported, PFamily::Casts)
                    }
                }
            }

            pub fn accuracy_and_batch<'a>(f: &'a Family, pf: &'a PFamily, q: Query) -> Option<(Acc, usize, Batch<'a>)> {
                let eps = <$R>::EPSILON as f64;
                let mut acc = Acc::default();
                match (&f.cases, pf) {
                    (Cases::Pairs(cases), PFamily::Pairs(shapes)) => {
                        for (c, (a, b)) in cases.iter().zip(shapes) {
                            let out = pair_query(q, a, b);
                            match q {
                                Query::Manifold => judge_manifold(&mut acc, c, eps, out, (Status::Converged, None)),
                                _ => judge_pair(&mut acc, q, c, eps, out, (Status::Converged, None)),
                            }
                        }
                        // One loop a query kind, as for gjk2d.
                        let pairs = || shapes.iter().take(TIMED_CASES).map(|(a, b)| (black_box(a), black_box(b)));
                        let batch: Batch<'a> = match q {
                            Query::Intersect => Box::new(move || {
                                for (a, b) in pairs() {
                                    let _ = black_box(query::intersection_test(&a.pos, &*a.s, &b.pos, &*b.s));
                                }
                            }),
                            Query::Distance => Box::new(move || {
                                for (a, b) in pairs() {
                                    let _ = black_box(query::distance(&a.pos, &*a.s, &b.pos, &*b.s));
                                }
                            }),
                            Query::Penetration => Box::new(move || {
                                for (a, b) in pairs() {
                                    let _ = black_box(query::contact(&a.pos, &*a.s, &b.pos, &*b.s, 0.0));
                                }
                            }),
                            Query::Manifold => Box::new(move || {
                                let mut manifolds: Vec<ContactManifold<(), ()>> = Vec::with_capacity(1);
                                for (a, b) in pairs() {
                                    manifold(a, b, &mut manifolds);
                                    black_box(&manifolds);
                                }
                            }),
                            Query::Ray | Query::Cast => unreachable!(),
                        };
                        Some((acc, shapes.len().min(TIMED_CASES), batch))
                    }
                    (Cases::Rays(cases), PFamily::Rays(rays)) => {
                        for (c, (ray, max, s)) in cases.iter().zip(rays) {
                            judge_ray(&mut acc, &c.truth, c.l, eps, ray_query(ray, *max, s), (Status::Converged, None));
                        }
                        let batch: Batch<'a> = Box::new(move || {
                            for (ray, max, s) in rays.iter().take(TIMED_CASES) {
                                let s = black_box(s);
                                black_box(s.s.cast_ray_and_get_normal(&s.pos, black_box(ray), *max, true));
                            }
                        });
                        Some((acc, rays.len().min(TIMED_CASES), batch))
                    }
                    (Cases::Casts(cases), PFamily::Casts(casts)) => {
                        for (c, (a, b, m)) in cases.iter().zip(casts) {
                            judge_ray(&mut acc, &c.truth, c.l, eps, cast_query(a, b, *m), (Status::Converged, None));
                        }
                        let batch: Batch<'a> = Box::new(move || {
                            let options = query::ShapeCastOptions::with_max_time_of_impact(1.0);
                            for (a, b, m) in casts.iter().take(TIMED_CASES) {
                                let (a, b) = (black_box(a), black_box(b));
                                let _ = black_box(query::cast_shapes(
                                    &a.pos,
                                    Vector::ZERO,
                                    &*a.s,
                                    &b.pos,
                                    *m,
                                    &*b.s,
                                    options,
                                ));
                            }
                        });
                        Some((acc, casts.len().min(TIMED_CASES), batch))
                    }
                    _ => None,
                }
            }
        }
    };
}

parry_side!(parry32, parry2d, f32);
parry_side!(parry64, parry2d_f64, f64);
