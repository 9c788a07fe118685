//! The `const` constructors of every shape against the run-time ones: a
//! shape declared as a constant is the shape `new` builds, bit for bit, and
//! every invalid input gets the same error from both. The constants below
//! are evaluated by the compiler, so this file also shows that each
//! constructor is usable in a `const`.

use gjk2d::glam::{DVec2, Vec2};
use gjk2d::{Capsule, Circle, Ellipse, Error, HalfEllipse, Rectangle, Rounded, Segment, Slice, Triangle};

/// A `const` that must be valid: an invalid one fails the build.
macro_rules! fixed {
    ($e:expr) => {
        match $e {
            Ok(shape) => shape,
            Err(e) => panic!("{}", e.as_str()),
        }
    };
}

/// Same bits: `Debug` prints every float exactly (and tells -0.0 from 0.0).
fn same<T: core::fmt::Debug>(a: &T, b: &T) -> bool {
    format!("{a:?}") == format!("{b:?}")
}

fn assert_same<T: core::fmt::Debug>(constant: &Result<T, Error>, runtime: &Result<T, Error>, what: &str) {
    let agree = match (constant, runtime) {
        (Ok(a), Ok(b)) => same(a, b),
        (Err(a), Err(b)) => a == b,
        _ => false,
    };
    assert!(agree, "{what}: const {constant:?}, run time {runtime:?}");
}

mod single {
    use super::*;
    pub const CIRCLE: Circle<f32> = fixed!(Circle::<f32>::at_const(Vec2::new(1.5, -2.0), 0.75));
    pub const RECTANGLE: Rectangle<f32> = fixed!(Rectangle::<f32>::new_const(3.0, 0.1));
    pub const TRIANGLE: Triangle<f32> =
        fixed!(Triangle::<f32>::new_const(Vec2::new(1e4, 1e4), Vec2::new(1e4 + 0.5, 1e4), Vec2::new(1e4, 1e4 + 0.25)));
    pub const SEGMENT: Segment<f32> = fixed!(Segment::<f32>::new_const(Vec2::new(-1.0, 0.1), Vec2::new(2.0, 0.3)));
    pub const CAPSULE: Capsule<f32> = fixed!(Capsule::<f32>::new_const(Vec2::new(-1.0, 0.0), Vec2::new(1.0, 0.5), 0.2));
    pub const ELLIPSE: Ellipse<f32> = fixed!(Ellipse::<f32>::new_const(4.0, 1.5));
    pub const HALF_ELLIPSE: HalfEllipse<f32> = fixed!(HalfEllipse::<f32>::new_const(4.0, 1.5));
    pub const SLICE: Slice<f32> = fixed!(Slice::<f32>::new_const(2.0, 1.2));
    pub const ROUNDED: Rounded<f32, Rectangle<f32>> = fixed!(Rounded::<f32, _>::new_const(RECTANGLE, 0.3));
}

mod double {
    use super::*;
    pub const CIRCLE: Circle<f64> = fixed!(Circle::<f64>::at_const(DVec2::new(1.5, -2.0), 0.75));
    pub const RECTANGLE: Rectangle<f64> = fixed!(Rectangle::<f64>::new_const(3.0, 0.1));
    pub const TRIANGLE: Triangle<f64> = fixed!(Triangle::<f64>::new_const(
        DVec2::new(1e9, 1e9),
        DVec2::new(1e9 + 0.5, 1e9),
        DVec2::new(1e9, 1e9 + 0.25)
    ));
    pub const SEGMENT: Segment<f64> = fixed!(Segment::<f64>::new_const(DVec2::new(-1.0, 0.1), DVec2::new(2.0, 0.3)));
    pub const CAPSULE: Capsule<f64> =
        fixed!(Capsule::<f64>::new_const(DVec2::new(-1.0, 0.0), DVec2::new(1.0, 0.5), 0.2));
    pub const ELLIPSE: Ellipse<f64> = fixed!(Ellipse::<f64>::new_const(4.0, 1.5));
    pub const HALF_ELLIPSE: HalfEllipse<f64> = fixed!(HalfEllipse::<f64>::new_const(4.0, 1.5));
    pub const SLICE: Slice<f64> = fixed!(Slice::<f64>::new_const(2.0, 1.2));
    pub const ROUNDED: Rounded<f64, Rectangle<f64>> = fixed!(Rounded::<f64, _>::new_const(RECTANGLE, 0.3));
}

