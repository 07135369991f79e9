//! Smooth shading: a triangle hit by the watertight test, whose normal is
//! blended from its three vertex normals (an OBJ file's `vn`), so that a
//! mesh of flat facets shades like the curved surface it approximates.
use raystep_core::{Aabb, DVec3, Hit, Interval, Ray, Shape};

use crate::{Triangle, TriangleTest, watertight};

// ANCHOR: barycentric
/// The barycentric coordinates (b₀, b₁, b₂) of the point `p` of the
/// triangle `v`: p = b₀V₀ + b₁V₁ + b₂V₂, with b₀ + b₁ + b₂ = 1, each bᵢ
/// the area of the triangle `p` makes with the edge facing Vᵢ over the
/// whole triangle's area. For shading only: the hit itself is the
/// watertight test's, and a hit on an edge, a rounding outside, is
/// brought back onto it.
pub fn barycentric(v: &[DVec3; 3], p: DVec3) -> DVec3 {
    // Step 1: the normal, as long as twice the triangle's area.
    let n = (v[1] - v[0]).cross(v[2] - v[0]);
    // Step 2: twice each smaller triangle's area, signed along n.
    let area = |a: DVec3, b: DVec3| (b - a).cross(p - a).dot(n);
    let b = DVec3::new(area(v[1], v[2]), area(v[2], v[0]), area(v[0], v[1]));
    // Step 3: over the whole, none below 0, summing to 1.
    let b = (b / n.dot(n)).max(DVec3::ZERO);
    b / b.element_sum()
}
// ANCHOR_END: barycentric

/// A triangle of a mesh with a normal at each corner: hit exactly as a
/// watertight [`Triangle`], shaded by the normal blended from its corners'.
#[derive(Clone, Debug, PartialEq)]
pub struct SmoothTriangle {
    /// The corners and the geometric normal, hit by the watertight test.
    triangle: Triangle,
    /// The unit normal at each corner.
    normals: [DVec3; 3],
}

impl SmoothTriangle {
    /// The triangle with these corners and these normals at them (each
    /// normalised here); refused as a [`Triangle`] is (the corners fix no
    /// plane).
    pub fn new(
        vertices: [DVec3; 3], normals: [DVec3; 3],
    ) -> Result<SmoothTriangle, String> {
        let triangle = Triangle::new(vertices, TriangleTest::Watertight)?;
        Ok(SmoothTriangle::from_triangle(triangle, normals))
    }

    /// The flat `triangle` (hit by the watertight test whatever test it
    /// was made with) with these normals at its corners, normalised here.
    pub(crate) fn from_triangle(
        triangle: Triangle, normals: [DVec3; 3],
    ) -> SmoothTriangle {
        SmoothTriangle {
            triangle,
            normals: normals.map(DVec3::normalize),
        }
    }

    /// The flat triangle it is hit as: its corners and geometric normal.
    pub fn triangle(&self) -> &Triangle {
        &self.triangle
    }

    /// The unit normals at the three corners.
    pub fn normals(&self) -> &[DVec3; 3] {
        &self.normals
    }

    // ANCHOR: shading_normal
    /// The shading normal at the point of barycentric coordinates `b`:
    /// the corners' normals blended by `b` and normalised, kept on the
    /// geometric normal's side.
    pub fn shading_normal(&self, b: DVec3) -> DVec3 {
        // Step 1: N = b₀N₀ + b₁N₁ + b₂N₂, normalised.
        let [n0, n1, n2] = self.normals;
        let blended = (b.x * n0 + b.y * n1 + b.z * n2).normalize();
        // Step 2: the side rule. The winding says which side is out (and
        // refraction asks it: entering or leaving); a blended normal on
        // the other side of the facet (vertex normals that disagree with
        // the winding, or no direction at all: a NaN) would turn the
        // surface inside out, so the lecture then takes the geometric
        // normal. (pbrt instead turns the geometric normal to the
        // shading normal's side.)
        let geometric = self.triangle.normal();
        if blended.dot(geometric) > 0.0 {
            blended
        } else {
            geometric
        }
    }
    // ANCHOR_END: shading_normal
}

// ANCHOR: smooth_intersect
/// A smooth triangle as an object of a scene.
///
/// The [`Hit`] carries the *shading* normal: the tracers shade with it,
/// and their shadow rays and normal offsets use it as they use any hit's
/// normal. It is always on the geometric normal's side of the facet.
impl Shape for SmoothTriangle {
    fn intersect(&self, ray: &Ray, interval: Interval) -> Option<Hit> {
        // Step 1: the watertight test, as for a flat triangle.
        let vertices = self.triangle.vertices();
        let t = watertight(vertices, ray, interval)?;
        // Step 2: where on the triangle, and the normal blended there.
        let b = barycentric(vertices, ray.at(t));
        Some(Hit {
            t,
            point: ray.at(t),
            normal: self.shading_normal(b),
        })
    }

    fn bounds(&self) -> Aabb {
        self.triangle.bounds()
    }
}
// ANCHOR_END: smooth_intersect
