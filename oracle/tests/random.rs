//! Randomised cross-checks: the prefiltered oracle against a brute-force evaluation
//! (every candidate exact) and against plain float formulas (agreement to ~1e-9).

use gjk2d_oracle::{pair, ray, transform_shape, ExactShape, RayStatus, Shape};

struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn ngon(rng: &mut Rng, n: usize, r: f64) -> Vec<[f64; 2]> {
    let mut angles: Vec<f64> = (0..n).map(|_| rng.next() * std::f64::consts::TAU).collect();
    angles.sort_by(|a, b| a.partial_cmp(b).unwrap());
    angles.iter().map(|a| [r * a.cos(), r * a.sin()]).collect()
}

/// Float reference: distance between disjoint convex polygons (vertex vs edge), and a
/// separating axis test.
fn float_dist(a: &[[f64; 2]], b: &[[f64; 2]]) -> f64 {
    let ps = |p: [f64; 2], s: [f64; 2], t: [f64; 2]| {
        let (ex, ey) = (t[0] - s[0], t[1] - s[1]);
        let (wx, wy) = (p[0] - s[0], p[1] - s[1]);
        let u = ((wx * ex + wy * ey) / (ex * ex + ey * ey)).clamp(0.0, 1.0);
        (wx - u * ex).hypot(wy - u * ey)
    };
    let mut m = f64::INFINITY;
    for (x, y) in [(a, b), (b, a)] {
        for &p in x {
            for j in 0..y.len() {
                m = m.min(ps(p, y[j], y[(j + 1) % y.len()]));
            }
        }
    }
    m
}

#[test]
fn polygons_agree_with_float_reference() {
    let mut rng = Rng(0x1234_5678_9abc_def1);
    for case in 0..300 {
        let n = [3, 8, 17, 64][case % 4];
        let a = ngon(&mut rng, n, 1.0);
        let b0 = ngon(&mut rng, n, 0.7);
        let (c, s) = (rng.next().cos(), rng.next().sin());
        let (tx, ty) = (rng.next() * 4.0 - 2.0, rng.next() * 4.0 - 2.0);
        let bt: Vec<[f64; 2]> = b0.iter().map(|p| [c * p[0] - s * p[1] + tx, s * p[0] + c * p[1] + ty]).collect();
        let ea = ExactShape::from(&Shape::Polygon(a.clone()));
        let eb = transform_shape(&Shape::Polygon(b0.clone()), c, s, tx, ty);
        let p = pair(&ea, &eb);
        if !p.touching_or_overlapping {
            let fd = float_dist(&a, &bt);
            assert!((p.distance - fd).abs() < 1e-9, "case {case}: {} vs {fd}", p.distance);
            let dx = p.point_b[0] - p.point_a[0];
            let dy = p.point_b[1] - p.point_a[1];
            assert!((dx.hypot(dy) - p.distance).abs() < 1e-9);
        } else {
            // Moving B by depth (+ a little) along the normal separates; by depth
            // (- a little) does not.
            let d = p.depth;
            let moved = |k: f64| {
                let v: Vec<[f64; 2]> = bt.iter().map(|q| [q[0] + p.normal[0] * k, q[1] + p.normal[1] * k]).collect();
                pair(&ea, &ExactShape::from(&Shape::Polygon(v))).touching_or_overlapping
            };
            assert!(!moved(d + 1e-9), "case {case}");
            assert!(moved(d - 1e-9), "case {case}");
        }
    }
}

#[test]
fn thousand_gons() {
    let mut rng = Rng(42);
    let a = ngon(&mut rng, 1500, 1.0);
    let b = ngon(&mut rng, 1200, 1.0);
    let ea = ExactShape::from(&Shape::Polygon(a.clone()));
    for (tx, ty) in [(2.5, 0.3), (1.2, 0.4), (0.3, 0.1)] {
        let bt: Vec<[f64; 2]> = b.iter().map(|p| [p[0] + tx, p[1] + ty]).collect();
        let eb = ExactShape::from(&Shape::Polygon(bt.clone()));
        let p = pair(&ea, &eb);
        if !p.touching_or_overlapping {
            assert!((p.distance - float_dist(&a, &bt)).abs() < 1e-9);
        } else {
            assert!(p.depth > 0.0);
        }
    }
}

#[test]
fn rays_agree_with_float_reference() {
    let mut rng = Rng(7);
    for _ in 0..200 {
        let r = rng.next() * 0.5 + 0.1;
        let c = [rng.next() * 2.0 - 1.0, rng.next() * 2.0 - 1.0];
        let s = ExactShape::from(&Shape::Circle { center: c, radius: r });
        let o = [rng.next() * 6.0 - 3.0, rng.next() * 6.0 - 3.0];
        let d = [rng.next() * 2.0 - 1.0, rng.next() * 2.0 - 1.0];
        let ans = ray(o, d, 0.0, &s);
        let dl = d[0].hypot(d[1]);
        let u = [d[0] / dl, d[1] / dl];
        let w = [o[0] - c[0], o[1] - c[1]];
        let b = u[0] * w[0] + u[1] * w[1];
        let cc = w[0] * w[0] + w[1] * w[1] - r * r;
        let disc = b * b - cc;
        match ans.status {
            RayStatus::Inside => assert!(cc <= 1e-12),
            RayStatus::Hit => {
                let t = -b - disc.sqrt();
                assert!((ans.t - t).abs() < 1e-9);
                let h = [o[0] + u[0] * t - c[0], o[1] + u[1] * t - c[1]];
                assert!((ans.normal[0] - h[0] / r).abs() < 1e-7);
                assert!((ans.normal[1] - h[1] / r).abs() < 1e-7);
            }
            RayStatus::Miss => {
                assert!(disc < 1e-12 || b > -1e-12);
                assert!(ans.margin > 0.0);
            }
        }
    }
}
