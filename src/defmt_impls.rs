//! `defmt::Format` for every public data type. glam's vectors have no
//! `Format`, and `Debug2Format` would link `core::fmt`'s formatting into
//! the firmware, so vectors are written as `(x, y)` by hand.

use defmt::{write, Format, Formatter};

use crate::real::Real;
use crate::shape::{
    Capsule, Circle, Ellipse, HalfEllipse, Polygon, Rectangle, Rounded, Segment, Slice, SupportMap, Triangle,
};
use crate::{
    CastHit, CastOutcome, CastStart, ContactPoint, Detection, EpaConfig, GjkConfig, Impact, ImpactConfig,
    ImpactOutcome, ImpactStart, Manifold, Motion, Penetration, PenetrationEstimate, Ray, RayCast, RayHit, RayOutcome,
    Separation, ShapeCast, SupportPoint, Sweep, TimeOfImpact, Transform,
};

/// A glam vector as `(x, y)`.
struct Xy<R: Real>(R::Vector);

impl<R: Real + Format> Format for Xy<R> {
    fn format(&self, f: Formatter<'_>) {
        let (x, y) = R::components(self.0);
        write!(f, "({}, {})", x, y)
    }
}

fn xy<R: Real>(v: R::Vector) -> Xy<R> {
    Xy(v)
}

impl Format for Detection {
    fn format(&self, f: Formatter<'_>) {
        write!(
            f,
            "Detection {{ intersecting: {}, iterations: {}, status: {} }}",
            self.intersecting, self.iterations, self.status
        )
    }
}

impl<R: Real + Format> Format for Separation<R> {
    fn format(&self, f: Formatter<'_>) {
        write!(
            f,
            "Separation {{ distance: {}, normal: {}, point_a: {}, point_b: {}, error_bound: {}, iterations: {}, status: {} }}",
            self.distance,
            xy::<R>(self.normal),
            xy::<R>(self.point_a),
            xy::<R>(self.point_b),
            self.error_bound,
            self.iterations,
            self.status
        )
    }
}

impl<R: Real + Format> Format for ContactPoint<R> {
    fn format(&self, f: Formatter<'_>) {
        write!(f, "ContactPoint {{ point: {}, separation: {}, id: {} }}", xy::<R>(self.point), self.separation, self.id)
    }
}

impl<R: Real + Format> Format for Manifold<R> {
    fn format(&self, f: Formatter<'_>) {
        write!(
            f,
            "Manifold {{ normal: {}, points: {}, iterations: {}, status: {} }}",
            xy::<R>(self.normal),
            self.points(),
            self.iterations,
            self.status
        )
    }
}

impl<R: Real + Format> Format for Penetration<R> {
    fn format(&self, f: Formatter<'_>) {
        write!(
            f,
            "Penetration {{ normal: {}, depth: {}, error_bound: {}, iterations: {}, status: {} }}",
            xy::<R>(self.normal),
            self.depth,
            self.error_bound,
            self.iterations,
            self.status
        )
    }
}

impl<R: Real + Format> Format for PenetrationEstimate<R> {
    fn format(&self, f: Formatter<'_>) {
        write!(
            f,
            "PenetrationEstimate {{ normal: {}, depth: {}, error_bound: {}, iterations: {}, status: {} }}",
            xy::<R>(self.normal),
            self.depth,
            self.error_bound,
            self.iterations,
            self.status
        )
    }
}

impl<R: Real + Format> Format for RayHit<R> {
    fn format(&self, f: Formatter<'_>) {
        write!(
            f,
            "RayHit {{ distance: {}, point: {}, normal: {}, error_bound: {} }}",
            self.distance,
            xy::<R>(self.point),
            xy::<R>(self.normal),
            self.error_bound
        )
    }
}

impl<R: Real + Format> Format for RayOutcome<R> {
    fn format(&self, f: Formatter<'_>) {
        match self {
            RayOutcome::Hit(h) => write!(f, "Hit({})", h),
            RayOutcome::Miss => write!(f, "Miss"),
            RayOutcome::Inside => write!(f, "Inside"),
        }
    }
}

