//! [`Gjk`]: the queries, one generic implementation for every shape pair.
//!
//! Each query places B relative to A once ([`Pair`]), runs GJK on the
//! shapes' cores, and adds their radii in closed form. Only what a query calls
//! is compiled into a program: the intersection test alone pulls in neither
//! EPA, closest points nor ray casts.

use crate::cast::{cast_pair, CastHit, CastOutcome, CastStart, Motion, ShapeCast};
use crate::config::{GjkConfig, ImpactConfig};
use crate::epa::{Epa, PenetrationSolver};
use crate::error::Error;
use crate::gjk::{intersect, CoreProximity, CoreSeparation, Enclosing};
use crate::impact::{advance, Sweep, TimeOfImpact};
use crate::minkowski::{Pair, SupportPoint};
use crate::point_cores::PointCores;
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
use crate::polytope::{cast_ray_small_polygon, FaceRounding, FaceVerdict};
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
use crate::quad_start::QuadStart;
use crate::ray::{cast_ray_gjk, Ray};
use crate::real::{Real, V2};
use crate::result::{Detection, FeatureId, Manifold, Penetration, RayCast, RayHit, RayOutcome, Separation, Status};
use crate::shape::{DiskRay, SupportMap};
use crate::simplex::{Payload, Simplex, Witness};
use crate::transform::Transform;
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
use crate::walked_axes::Walked;
use crate::warm::PairCache;

/// The narrow-phase detector: configuration plus a penetration solver (EPA
/// by default), as dyn4j's `Gjk`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Gjk<R: Real, P = Epa<R>> {
    pub config: GjkConfig<R>,
    pub solver: P,
    /// Use the exact closed-form ray casts of polygons, circles, capsules and
    /// segments (default true); false makes every ray cast iterate.
    pub closed_form_rays: bool,
}

impl<R: Real> Gjk<R> {
    /// Default configuration and EPA.
    pub fn new() -> Self {
        Self::with_solver(GjkConfig::default(), Epa::default())
    }
}

impl<R: Real, P> Gjk<R, P> {
    /// A detector with the given configuration and penetration solver.
    pub fn with_solver(config: GjkConfig<R>, solver: P) -> Self {
        Self { config, solver, closed_form_rays: true }
    }

    /// Whether A and B overlap (touching counts), without computing how much.
    ///
    /// ```
    /// use gjk2d::{Circle, Gjk, Rectangle, Transform};
    /// use glam::Vec2;
    ///
    /// let gjk = Gjk::<f32>::new();
    /// let wall = Rectangle::new(2.0, 1.0)?;
    /// let ball = Circle::new(0.5)?;
    /// let near = Transform::from_translation(Vec2::new(1.4, 0.0))?;
    /// let far = Transform::from_translation(Vec2::new(3.0, 0.0))?;
    /// assert!(gjk.intersects(&wall, &Transform::IDENTITY, &ball, &near).intersecting);
    /// assert!(!gjk.intersects(&wall, &Transform::IDENTITY, &ball, &far).intersecting);
    /// # Ok::<(), gjk2d::Error>(())
    /// ```
    #[cfg_attr(not(target_os = "none"), inline)]
    pub fn intersects<A, B>(&self, a: &A, ta: &Transform<R>, b: &B, tb: &Transform<R>) -> Detection
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R> + ?Sized,
    {
        let pair = Pair::new(a, ta, b, tb);
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        if pair.inner_disks_overlap() {
            return Detection { intersecting: true, iterations: 0, status: Status::Converged };
        }
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        if self.config.detect_epsilon() == R::ZERO && pair.bounding_disks_apart() {
            return Detection { intersecting: false, iterations: 0, status: Status::Converged };
        }
        // Two small f64 polygons, where the processor has AVX2: the axes'
        // verdict (as `intersects_of` takes it) in its wide lanes.
        #[cfg(all(target_arch = "x86_64", target_feature = "sse2", not(target_os = "none")))]
        if self.config.detect_epsilon() == R::ZERO {
            if let Some(separated) = separated_in_wide_lanes(a, ta, b, tb) {
                return Detection { intersecting: !separated, iterations: 1, status: Status::Converged };
            }
        }
        self.intersects_of(&pair)
    }

