//! Measures the oracle's cost per pair query (run with `--release`).

use gjk2d_oracle::{pair, ray, transform_shape, ExactShape, Shape};
use std::time::Instant;

fn main() {
    let mut seed: u64 = 99;
    let mut rnd = move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 11) as f64 / (1u64 << 53) as f64
    };
    for n in [8usize, 64, 1000] {
        let cases = if n >= 1000 { 20 } else { 2000 };
        let mut shapes = Vec::new();
        for _ in 0..cases {
            let mut ang: Vec<f64> = (0..n).map(|_| rnd() * std::f64::consts::TAU).collect();
            ang.sort_by(|a, b| a.partial_cmp(b).unwrap());
            let poly = Shape::Polygon(ang.iter().map(|a| [a.cos(), a.sin()]).collect());
            let t = rnd() * 6.0;
            let (tx, ty) = (rnd() * 5.0 - 2.5, rnd() * 5.0 - 2.5);
            let a = ExactShape::from(&poly);
            let b = transform_shape(&poly, t.cos(), t.sin(), tx, ty);
            shapes.push((a, b));
        }
        let start = Instant::now();
        let mut overlapping = 0;
        for (a, b) in &shapes {
            if pair(a, b).touching_or_overlapping {
                overlapping += 1;
            }
        }
        let us = start.elapsed().as_secs_f64() * 1e6 / cases as f64;
        let start = Instant::now();
        for (_, b) in shapes.iter().take(if n >= 1000 { 3 } else { 200 }) {
            let _ = ray([-3.0, 0.1], [1.0, 0.05], 0.0, b);
        }
        let rus = start.elapsed().as_secs_f64() * 1e6 / cases.min(if n >= 1000 { 3 } else { 200 }) as f64;
        println!("{n:5}-gon pairs: {us:9.1} us/pair ({overlapping}/{cases} overlapping); rays {rus:9.1} us/ray");
    }
}
