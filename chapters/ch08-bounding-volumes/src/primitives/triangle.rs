use ch02::{Plane, Polygon};
use raystep_core::{Aabb, DVec3, Hit, Interval, Ray, Shape};

use crate::{BoundingSphere, Primitive, moller_trumbore, watertight};

/// Which ray–triangle test a [`Triangle`] uses: the chapter compares them
/// side by side.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TriangleTest {
    /// Chapter 2: hit the plane, then the inside test in 2D (a
    /// [`Polygon`] with three vertices).
    PlaneInside,
    /// Möller & Trumbore (1997): barycentric coordinates by Cramer's rule
    /// ([`moller_trumbore`]).
    MollerTrumbore,
    /// Woop, Benthin & Wald (2013): no leaks and no double hits along
    /// shared edges ([`watertight`]).
    Watertight,
}

impl TriangleTest {
    /// All three, in the lecture's order.
    pub const ALL: [TriangleTest; 3] = [
        TriangleTest::PlaneInside,
        TriangleTest::MollerTrumbore,
        TriangleTest::Watertight,
    ];

    /// Its name in tables and charts.
    pub fn name(self) -> &'static str {
        match self {
            TriangleTest::PlaneInside => "triangle (plane + inside)",
            TriangleTest::MollerTrumbore => "triangle (Möller–Trumbore)",
            TriangleTest::Watertight => "triangle (watertight)",
        }
    }
}

/// A triangle, hit by the test of your choice; its normal follows the
/// winding (counter-clockwise seen from the side it points to).
#[derive(Clone, Debug, PartialEq)]
pub struct Triangle {
    vertices: [DVec3; 3],
    normal: DVec3,
    method: Method,
}

/// The test, with what it keeps of its own.
#[derive(Clone, Debug, PartialEq)]
enum Method {
    /// Chapter 2's polygon: its plane and projected outline.
    PlaneInside(Polygon),
    MollerTrumbore,
    Watertight,
}

impl Triangle {
    /// The triangle with these corners; refused if a coordinate is not
    /// finite or the corners fix no plane (two coincide, or all three lie
    /// on a line).
    pub fn new(
        vertices: [DVec3; 3], test: TriangleTest,
    ) -> Result<Triangle, String> {
        let [v0, v1, v2] = vertices;
        let plane = Plane::through(v0, v1, v2)
            .map_err(|e| format!("vertices: no triangle, {e}"))?;
        let method = match test {
            TriangleTest::PlaneInside => Method::PlaneInside(
                Polygon::new(vertices.to_vec())
                    .map_err(|e| format!("vertices: no triangle, {e}"))?,
            ),
            TriangleTest::MollerTrumbore => Method::MollerTrumbore,
            TriangleTest::Watertight => Method::Watertight,
        };
        Ok(Triangle {
            vertices,
            normal: plane.normal,
            method,
        })
    }

    /// The three corners.
    pub fn vertices(&self) -> &[DVec3; 3] {
        &self.vertices
    }

    /// The test it is hit by.
    pub fn test(&self) -> TriangleTest {
        match self.method {
            Method::PlaneInside(_) => TriangleTest::PlaneInside,
            Method::MollerTrumbore => TriangleTest::MollerTrumbore,
            Method::Watertight => TriangleTest::Watertight,
        }
    }

    /// The unit normal, (V₁ − V₀) × (V₂ − V₀) normalised.
    pub fn normal(&self) -> DVec3 {
        self.normal
    }

    /// The `t` of the hit of `ray` in `interval` by the triangle's test.
    pub fn hit_t(&self, ray: &Ray, interval: Interval) -> Option<f64> {
        match &self.method {
            Method::PlaneInside(polygon) => {
                Some(polygon.intersect(ray, interval)?.t)
            }
            Method::MollerTrumbore => {
                moller_trumbore(&self.vertices, ray, interval)
            }
            Method::Watertight => watertight(&self.vertices, ray, interval),
        }
    }
}

/// A triangle as an object of a scene: its hit, and the box around its
/// corners.
impl Shape for Triangle {
    fn intersect(&self, ray: &Ray, interval: Interval) -> Option<Hit> {
        let t = self.hit_t(ray, interval)?;
        Some(Hit {
            t,
            point: ray.at(t),
            normal: self.normal,
        })
    }

    fn bounds(&self) -> Aabb {
        Aabb::around(self.vertices)
    }
}

/// Its bounding sphere: around the centre of its box, through the corner
/// farthest from it (tighter than the box's circumsphere).
impl Primitive for Triangle {
    fn name(&self) -> &'static str {
        self.test().name()
    }

    fn bounding_sphere(&self) -> BoundingSphere {
        super::chapter_shapes::triangle_sphere(&self.vertices)
    }
}
