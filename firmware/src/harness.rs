//! Counts checks and prints the failures (and, at the end, the tally).

use crate::hprintln;
use gjk2d::Real;

pub struct Tally {
    pub passed: u32,
    pub failed: u32,
    /// Printed before each failure: the precision and group under test.
    pub context: &'static str,
}

impl Default for Tally {
    fn default() -> Self {
        Self::new()
    }
}

impl Tally {
    pub const fn new() -> Self {
        Self { passed: 0, failed: 0, context: "" }
    }

    pub fn ok(&mut self, name: &str, ok: bool) -> bool {
        if ok {
            self.passed += 1;
        } else {
            self.failed += 1;
            hprintln!("FAIL [{}] {}", self.context, name);
        }
        ok
    }

    /// |got - want| <= tol.
    pub fn near<R: Real>(&mut self, name: &str, got: R, want: R, tol: R) -> bool {
        let ok = (got - want).abs() <= tol;
        if ok {
            self.passed += 1;
        } else {
            self.failed += 1;
            hprintln!(
                "FAIL [{}] {}: got {:e}, want {:e} (diff {:e}, tol {:e})",
                self.context,
                name,
                got.to_f64(),
                want.to_f64(),
                (got - want).abs().to_f64(),
                tol.to_f64()
            );
        }
        ok
    }

    /// Each component within tol.
    pub fn near_v<R: Real>(&mut self, name: &str, got: R::Vector, want: (R, R), tol: R) -> bool {
        let (x, y) = R::components(got);
        let ok = (x - want.0).abs() <= tol && (y - want.1).abs() <= tol;
        if ok {
            self.passed += 1;
        } else {
            self.failed += 1;
            hprintln!(
                "FAIL [{}] {}: got ({:e}, {:e}), want ({:e}, {:e}), tol {:e}",
                self.context,
                name,
                x.to_f64(),
                y.to_f64(),
                want.0.to_f64(),
                want.1.to_f64(),
                tol.to_f64()
            );
        }
        ok
    }

    /// lo - tol <= got <= hi + tol.
    pub fn within<R: Real>(&mut self, name: &str, got: R, lo: R, hi: R, tol: R) -> bool {
        let ok = got >= lo - tol && got <= hi + tol;
        if ok {
            self.passed += 1;
        } else {
            self.failed += 1;
            hprintln!(
                "FAIL [{}] {}: got {:e}, want in [{:e}, {:e}] (tol {:e})",
                self.context,
                name,
                got.to_f64(),
                lo.to_f64(),
                hi.to_f64(),
                tol.to_f64()
            );
        }
        ok
    }
}