impl<R: Real + Format> Format for RayCast<R> {
    fn format(&self, f: Formatter<'_>) {
        write!(f, "RayCast {{ outcome: {}, iterations: {}, status: {} }}", self.outcome, self.iterations, self.status)
    }
}

impl<R: Real + Format> Format for Motion<R> {
    fn format(&self, f: Formatter<'_>) {
        write!(f, "Motion {{ translation: {} }}", xy::<R>(self.translation()))
    }
}

impl<R: Real + Format> Format for CastHit<R> {
    fn format(&self, f: Formatter<'_>) {
        write!(
            f,
            "CastHit {{ fraction: {}, distance: {}, normal: {}, point_a: {}, point_b: {}, error_bound: {} }}",
            self.fraction,
            self.distance,
            xy::<R>(self.normal),
            xy::<R>(self.point_a),
            xy::<R>(self.point_b),
            self.error_bound
        )
    }
}

impl<R: Real + Format> Format for CastStart<R> {
    fn format(&self, f: Formatter<'_>) {
        write!(f, "CastStart {{ penetration: {}, separating: {} }}", self.penetration, self.separating)
    }
}

impl<R: Real + Format> Format for CastOutcome<R> {
    fn format(&self, f: Formatter<'_>) {
        match self {
            CastOutcome::Hit(h) => write!(f, "Hit({})", h),
            CastOutcome::Miss => write!(f, "Miss"),
            CastOutcome::Start(s) => write!(f, "Start({})", s),
        }
    }
}

impl<R: Real + Format> Format for ShapeCast<R> {
    fn format(&self, f: Formatter<'_>) {
        write!(f, "ShapeCast {{ outcome: {}, iterations: {}, status: {} }}", self.outcome, self.iterations, self.status)
    }
}

impl<R: Real + Format> Format for Sweep<R> {
    fn format(&self, f: Formatter<'_>) {
        write!(f, "Sweep {{ start: {}, linear: {}, angle: {} }}", self.start(), xy::<R>(self.linear()), self.angle())
    }
}

impl<R: Real + Format> Format for ImpactConfig<R> {
    fn format(&self, f: Formatter<'_>) {
        write!(
            f,
            "ImpactConfig {{ target: {}, tolerance: {}, max_iterations: {} }}",
            self.target(),
            self.tolerance(),
            self.max_iterations()
        )
    }
}

impl<R: Real + Format> Format for Impact<R> {
    fn format(&self, f: Formatter<'_>) {
        write!(
            f,
            "Impact {{ time: {}, separation: {}, normal: {}, point_a: {}, point_b: {}, features: {} }}",
            self.time,
            self.separation,
            xy::<R>(self.normal),
            xy::<R>(self.point_a),
            xy::<R>(self.point_b),
            self.features
        )
    }
}

impl<R: Real + Format> Format for ImpactStart<R> {
    fn format(&self, f: Formatter<'_>) {
        write!(f, "ImpactStart {{ separation: {}, normal: {} }}", self.separation, xy::<R>(self.normal))
    }
}

impl<R: Real + Format> Format for ImpactOutcome<R> {
    fn format(&self, f: Formatter<'_>) {
        match self {
            ImpactOutcome::Hit(h) => write!(f, "Hit({})", h),
            ImpactOutcome::Miss => write!(f, "Miss"),
            ImpactOutcome::Start(s) => write!(f, "Start({})", s),
        }
    }
}

impl<R: Real + Format> Format for TimeOfImpact<R> {
    fn format(&self, f: Formatter<'_>) {
        write!(
            f,
            "TimeOfImpact {{ outcome: {}, iterations: {}, status: {} }}",
            self.outcome, self.iterations, self.status
        )
    }
}

