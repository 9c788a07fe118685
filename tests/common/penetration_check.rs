//! The check of one penetration answer against the exact one, shared by the
//! suites of the separating-axes paths.

type Pt = [f64; 2];

/// A penetration as plain numbers: depth, unit normal (from A towards B),
/// whether it converged.
pub type Answer = (f64, Pt, bool);

/// `answer` against the exact signed distance and depth, within `bound`:
/// none only where the shapes are at most touching, one only where they
/// overlap or touch, its depth within the bound, and the overlap along its
/// normal (A's reach along it plus B's against it, `reach_a(n)` and
/// `reach_b(-n)`) equal to the depth within twice the bound.
pub fn check_penetration(
    path: &str,
    answer: Option<Answer>,
    signed_distance: f64,
    depth: f64,
    bound: f64,
    reach_a: impl Fn(Pt) -> f64,
    reach_b: impl Fn(Pt) -> f64,
) -> Result<(), String> {
    let Some((got, n, converged)) = answer else {
        return match signed_distance >= -bound {
            true => Ok(()),
            false => Err(format!("{path}: no penetration, exact depth {depth}")),
        };
    };
    if signed_distance > bound {
        return Err(format!("{path}: penetration, exact distance {signed_distance}"));
    }
    if (got - depth).abs() > bound {
        return Err(format!("{path}: depth {got}, exact {depth}, bound {bound}"));
    }
    let along = reach_a(n) + reach_b([-n[0], -n[1]]);
    if (along - got).abs() > 2.0 * bound {
        return Err(format!("{path}: overlap {along} along the normal, depth {got}"));
    }
    if !converged {
        return Err(format!("{path}: not converged"));
    }
    Ok(())
}

/// The farthest of `points` along `n`, plus `radius`.
pub fn reach(points: &[Pt], radius: f64, n: Pt) -> f64 {
    points.iter().map(|q| q[0] * n[0] + q[1] * n[1]).fold(f64::MIN, f64::max) + radius
}
