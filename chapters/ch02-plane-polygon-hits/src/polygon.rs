use crate::{
    dominant_axis, inside_convex, inside_crossing, project, ray_plane,
};
use ch01::{Degenerate, Plane};
use raystep_core::{Aabb, DVec2, DVec3, Hit, Interval, Ray, Shape};
use thiserror::Error;

/// Why a list of points is no polygon.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Error)]
pub enum PolygonError {
    /// Fewer than three vertices.
    #[error("a polygon needs at least 3 vertices, got {0}")]
    TooFewVertices(usize),
    /// No three vertices fix a plane (all collinear or coincident), or a
    /// coordinate is not finite.
    #[error("no plane through the vertices: {0}")]
    NoPlane(Degenerate),
}

/// A planar polygon in 3D: its vertices, its plane, and its outline
/// projected to 2D for the inside test.
#[derive(Clone, Debug, PartialEq)]
pub struct Polygon {
    vertices: Vec<DVec3>,
    plane: Plane,
    axis: usize,
    outline: Vec<DVec2>,
    convex: bool,
}

impl Polygon {
    /// The polygon with these vertices, in order. They are taken to lie in
    /// one plane: the plane through the first corner that fixes one
    /// (chapter 1), with N turned to agree with the winding.
    pub fn new(vertices: Vec<DVec3>) -> Result<Polygon, PolygonError> {
        if vertices.len() < 3 {
            return Err(PolygonError::TooFewVertices(vertices.len()));
        }
        if !vertices.iter().all(|v| v.is_finite()) {
            return Err(PolygonError::NoPlane(Degenerate::NonFinite));
        }
        let plane = plane_of(&vertices)?;
        // Drop the axis the normal points along most; make the outline
        // counter-clockwise so the edge test has one sign to look for.
        let axis = dominant_axis(plane.normal);
        let mut outline: Vec<DVec2> =
            vertices.iter().map(|&v| project(v, axis)).collect();
        if signed_area(&outline) < 0.0 {
            outline.reverse();
        }
        let convex = is_convex(&outline);
        Ok(Polygon {
            vertices,
            plane,
            axis,
            outline,
            convex,
        })
    }

    /// The vertices as given.
    pub fn vertices(&self) -> &[DVec3] {
        &self.vertices
    }

    /// The polygon's plane.
    pub fn plane(&self) -> &Plane {
        &self.plane
    }

    /// The axis dropped for the inside test (0 = x, 1 = y, 2 = z).
    pub fn dropped_axis(&self) -> usize {
        self.axis
    }

    /// The outline projected to 2D, counter-clockwise.
    pub fn outline(&self) -> &[DVec2] {
        &self.outline
    }

    /// Is the outline convex, every vertex turning left by more than a
    /// rounding error (then the edge test decides inside)?
    pub fn is_convex(&self) -> bool {
        self.convex
    }

    // ANCHOR: intersect
    /// The hit of `ray` with the polygon within `interval`, if any.
    pub fn intersect(&self, ray: &Ray, interval: Interval) -> Option<Hit> {
        // Step 1: hit the polygon's plane.
        let t = ray_plane(&self.plane, ray, interval).t()?;
        let point = ray.at(t);
        // Step 2: project the hit point the way the outline was projected.
        let p = project(point, self.axis);
        // Step 3: inside? The edge test for convex outlines, the crossing
        // number for any other.
        let inside = if self.convex {
            inside_convex(&self.outline, p)
        } else {
            inside_crossing(&self.outline, p)
        };
        inside.then_some(Hit {
            t,
            point,
            normal: self.plane.normal,
        })
    }
    // ANCHOR_END: intersect
}

/// A polygon as an object of a scene (chapter 3 on): its hit, and the box
/// around its vertices.
impl Shape for Polygon {
    fn intersect(&self, ray: &Ray, interval: Interval) -> Option<Hit> {
        Polygon::intersect(self, ray, interval)
    }

    fn bounds(&self) -> Aabb {
        Aabb::around(self.vertices.iter().copied())
    }
}