impl<R: Real + Format> Format for Ray<R> {
    fn format(&self, f: Formatter<'_>) {
        write!(f, "Ray {{ origin: {}, direction: {} }}", xy::<R>(self.origin()), xy::<R>(self.direction()))
    }
}

impl<R: Real + Format> Format for Transform<R> {
    fn format(&self, f: Formatter<'_>) {
        write!(
            f,
            "Transform {{ translation: {}, cos: {}, sin: {} }}",
            xy::<R>(self.translation()),
            self.cos(),
            self.sin()
        )
    }
}

impl<R: Real + Format> Format for SupportPoint<R> {
    fn format(&self, f: Formatter<'_>) {
        write!(f, "SupportPoint {{ point: {}, id: {} }}", xy::<R>(self.point), self.id)
    }
}

impl<R: Real + Format> Format for GjkConfig<R> {
    fn format(&self, f: Formatter<'_>) {
        write!(
            f,
            "GjkConfig {{ iterations: {}/{}/{}, epsilons: {}/{}/{} }}",
            self.max_detect_iterations(),
            self.max_distance_iterations(),
            self.max_raycast_iterations(),
            self.detect_epsilon(),
            self.distance_epsilon(),
            self.raycast_epsilon()
        )
    }
}

impl<R: Real + Format> Format for EpaConfig<R> {
    fn format(&self, f: Formatter<'_>) {
        write!(f, "EpaConfig {{ max_iterations: {}, epsilon: {} }}", self.max_iterations(), self.epsilon())
    }
}

impl<R: Real + Format> Format for Circle<R> {
    fn format(&self, f: Formatter<'_>) {
        write!(f, "Circle {{ center: {}, radius: {} }}", xy::<R>(self.center_point()), self.circle_radius())
    }
}

impl<R: Real + Format> Format for Segment<R> {
    fn format(&self, f: Formatter<'_>) {
        let (a, b) = self.points();
        write!(f, "Segment {{ {} - {} }}", xy::<R>(a), xy::<R>(b))
    }
}

impl<R: Real + Format> Format for Capsule<R> {
    fn format(&self, f: Formatter<'_>) {
        write!(f, "Capsule {{ {}, radius: {} }}", self.segment(), self.capsule_radius())
    }
}

impl<R: Real + Format, const N: usize> Format for Polygon<R, N> {
    fn format(&self, f: Formatter<'_>) {
        write!(f, "Polygon {{ {} vertices:", self.len());
        for i in 0..self.len() {
            if let Some(v) = self.vertex(i) {
                write!(f, " {}", xy::<R>(v));
            }
        }
        write!(f, " }}")
    }
}

impl<R: Real + Format> Format for Triangle<R> {
    fn format(&self, f: Formatter<'_>) {
        write!(f, "Triangle {{ {} }}", self.polygon())
    }
}

impl<R: Real + Format> Format for Rectangle<R> {
    fn format(&self, f: Formatter<'_>) {
        write!(f, "Rectangle {{ width: {}, height: {} }}", self.width(), self.height())
    }
}

impl<R: Real + Format> Format for Ellipse<R> {
    fn format(&self, f: Formatter<'_>) {
        write!(f, "Ellipse {{ half_width: {}, half_height: {} }}", self.half_width(), self.half_height())
    }
}

impl<R: Real + Format> Format for HalfEllipse<R> {
    fn format(&self, f: Formatter<'_>) {
        write!(f, "HalfEllipse {{ half_width: {}, height: {} }}", self.half_width(), self.height())
    }
}

impl<R: Real + Format> Format for Slice<R> {
    fn format(&self, f: Formatter<'_>) {
        write!(f, "Slice {{ radius: {}, theta: {} }}", self.slice_radius(), self.theta())
    }
}

impl<R: Real + Format, S: SupportMap<R> + Format> Format for Rounded<R, S> {
    fn format(&self, f: Formatter<'_>) {
        write!(f, "Rounded {{ {}, radius: {} }}", self.inner(), self.extra_radius())
    }
}
