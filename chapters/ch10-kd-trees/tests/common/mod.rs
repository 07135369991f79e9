//! What the chapter's test files share: the bunny as objects.
#![allow(dead_code)]
use ch10::Object;

/// The bunny's triangles as objects (degenerate ones left out).
pub fn bunny_objects() -> Vec<Object> {
    raystep_bench::triangle_objects(&raystep_bench::bunny())
}
