//! Geometry stored far from its own local origin (10 to 1000 of its sizes
//! away, as the parts of a compound body are from the body's origin),
//! rotated and placed next to other such geometry, against the exact
//! oracle, in f32 and f64. With the feature `far-geometry` the pair is
//! placed with error-free sums and products, and the queries keep README's
//! 8·eps·L (L the larger bounding radius, not the distance from the local
//! origin) with no wrong verdict beyond it. Without it, rotating such a
//! shape rounds at the reference's distance d (both shapes' summed), and
//! the figure is 8·eps·(L + d). `GJK2D_LONG=N` multiplies the cases by N.

use gjk2d::*;
use gjk2d_oracle::{pair, transform_shape, Shape};
use std::f64::consts::TAU;

#[path = "common/rng.rs"]
mod rng;
use rng::{cases, polygon_about_origin, Rng};

type Pt = [f64; 2];

fn norm(p: Pt) -> f64 {
    p[0].hypot(p[1])
}

/// Pairs per kind of pair, distance from the origin and precision.
const CASES: u32 = 300;

#[derive(Clone, Copy, Debug)]
enum Kind {
    Gon8,
    Circle,
    Capsule,
}

fn v<R: Real>(p: Pt) -> R::Vector {
    R::vector(R::from_f64(p[0]), R::from_f64(p[1]))
}
fn q<R: Real>(x: f64) -> f64 {
    R::from_f64(x).to_f64()
}

/// A shape of size `s` about `at` in its local frame, with the oracle's
/// copy of it (the coordinates gjk2d holds).
fn shape<R: Real>(kind: Kind, rng: &mut Rng, at: Pt, s: f64) -> Option<(Box<dyn SupportMap<R>>, Shape)> {
    let p = |x: f64, y: f64| [q::<R>(at[0] + s * x), q::<R>(at[1] + s * y)];
    Some(match kind {
        Kind::Gon8 => {
            let local: Vec<Pt> = polygon_about_origin(rng, 8, |x| x).iter().map(|c| p(c[0], c[1])).collect();
            let poly = Polygon::<R, 8>::new(&local.iter().map(|&c| v::<R>(c)).collect::<Vec<_>>()).ok()?;
            let held = (0..poly.len())
                .map(|i| poly.vertex(i).map(|c| R::components(c)).map(|(x, y)| [x.to_f64(), y.to_f64()]))
                .collect::<Option<_>>()?;
            (Box::new(poly), Shape::Polygon(held))
        }
        Kind::Circle => {
            let (c, r) = (p(0.0, 0.0), q::<R>(s * rng.range(0.3, 1.0)));
            (Box::new(Circle::<R>::at(v::<R>(c), R::from_f64(r)).ok()?), Shape::Circle { center: c, radius: r })
        }
        Kind::Capsule => {
            let u = [rng.range(-1.0, 1.0), rng.range(-1.0, 1.0)];
            let (a, b, r) = (p(u[0], u[1]), p(-u[0], -u[1]), q::<R>(s * rng.range(0.1, 0.6)));
            (
                Box::new(Capsule::<R>::new(v::<R>(a), v::<R>(b), R::from_f64(r)).ok()?),
                Shape::Capsule { a, b, radius: r },
            )
        }
    })
}