    /// [`intersects`](Self::intersects) of a placed pair.
    #[inline(always)]
    fn intersects_of<A, B>(&self, pair: &Pair<'_, R, A, B>) -> Detection
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R> + ?Sized,
    {
        if pair.point_cores() {
            return crate::point_cores::overlap_test(pair, self.config.detect_epsilon());
        }
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        if self.config.detect_epsilon() == R::ZERO {
            if let Some((pa, pb)) = pair.small_polygons() {
                let intersecting = !crate::sat::Axes::new(pair, pa, pb).separated();
                return Detection { intersecting, iterations: 1, status: Status::Converged };
            }
            if let Some((p, polygon, _)) = pair.point_and_small_polygon() {
                if let Some(intersecting) = crate::point_polygon::within(polygon, p, pair.radius()) {
                    return Detection { intersecting, iterations: 1, status: Status::Converged };
                }
            }
            // A segment: the axes decide, as for two polygons. A capsule's
            // cores are mostly apart by less than the radius, which the
            // axes cannot decide: its ends and the polygon's vertices do.
            if let Some(intersecting) = segment_within_small_polygon(pair) {
                return Detection { intersecting, iterations: 1, status: Status::Converged };
            }
        }
        let (intersecting, iterations, status) = intersect(
            pair,
            self.config.max_detect_iterations(),
            self.config.detect_epsilon(),
            self.config.distance_epsilon(),
        );
        Detection { intersecting, iterations, status }
    }

    /// The separation of A and B: `None` means they certainly overlap or
    /// touch. A result with `Status::IterationLimit` is a best guess whose
    /// `error_bound` may exceed its distance.
    ///
    /// ```
    /// use gjk2d::{Capsule, Gjk, Rectangle, Transform};
    /// use glam::Vec2;
    ///
    /// let gjk = Gjk::<f32>::new();
    /// let floor = Rectangle::new(10.0, 1.0)?; // its top face at y = 0.5
    /// let pill = Capsule::new(Vec2::new(-1.0, 0.0), Vec2::new(1.0, 0.0), 0.25)?;
    /// let above = Transform::from_translation(Vec2::new(0.0, 2.0))?;
    /// let sep = gjk.distance(&floor, &Transform::IDENTITY, &pill, &above).expect("apart");
    /// assert!((sep.distance - 1.25).abs() < 1e-6);
    /// assert_eq!(sep.normal, Vec2::Y); // from A towards B
    /// assert!((sep.point_b.y - 1.75).abs() < 1e-6); // the closest point on B
    /// # Ok::<(), gjk2d::Error>(())
    /// ```
    pub fn distance<A, B>(&self, a: &A, ta: &Transform<R>, b: &B, tb: &Transform<R>) -> Option<Separation<R>>
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R> + ?Sized,
    {
        self.distance_of(&Pair::new(a, ta, b, tb))
    }

    /// [`distance`](Self::distance) of a placed pair.
    #[inline(always)]
    fn distance_of<A, B>(&self, pair: &Pair<'_, R, A, B>) -> Option<Separation<R>>
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R> + ?Sized,
    {
        if pair.point_cores() {
            // Coincident cores overlap, as GJK's loop finds.
            let core = &PointCores::new(pair)?;
            if core.certainly_within(pair.radius_a() + pair.radius_b()) {
                return None;
            }
            return core.separation(pair);
        }
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        if pair.inner_disks_overlap() {
            return None;
        }
        // GJK's first supports scan both polygons whole.
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        pair.prefetch_scanned_cores();
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        if let Some((p, polygon, point_is_a)) = pair.point_and_small_polygon() {
            if let Some(beyond) = crate::point_polygon::beyond(polygon, p) {
                return point_polygon_separation(pair, beyond, point_is_a);
            }
        }
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        if let Some((pa, pb)) = pair.small_polygons() {
            return self.small_polygons_distance(pair, (pa, pb), &crate::sat::Axes::new_in_wide_lanes(pair, pa, pb));
        }
        // Shapes whose bounding circles are apart need no verdict: GJK
        // finds their distance, and the closed form would only add its cost.
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        if !pair.bounding_disks_apart() && segment_within_small_polygon(pair) == Some(true) {
            return None;
        }
        let mut simplex = None::<Simplex<R, Witness<R>>>;
        match pair.core_distance(&mut simplex, self.config.max_distance_iterations(), self.config.distance_epsilon()) {
            CoreProximity::Overlapping { .. } => None,
            CoreProximity::Separated(ref core) => separation(pair, core),
        }
    }

    /// The distance of two small polygons from their separating axes:
    /// `None` where no axis parts them (most pairs in a scene overlap, and
    /// GJK would take several iterations to find it out); the axis that
    /// parts them the most where an edge and a vertex are closest (the
    /// common case); else GJK's. That axis is measured again alone, not
    /// read off the polygons the axes were measured on: kept for the pairs
    /// apart, the laid-out polygons slowed the overlapping ones too.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    fn small_polygons_distance<A, B>(
        &self,
        pair: &Pair<'_, R, A, B>,
        (pa, pb): (&[V2<R>], &[V2<R>]),
        axes: &crate::sat::Axes<R>,
    ) -> Option<Separation<R>>
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R> + ?Sized,
    {
        if !axes.separated() {
            return None;
        }
        if let Some(found) = crate::sat::face_and_vertex_placed(pair, pa, pb, axes.most_separating_by_square()) {
            return Some(closed_form_separation(pair, found));
        }
        let mut simplex = None::<Simplex<R, Witness<R>>>;
        let (max, epsilon) = (self.config.max_distance_iterations(), self.config.distance_epsilon());
        match crate::gjk::distance_loop_from(pair, &mut simplex, None, max, epsilon) {
            CoreProximity::Overlapping { .. } => None,
            CoreProximity::Separated(ref core) => separation(pair, core),
        }
    }

    /// The penetration of A and B: `None` means they are certainly apart.
    /// Cores that overlap go to the penetration solver; rounded shapes whose
    /// cores are apart are resolved in closed form from the core distance.
    ///
    /// ```
    /// use gjk2d::{Gjk, Rectangle, Transform};
    /// use glam::DVec2;
    ///
    /// let gjk = Gjk::<f64>::new();
    /// let box_ = Rectangle::new(1.0, 1.0)?;
    /// let pushed_in = Transform::from_translation(DVec2::new(0.8, 0.1))?;
    /// let pen = gjk.penetration(&box_, &Transform::IDENTITY, &box_, &pushed_in).expect("overlap");
    /// // Moving B by `depth` along `normal` separates the shapes.
    /// assert!((pen.depth - 0.2).abs() < 1e-12);
    /// assert_eq!(pen.normal, DVec2::X);
    /// # Ok::<(), gjk2d::Error>(())
    /// ```
    pub fn penetration<A, B>(&self, a: &A, ta: &Transform<R>, b: &B, tb: &Transform<R>) -> Option<Penetration<R>>
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R> + ?Sized,
        P: PenetrationSolver<R>,
    {
        self.penetration_of(&Pair::new(a, ta, b, tb))
    }

    /// [`penetration`](Self::penetration) of a placed pair.
    #[inline(always)]
    fn penetration_of<A, B>(&self, pair: &Pair<'_, R, A, B>) -> Option<Penetration<R>>
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R> + ?Sized,
        P: PenetrationSolver<R>,
    {
        if pair.point_cores() {
            if let Some(ref core) = PointCores::new(pair) {
                return core.penetration(pair);
            }
        }
        // Shapes whose bounding disks are apart have no penetration: said
        // before any support, which for large polygons reads both from memory.
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        if pair.bounding_disks_apart() {
            return None;
        }
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        if P::SEPARATING_AXES {
            if let Some((p, polygon, point_is_a)) = pair.point_and_small_polygon() {
                if let Some(near) = crate::point_polygon::nearest(polygon, p) {
                    return point_polygon_penetration(pair, near, point_is_a);
                }
            }
            if let Some((pa, pb)) = pair.small_polygons() {
                let axes = crate::sat::Axes::new(pair, pa, pb);
                if axes.separated() {
                    return None;
                }
                let (depth, normal) = axes.penetration();
                return Some(separating_axes_penetration(pair, depth, normal));
            }
            if let Some((pa, pb)) = pair.polygon_cores() {
                match crate::walked_axes::penetration(pair, pa, pb) {
                    Some(Walked::Apart) => return None,
                    Some(Walked::Overlapping(depth, normal)) => {
                        return Some(separating_axes_penetration(pair, depth, normal))
                    }
                    None => {}
                }
                // Counted as one iteration: the four supports are one round.
                match crate::quad_start::quad_start(pair) {
                    QuadStart::Apart => return None,
                    QuadStart::Enclosing(ref start) => {
                        return Some(solved_from(&self.solver, pair, start.points(), || 1))
                    }
                    QuadStart::Undecided => {}
                }
            }
            if let Some(ref axes) = crate::sat::Axes::of_segment_and_polygon(pair) {
                match rounded_axes(pair, axes) {
                    RoundedAxes::Overlapping(depth, normal) => {
                        return Some(separating_axes_penetration(pair, depth, normal))
                    }
                    RoundedAxes::Apart => return None,
                    RoundedAxes::Undecided => {}
                }
            }
        }
        // GJK in a function of its own, its result matched by reference, so
        // that its working values are gone before the solver's polytope exists.
        match core_proximity(pair, self.config.max_distance_iterations(), self.config.distance_epsilon()) {
            Proximity::Overlapping(ref enclosing) => Some(solved(&self.solver, pair, enclosing)),
            Proximity::Resolved(penetration) => penetration,
        }
    }

    /// The contact manifold of A and B: up to two points whose separation
    /// is at most `margin` (a speculative margin, zero for touching and
    /// overlapping points only), with the normal from A towards B that
    /// they share and the features that made them. Empty when the pair is
    /// farther apart than `margin`.
    ///
    /// The normal and the least separation are the distance query's when
    /// the shapes are apart, the penetration query's when they overlap;
    /// the manifold keeps that query's iterations and status. Polytope
    /// cores (polygons, rectangles, segments, capsules and rounded polygons
    /// by their cores) give two points where faces meet, the ends of the
    /// region where they face each other; curved shapes give one.
    ///
    /// A negative margin is [`Error::OutOfRange`], a NaN or infinite one
    /// [`Error::NonFinite`]. Shapes the two queries call touching and apart
    /// at once (rounding at contact) give an empty manifold.
    ///
    /// ```
    /// use gjk2d::{Feature, Gjk, Rectangle, Transform};
    /// use glam::Vec2;
    ///
    /// let gjk = Gjk::<f32>::new();
    /// let floor = Rectangle::new(10.0, 1.0)?; // its top face at y = 0.5
    /// let crate_ = Rectangle::new(2.0, 2.0)?;
    /// let resting = Transform::from_translation(Vec2::new(3.0, 1.4))?; // 0.1 deep
    /// let m = gjk.manifold(&floor, &Transform::IDENTITY, &crate_, &resting, 0.05)?;
    /// assert_eq!(m.normal, Vec2::Y);
    /// assert_eq!(m.points().len(), 2); // the crate's two bottom corners
    /// for p in m.points() {
    ///     assert!((p.separation + 0.1).abs() < 1e-6);
    ///     assert!((p.point.y - 0.5).abs() < 1e-6); // on the floor's top face
    ///     assert!(matches!(p.id.b, Feature::Vertex(_)));
    /// }
    /// # Ok::<(), gjk2d::Error>(())
    /// ```
    pub fn manifold<A, B>(
        &self,
        a: &A,
        ta: &Transform<R>,
        b: &B,
        tb: &Transform<R>,
        margin: R,
    ) -> Result<Manifold<R>, Error>
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R> + ?Sized,
        P: PenetrationSolver<R>,
    {
        self.manifold_by(a, ta, b, tb, margin, || self.contact(a, ta, b, tb))
    }

    /// [`manifold`](Self::manifold) with the normal and least separation
    /// from `nearest` (called once the margin is found sound).
    #[inline(always)]
    fn manifold_by<A, B>(
        &self,
        a: &A,
        ta: &Transform<R>,
        b: &B,
        tb: &Transform<R>,
        margin: R,
        nearest: impl FnOnce() -> Option<Nearest<R>>,
    ) -> Result<Manifold<R>, Error>
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R> + ?Sized,
    {
        if !margin.is_finite() {
            return Err(Error::NonFinite);
        }
        if margin < R::ZERO || margin > R::MAX_COORDINATE {
            return Err(Error::OutOfRange);
        }
        let Some((normal, separation, iterations, status)) = nearest() else {
            // Touching to the one query, apart to the other: no point either
            // would vouch for.
            return Ok(Manifold::empty(R::vector(R::ONE, R::ZERO), 0, Status::Converged));
        };
        // On bare metal the clipping runs after the queries above have
        // returned, so that a manifold needs no more of a microcontroller's
        // small stack than its deepest part.
        #[cfg(target_os = "none")]
        return in_own_frame(move || {
            let mut manifold = Manifold::empty(normal, iterations, status);
            if separation <= margin {
                let local = ta.inverse_rotate(V2::from_glam(normal));
                crate::manifold::contact_points(&Pair::new(a, ta, b, tb), local, margin, &mut manifold);
            }
            Ok(manifold)
        });
        #[cfg(not(target_os = "none"))]
        {
            let mut manifold = Manifold::empty(normal, iterations, status);
            if separation <= margin {
                let local = ta.inverse_rotate(V2::from_glam(normal));
                in_own_frame(|| {
                    crate::manifold::contact_points(&Pair::new(a, ta, b, tb), local, margin, &mut manifold)
                });
            }
            Ok(manifold)
        }
    }

    /// What a manifold starts from: the distance query's normal and
    /// distance when the shapes are apart, else the penetration query's
    /// normal and depth (negated), with that query's iterations and status.
    /// The same answers as the two queries asked in turn, but GJK runs once:
    /// its simplex, enclosing the origin, goes on to the penetration solver.
    fn contact<A, B>(&self, a: &A, ta: &Transform<R>, b: &B, tb: &Transform<R>) -> Option<Nearest<R>>
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R> + ?Sized,
        P: PenetrationSolver<R>,
    {
        // Bare metal and wasm run the two queries one after the other (an
        // early return, not a `match`), so that the pair needs no more of a
        // small stack than the deeper query.
        #[cfg(any(target_os = "none", target_family = "wasm"))]
        {
            if let Some(s) = in_own_frame(|| self.distance(a, ta, b, tb)) {
                return Some(apart(s));
            }
            in_own_frame(|| self.penetration(a, ta, b, tb)).map(overlapping)
        }
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        self.contact_of(Pair::new(a, ta, b, tb))
    }

    /// [`contact`](Self::contact) of a placed pair, with one GJK run.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    fn contact_of<A, B>(&self, pair: Pair<'_, R, A, B>) -> Option<Nearest<R>>
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R> + ?Sized,
        P: PenetrationSolver<R>,
    {
        if pair.point_cores() {
            if let Some(ref core) = PointCores::new(&pair) {
                if !core.certainly_within(pair.radius_a() + pair.radius_b()) {
                    if let Some(s) = core.separation(&pair) {
                        return Some(apart(s));
                    }
                }
                return core.penetration(&pair).map(overlapping);
            }
        }
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        if let Some((p, polygon, point_is_a)) = pair.point_and_small_polygon() {
            if let Some(near) = crate::point_polygon::nearest(polygon, p) {
                if let crate::point_polygon::Nearest::Outside { distance, normal, point } = near {
                    if let Some(s) = point_polygon_separation(&pair, (false, distance, normal, point), point_is_a) {
                        return Some(apart(s));
                    }
                }
                if P::SEPARATING_AXES {
                    return point_polygon_penetration(&pair, near, point_is_a).map(overlapping);
                }
            }
        }
        // Two small polygons: their axes decide overlap as the distance
        // query does, and give the penetration too, with no GJK; apart,
        // the distance query's answer (or where its GJK finds them
        // touching after all, the penetration query's).
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        if let Some((pa, pb)) = pair.small_polygons() {
            let axes = crate::sat::Axes::new(&pair, pa, pb);
            if axes.separated() {
                return match self.small_polygons_distance(&pair, (pa, pb), &axes) {
                    Some(s) => Some(apart(s)),
                    None => self.penetration_of(&pair).map(overlapping),
                };
            }
            if P::SEPARATING_AXES {
                let (depth, normal) = axes.penetration();
                return Some(overlapping(separating_axes_penetration(&pair, depth, normal)));
            }
            return self.penetration_of(&pair).map(overlapping);
        }
        // Polygons past eight vertices: the penetration query's walked
        // answer, asked once. Overlapping by far more than rounding, the
        // distance query certainly finds no separation, and GJK need not run.
        let axes = if P::SEPARATING_AXES && pair.small_polygons().is_none() {
            pair.polygon_cores().map(|(pa, pb)| crate::walked_axes::penetration(&pair, pa, pb))
        } else {
            None
        };
        let walked = match axes {
            Some(Some(Walked::Overlapping(depth, normal))) => Some((depth, normal)),
            _ => None,
        };
        if let Some((depth, normal)) = walked {
            if depth > R::from_u32(256) * R::EPSILON * pair.scale() {
                return Some(overlapping(separating_axes_penetration(&pair, depth, normal)));
            }
        }
        // Polygons too large to walk: the penetration query's four
        // supports, where they enclose the origin (by far more than
        // rounding, so again GJK need not run).
        if let Some(None) = axes {
            if let QuadStart::Enclosing(ref start) = crate::quad_start::quad_start(&pair) {
                return Some(overlapping(solved_from(&self.solver, &pair, start.points(), || 1)));
            }
        }
        match core_contact(&pair, self.config.max_distance_iterations(), self.config.distance_epsilon()) {
            CoreContact::Apart(s) => {
                // A segment core and a small polygon that the closed form
                // finds within reach, which the distance query then calls
                // touching (small polygons were decided above), part from GJK only
                // within rounding of touching (a margin far above it here):
                // the penetration query's answer is then the one to give.
                let offset = pair.pose().2;
                let reach = R::TWO * pair.scale() + offset.l1() + pair.radius();
                let near = s.distance <= s.error_bound + R::from_u32(1024) * R::EPSILON * reach;
                if near && segment_within_small_polygon(&pair) == Some(true) {
                    return self.penetration_of(&pair).map(overlapping);
                }
                Some(apart(s))
            }
            CoreContact::Resolved(p) => p.map(overlapping),
            CoreContact::Overlapping(ref enclosing) => {
                #[cfg(not(any(target_os = "none", target_family = "wasm")))]
                if P::SEPARATING_AXES {
                    // Small polygons get here only where an axis separates
                    // them (touching, to rounding): so says the penetration
                    // query.
                    if pair.small_polygons().is_some() {
                        return None;
                    }
                    // The penetration query's answer, to the bit: axes that
                    // say apart (touching, to rounding) leave it to EPA.
                    if let Some((depth, normal)) = walked {
                        return Some(overlapping(separating_axes_penetration(&pair, depth, normal)));
                    }
                    if let Some(ref axes) = crate::sat::Axes::of_segment_and_polygon(&pair) {
                        if let RoundedAxes::Overlapping(depth, normal) = rounded_axes(&pair, axes) {
                            return Some(overlapping(separating_axes_penetration(&pair, depth, normal)));
                        }
                    }
                }
                Some(overlapping(solved(&self.solver, &pair, enclosing)))
            }
        }
    }

    /// [`intersects`](Self::intersects), warm started from `cache` (the
    /// last step's of this pair, or a new one) and updating it: the same
    /// verdict. Two polygons of up to eight vertices are decided by the
    /// axis that separated them last or the triangle that enclosed the
    /// origin, where either still does; other shapes start GJK along the
    /// last normal.
    ///
    /// ```
    /// use gjk2d::{Gjk, PairCache, Rectangle, Transform};
    /// use glam::Vec2;
    ///
    /// let gjk = Gjk::<f32>::new();
    /// let box_ = Rectangle::new(1.0, 1.0)?;
    /// let mut cache = PairCache::default(); // one per pair, kept between steps
    /// for step in 0..10 {
    ///     let there = Transform::from_translation(Vec2::new(2.0 - 0.1 * step as f32, 0.0))?;
    ///     let cold = gjk.intersects(&box_, &Transform::IDENTITY, &box_, &there);
    ///     let warm = gjk.intersects_cached(&box_, &Transform::IDENTITY, &box_, &there, &mut cache);
    ///     assert_eq!(warm.intersecting, cold.intersecting);
    /// }
    /// # Ok::<(), gjk2d::Error>(())
    /// ```
    pub fn intersects_cached<A, B>(
        &self,
        a: &A,
        ta: &Transform<R>,
        b: &B,
        tb: &Transform<R>,
        cache: &mut PairCache<R>,
    ) -> Detection
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R> + ?Sized,
    {
        let mut pair = Pair::new(a, ta, b, tb);
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        if pair.inner_disks_overlap() {
            return Detection { intersecting: true, iterations: 0, status: Status::Converged };
        }
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        if self.config.detect_epsilon() == R::ZERO {
            if let Some((pa, pb)) = pair.small_polygons() {
                return cache.intersects_small(&pair, pa, pb);
            }
        }
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        if self.config.detect_epsilon() == R::ZERO && pair.bounding_disks_apart() {
            return Detection { intersecting: false, iterations: 0, status: Status::Converged };
        }
        if let Some(d) = cache.first_direction() {
            pair.first_direction = d;
        }
        self.intersects_of(&pair)
    }

    /// [`distance`](Self::distance), warm started from `cache` and
    /// updating it, within the same guarantees (its error bound and status
    /// are its own). For polygons of up to eight vertices the verdict is
    /// the cold query's, from the cached axis or triangle where either
    /// still decides; apart, the distance is read off the cached axis where
    /// its edge and nearest vertex are still the closest features, else GJK
    /// starts from the last simplex, its points measured again, as it does
    /// for larger polygons. Other shapes start GJK along the last normal.
    pub fn distance_cached<A, B>(
        &self,
        a: &A,
        ta: &Transform<R>,
        b: &B,
        tb: &Transform<R>,
        cache: &mut PairCache<R>,
    ) -> Option<Separation<R>>
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R> + ?Sized,
    {
        let pair = Pair::new(a, ta, b, tb);
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        if let Some((pa, pb)) = pair.small_polygons() {
            // Disks first, as the cold query asks them: a pair they decide
            // never reads its cache.
            if pair.inner_disks_overlap() {
                return None;
            }
            // Overlapping or apart as the cold query says; apart, from the
            // cached axis where it still gives the distance.
            match cache.face_and_vertex(&pair, pa, pb) {
                None => return None,
                Some(Some(found)) => return Some(closed_form_separation(&pair, found)),
                Some(None) => {}
            }
            return self.distance_from_cached_simplex(&pair, (pa, pb), cache);
        }
        // Larger polygons: GJK from the last simplex as well, where the
        // last normal would only save its first support or two.
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        if let Some((pa, pb)) = pair.polygon_cores() {
            if pair.inner_disks_overlap() {
                return None;
            }
            pair.prefetch_scanned_cores();
            let found = self.distance_from_cached_simplex(&pair, (pa, pb), cache);
            if let Some(s) = &found {
                // For a penetration query sharing the cache.
                cache.remember_normal(ta.inverse_rotate(V2::from_glam(s.normal)));
            }
            return found;
        }
        along_last_normal(pair, ta, cache, |pair| self.distance_of(pair), |s| s.normal)
    }

    /// GJK's distance loop of two polygon cores from the cached simplex,
    /// its points measured again (a cold start where the cache holds none
    /// that fits), and its last simplex kept for the next step.
    #[cfg(not(any(target_os = "none", target_family = "wasm")))]
    #[inline(always)]
    fn distance_from_cached_simplex<A, B>(
        &self,
        pair: &Pair<'_, R, A, B>,
        (pa, pb): (&[V2<R>], &[V2<R>]),
        cache: &mut PairCache<R>,
    ) -> Option<Separation<R>>
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R> + ?Sized,
    {
        let start = cache.simplex(pair, pa, pb);
        let mut simplex = None::<Simplex<R, Witness<R>>>;
        let (max, epsilon) = (self.config.max_distance_iterations(), self.config.distance_epsilon());
        match crate::gjk::distance_loop_from(pair, &mut simplex, start, max, epsilon) {
            CoreProximity::Overlapping { simplex, .. } => {
                cache.remember_simplex(simplex);
                None
            }
            CoreProximity::Separated(ref core) => {
                cache.remember_simplex(core.simplex);
                separation(pair, core)
            }
        }
    }

    /// [`penetration`](Self::penetration), warm started from `cache` and
    /// updating it, within the same guarantees. Two polygons of up to eight
    /// vertices get the cold answer to the bit: apart, from the last
    /// separating axis while it still separates; overlapping, in f64 (and
    /// in f32 without SIMD), from the last few leading axes alone while the
    /// motion since cannot have let another catch up (in f32 with SIMD all
    /// sixteen axes cost less than checking that). Other shapes start GJK
    /// along the last normal; polygons past the walked axes' 32 vertices
    /// start EPA there, with the support's neighbours on the boundary.
    pub fn penetration_cached<A, B>(
        &self,
        a: &A,
        ta: &Transform<R>,
        b: &B,
        tb: &Transform<R>,
        cache: &mut PairCache<R>,
    ) -> Option<Penetration<R>>
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R> + ?Sized,
        P: PenetrationSolver<R>,
    {
        let pair = Pair::new(a, ta, b, tb);
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        if P::SEPARATING_AXES {
            if let Some((pa, pb)) = pair.small_polygons() {
                return cache.penetration_small(&pair, pa, pb);
            }
        }
        along_last_normal(pair, ta, cache, |pair| self.penetration_of(pair), |p| p.normal)
    }

    /// [`manifold`](Self::manifold), its distance and penetration queries
    /// warm started from `cache` ([`distance_cached`](Self::distance_cached),
    /// [`penetration_cached`](Self::penetration_cached)) and updating it.
    pub fn manifold_cached<A, B>(
        &self,
        a: &A,
        ta: &Transform<R>,
        b: &B,
        tb: &Transform<R>,
        margin: R,
        cache: &mut PairCache<R>,
    ) -> Result<Manifold<R>, Error>
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R> + ?Sized,
        P: PenetrationSolver<R>,
    {
        self.manifold_by(a, ta, b, tb, margin, || {
            // Two small polygons: both queries say whether they overlap as
            // the cold ones do (by their axes). The one the cache expects
            // first: the distance where it holds a separating axis (which
            // then decides and measures in one pass), else the penetration.
            #[cfg(not(any(target_os = "none", target_family = "wasm")))]
            if P::SEPARATING_AXES && Pair::new(a, ta, b, tb).small_polygons().is_some() {
                if cache.expects_apart() {
                    if let Some(s) = self.distance_cached(a, ta, b, tb, cache) {
                        return Some(apart(s));
                    }
                    return self.penetration_cached(a, ta, b, tb, cache).map(overlapping);
                }
                return match self.penetration_cached(a, ta, b, tb, cache) {
                    Some(p) => Some(overlapping(p)),
                    None => self.distance_cached(a, ta, b, tb, cache).map(apart),
                };
            }
            nearest(self.distance_cached(a, ta, b, tb, cache), || self.penetration_cached(a, ta, b, tb, cache))
        })
    }

    /// Casts `ray` (world coordinates) against `shape` placed by `transform`,
    /// up to `max_length` (zero, negative or infinite: unbounded).
    ///
    /// ```
    /// use gjk2d::{Capsule, Gjk, Ray, RayOutcome, Transform};
    /// use glam::Vec2;
    ///
    /// let gjk = Gjk::<f32>::new();
    /// let pill = Capsule::new(Vec2::new(0.0, -1.0), Vec2::new(0.0, 1.0), 0.5)?;
    /// let placed = Transform::from_translation(Vec2::new(5.0, 0.0))?;
    /// let ray = Ray::new(Vec2::ZERO, Vec2::X)?;
    /// match gjk.raycast(&ray, 0.0, &pill, &placed).outcome {
    ///     RayOutcome::Hit(hit) => {
    ///         assert!((hit.distance - 4.5).abs() < 1e-6);
    ///         assert_eq!(hit.normal, -Vec2::X); // the surface's outward normal
    ///     }
    ///     other => panic!("expected a hit, got {other:?}"),
    /// }
    /// // At most 3 units long, the same ray misses.
    /// assert_eq!(gjk.raycast(&ray, 3.0, &pill, &placed).outcome, RayOutcome::Miss);
    /// # Ok::<(), gjk2d::Error>(())
    /// ```
    #[cfg_attr(not(target_os = "none"), inline(always))]
    pub fn raycast<S>(&self, ray: &Ray<R>, max_length: R, shape: &S, transform: &Transform<R>) -> RayCast<R>
    where
        S: SupportMap<R> + ?Sized,
    {
        // A polygon's fields are read far apart in the cast: asked for at
        // once, their lines arrive together.
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        if shape.casts_face_rays() {
            crate::polytope::prefetch_small(shape);
        }
        let max = if max_length > R::ZERO { max_length } else { R::INFINITY };
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        if let Some(radius) = shape.disk_radius().filter(|_| self.closed_form_rays) {
            return cast_ray_disk_scalar(ray, max, shape, transform, radius);
        }
        let (origin, rounded_reference, direction) = local_ray(ray, shape, transform);
        #[cfg(any(target_os = "none", target_family = "wasm"))]
        if let Some(radius) = shape.disk_radius().filter(|_| self.closed_form_rays) {
            return Disk::of(shape, radius).cast_placed(ray, max, origin, direction, rounded_reference);
        }
        // A polygon's cast in face form, every other shape's in the form of
        // `cast_local_ray` (or by GJK).
        let face = self.closed_form_rays && shape.casts_face_rays();
        let size = shape.bounding_radius();
        // A small polygon of a type known when the program is compiled is
        // clipped by every edge at once on hosts (never through `dyn
        // SupportMap`, so every target shares the golden batch's path).
        #[cfg(not(any(target_os = "none", target_family = "wasm")))]
        if face && Pair::<R, S, S>::shapes_known() {
            if let Some(polygon) = shape.small_polygon() {
                let rounding = FaceRounding::new(origin, rounded_reference, size);
                let cast = cast_ray_small_polygon(polygon.vertices, origin, direction, max, rounding);
                let outcome = match cast.verdict {
                    FaceVerdict::Hit if cast.t.is_finite() && cast.t <= max => {
                        let (normal, error_bound) = face_hit_world(
                            cast.normal,
                            direction,
                            (cast.t, cast.late),
                            origin,
                            rounded_reference,
                            size,
                        );
                        RayOutcome::Hit(world_hit(ray, cast.t, transform.rotate(normal), error_bound))
                    }
                    FaceVerdict::Inside => RayOutcome::Inside,
                    _ => RayOutcome::Miss,
                };
                return RayCast::closed_form(outcome);
            }
        }
        let local = if face {
            shape
                .cast_local_face_ray(origin.to_glam(), direction.to_glam(), max)
                .unwrap_or(RayCast::closed_form(RayOutcome::Miss))
        } else {
            let local = if self.closed_form_rays {
                shape.cast_local_ray(origin.to_glam(), direction.to_glam(), max)
            } else {
                None
            };
            local.unwrap_or_else(|| {
                cast_ray_gjk(
                    shape,
                    origin,
                    direction,
                    max,
                    self.config.max_raycast_iterations(),
                    self.config.raycast_epsilon(),
                )
            })
        };
        let outcome = match local.outcome {
            // A closed form of a user's shape could report a hit at infinity
            // (a ray parallel to rounding); no finite hit is a miss.
            RayOutcome::Hit(h) if !(h.distance.is_finite() && h.distance <= max) => RayOutcome::Miss,
            RayOutcome::Hit(h) => {
                let (normal, error_bound) = if face {
                    let gap = (h.distance, h.error_bound);
                    face_hit_world(V2::from_glam(h.normal), direction, gap, origin, rounded_reference, size)
                } else {
                    let normal = V2::from_glam(h.normal);
                    let cos = normal.dot(direction).abs();
                    (normal, hit_error_bound(h.error_bound, h.distance, cos, origin, rounded_reference, size))
                };
                RayOutcome::Hit(world_hit(ray, h.distance, transform.rotate(normal), error_bound))
            }
            other => other,
        };
        RayCast { outcome, ..local }
    }
    /// Where B, translating by `motion` (relative to A) from where `tb`
    /// places it, first touches A: the fraction of the motion, the unit
    /// normal from A towards B and the touching points (B's moved to the
    /// contact), or a miss. Shapes overlapping or touching at the start get
    /// [`CastOutcome::Start`] with their penetration, and whether the motion
    /// separates them. Curved cores iterate within the ray-cast settings
    /// ([`GjkConfig::max_raycast_iterations`], [`GjkConfig::raycast_epsilon`]).
    ///
    /// ```
    /// use gjk2d::{CastOutcome, Circle, Gjk, Motion, Rectangle, Transform};
    /// use glam::Vec2;
    ///
    /// let gjk = Gjk::<f32>::new();
    /// let wall = Rectangle::new(1.0, 4.0)?; // its left face at x = -0.5
    /// let ball = Circle::new(0.5)?;
    /// let start = Transform::from_translation(Vec2::new(-5.0, 0.0))?;
    /// let motion = Motion::new(Vec2::new(8.0, 0.0))?;
    /// match gjk.cast(&wall, &Transform::IDENTITY, &ball, &start, &motion).outcome {
    ///     CastOutcome::Hit(hit) => {
    ///         assert!((hit.distance - 4.0).abs() < 1e-6); // the ball's centre stops at x = -1
    ///         assert!((hit.fraction - 0.5).abs() < 1e-6);
    ///         assert_eq!(hit.normal, -Vec2::X); // from A (the wall) towards B (the ball)
    ///         assert!((hit.point_b - Vec2::new(-0.5, 0.0)).length() < 1e-6);
    ///     }
    ///     other => panic!("expected a hit, got {other:?}"),
    /// }
    /// // Moving away, the ball never touches the wall.
    /// let away = Motion::new(Vec2::new(-8.0, 0.0))?;
    /// assert_eq!(gjk.cast(&wall, &Transform::IDENTITY, &ball, &start, &away).outcome, CastOutcome::Miss);
    /// # Ok::<(), gjk2d::Error>(())
    /// ```
    pub fn cast<A, B>(&self, a: &A, ta: &Transform<R>, b: &B, tb: &Transform<R>, motion: &Motion<R>) -> ShapeCast<R>
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R> + ?Sized,
        P: PenetrationSolver<R>,
    {
        // The cheap intersection test first: most casts start apart, and it
        // proves it.
        let start = in_own_frame(|| {
            if self.intersects(a, ta, b, tb).intersecting {
                self.penetration(a, ta, b, tb)
            } else {
                None
            }
        });
        if let Some(penetration) = start {
            let separating = V2::from_glam(penetration.normal).dot(motion.translation) > R::ZERO;
            return ShapeCast {
                outcome: CastOutcome::Start(CastStart { penetration, separating }),
                iterations: penetration.iterations,
                status: penetration.status,
            };
        }
        let pair = Pair::new(a, ta, b, tb);
        cast_pair(
            &pair,
            ta.inverse_rotate(motion.translation),
            self.config.max_raycast_iterations(),
            self.config.raycast_epsilon(),
        )
    }

    /// The features of A and B that touch at a cast's `hit`: each shape's
    /// face flat to the hit's normal (within 2.5 degrees), else its vertex
    /// nearest the other, named as [`Gjk::manifold`] names them. They
    /// depend on the normal only, not on where along the motion B is, so
    /// A and B are given as the cast was. Asked apart from the cast, so that
    /// a cast that needs no ids costs nothing for them.
    ///
    /// ```
    /// use gjk2d::{CastOutcome, Feature, Gjk, Motion, Rectangle, Transform};
    /// use glam::Vec2;
    ///
    /// let gjk = Gjk::<f32>::new();
    /// let floor = Rectangle::new(10.0, 1.0)?; // its top face at y = 0.5
    /// let crate_ = Rectangle::new(2.0, 2.0)?;
    /// let above = Transform::from_translation(Vec2::new(0.0, 4.0))?;
    /// let fall = Motion::new(Vec2::new(0.0, -5.0))?;
    /// let CastOutcome::Hit(hit) = gjk.cast(&floor, &Transform::IDENTITY, &crate_, &above, &fall).outcome else {
    ///     panic!("the crate lands on the floor")
    /// };
    /// let features = gjk.cast_features(&floor, &Transform::IDENTITY, &crate_, &above, &hit);
    /// // Face on face: the floor's top edge, the crate's bottom edge.
    /// assert!(matches!((features.a, features.b), (Feature::Edge(_), Feature::Edge(_))));
    /// # Ok::<(), gjk2d::Error>(())
    /// ```
    pub fn cast_features<A, B>(&self, a: &A, ta: &Transform<R>, b: &B, tb: &Transform<R>, hit: &CastHit<R>) -> FeatureId
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R> + ?Sized,
    {
        let normal = ta.inverse_rotate(V2::from_glam(hit.normal));
        crate::manifold::facing_features(&Pair::new(a, ta, b, tb), normal)
    }

    /// When A and B, each moving by its [`Sweep`] over a step (translating
    /// and turning), first come within `config`'s target distance: the
    /// time, a fraction of the step, with their separation (within the
    /// tolerance above the target), normal and closest points there; a miss
    /// when they stay farther apart; [`ImpactOutcome::Start`](crate::ImpactOutcome::Start) when they are
    /// closer than the target at the start.
    ///
    /// Conservative advancement: each iteration asks the distance query
    /// and moves the time on by the gap over the fastest the shapes could
    /// close it along its normal, so the time is never after the first
    /// contact, even where it stops at the iteration limit
    /// ([`Status::IterationLimit`]). A fast spin or a target of zero takes
    /// more iterations. A tolerance below the distance query's own
    /// (`distance_epsilon` times the pair's size) on curved shapes may stop
    /// it early, at a safe time, with that status.
    ///
    /// ```
    /// use gjk2d::{Gjk, ImpactConfig, Rectangle, Sweep, Transform};
    /// use glam::Vec2;
    ///
    /// let gjk = Gjk::<f32>::new();
    /// let wall = Rectangle::new(1.0, 10.0)?; // its left face at x = -0.5
    /// let plank = Rectangle::new(4.0, 0.2)?;
    /// let start = Transform::from_translation(Vec2::new(-6.0, 0.0))?;
    /// // Moving 8 to the right while turning a quarter turn about its centre.
    /// let spin = Sweep::new(&start, Vec2::ZERO, Vec2::new(8.0, 0.0), core::f32::consts::FRAC_PI_2)?;
    /// let config = ImpactConfig::new(0.01, 0.005)?;
    /// let toi = gjk.time_of_impact(&wall, &Sweep::still(&Transform::IDENTITY), &plank, &spin, &config);
    /// let hit = toi.hit().expect("the plank's end reaches the wall");
    /// assert!(hit.time < 1.0);
    /// assert!(hit.separation >= 0.0099 && hit.separation <= 0.0151);
    /// assert!((hit.normal - -Vec2::X).length() < 1e-3);
    /// # Ok::<(), gjk2d::Error>(())
    /// ```
    pub fn time_of_impact<A, B>(
        &self,
        a: &A,
        sweep_a: &Sweep<R>,
        b: &B,
        sweep_b: &Sweep<R>,
        config: &ImpactConfig<R>,
    ) -> TimeOfImpact<R>
    where
        A: SupportMap<R> + ?Sized,
        B: SupportMap<R> + ?Sized,
        P: PenetrationSolver<R>,
    {
        advance(
            a,
            sweep_a,
            b,
            sweep_b,
            config,
            |ta, tb| in_own_frame(|| self.distance(a, ta, b, tb)),
            |ta, tb| in_own_frame(|| self.penetration(a, ta, b, tb)),
        )
    }
}

/// `query` of the pair with GJK's first search direction from `cache`,
/// whose answer's normal (`normal`) the cache keeps for the next step.
#[inline(always)]
fn along_last_normal<'s, R, A, B, T>(
    mut pair: Pair<'s, R, A, B>,
    ta: &Transform<R>,
    cache: &mut PairCache<R>,
    query: impl FnOnce(&Pair<'s, R, A, B>) -> Option<T>,
    normal: impl FnOnce(&T) -> R::Vector,
) -> Option<T>
where
    R: Real,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
{
    if let Some(d) = cache.first_direction() {
        pair.first_direction = d;
    }
    let found = query(&pair);
    if let Some(found) = &found {
        cache.remember_normal(ta.inverse_rotate(V2::from_glam(normal(found))));
    }
    found
}

/// What a manifold keeps of the query that found its normal: the normal,
/// the least separation (negative: depth), iterations and status.
type Nearest<R> = (<R as Real>::Vector, R, u32, Status);

/// The distance query's answer where the shapes are apart, else the
/// penetration query's; `None` where neither vouches for a normal.
#[inline(always)]
fn nearest<R: Real>(
    separation: Option<Separation<R>>,
    penetration: impl FnOnce() -> Option<Penetration<R>>,
) -> Option<Nearest<R>> {
    match separation {
        Some(s) => Some(apart(s)),
        None => penetration().map(overlapping),
    }
}

/// `f()` in a frame of its own on bare metal, so that a query that asks
/// several (the cast, the manifold) never holds two of their working sets
/// at once on a microcontroller's small stack.
#[cfg_attr(target_os = "none", inline(never))]
fn in_own_frame<T>(f: impl FnOnce() -> T) -> T {
    f()
}

/// A hit `t` along the world ray: its point from the world ray, not from
/// the local point (one rounding less).
#[inline(always)]
fn world_hit<R: Real>(ray: &Ray<R>, t: R, normal: V2<R>, error_bound: R) -> RayHit<R> {
    RayHit { distance: t, point: (ray.origin + ray.direction * t).to_glam(), normal: normal.to_glam(), error_bound }
}

/// The ray in the shape's frame: its origin relative to the shape's
/// reference point, that reference as it rounded into the origin (zero
/// where far geometry sums the gap error-free), and its direction.
#[inline(always)]
fn local_ray<R, S>(ray: &Ray<R>, shape: &S, transform: &Transform<R>) -> (V2<R>, V2<R>, V2<R>)
where
    R: Real,
    S: SupportMap<R> + ?Sized,
{
    let reference = V2::from_glam(shape.reference_point());
    // Into the shape's frame, relative to its reference point: the
    // difference first, so a ray near a far-away shape keeps its precision.
    #[cfg_attr(not(feature = "far-geometry"), allow(unused_mut))]
    let (mut origin, mut rounded_reference) =
        (transform.inverse_rotate(ray.origin - transform.translation) - reference, reference);
    // Geometry far from its local origin, placed: that difference rounds
    // at the reference's distance; the origin's gap to the placed
    // reference, summed error-free, does not. (Not placed, it is one
    // difference, rounded at the origin's scale.)
    #[cfg(feature = "far-geometry")]
    if shape.far_from_origin() {
        if !transform.is_identity() {
            let gap = crate::compensated::placed_gap(transform, reference, &Transform::IDENTITY, ray.origin);
            origin = transform.inverse_rotate(gap);
        }
        rounded_reference = V2::zero();
    }
    (origin, rounded_reference, transform.inverse_rotate(ray.direction))
}

/// A ray against a disk on hosts, where the closed form is short and
/// scalar: packed into vector registers, its rotations and cross products
/// cost more in shuffles than in arithmetic, so its numbers pass the scalar
/// barrier.
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
#[inline(always)]
fn cast_ray_disk_scalar<R, S>(ray: &Ray<R>, max: R, shape: &S, transform: &Transform<R>, radius: R) -> RayCast<R>
where
    R: Real,
    S: SupportMap<R> + ?Sized,
{
    let (ray, transform) = (&ray.scalar_barrier(), &transform.scalar_barrier());
    let (origin, reference, direction) = local_ray(ray, shape, transform);
    Disk::of(shape, radius).cast_placed(ray, max, origin.scalar_barrier(), direction.scalar_barrier(), reference)
}

/// A disk in the shape's frame: its center relative to the reference
/// point, its radius, and the shape's bounding radius.
struct Disk<R: Real> {
    center: V2<R>,
    radius: R,
    size: R,
}

impl<R: Real> Disk<R> {
    /// The disk of a shape whose [`SupportMap::disk_radius`] is `radius`.
    #[inline(always)]
    fn of<S: SupportMap<R> + ?Sized>(shape: &S, radius: R) -> Self {
        Self { center: V2::from_glam(shape.center()), radius, size: shape.bounding_radius() }
    }

    /// A ray against the disk ([`DiskRay`]) on the ray's local origin and
    /// direction, its normal from the ray's world direction, so it needs no
    /// rotation back. On hosts the outcome is picked by selects: which of
    /// inside, miss and hit a ray of a scene gives is a coin toss a
    /// predictor would miss.
    #[inline(always)]
    fn cast_placed(&self, ray: &Ray<R>, max: R, origin: V2<R>, d: V2<R>, reference: V2<R>) -> RayCast<R> {
        let local = match DiskRay::new(self.center, self.radius, origin, d) {
            Ok(local) => local,
            Err(outcome) => return RayCast::closed_form(outcome),
        };
        let (t, inverse_radius) = (local.t, R::ONE / self.radius);
        let hit = RayHit {
            distance: t,
            point: (ray.origin + ray.direction * t).to_glam(),
            normal: local.normal(ray.direction, inverse_radius).to_glam(),
            error_bound: disk_error_bound(t, local.half_chord, self.radius, origin, reference, self.size),
        };
        // A finite hit within the limit, never inf or NaN.
        let hits = !local.inside & !local.misses & (t < R::INFINITY) & (t <= max);
        let missed = core::hint::select_unpredictable(local.inside, RayOutcome::Inside, RayOutcome::Miss);
        RayCast::closed_form(core::hint::select_unpredictable(hits, RayOutcome::Hit(hit), missed))
    }
}

/// A hit distance's error bound: what may have moved the boundary across
/// the ray (the local cast's gap, and rounding at the scale of the ray's
/// origin, the reference point, the shape's size and the distance) over the
/// incidence `cos = |n . d|`, less the normal's own rounding: a ray turning
/// towards the tangent moves its hit that much more (on a curve, at most
/// `sqrt(2 r e)`, which `e / cos` covers with the computed `cos`). At most
/// the distance plus the shape's diameter, so never inf or NaN. One
/// formula for every shape but the disk and the polygons
/// ([`disk_error_bound`], [`face_hit_world`]), out of line on bare metal so
/// that one copy serves every other shape's cast.
#[cfg_attr(target_os = "none", inline(never))]
fn hit_error_bound<R: Real>(gap: R, t: R, cos: R, origin: V2<R>, reference: V2<R>, size: R) -> R {
    let eps = R::EPSILON;
    let across = gap + R::from_u32(8) * eps * (origin.l1() + reference.l1() + size + t);
    let cap = t + R::TWO * size + gap;
    let cos = cos - R::TWO * eps;
    // The reciprocal waits only for the normal, not for the distance too.
    let bound = across * (R::ONE / cos) + R::from_u32(4) * eps * t;
    if (cos > R::ZERO) & (bound < cap) {
        bound
    } else {
        cap
    }
}

/// [`hit_error_bound`] of a hit in face form
/// ([`SupportMap::cast_local_face_ray`]), and its unit normal. With `m`
/// the face's normal and `c = |m . d|`, the incidence is `c / |m|`: the
/// gap and the rounding over it less its own rounding are one quotient by
/// `c - 2 eps |m|`, which waits only for the square root, as the unit
/// normal does. A face too small to have a normal gets the ray's reverse,
/// as the local cast's does.
#[inline(always)]
fn face_hit_world<R: Real>(
    m: V2<R>,
    d: V2<R>,
    (t, late): (R, R),
    origin: V2<R>,
    reference: V2<R>,
    size: R,
) -> (V2<R>, R) {
    let ((length, unit), m) = match m.try_length_and_unit() {
        Some(normal) => (normal, m),
        None => ((R::ONE, -d), -d),
    };
    let eps = R::EPSILON;
    let c = m.dot(d).abs();
    let across = late * c + R::from_u32(8) * eps * (origin.l1() + reference.l1() + size + t) * length;
    let cap = t + R::TWO * size + late;
    let edge = c - R::TWO * eps * length;
    let bound = across / edge + R::from_u32(4) * eps * t;
    (unit, core::hint::select_unpredictable((edge > R::ZERO) & (bound < cap), bound, cap))
}

/// [`hit_error_bound`] of a disk's hit, whose incidence is the half chord
/// over the radius: the reciprocal of the incidence less its rounding is
/// the radius over the half chord less the radius's share of it, one
/// division that waits only for the square root, as the distance's does.
#[inline(always)]
fn disk_error_bound<R: Real>(t: R, half_chord: R, radius: R, origin: V2<R>, reference: V2<R>, size: R) -> R {
    let eps = R::EPSILON;
    let across = R::from_u32(8) * eps * (origin.l1() + reference.l1() + size + t);
    let cap = t + R::TWO * size;
    let edge = half_chord - R::TWO * eps * radius;
    let bound = across * (radius / edge) + R::from_u32(4) * eps * t;
    core::hint::select_unpredictable((edge > R::ZERO) & (bound < cap), bound, cap)
}

/// Whether a segment core (a capsule's, a segment's) lies within the
/// radius of a small polygon, in closed form ([`crate::segment_polygon`]);
/// `None` for other pairs, and where the closed form leaves it to GJK.
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
#[inline(always)]
fn segment_within_small_polygon<R, A, B>(pair: &Pair<'_, R, A, B>) -> Option<bool>
where
    R: Real,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
{
    let (segment, polygon) = pair.segment_in_small_polygon()?;
    crate::segment_polygon::within(polygon, segment[0], segment[1], pair.radius())
}

/// The separation of a point core and a small polygon from the polygon's
/// nearest feature ([`crate::point_polygon::beyond`]'s answer): what GJK's
/// loop ends with, in closed form. `None` where the point core is inside
/// or within the radii, one branch for both.
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
#[inline(always)]
fn point_polygon_separation<R, A, B>(
    pair: &Pair<'_, R, A, B>,
    (inside, distance, normal, point): (bool, R, V2<R>, V2<R>),
    point_is_a: bool,
) -> Option<Separation<R>>
where
    R: Real,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
{
    let (radius_a, radius_b) = (pair.radius_a(), pair.radius_b());
    if inside | (distance <= radius_a + radius_b) {
        return None;
    }
    // `normal` points from the polygon towards the point; the circle's
    // closest point lies that far back from its centre.
    let (normal, point_a, point_b) = if point_is_a {
        let (normal, point) = (pair.b_vector_to_pair(normal), pair.b_to_pair(point));
        let centre = V2::from_glam(pair.a_center());
        (-normal, centre - normal * radius_a, point)
    } else {
        let centre = pair.b_to_pair(V2::from_glam(pair.b_center()));
        (normal, point, centre - normal * radius_b)
    };
    Some(closed_form_separation(pair, (distance - (radius_a + radius_b), normal, point_a, point_b)))
}

/// The separation a closed form found, exact, with no iteration: the
/// distance, the unit normal from A towards B and the closest points on A
/// and B, all in the pair frame (a point core against a small polygon; two
/// small polygons whose closest features are an edge and a vertex,
/// [`crate::sat::face_and_vertex_placed`]).
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
#[inline(always)]
fn closed_form_separation<R, A, B>(
    pair: &Pair<'_, R, A, B>,
    (distance, normal, point_a, point_b): crate::sat::FaceAndVertex<R>,
) -> Separation<R>
where
    R: Real,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
{
    Separation {
        distance,
        normal: pair.to_world_vector(normal),
        point_a: pair.to_world_point(point_a),
        point_b: pair.to_world_point(point_b),
        error_bound: R::ZERO,
        iterations: 1,
        status: Status::Converged,
    }
}

/// The penetration the separating axes found: exact, with no iteration.
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
#[inline(always)]
fn separating_axes_penetration<R, A, B>(pair: &Pair<'_, R, A, B>, depth: R, normal: V2<R>) -> Penetration<R>
where
    R: Real,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
{
    Penetration {
        normal: pair.to_world_vector(normal),
        depth,
        error_bound: R::ZERO,
        iterations: 1,
        status: Status::Converged,
    }
}

/// What the separating axes of a rounded core pair decide.
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
enum RoundedAxes<R> {
    /// The cores overlap: the shapes' depth (the cores' plus the radii) and
    /// normal.
    Overlapping(R, V2<R>),
    /// An axis separates the cores by more than the radii.
    Apart,
    /// The cores are apart, by less than the radii along every axis: their
    /// distance, which may be more, is GJK's to find.
    Undecided,
}

/// The verdict of a segment core's and a small polygon's separating axes
/// on the rounded shapes. An axis's separation is at most the cores'
/// distance, so beyond the radii by more than its rounding (the shapes' sizes
/// and offset, 16 eps of them) it proves them apart; short of it, only
/// overlapping cores are certain.
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
#[inline(always)]
fn rounded_axes<R, A, B>(pair: &Pair<'_, R, A, B>, axes: &crate::sat::Axes<R>) -> RoundedAxes<R>
where
    R: Real,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
{
    let (core_depth, normal) = axes.penetration();
    let radius = pair.radius();
    if core_depth >= R::ZERO {
        return RoundedAxes::Overlapping(core_depth + radius, normal);
    }
    let size = pair.scale() + pair.centers.x.abs() + pair.centers.y.abs();
    if -core_depth > radius + R::from_u32(16) * R::EPSILON * size {
        RoundedAxes::Apart
    } else {
        RoundedAxes::Undecided
    }
}

/// The penetration of a point core and a small polygon: the circle's radius
/// less the centre's distance outside, or plus its depth inside, along the
/// nearest feature's normal.
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
fn point_polygon_penetration<R, A, B>(
    pair: &Pair<'_, R, A, B>,
    near: crate::point_polygon::Nearest<R>,
    point_is_a: bool,
) -> Option<Penetration<R>>
where
    R: Real,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
{
    use crate::point_polygon::Nearest;
    let radius = pair.radius();
    let (depth, normal) = match near {
        Nearest::Outside { distance, .. } if distance > radius => return None,
        Nearest::Outside { distance, normal, .. } => (radius - distance, normal),
        Nearest::Inside { depth, normal } => (radius + depth, normal),
    };
    // From A towards B: the polygon's outward normal when it is A.
    let normal = if point_is_a { -pair.b_vector_to_pair(normal) } else { normal };
    Some(Penetration {
        normal: pair.to_world_vector(normal),
        depth,
        error_bound: R::ZERO,
        iterations: 1,
        status: Status::Converged,
    })
}

/// What the penetration query's GJK leaves for the solver: the simplex
/// that encloses the origin, or the answer already (cores apart).
enum Proximity<R: Real> {
    Overlapping(Enclosing<R>),
    Resolved(Option<Penetration<R>>),
}

/// GJK for the penetration query, with the closed form for rounded shapes
/// whose cores are apart. Not inlined on bare metal, and returning no
/// simplex, so that GJK's values are gone before the solver's polytope
/// exists: a microcontroller's small stack never holds both.
#[cfg_attr(target_os = "none", inline(never))]
#[cfg_attr(not(target_os = "none"), inline(always))]
fn core_proximity<R, A, B>(pair: &Pair<'_, R, A, B>, max_iterations: u32, epsilon: R) -> Proximity<R>
where
    R: Real,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
{
    // Witness points on bare metal, so that one GJK loop serves the distance
    // and the penetration query; nothing elsewhere, which is faster.
    #[cfg(target_os = "none")]
    let gjk = core_gjk::<R, A, B, Witness<R>, _>(pair, max_iterations, epsilon, |core| rounded_overlap(pair, core));
    #[cfg(not(target_os = "none"))]
    let gjk = core_gjk::<R, A, B, (), _>(pair, max_iterations, epsilon, |core| rounded_overlap(pair, core));
    match gjk {
        Err(enclosing) => Proximity::Overlapping(enclosing),
        Ok(penetration) => Proximity::Resolved(penetration),
    }
}

/// GJK on the cores: `apart` of their separation where they are apart,
/// else the simplex that encloses the origin.
#[inline(always)]
fn core_gjk<R, A, B, W, T>(
    pair: &Pair<'_, R, A, B>,
    max_iterations: u32,
    epsilon: R,
    apart: impl FnOnce(&CoreSeparation<'_, R, W>) -> T,
) -> Result<T, Enclosing<R>>
where
    R: Real,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
    W: Payload<R>,
{
    let mut simplex = None::<Simplex<R, W>>;
    match pair.core_distance(&mut simplex, max_iterations, epsilon) {
        CoreProximity::Overlapping { simplex, iterations } => Err(Enclosing::from_simplex(simplex, iterations)),
        CoreProximity::Separated(ref core) => Ok(apart(core)),
    }
}

/// The penetration of cores that overlap, from the solver started on GJK's
/// enclosing simplex, the radii added.
#[inline(always)]
fn solved<R, A, B, P>(solver: &P, pair: &Pair<'_, R, A, B>, enclosing: &Enclosing<R>) -> Penetration<R>
where
    R: Real,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
    P: PenetrationSolver<R>,
{
    solved_from(solver, pair, enclosing.points(), || enclosing.iterations)
}

/// The penetration of cores that overlap, from the solver started on
/// `points` (counter-clockwise, enclosing the origin) found in
/// `iterations`, the radii added. The count is asked for after the solver
/// has run: read before, it would hold a register across the call, and
/// every query it is inlined into would be allocated otherwise.
#[inline(always)]
fn solved_from<R, A, B, P>(
    solver: &P,
    pair: &Pair<'_, R, A, B>,
    points: &[SupportPoint<R>],
    iterations: impl FnOnce() -> u32,
) -> Penetration<R>
where
    R: Real,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
    P: PenetrationSolver<R>,
{
    let estimate = solver.solve(pair, points);
    Penetration {
        normal: pair.to_world_vector(V2::from_glam(estimate.normal)),
        depth: estimate.depth + pair.radius(),
        error_bound: estimate.error_bound,
        iterations: iterations() + estimate.iterations,
        status: estimate.status,
    }
}

/// The manifold's start from shapes apart.
#[inline(always)]
fn apart<R: Real>(s: Separation<R>) -> Nearest<R> {
    (s.normal, s.distance, s.iterations, s.status)
}

/// The manifold's start from shapes that overlap (or touch).
#[inline(always)]
fn overlapping<R: Real>(p: Penetration<R>) -> Nearest<R> {
    (p.normal, -p.depth, p.iterations, p.status)
}

/// What the manifold's GJK run leaves: the separation of shapes apart, the
/// penetration of rounded shapes whose cores are apart, or the simplex that
/// encloses the origin for the solver.
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
enum CoreContact<R: Real> {
    Apart(Separation<R>),
    Resolved(Option<Penetration<R>>),
    Overlapping(Enclosing<R>),
}

/// GJK for the manifold's normal: [`core_proximity`] with the distance
/// query's witness points, so shapes apart get their separation.
#[cfg(not(any(target_os = "none", target_family = "wasm")))]
#[inline(always)]
fn core_contact<R, A, B>(pair: &Pair<'_, R, A, B>, max_iterations: u32, epsilon: R) -> CoreContact<R>
where
    R: Real,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
{
    let separated = |core: &CoreSeparation<'_, R, Witness<R>>| match separation(pair, core) {
        Some(s) => CoreContact::Apart(s),
        None => CoreContact::Resolved(rounded_overlap(pair, core)),
    };
    core_gjk(pair, max_iterations, epsilon, separated).unwrap_or_else(CoreContact::Overlapping)
}

/// The penetration of rounded shapes whose cores are apart, in closed form
/// from the core distance; `None` when the shapes are certainly apart. Not
/// inlined on bare metal, so that a microcontroller's small stack holds its
/// working values and GJK's one after the other, never both.
#[cfg_attr(target_os = "none", inline(never))]
fn rounded_overlap<R, A, B, P>(pair: &Pair<'_, R, A, B>, core: &CoreSeparation<'_, R, P>) -> Option<Penetration<R>>
where
    R: Real,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
{
    // Asked once: through `dyn SupportMap` each ask is two calls.
    let radius = pair.radius();
    // A closest point too small to give a direction is touching.
    let (distance, normal) = core
        .simplex
        .distance_and_normal(core.v, pair.centers)
        .unwrap_or_else(|| (R::ZERO, pair.centers.try_normalize().unwrap_or(V2::new(R::ONE, R::ZERO))));
    let error_bound = (distance - core.lower_bound).max(R::ZERO);
    let certain = core.status.is_converged() || core.lower_bound > radius;
    if distance > radius && certain {
        return None;
    }
    Some(Penetration {
        normal: pair.to_world_vector(normal),
        depth: (radius - distance).max(R::ZERO),
        error_bound,
        iterations: core.iterations,
        status: core.status,
    })
}

#[cfg_attr(not(target_os = "none"), inline(always))]
fn separation<R, A, B>(pair: &Pair<'_, R, A, B>, core: &CoreSeparation<'_, R, Witness<R>>) -> Option<Separation<R>>
where
    R: Real,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
{
    let (core_distance, normal) = core.simplex.distance_and_normal(core.v, pair.centers)?;
    // Each radius asked once: through `dyn SupportMap` each ask is a call.
    let (radius_a, radius_b) = (pair.radius_a(), pair.radius_b());
    let radius = radius_a + radius_b;
    // `core_distance` is an upper bound: within the radii, certainly touching.
    if core_distance <= radius {
        return None;
    }
    let (a, b) = core.simplex.witness_points();
    // Only where there is a radius: for polygons the compiler then sees
    // there is nothing to add (`p + n * 0.0` is not `p` to it).
    let a = if radius_a > R::ZERO { a + normal * radius_a } else { a };
    let b = if radius_b > R::ZERO { b - normal * radius_b } else { b };
    Some(Separation {
        distance: (core_distance - radius).max(R::ZERO),
        normal: pair.to_world_vector(normal),
        point_a: pair.to_world_point(a),
        point_b: pair.to_world_point(b),
        error_bound: (core_distance - core.lower_bound).max(R::ZERO),
        iterations: core.iterations,
        status: core.status,
    })
}

/// Whether the separating axes part two small f64 polygons, measured in
/// code compiled for AVX2 where the processor has it
/// ([`run_wide`](crate::real::run_wide)); `None` for any other pair or
/// processor. The pair is placed inside that code too: only the verdict
/// crosses back.
#[cfg(all(target_arch = "x86_64", target_feature = "sse2", not(target_os = "none")))]
#[inline(always)]
fn separated_in_wide_lanes<R, A, B>(a: &A, ta: &Transform<R>, b: &B, tb: &Transform<R>) -> Option<bool>
where
    R: Real,
    A: SupportMap<R> + ?Sized,
    B: SupportMap<R> + ?Sized,
{
    if !(R::wide_lanes() && Pair::new(a, ta, b, tb).small_polygons().is_some()) {
        return None;
    }
    crate::real::run_wide(
        #[inline(always)]
        || {
            let pair = Pair::new(a, ta, b, tb);
            let (pa, pb) = pair.small_polygons()?;
            Some(crate::sat::Axes::new_wide(&pair, pa, pb).separated())
        },
    )
}
