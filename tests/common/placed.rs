//! A test shape placed by a transform, next to its exact counterpart: the
//! same struct for the property and the stiff suites. Expanded inside each
//! suite's per-precision module, where `R`, `pt`, `Geo`, `Pt`, `norm`,
//! `ExactShape` and `transform_shape` are in scope.

macro_rules! placed_shape {
    () => {
        /// A shape placed by a transform, with its exact counterpart.
        struct Placed {
            geo: Geo,
            shape: Box<dyn SupportMap<R>>,
            tf: Transform<R>,
            cs: (f64, f64),
            t: Pt,
            exact: ExactShape,
        }

        #[allow(dead_code)] // each suite uses its own subset
        impl Placed {
            fn from_parts(geo: Geo, shape: Box<dyn SupportMap<R>>, tf: Transform<R>) -> Self {
                let cs = (tf.cos() as f64, tf.sin() as f64);
                let t = pt(tf.translation());
                let exact = transform_shape(&geo.oracle(), cs.0, cs.1, t[0], t[1]);
                Self { geo, shape, tf, cs, t, exact }
            }
            fn map(&self, p: Pt) -> Pt {
                [self.cs.0 * p[0] - self.cs.1 * p[1] + self.t[0], self.cs.1 * p[0] + self.cs.0 * p[1] + self.t[1]]
            }
            fn center(&self) -> Pt {
                self.map(pt(self.shape.reference_point() + self.shape.center()))
            }
            fn radius(&self) -> f64 {
                self.shape.bounding_radius() as f64
            }
            fn support(&self, n: Pt) -> f64 {
                self.geo.support(self.cs, self.t, n)
            }
            fn identity(&self) -> bool {
                self.tf == Transform::IDENTITY
            }
            /// Largest world coordinate magnitude of the shape.
            fn reach(&self) -> f64 {
                norm(self.t) + self.geo.extent() * 1.0001
            }
        }
    };
}