/// The pair queries of `CASES` pairs of `kinds` whose geometry
/// lies `away` sizes from their local origins: the worst error
/// over eps L, and the failures.
fn run<R: Real>(kinds: (Kind, Kind), away: f64, seed: u64) -> (f64, Vec<String>) {
    let eps = R::EPSILON.to_f64();
    let mut rng = Rng(seed);
    let gjk = Gjk::<R>::new();
    let (mut worst, mut failures) = (0.0f64, Vec::new());
    let mut plain_beyond = 0.0f64;
    for _ in 0..cases(CASES) {
        let s = 10f64.powf(rng.range(-2.0, 2.0));
        let local = |rng: &mut Rng| {
            let a = rng.range(0.0, TAU);
            [s * away * a.cos(), s * away * a.sin()]
        };
        let (at_a, at_b) = (local(&mut rng), local(&mut rng));
        let (Some((a, exact_a)), Some((b, exact_b))) =
            (shape::<R>(kinds.0, &mut rng, at_a, s), shape::<R>(kinds.1, &mut rng, at_b, s))
        else {
            continue;
        };
        // A anywhere within 100 sizes; B's geometry 0.5 to 3 sizes
        // from A's, each turned at random.
        let (turn_a, turn_b) = (rng.range(0.0, TAU), rng.range(0.0, TAU));
        let ta_at = [s * rng.range(-100.0, 100.0), s * rng.range(-100.0, 100.0)];
        let Ok(ta) = Transform::new(v::<R>(ta_at), R::from_f64(turn_a)) else { continue };
        let place = |c: f64, sn: f64, p: Pt, t: Pt| [c * p[0] - sn * p[1] + t[0], sn * p[0] + c * p[1] + t[1]];
        let a_world = place(turn_a.cos(), turn_a.sin(), at_a, ta_at);
        let gap = rng.range(0.5, 3.0) * s;
        let dir = rng.range(0.0, TAU);
        let b_world = [a_world[0] + gap * dir.cos(), a_world[1] + gap * dir.sin()];
        let b_turned = place(turn_b.cos(), turn_b.sin(), at_b, [0.0; 2]);
        let Ok(tb) = Transform::new(v::<R>([b_world[0] - b_turned[0], b_world[1] - b_turned[1]]), R::from_f64(turn_b))
        else {
            continue;
        };
        let placed = |shape: &Shape, t: &Transform<R>| {
            let (x, y) = R::components(t.translation());
            transform_shape(shape, t.cos().to_f64(), t.sin().to_f64(), x.to_f64(), y.to_f64())
        };
        let exact = pair(&placed(&exact_a, &ta), &placed(&exact_b, &tb));
        let l = a.bounding_radius().to_f64().max(b.bounding_radius().to_f64());
        let rounded = if cfg!(feature = "far-geometry") { 0.0 } else { norm(at_a) + norm(at_b) };
        let tol = 8.0 * eps * (l + rounded);
        let what = || format!("{kinds:?} {away} sizes away, size {s:e}, turns {turn_a} {turn_b}");
        let overlap = gjk.intersects(&*a, &ta, &*b, &tb).intersecting;
        if exact.signed_distance.abs() > tol && overlap != exact.touching_or_overlapping {
            failures.push(format!(
                "{}: intersects {overlap}, exact signed distance {:e}",
                what(),
                exact.signed_distance
            ));
        }
        let (got, want) = match (gjk.distance(&*a, &ta, &*b, &tb), gjk.penetration(&*a, &ta, &*b, &tb)) {
            (Some(d), _) => (d.distance.to_f64(), exact.distance),
            (None, Some(p)) => (p.depth.to_f64(), exact.depth),
            (None, None) => (0.0, exact.signed_distance.abs()),
        };
        let err = (got - want).abs();
        worst = worst.max(err / (eps * l));
        if err > tol {
            failures.push(format!("{}: {got} against exact {want} ({:.1} eps L)", what(), err / (eps * l)));
        }
        // Far from the origins the plain placement rounds far
        // beyond the figure: the test can tell the two apart.
        if !cfg!(feature = "far-geometry") && away >= 100.0 {
            plain_beyond = plain_beyond.max(err / (8.0 * eps * l));
        }
    }
    if !cfg!(feature = "far-geometry") && away >= 100.0 && plain_beyond <= 1.0 {
        failures.push(format!("{kinds:?} {away} sizes away: the plain placement kept 8 eps L"));
    }
    (worst, failures)
}

/// Every kind of pair at 10, 100 and 1000 sizes from the origins.
fn far_geometry_keeps_the_pair_precision<R: Real>(precision: &str) {
    let kinds = [
        (Kind::Gon8, Kind::Gon8),
        (Kind::Circle, Kind::Gon8),
        (Kind::Capsule, Kind::Gon8),
        (Kind::Capsule, Kind::Capsule),
    ];
    let mut failures = Vec::new();
    for (k, &pair_kinds) in kinds.iter().enumerate() {
        for (j, away) in [10.0, 100.0, 1000.0].into_iter().enumerate() {
            let (worst, found) = run::<R>(pair_kinds, away, 0xfa7 + 16 * k as u64 + j as u64);
            eprintln!("{precision} {pair_kinds:?} {away} sizes away: worst {worst:.2} eps L");
            failures.extend(found.into_iter().take(3));
        }
    }
    assert!(failures.is_empty(), "{} failures:\n{}", failures.len(), failures.join("\n"));
}

#[test]
fn far_geometry_f32() {
    far_geometry_keeps_the_pair_precision::<f32>("f32");
}
#[test]
fn far_geometry_f64() {
    far_geometry_keeps_the_pair_precision::<f64>("f64");
}