#[test]
fn constants_are_the_shapes_new_builds() {
    macro_rules! check {
        ($m:ident, $R:ty, $V:ident, $e:literal) => {{
            let e: $R = $e;
            let v = |x: $R, y: $R| $V::new(x, y);
            assert_same(&Ok($m::CIRCLE), &Circle::at(v(1.5, -2.0), 0.75), "circle");
            assert_same(&Ok($m::RECTANGLE), &Rectangle::new(3.0, 0.1), "rectangle");
            let triangle = Triangle::new(v(e, e), v(e + 0.5, e), v(e, e + 0.25));
            assert_same(&Ok($m::TRIANGLE), &triangle, "triangle");
            assert_same(&Ok($m::SEGMENT), &Segment::new(v(-1.0, 0.1), v(2.0, 0.3)), "segment");
            assert_same(&Ok($m::CAPSULE), &Capsule::new(v(-1.0, 0.0), v(1.0, 0.5), 0.2), "capsule");
            assert_same(&Ok($m::ELLIPSE), &Ellipse::new(4.0, 1.5), "ellipse");
            assert_same(&Ok($m::HALF_ELLIPSE), &HalfEllipse::new(4.0, 1.5), "half ellipse");
            assert_same(&Ok($m::SLICE), &Slice::new(2.0, 1.2), "slice");
            let rounded = Rectangle::new(3.0, 0.1).and_then(|r| Rounded::new(r, 0.3));
            assert_same(&Ok($m::ROUNDED), &rounded, "rounded");
        }};
    }
    check!(single, f32, Vec2, 1e4);
    check!(double, f64, DVec2, 1e9);
}

/// Every constructor on a grid of hard inputs, valid or not: NaN, the
/// infinities, signed zeros, subnormals, negative values, the coordinate
/// limit and just past it, and angles at and around 0 and pi.
#[test]
fn both_agree_on_every_hard_input() {
    macro_rules! check {
        ($R:ident, $V:ident, $limit:expr) => {{
            let limit: $R = $limit;
            let above = $R::from_bits(limit.to_bits() + 1);
            let pi = core::$R::consts::PI;
            let scalars: &[$R] = &[
                $R::NAN,
                $R::INFINITY,
                $R::NEG_INFINITY,
                -1.0,
                -0.0,
                0.0,
                $R::from_bits(1),
                $R::MIN_POSITIVE,
                1e-30,
                0.3,
                1.0,
                1.2,
                $R::from_bits(pi.to_bits() - 1),
                pi,
                $R::from_bits(pi.to_bits() + 1),
                4.0,
                1e6,
                limit,
                above,
                $R::MAX,
            ];
            for &a in scalars {
                let p = $V::new(a, 0.5);
                assert_same(&Circle::<$R>::new_const(a), &Circle::new(a), "circle");
                assert_same(&Circle::<$R>::at_const(p, 0.5), &Circle::at(p, 0.5), "circle at");
                assert_same(&Slice::<$R>::new_const(1.0, a), &Slice::new(1.0, a), "slice angle");
                for &b in scalars {
                    let q = $V::new(0.25, b);
                    assert_same(&Rectangle::<$R>::new_const(a, b), &Rectangle::new(a, b), "rectangle");
                    assert_same(&Ellipse::<$R>::new_const(a, b), &Ellipse::new(a, b), "ellipse");
                    assert_same(&HalfEllipse::<$R>::new_const(a, b), &HalfEllipse::new(a, b), "half ellipse");
                    assert_same(&Slice::<$R>::new_const(a, b), &Slice::new(a, b), "slice");
                    assert_same(&Segment::<$R>::new_const(p, q), &Segment::new(p, q), "segment");
                    assert_same(&Segment::<$R>::new_const(p, p), &Segment::new(p, p), "segment, no length");
                    assert_same(&Capsule::<$R>::new_const(p, q, b), &Capsule::new(p, q, b), "capsule");
                    let r = $V::new(b, a);
                    assert_same(&Triangle::<$R>::new_const(p, q, r), &Triangle::new(p, q, r), "triangle");
                    let square = Rectangle::<$R>::new(1.0, 1.0).unwrap();
                    assert_same(&Rounded::<$R, _>::new_const(square, b), &Rounded::new(square, b), "rounded");
                }
            }
        }};
    }
    check!(f32, Vec2, 1.0e15);
    check!(f64, DVec2, 1.0e150);
}

/// Slice angles across (0, pi], where the two precisions take their sine
/// and cosine from different `const` code.
#[test]
fn slices_agree_across_the_angle_range() {
    for i in 1..=20_000 {
        let t = core::f64::consts::PI * i as f64 / 20_000.0;
        assert_same(&Slice::<f64>::new_const(1.5, t), &Slice::new(1.5, t), "f64 slice");
        let t = t as f32;
        assert_same(&Slice::<f32>::new_const(1.5, t), &Slice::new(1.5, t), "f32 slice");
    }
}