/// The plane through the first three vertices that fix one, with its normal
/// flipped if needed to point the way the whole polygon winds (Newell's
/// normal), so a concave first corner cannot turn it over.
fn plane_of(vertices: &[DVec3]) -> Result<Plane, PolygonError> {
    let mut last_error = Degenerate::Collinear;
    let v0 = vertices[0];
    for pair in vertices[1..].windows(2) {
        match Plane::through(v0, pair[0], pair[1]) {
            Ok(plane) => {
                return Ok(
                    if plane.normal.dot(newell_normal(vertices)) < 0.0 {
                        Plane {
                            normal: -plane.normal,
                            d: -plane.d,
                        }
                    } else {
                        plane
                    },
                );
            }
            Err(e) => last_error = e,
        }
    }
    Err(PolygonError::NoPlane(last_error))
}

/// Newell's normal: twice the vector area of the polygon.
fn newell_normal(vertices: &[DVec3]) -> DVec3 {
    let mut n = DVec3::ZERO;
    for (i, &a) in vertices.iter().enumerate() {
        let b = vertices[(i + 1) % vertices.len()];
        n += (a - vertices[0]).cross(b - vertices[0]);
    }
    n
}

/// Twice the signed area of a 2D outline: positive if counter-clockwise.
fn signed_area(outline: &[DVec2]) -> f64 {
    let mut area = 0.0;
    for (i, &a) in outline.iter().enumerate() {
        let b = outline[(i + 1) % outline.len()];
        area += a.perp_dot(b);
    }
    area
}

/// Below this sine of the turn at a vertex, the outline counts as not
/// convex and gets the crossing test. At an almost straight vertex the edge
/// test would consult the neighbouring edge for points on an edge, where
/// that edge's f is rounding noise; the crossing test never does.
const CONVEX_TURN_SINE: f64 = 1e-9;

/// Does a counter-clockwise outline turn clearly left at every vertex?
/// (Repeated vertices are skipped.)
fn is_convex(ccw: &[DVec2]) -> bool {
    let n = ccw.len();
    (0..n).all(|i| {
        let (a, b, c) = (ccw[i], ccw[(i + 1) % n], ccw[(i + 2) % n]);
        let (e1, e2) = (b - a, c - b);
        if e1 == DVec2::ZERO || e2 == DVec2::ZERO {
            return true;
        }
        e1.perp_dot(e2) > CONVEX_TURN_SINE * e1.length() * e2.length()
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn v(x: f64, y: f64, z: f64) -> DVec3 {
        DVec3::new(x, y, z)
    }

    #[test]
    fn clockwise_input_gives_a_counter_clockwise_outline() {
        let square = vec![
            v(0.0, 0.0, 1.0),
            v(0.0, 1.0, 1.0),
            v(1.0, 1.0, 1.0),
            v(1.0, 0.0, 1.0),
        ];
        let p = Polygon::new(square).unwrap();
        assert_eq!(p.plane().normal, v(0.0, 0.0, -1.0));
        assert!(signed_area(p.outline()) > 0.0);
        assert!(p.is_convex());
    }

    #[test]
    fn concave_first_corner_does_not_flip_the_normal() {
        // an arrow head whose first vertex is the reflex one
        let arrow = vec![
            v(0.0, 0.5, 0.0),
            v(-1.0, -1.0, 0.0),
            v(0.0, 2.0, 0.0),
            v(1.0, -1.0, 0.0),
        ];
        let p = Polygon::new(arrow).unwrap();
        assert!(!p.is_convex());
        assert_eq!(p.plane().normal, v(0.0, 0.0, -1.0));
    }

    #[test]
    fn bad_vertex_lists_are_errors() {
        assert_eq!(
            Polygon::new(vec![v(0.0, 0.0, 0.0), v(1.0, 0.0, 0.0)]),
            Err(PolygonError::TooFewVertices(2))
        );
        assert_eq!(
            Polygon::new(vec![
                v(0.0, 0.0, 0.0),
                v(1.0, 0.0, 0.0),
                v(2.0, 0.0, 0.0)
            ]),
            Err(PolygonError::NoPlane(Degenerate::Collinear))
        );
        assert_eq!(
            Polygon::new(vec![
                v(0.0, 0.0, 0.0),
                v(1.0, f64::NAN, 0.0),
                v(2.0, 0.0, 0.0)
            ]),
            Err(PolygonError::NoPlane(Degenerate::NonFinite))
        );
    }
}
