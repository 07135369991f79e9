mod common;
use ch10::*;
use std::time::Instant;
#[test]
fn debug() {
    let bunny = common::bunny();
    let big = raystep_scene::Mesh::load_obj(std::path::Path::new("/work/shared/meshes/bunny-235k.obj")).unwrap();
    let big: Vec<[DVec3;3]> = (0..big.triangles.len()).map(|k| big.triangle(k)).collect();
    for (name, tris) in [("bunny", &bunny), ("235k", &big), ("uniform", &ch09::uniform_triangles(100000, 9))] {
        let bounds = Aabb::around(tris.iter().flatten().copied());
        let cam: Vec<ch08::Ray32> = ch08::camera_rays(ch08::BoundingSphere::around_box(&bounds), 256).iter().map(ch08::Ray32::rounded).collect();
        let inc: Vec<ch08::Ray32> = ch08::incoherent_rays(bounds, 65536, 3).iter().map(ch08::Ray32::rounded).collect();
        for costs in [KdCosts::PBRT_V3, KdCosts::WALD_HAVRAN, KdCosts{traversal:1.0, intersection: 1.5, empty_bonus: 0.5}, KdCosts{traversal:1.0, intersection: 4.0, empty_bonus: 0.5}, KdCosts{traversal:1.0, intersection: 20.0, empty_bonus: 0.5}] {
          for (builder, clip) in [(KdBuilder::SahEvents, Clip::Boxes), (KdBuilder::SahEvents, Clip::Triangles), (KdBuilder::SahSorting, Clip::Boxes)] {
            let t0 = Instant::now();
            let kd = MeshKd::new(tris, builder, costs, clip);
            let build = t0.elapsed().as_secs_f64()*1e3;
            let st = kd.tree.stats(&costs);
            let mut line = format!("{name} {} {:?} {:?}: build {build:.0} ms, nodes {} depth {} entries {} sah {:.1}", costs.name(), builder, clip, st.nodes, st.depth, st.entries, st.sah_cost);
            for rays in [&cam, &inc] {
                let mut c = ch08::TraceCounts::default();
                let t0 = Instant::now();
                for r in rays.iter() { kd.closest_hit(r, Interval::FORWARD, &mut c); }
                let ns = t0.elapsed().as_secs_f64()*1e9 / rays.len() as f64;
                line += &format!(" | {ns:.0} ns, {:.1} nodes {:.1} tris", c.nodes as f64/rays.len() as f64, c.triangles as f64 / rays.len() as f64);
            }
            println!("{line}");
          }
        }
    }
}
