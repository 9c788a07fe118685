//! Signed distances from a point to curved shapes, in f64 and independent of
//! gjk2d's methods: the ellipse's by bisection on Eberly's root function, the
//! half disk's and the sector's in closed form. They answer a curved shape
//! against a circle (the distance of the circle's centre less its radius),
//! which cross-checks the support-function oracle (`tests/curved.rs`).
// Each suite uses its own subset.
#![allow(dead_code)]

use super::geo::{norm, sub, Pt};

/// Distance from `p` to the ellipse `x^2/e0^2 + y^2/e1^2 = 1` (first quadrant
/// point, `e0 >= e1`), by bisection on Eberly's root function: exact to a few
/// ulps, and independent of gjk2d's method. Inside points give the distance
/// to the boundary too.
pub fn point_ellipse_quadrant(e0: f64, e1: f64, y0: f64, y1: f64) -> f64 {
    if y1 > 0.0 {
        if y0 > 0.0 {
            let (z0, z1) = (y0 / e0, y1 / e1);
            let g = z0 * z0 + z1 * z1 - 1.0;
            if g == 0.0 {
                return 0.0;
            }
            let r0 = (e0 / e1) * (e0 / e1);
            let n0 = r0 * z0;
            let mut s0 = z1 - 1.0;
            let mut s1 = if g < 0.0 { 0.0 } else { n0.hypot(z1) - 1.0 };
            let mut s = 0.0;
            for _ in 0..2200 {
                s = 0.5 * (s0 + s1);
                if s == s0 || s == s1 {
                    break;
                }
                let (q0, q1) = (n0 / (s + r0), z1 / (s + 1.0));
                let gs = q0 * q0 + q1 * q1 - 1.0;
                if gs > 0.0 {
                    s0 = s;
                } else if gs < 0.0 {
                    s1 = s;
                } else {
                    break;
                }
            }
            let x = [r0 * y0 / (s + r0), y1 / (s + 1.0)];
            (x[0] - y0).hypot(x[1] - y1)
        } else {
            (y1 - e1).abs()
        }
    } else {
        let (numer0, denom0) = (e0 * y0, e0 * e0 - e1 * e1);
        if numer0 < denom0 {
            let xde0 = numer0 / denom0;
            let x = [e0 * xde0, e1 * (1.0 - xde0 * xde0).sqrt()];
            (x[0] - y0).hypot(x[1])
        } else {
            (y0 - e0).abs()
        }
    }
}

/// Signed distance from `p` to the ellipse of semi-axes `(a, b)` at the
/// origin: negative inside (minus the distance to the boundary).
pub fn signed_ellipse(a: f64, b: f64, p: Pt) -> f64 {
    let (px, py) = (p[0].abs(), p[1].abs());
    let d = if a >= b { point_ellipse_quadrant(a, b, px, py) } else { point_ellipse_quadrant(b, a, py, px) };
    let inside = (px / a).powi(2) + (py / b).powi(2) < 1.0;
    if inside {
        -d
    } else {
        d
    }
}

/// Distance from `p` to the segment `a`-`b`.
pub fn point_segment(p: Pt, a: Pt, b: Pt) -> f64 {
    let (e, w) = (sub(b, a), sub(p, a));
    let t = ((w[0] * e[0] + w[1] * e[1]) / (e[0] * e[0] + e[1] * e[1])).clamp(0.0, 1.0);
    norm(sub(w, [e[0] * t, e[1] * t]))
}

/// Signed distance from `p` to the half disk of radius `a` above the x axis.
pub fn signed_half_disk(a: f64, p: Pt) -> f64 {
    let r = norm(p);
    if p[1] >= 0.0 && r <= a {
        -(a - r).min(p[1])
    } else if p[1] >= 0.0 {
        r - a
    } else {
        point_segment(p, [-a, 0.0], [a, 0.0])
    }
}

/// Signed distance from `p` to the sector of radius `r` between the unit
/// directions `u0` and `u1` (counter-clockwise, less than a half turn
/// apart), its apex at the origin.
pub fn signed_sector(r: f64, u0: Pt, u1: Pt, p: Pt) -> f64 {
    let cross = |a: Pt, b: Pt| a[0] * b[1] - a[1] * b[0];
    let within = cross(u0, p) >= 0.0 && cross(p, u1) >= 0.0;
    let (e0, e1) = ([u0[0] * r, u0[1] * r], [u1[0] * r, u1[1] * r]);
    let edges = point_segment(p, [0.0, 0.0], e0).min(point_segment(p, [0.0, 0.0], e1));
    let pr = norm(p);
    if within && pr <= r {
        -edges.min(r - pr)
    } else if within {
        pr - r
    } else {
        edges.min(if within { (pr - r).abs() } else { f64::INFINITY })
    }
}
