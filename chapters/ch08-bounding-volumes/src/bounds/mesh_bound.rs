//! "Collections of stuff → meshes": a mesh is many fast primitives, and
//! testing a ray against each one is slow however fast each test is. One
//! box around the whole mesh turns most missing rays away with one test;
//! the rays that hit the box still test every triangle (part 2's
//! hierarchies fix that).
use raystep_core::{Aabb, DVec3, Hit, Interval, Ray, Shape};
use raystep_scene::Mesh;

use crate::{Bounded, BoundingSphere, TestCounts, Triangle, TriangleTest};

/// The triangle meshes are made of: the chapter's triangle with the
/// watertight test, so that no ray slips between two triangles of a
/// closed mesh.
pub type MeshTriangle = Triangle;

/// The mesh triangle with these corners, or None if they fix no plane
/// (zero area). Every mesh triangle is made here.
pub fn mesh_triangle(corners: [DVec3; 3]) -> Option<MeshTriangle> {
    Triangle::new(corners, TriangleTest::Watertight).ok()
}

/// A mesh as one object: its triangles, each tested in turn.
#[derive(Clone, Debug)]
pub struct TriangleMesh {
    triangles: Vec<MeshTriangle>,
    skipped: usize,
    bounds: Aabb,
}

impl TriangleMesh {
    /// The triangles of `mesh`; those of zero area are left out (and
    /// counted by [`TriangleMesh::skipped`]).
    pub fn new(mesh: &Mesh) -> TriangleMesh {
        let mut triangles = Vec::with_capacity(mesh.triangles.len());
        for k in 0..mesh.triangles.len() {
            if let Some(triangle) = mesh_triangle(mesh.triangle(k)) {
                triangles.push(triangle);
            }
        }
        TriangleMesh {
            skipped: mesh.triangles.len() - triangles.len(),
            bounds: Aabb::around(
                triangles.iter().flat_map(|t| t.vertices().to_vec()),
            ),
            triangles,
        }
    }

    /// The triangles, in the mesh's order.
    pub fn triangles(&self) -> &[MeshTriangle] {
        &self.triangles
    }

    /// How many of the mesh's triangles had zero area and were left out.
    pub fn skipped(&self) -> usize {
        self.skipped
    }
}

// ANCHOR: mesh_intersect
/// The lecture's closest-hit loop over a mesh's triangles: every ray tests
/// every one of them.
fn closest_triangle_hit(
    triangles: &[MeshTriangle], ray: &Ray, interval: Interval,
) -> Option<Hit> {
    let mut closest = None;
    let mut interval = interval;
    for triangle in triangles {
        if let Some(hit) = triangle.intersect(ray, interval) {
            interval = interval.with_max(hit.t); // only closer ones now
            closest = Some(hit);
        }
    }
    closest
}
// ANCHOR_END: mesh_intersect

impl Shape for TriangleMesh {
    fn intersect(&self, ray: &Ray, interval: Interval) -> Option<Hit> {
        closest_triangle_hit(&self.triangles, ray, interval)
    }

    fn bounds(&self) -> Aabb {
        self.bounds
    }
}

/// What a set of rays cost against a mesh, triangle by triangle and
/// behind one box around it.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MeshBoxCounts {
    /// The rays shot.
    pub rays: u64,
    /// Rays that hit the mesh (triangle by triangle).
    pub hits: u64,
    /// Rays that hit the box.
    pub box_hits: u64,
    /// Rays whose hit behind the box differs from the hit triangle by
    /// triangle (another t, or a hit against none): 0 for a correct box.
    pub disagreements: u64,
    /// Triangle tests without the box: every triangle for every ray.
    pub triangle_tests_without_box: u64,
    /// Triangle tests behind the box: every triangle for the rays that
    /// hit the box.
    pub triangle_tests_with_box: u64,
}

impl MeshBoxCounts {
    /// Tests per ray without the box (the number of triangles).
    pub fn tests_per_ray_without_box(&self) -> f64 {
        self.triangle_tests_without_box as f64 / self.rays as f64
    }

    /// Tests per ray behind the box, the box's own test included:
    /// 1 + P(box hit) × the number of triangles.
    pub fn tests_per_ray_with_box(&self) -> f64 {
        (self.rays + self.triangle_tests_with_box) as f64 / self.rays as f64
    }

    /// P(box hit).
    pub fn p_box(&self) -> f64 {
        self.box_hits as f64 / self.rays as f64
    }
}

/// Shoots `rays` at `mesh` triangle by triangle and behind its box,
/// counts the tests each way and checks that both find the same hits.
pub fn mesh_behind_box(mesh: &TriangleMesh, rays: &[Ray]) -> MeshBoxCounts {
    let boxed = Bounded::boxed(Box::new(mesh.clone()));
    let per_ray = mesh.triangles().len() as u64;
    let mut tests = TestCounts::default();
    let mut counts = MeshBoxCounts::default();
    for ray in rays {
        // Step 1: triangle by triangle.
        let flat = mesh.intersect(ray, Interval::FORWARD);
        // Step 2: behind the box.
        let before = tests.object;
        let behind =
            boxed.intersect_counted(ray, Interval::FORWARD, &mut tests);
        // Step 3: count, and compare.
        counts.rays += 1;
        counts.hits += u64::from(flat.is_some());
        counts.box_hits += tests.object - before;
        counts.disagreements += u64::from(flat != behind);
        counts.triangle_tests_without_box += per_ray;
    }
    counts.triangle_tests_with_box = tests.object * per_ray;
    counts
}

impl crate::Primitive for TriangleMesh {
    fn name(&self) -> &'static str {
        "mesh"
    }

    /// The tight sphere around its corners
    /// ([`sphere_of_points`](crate::sphere_of_points)).
    fn bounding_sphere(&self) -> BoundingSphere {
        let corners: Vec<DVec3> = self
            .triangles
            .iter()
            .flat_map(|t| t.vertices().to_vec())
            .collect();
        crate::sphere_of_points(&corners)
    }
}
