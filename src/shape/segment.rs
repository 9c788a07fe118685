use super::SupportMap;
use crate::error::Error;
use crate::real::{Real, V2};
use crate::result::{hit, LocalRayCast, RayCast, RayOutcome};
use crate::transform::check_point;

/// A line segment: a two-vertex core with no radius.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Segment<R: Real> {
    /// The first end point: the reference point.
    pub(crate) start: V2<R>,
    /// The second end point relative to the first.
    pub(crate) delta: V2<R>,
}

impl<R: Real> Segment<R> {
    /// The segment from `a` to `b`, which must differ.
    pub fn new(a: R::Vector, b: R::Vector) -> Result<Self, Error> {
        let start = check_point(V2::from_glam(a))?;
        let end = check_point(V2::from_glam(b))?;
        let delta = end - start;
        if delta.x == R::ZERO && delta.y == R::ZERO {
            return Err(Error::ZeroLength);
        }
        Ok(Self { start, delta })
    }
    /// The end points in local coordinates.
    pub fn points(&self) -> (R::Vector, R::Vector) {
        (self.start.to_glam(), (self.start + self.delta).to_glam())
    }
    pub fn length(&self) -> R {
        self.delta.length()
    }
    #[inline]
    pub(crate) fn support_local(&self, d: V2<R>) -> (V2<R>, u32) {
        if self.delta.dot(d) > R::ZERO {
            (self.delta, 1)
        } else {
            (V2::zero(), 0)
        }
    }
}

/// The `const` constructors, for each scalar type (a `const fn` cannot be
/// generic over [`Real`]'s arithmetic).
macro_rules! const_constructors {
    ($R:ty, $vector:ty, $checks:ident) => {
        impl Segment<$R> {
            /// [`Segment::new`] as a `const fn`: a segment declared as a constant is
            /// checked when the program is compiled (an invalid one fails the
            /// build) and stored bit for bit as `new` stores it.
            pub const fn new_const(a: $vector, b: $vector) -> Result<Self, Error> {
                let start = V2 { x: a.x, y: a.y };
                let end = V2 { x: b.x, y: b.y };
                const_try!(crate::checks::$checks::check_point(start));
                const_try!(crate::checks::$checks::check_point(end));
                let delta = V2 { x: end.x - start.x, y: end.y - start.y };
                if delta.x == 0.0 && delta.y == 0.0 {
                    return Err(Error::ZeroLength);
                }
                Ok(Self { start, delta })
            }
        }
    };
}

const_constructors!(f32, glam::Vec2, single);
const_constructors!(f64, glam::DVec2, double);

impl<R: Real> SupportMap<R> for Segment<R> {
    #[inline]
    fn support(&self, direction: R::Vector) -> R::Vector {
        self.support_local(V2::from_glam(direction)).0.to_glam()
    }
    #[inline]
    fn support_feature(&self, direction: R::Vector, _near: u32) -> (R::Vector, u32) {
        let (p, id) = self.support_local(V2::from_glam(direction));
        (p.to_glam(), id)
    }
    fn is_polytope(&self) -> bool {
        true
    }
    fn core_vertex_bound(&self) -> usize {
        2
    }
    fn center(&self) -> R::Vector {
        (self.delta * R::HALF).to_glam()
    }
    fn bounding_radius(&self) -> R {
        self.delta.length() * R::HALF
    }
    fn reference_point(&self) -> R::Vector {
        self.start.to_glam()
    }
    #[cfg(feature = "far-geometry")]
    /// Twice the bounding radius is the length: compared squared.
    fn far_from_origin(&self) -> bool {
        self.start.length_squared() > self.delta.length_squared()
    }
    fn cast_local_ray(&self, o: R::Vector, d: R::Vector, max: R) -> Option<LocalRayCast<R>> {
        Some(cast_ray_segment(V2::zero(), self.delta, V2::from_glam(o), V2::from_glam(d), max))
    }
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    fn segment_core(&self) -> Option<[V2<R>; 2]> {
        Some([V2::zero(), self.delta])
    }
}

/// Ray against the bare segment `a`-`a + delta`. A segment has no inside, so
/// a ray nearly along its line is ill-conditioned: an end point the ray
/// passes within rounding distance of counts as hit, as a user expects of a
/// ray aimed along a wall.
fn cast_ray_segment<R: Real>(a: V2<R>, delta: V2<R>, o: V2<R>, d: V2<R>, max: R) -> RayCast<R> {
    let rel = a - o;
    let slack = R::from_u32(4) * R::EPSILON;
    // An origin on the segment (to rounding) is on the shape.
    let along = -rel.dot(delta);
    let scale = rel.length() + delta.length();
    if along >= R::ZERO && along <= delta.length_squared() && delta.cross(rel).abs() <= slack * scale * delta.length() {
        return RayCast::closed_form(RayOutcome::Inside);
    }
    let denominator = d.cross(delta);
    let mut best: Option<(R, V2<R>)> = None;
    if denominator != R::ZERO {
        let t = rel.cross(delta) / denominator;
        let s = rel.cross(d) / denominator;
        if s >= R::ZERO && s <= R::ONE && t >= R::ZERO && t <= max {
            if t == R::ZERO {
                return RayCast::closed_form(RayOutcome::Inside);
            }
            // The face normal on the side the ray comes from.
            let n = delta.perp();
            let n = if n.dot(d) > R::ZERO { -n } else { n };
            best = Some((t, n.try_normalize().unwrap_or(-d)));
        }
    }
    for end in [rel, rel + delta] {
        let t = end.dot(d);
        let off = d.cross(end).abs();
        if t >= R::ZERO
            && t <= max
            && off <= slack * (end.length() + delta.length())
            && best.is_none_or(|(bt, _)| t < bt)
        {
            if t == R::ZERO {
                return RayCast::closed_form(RayOutcome::Inside);
            }
            best = Some((t, -d));
        }
    }
    RayCast::closed_form(match best {
        Some((t, normal)) => hit(o, d, t, normal),
        None => RayOutcome::Miss,
    })
}
