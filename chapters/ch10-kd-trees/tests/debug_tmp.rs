mod common;
use ch10::*;
#[test]
fn debug() {
    let bunny = common::bunny();
    let scene = kd_scenes(&bunny).remove(0);
    let sah = KdTree::for_objects(&scene.objects, KdBuilder::SahEvents, KdCosts::PBRT_V3);
    let ray = Ray::new(DVec3::new(0.7118726610103104, 5.774684906005859, -17.07483096016926), DVec3::new(-3.8637456272500845, 0.0, 20.4495890609172));
    let (k, hit) = ch03::BruteForce.closest_hit(&scene.objects, &ray, Interval::FORWARD).unwrap();
    println!("brute hit obj {k} t {}", hit.t);
    let leaves: Vec<_> = sah.nodes.iter().enumerate().filter_map(|(i, n)| match n { KdNode::Leaf{first,count} => sah.leaf_objects(*first,*count).contains(&(k as u32)).then_some(i), _ => None}).collect();
    println!("leaves holding it: {leaves:?}");
    kd_walk(&sah, &ray, Interval::FORWARD, |v| { println!("visit {} [{}, {}] leaf {:?}", v.node, v.t_min, v.t_max, v.objects.map(|o| o.len())); f64::INFINITY });
    println!("any {}", sah.any_hit(&scene.objects, &ray, Interval::FORWARD));
}
