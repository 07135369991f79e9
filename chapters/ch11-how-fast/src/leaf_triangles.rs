//! Step 3: the leaves' triangles laid out for the test. Side by side in
//! leaf order (as chapter 8 already has them), and in `f32` when that
//! loses nothing: every corner of a mesh read from an OBJ file is an
//! `f32`, so 36 bytes per triangle hold exactly what chapter 8's 72 do.
//! The test widens them back to `f64` (exactly) and runs chapter 8's
//! watertight test unchanged: the same answer, bit for bit, from half the
//! memory traffic.
use ch08::PreparedRay;
use raystep_core::{DVec3, Interval};

/// The triangles of the leaves, in leaf order.
#[derive(Clone, Debug, PartialEq)]
pub enum LeafTriangles {
    /// Corners in `f64`, as chapter 8 stores them.
    Double(Vec<[DVec3; 3]>),
    /// Corners in `f32`: only when each is exactly an `f32`.
    Single(Vec<[f32; 9]>),
}

impl LeafTriangles {
    // ANCHOR: leaf_triangles
    /// `triangles` (in leaf order) in `f32` if `single` is asked for and
    /// every coordinate is exactly an `f32`; in `f64` otherwise.
    pub fn new(triangles: Vec<[DVec3; 3]>, single: bool) -> LeafTriangles {
        let exact = |x: f64| f64::from(x as f32) == x || x.is_nan();
        let fits = triangles
            .iter()
            .flatten()
            .all(|p| p.to_array().into_iter().all(exact));
        if !(single && fits) {
            return LeafTriangles::Double(triangles);
        }
        LeafTriangles::Single(
            triangles
                .iter()
                .map(|[a, b, c]| {
                    let f = |p: &DVec3, i: usize| p[i] as f32;
                    [
                        f(a, 0),
                        f(a, 1),
                        f(a, 2),
                        f(b, 0),
                        f(b, 1),
                        f(b, 2),
                        f(c, 0),
                        f(c, 1),
                        f(c, 2),
                    ]
                })
                .collect(),
        )
    }

    /// Chapter 8's watertight test of triangle `k`: its `t` within
    /// `interval`.
    #[inline]
    pub fn test(
        &self,
        k: usize,
        ray: &PreparedRay,
        interval: Interval,
    ) -> Option<f64> {
        match self {
            LeafTriangles::Double(v) => ray.triangle(&v[k], interval),
            LeafTriangles::Single(v) => {
                let v = &v[k];
                let corner = |i: usize| {
                    DVec3::new(
                        f64::from(v[i]),
                        f64::from(v[i + 1]),
                        f64::from(v[i + 2]),
                    )
                };
                ray.triangle(&[corner(0), corner(3), corner(6)], interval)
            }
        }
    }
    // ANCHOR_END: leaf_triangles

    /// How many triangles.
    pub fn len(&self) -> usize {
        match self {
            LeafTriangles::Double(v) => v.len(),
            LeafTriangles::Single(v) => v.len(),
        }
    }

    /// No triangles?
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Their bytes.
    pub fn bytes(&self) -> usize {
        match self {
            LeafTriangles::Double(v) => v.len() * size_of::<[DVec3; 3]>(),
            LeafTriangles::Single(v) => v.len() * size_of::<[f32; 9]>(),
        }
    }
}
