//! Chapter 10's lecture figures, each drawn from the chapter's own code:
//! the lecture's sketch of planes splitting space, split by split; one
//! ray's walk through the tree, front to back; and the SAH's cost of
//! every candidate plane at the root.
use std::sync::Arc;

use ch08::TriangleMesh;
use ch10::{
    Aabb, DVec3, Interval, KdBuilder, KdCosts, KdNode, KdTree, Object, Ray,
    split_cost,
};
use raystep_figure::numbers::fixed;
use raystep_figure::{Anchor, Color, DVec2, Figure, Page, Stroke, palette};
use raystep_scene::Mesh;

/// Every lecture figure of the chapter.
pub fn all() -> Vec<Figure> {
    vec![kd_splits(), kd_traversal(), sah_sweep()]
}

/// One object of the lecture's sketch, in the plane z = 0.
#[derive(Clone, Copy, Debug)]
enum Thing {
    /// A circle: centre and radius.
    Circle(DVec2, f64),
    /// A triangle: its corners.
    Triangle([DVec2; 3]),
}

impl Thing {
    /// Its box, flat in z = 0: the tree only cuts x and y.
    fn flat_box(&self) -> Aabb {
        let (lo, hi) = match *self {
            Thing::Circle(c, r) => (c - r, c + r),
            Thing::Triangle(p) => {
                (p[0].min(p[1]).min(p[2]), p[0].max(p[1]).max(p[2]))
            }
        };
        Aabb::new(DVec3::new(lo.x, lo.y, 0.0), DVec3::new(hi.x, hi.y, 0.0))
    }

    /// The object a ray in the plane z = 0 can hit: a sphere (chapter 8's
    /// shape, cut by z = 0 it is the circle) or a prism of chapter 8's
    /// mesh triangles standing on the triangle (cut by z = 0, the
    /// triangle).
    fn object(&self) -> Object {
        let shape: Arc<dyn ch08::Shape> = match *self {
            Thing::Circle(c, radius) => {
                ch08::shape(&raystep_scene::Shape::Sphere {
                    center: DVec3::new(c.x, c.y, 0.0),
                    radius,
                })
                .expect("a sphere")
            }
            Thing::Triangle(p) => {
                let at = |q: DVec2, z: f64| DVec3::new(q.x, q.y, z);
                let mut vertices: Vec<DVec3> =
                    p.iter().map(|&q| at(q, -1.0)).collect();
                vertices.extend(p.iter().map(|&q| at(q, 1.0)));
                // three side walls of two triangles each, and two lids
                let mut triangles = vec![[0, 2, 1], [3, 4, 5]];
                for i in 0..3 {
                    let j = (i + 1) % 3;
                    triangles.push([i, j, j + 3]);
                    triangles.push([i, j + 3, i + 3]);
                }
                Arc::new(TriangleMesh::new(&Mesh {
                    vertices,
                    triangles,
                }))
            }
        };
        Object { shape, material: 0 }
    }

    /// Draws it, filled and outlined.
    fn draw(
        &self,
        page: &mut Page,
        offset: DVec2,
        fill: Color,
        stroke: &Stroke,
    ) {
        let fill = Some(fill.with_alpha(0.4));
        match *self {
            Thing::Circle(c, r) => {
                page.circle_alpha(offset + c, r, fill, Some(stroke));
            }
            Thing::Triangle(p) => {
                page.polygon_alpha(&p.map(|q| offset + q), fill, Some(stroke));
            }
        }
    }
}

/// The lecture's sketch: 13 circles and triangles of mixed sizes, three
/// small circles in a clump and a few objects near each other on the
/// right, with empty space between.
fn sketch_scene() -> Vec<Thing> {
    let c = |x, y, r| Thing::Circle(DVec2::new(x, y), r);
    let t = |a: [f64; 6]| {
        Thing::Triangle([
            DVec2::new(a[0], a[1]),
            DVec2::new(a[2], a[3]),
            DVec2::new(a[4], a[5]),
        ])
    };
    vec![
        // the clump, bottom left, and a small triangle above it
        c(1.0, 1.125, 0.5),
        c(1.75, 0.75, 0.375),
        c(1.625, 1.625, 0.375),
        t([0.5, 2.625, 1.625, 2.875, 0.875, 3.625]),
        // a big triangle, top left; a long thin one across the middle
        t([1.25, 4.375, 3.875, 5.25, 2.0, 6.25]),
        t([3.0, 1.0, 6.625, 2.875, 3.5, 1.75]),
        // alone in the middle
        c(5.875, 4.625, 0.375),
        // a big circle, bottom right
        c(8.75, 1.5, 1.125),
        // the group, top right
        t([8.375, 4.625, 9.75, 4.75, 8.875, 5.875]),
        t([10.0, 5.125, 11.375, 4.875, 10.875, 6.25]),
        c(9.625, 3.75, 0.5),
        c(11.0, 4.125, 0.25),
        c(10.5, 2.875, 0.25),
    ]
}

/// The sketch's objects' flat boxes.
fn sketch_boxes(things: &[Thing]) -> Vec<Aabb> {
    things.iter().map(Thing::flat_box).collect()
}

/// The tree the chapter's builder makes for the sketch: SAH by events,
/// with the chapter's costs.
fn sketch_tree(boxes: &[Aabb]) -> KdTree {
    KdTree::build(boxes, KdBuilder::SahEvents, KdCosts::CHOSEN)
}

/// A point of the plane z = 0 as a figure point.
fn flat(p: DVec3) -> DVec2 {
    DVec2::new(p.x, p.y)
}

/// The corners of a box in the plane.
fn corners(b: &Aabb, offset: DVec2) -> [DVec2; 4] {
    [
        offset + DVec2::new(b.min.x, b.min.y),
        offset + DVec2::new(b.max.x, b.min.y),
        offset + DVec2::new(b.max.x, b.max.y),
        offset + DVec2::new(b.min.x, b.max.y),
    ]
}

/// The part of an interior node's plane inside the node's box: its two
/// ends.
fn plane_segment(node: &KdNode, b: &Aabb) -> Option<(DVec2, DVec2)> {
    let KdNode::Split { axis, plane, .. } = *node else {
        return None;
    };
    Some(if axis == 0 {
        (DVec2::new(plane, b.min.y), DVec2::new(plane, b.max.y))
    } else {
        (DVec2::new(b.min.x, plane), DVec2::new(b.max.x, plane))
    })
}

/// A plane's name: `x = 7.4`.
fn plane_name(node: &KdNode) -> String {
    match *node {
        KdNode::Split { axis, plane, .. } => {
            format!("{} = {}", ["x", "y", "z"][axis as usize], short(plane))
        }
        KdNode::Leaf { .. } => String::new(),
    }
}

/// A coordinate as short as it is exact to 2 decimals: `7.4`, `0.65`.
fn short(x: f64) -> String {
    let s = fixed(x, 2);
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// The lecture's sketch, split by split: the planes of depth ≤ 1, ≤ 2,
/// ≤ 3, and the finished tree, each level's new planes in vermilion.
fn kd_splits() -> Figure {
    let things = sketch_scene();
    let boxes = sketch_boxes(&things);
    let tree = sketch_tree(&boxes);
    let node_boxes = tree.node_boxes();
    let depths = tree.node_depths();
    let stats = tree.stats(&KdCosts::CHOSEN);
    let root = tree.bounds;
    // the panels: the planes down to this depth (the last: all of them)
    let panels = [1, 2, 3, stats.depth];
    let pad = 0.25;
    let size = DVec2::new(
        root.max.x - root.min.x + 2.0 * pad,
        root.max.y - root.min.y + 2.0 * pad,
    );
    let gap = DVec2::new(0.6, 1.1);
    let mut page = Page::new(900.0, 640.0).view(
        DVec2::new(root.min.x - pad, root.min.y - pad - size.y - gap.y - 1.4),
        DVec2::new(
            root.min.x - pad + 2.0 * size.x + gap.x,
            root.max.y + pad + 0.7,
        ),
    );
    for (k, &deepest) in panels.iter().enumerate() {
        let offset = DVec2::new(
            (k % 2) as f64 * (size.x + gap.x),
            -((k / 2) as f64) * (size.y + gap.y),
        );
        let last = k + 1 == panels.len();
        // the finished tree: leaves holding objects shaded, empty ones white
        if last {
            for (node, b) in tree.nodes.iter().zip(&node_boxes) {
                if let KdNode::Leaf { count, .. } = *node
                    && count > 0
                {
                    page.polygon_alpha(
                        &corners(b, offset),
                        Some(palette::SKY_BLUE.with_alpha(0.25)),
                        None,
                    );
                }
            }
        }
        for thing in &things {
            thing.draw(
                &mut page,
                offset,
                palette::GREY,
                &Stroke::new(palette::GREY).width(1.0),
            );
        }
        // the root's box
        page.polygon(
            &corners(&root, offset),
            None,
            Some(&Stroke::new(palette::BLACK).width(1.0)),
        );
        // earlier planes thin, this level's thick (the finished tree:
        // planes of depth ≤ 3 black, deeper ones vermilion)
        let newest = if last { panels[k - 1] + 1 } else { deepest };
        let mut new_planes = 0;
        for (n, node) in tree.nodes.iter().enumerate() {
            let Some((a, b)) = plane_segment(node, &node_boxes[n]) else {
                continue;
            };
            if depths[n] > deepest {
                continue;
            }
            let stroke = if depths[n] >= newest {
                new_planes += 1;
                Stroke::new(palette::VERMILION).width(if last {
                    1.5
                } else {
                    2.5
                })
            } else {
                Stroke::new(palette::BLACK).width(1.0)
            };
            page.segment(offset + a, offset + b, &stroke);
            if !last && depths[n] == deepest {
                // the new plane's name at its upper or right end
                let (at, anchor) = match *node {
                    KdNode::Split { axis: 0, .. } => (b, Anchor::N),
                    _ => (b, Anchor::E),
                };
                page.label_sized(
                    offset + at,
                    &plane_name(node),
                    anchor,
                    13.0,
                    palette::VERMILION,
                );
            }
        }
        let planes = tree
            .nodes
            .iter()
            .zip(&depths)
            .filter(|(n, d)| {
                matches!(n, KdNode::Split { .. }) && **d <= deepest
            })
            .count();
        let title = if last {
            format!(
                "finished: {planes} planes, {} leaves ({} empty)",
                stats.leaves, stats.empty_leaves
            )
        } else if deepest == 1 {
            format!("depth ≤ 1: the root's plane and its children's ({planes})")
        } else {
            format!("depth ≤ {deepest}: {new_planes} new, {planes} planes")
        };
        page.label_sized(
            offset + DVec2::new(root.min.x - pad, root.max.y + pad + 0.35),
            &title,
            Anchor::E,
            15.0,
            palette::BLACK,
        );
    }
    page.text_page(
        DVec2::new(14.0, 612.0),
        "vermilion: the planes a level adds · black: earlier planes · blue: leaves that hold an object",
        Anchor::E,
        15.0,
    );
    Figure::new(
        "kd-splits",
        &format!(
            "The lecture's sketch, built by the chapter's SAH builder (events, costs {}): {} objects, {} nodes, {} leaves, depth {}.",
            KdCosts::CHOSEN.name(),
            things.len(),
            stats.nodes,
            stats.leaves,
            stats.depth
        ),
        page,
    )
}

/// The ray of the traversal figure, in the plane z = 0.
fn walk_ray() -> Ray {
    Ray::new(DVec3::new(0.2, 4.2, 0.0), DVec3::new(1.0, -0.12, 0.0))
}

/// One ray through the sketch's tree, front to back.
fn kd_traversal() -> Figure {
    let things = sketch_scene();
    let boxes = sketch_boxes(&things);
    let tree = sketch_tree(&boxes);
    let objects: Vec<Object> = things.iter().map(Thing::object).collect();
    let node_boxes = tree.node_boxes();
    let ray = walk_ray();
    // the leaves visited: node, and where the ray enters and leaves it
    let mut leaves: Vec<(u32, f64, f64)> = Vec::new();
    let mut tested: Vec<(usize, u32)> = Vec::new();
    let hit = tree.closest_hit_observed(
        &objects,
        &ray,
        Interval::FORWARD,
        &mut |visit, object| match object {
            None if visit.objects.is_some() => {
                leaves.push((visit.node, visit.t_min, visit.t_max));
            }
            None => {}
            Some(k) => tested.push((leaves.len() - 1, k)),
        },
    );
    let root = tree.bounds;
    let mut page = Page::new(900.0, 560.0).view(
        DVec2::new(root.min.x - 0.5, root.min.y - 1.3),
        DVec2::new(root.max.x + 0.3, root.max.y + 0.3),
    );
    for (k, &(node, t_min, t_max)) in leaves.iter().enumerate() {
        let last = k + 1 == leaves.len();
        let fill = if last {
            palette::ORANGE.with_alpha(0.35)
        } else {
            palette::SKY_BLUE.with_alpha(0.3)
        };
        page.polygon_alpha(
            &corners(&node_boxes[node as usize], DVec2::ZERO),
            Some(fill),
            None,
        );
        let middle = flat(ray.at(0.5 * (t_min + t_max)));
        page.label_sized(
            middle + DVec2::new(0.0, 0.12),
            &(k + 1).to_string(),
            Anchor::N,
            13.0,
            palette::BLUE,
        );
    }
    for (n, node) in tree.nodes.iter().enumerate() {
        if let Some((a, b)) = plane_segment(node, &node_boxes[n]) {
            page.segment(a, b, &Stroke::new(palette::GREY).width(1.0));
        }
    }
    page.polygon(
        &corners(&root, DVec2::ZERO),
        None,
        Some(&Stroke::new(palette::BLACK).width(1.0)),
    );
    let was_tested = |i: usize| tested.iter().any(|&(_, k)| k as usize == i);
    for (i, thing) in things.iter().enumerate() {
        let hit_here = hit.is_some_and(|(k, _)| k == i);
        let (fill, stroke) = if hit_here {
            (
                palette::VERMILION,
                Stroke::new(palette::VERMILION).width(2.0),
            )
        } else if was_tested(i) {
            (palette::ORANGE, Stroke::new(palette::ORANGE).width(1.5))
        } else {
            (palette::GREY, Stroke::new(palette::GREY).width(1.0))
        };
        thing.draw(&mut page, DVec2::ZERO, fill, &stroke);
    }
    let ray_stroke = Stroke::new(palette::BLUE).width(2.5);
    let end = hit.map_or(12.0, |(_, h)| h.t);
    page.arrow(flat(ray.origin), flat(ray.at(end)), &ray_stroke);
    if let Some((_, h)) = hit {
        page.cross(flat(h.point));
    }
    page.point(flat(ray.origin), palette::BLUE);
    page.text_page(
        DVec2::new(14.0, 530.0),
        &format!(
            "blue: the {} leaves the ray visits, in order · orange: the leaf that holds the hit, where the walk stops",
            leaves.len()
        ),
        Anchor::E,
        15.0,
    );
    Figure::new(
        "kd-traversal",
        &format!(
            "One ray through the sketch's tree: {} leaves visited of {}, {} objects tested.",
            leaves.len(),
            tree.stats(&KdCosts::CHOSEN).leaves,
            tested.len()
        ),
        page,
    )
}

/// Object counts on each side of the plane `x[axis] = p`, counted as the
/// builder counts: a box ending at p or before is below, one starting at
/// p or after is above, one across p is on both sides.
fn counts_at(boxes: &[Aabb], axis: usize, p: f64) -> (usize, usize) {
    let below = boxes.iter().filter(|b| b.min[axis] < p).count();
    let above = boxes.iter().filter(|b| b.max[axis] > p).count();
    (below, above)
}

/// The SAH cost of every candidate plane across the root, on x: the
/// candidates (box starts and ends strictly inside the root) and their
/// costs, in order of x.
fn root_sweep(boxes: &[Aabb], root: &Aabb) -> Vec<(f64, f64)> {
    let mut candidates: Vec<f64> = boxes
        .iter()
        .flat_map(|b| [b.min.x, b.max.x])
        .filter(|&x| root.min.x < x && x < root.max.x)
        .collect();
    candidates.sort_by(f64::total_cmp);
    candidates.dedup();
    candidates
        .into_iter()
        .map(|x| {
            let (below, above) = counts_at(boxes, 0, x);
            (x, split_cost(root, 0, x, below, above, &KdCosts::CHOSEN))
        })
        .collect()
}

/// The cheapest candidate of a sweep (the first, on a tie).
fn cheapest(sweep: &[(f64, f64)]) -> (f64, f64) {
    sweep
        .iter()
        .copied()
        .fold((f64::NAN, f64::INFINITY), |best, c| {
            if c.1 < best.1 { c } else { best }
        })
}

/// The SAH cost along x at the sketch's root.
fn sah_sweep() -> Figure {
    let things = sketch_scene();
    let boxes = sketch_boxes(&things);
    let tree = sketch_tree(&boxes);
    let root = tree.bounds;
    let sweep = root_sweep(&boxes, &root);
    let (best_x, best_cost) = cheapest(&sweep);
    // the builder's own choice: the same plane
    let KdNode::Split { axis: 0, plane, .. } = tree.nodes[0] else {
        panic!("the sketch's root is cut along x");
    };
    assert_eq!(
        plane, best_x,
        "the figure's sweep finds the builder's plane"
    );
    let costs = KdCosts::CHOSEN;
    let leaf_cost = boxes.len() as f64 * costs.intersection;
    // the cost chart below the scene: cost c at world y = chart_y(c)
    let (top, height) = (root.min.y - 0.8, 4.2);
    let max_cost = 300.0;
    let chart_y = |c: f64| top - height + height * c / max_cost;
    let mut page = Page::new(900.0, 800.0).view(
        DVec2::new(root.min.x - 1.4, top - height - 1.2),
        DVec2::new(root.max.x + 0.3, root.max.y + 0.3),
    );
    // the scene, its boxes' x extents as the candidate planes
    page.polygon(
        &corners(&root, DVec2::ZERO),
        None,
        Some(&Stroke::new(palette::BLACK).width(1.0)),
    );
    for thing in &things {
        thing.draw(
            &mut page,
            DVec2::ZERO,
            palette::GREY,
            &Stroke::new(palette::GREY).width(1.0),
        );
    }
    // the chart's axes and grid
    let axis = Stroke::new(palette::BLACK).width(1.0);
    let x0 = root.min.x - 0.1;
    page.segment(
        DVec2::new(x0, chart_y(0.0)),
        DVec2::new(x0, chart_y(max_cost)),
        &axis,
    );
    for c in (0..=300).step_by(50) {
        let y = chart_y(c as f64);
        page.segment(
            DVec2::new(x0, y),
            DVec2::new(root.max.x, y),
            &Stroke::new(palette::LIGHT_GREY).width(1.0),
        );
        page.label_sized(
            DVec2::new(x0, y),
            &c.to_string(),
            Anchor::W,
            13.0,
            palette::BLACK,
        );
    }
    // the leaf's cost: test every object
    let leaf = Stroke::new(palette::GREEN).width(2.0).dashed();
    page.segment(
        DVec2::new(root.min.x, chart_y(leaf_cost)),
        DVec2::new(root.max.x, chart_y(leaf_cost)),
        &leaf,
    );
    page.label_sized(
        DVec2::new(root.max.x, chart_y(leaf_cost)),
        &format!("leaf: N·C_{{isect}} = {}", fixed(leaf_cost, 0)),
        Anchor::NW,
        16.0,
        palette::GREEN,
    );
    // the cost at every candidate plane
    let points: Vec<DVec2> = sweep
        .iter()
        .map(|&(x, c)| DVec2::new(x, chart_y(c)))
        .collect();
    page.polyline(&points, &Stroke::new(palette::BLUE).width(1.5));
    for p in &points {
        page.circle(*p, 0.06, Some(palette::BLUE), None);
    }
    // the chosen plane, through the scene and the chart
    let chosen = Stroke::new(palette::VERMILION).width(2.5);
    page.segment(
        DVec2::new(best_x, chart_y(0.0)),
        DVec2::new(best_x, root.max.y),
        &chosen.dashed(),
    );
    let (below, above) = counts_at(&boxes, 0, best_x);
    page.label_sized(
        DVec2::new(best_x, chart_y(best_cost)),
        &format!("x = {}: C = {}", short(best_x), fixed(best_cost, 1)),
        Anchor::SE,
        15.0,
        palette::VERMILION,
    );
    page.label_sized(
        DVec2::new(best_x, root.max.y),
        &format!("{below} objects below | {above} above"),
        Anchor::N,
        15.0,
        palette::VERMILION,
    );
    Figure::new(
        "sah-sweep",
        &format!(
            "The SAH cost of every candidate plane across the sketch's root, along x: the cheapest is x = {} (cost {:.1} against {} for a leaf).",
            short(best_x),
            best_cost,
            leaf_cost
        ),
        page,
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The figure's sweep picks the root plane the builder picks.
    #[test]
    fn the_sweep_finds_the_builders_root_plane() {
        let boxes = sketch_boxes(&sketch_scene());
        let tree = sketch_tree(&boxes);
        let (x, _) = cheapest(&root_sweep(&boxes, &tree.bounds));
        assert!(
            matches!(tree.nodes[0], KdNode::Split { axis: 0, plane, .. } if plane == x),
            "{:?} vs x = {x}",
            tree.nodes[0]
        );
    }

    /// Every object's box, cut by z = 0, is its flat box: the tree over
    /// the flat boxes holds what a ray in the plane can hit.
    #[test]
    fn the_objects_lie_in_their_flat_boxes() {
        for thing in sketch_scene() {
            let (flat, real) =
                (thing.flat_box(), thing.object().shape.bounds());
            assert!(
                real.min.x <= flat.min.x + 1e-12
                    && flat.max.x <= real.max.x + 1e-12
            );
            assert!(
                real.min.y <= flat.min.y + 1e-12
                    && flat.max.y <= real.max.y + 1e-12
            );
        }
    }

    #[test]
    fn print_tree() {
        let things = sketch_scene();
        let boxes: Vec<Aabb> = things.iter().map(Thing::flat_box).collect();
        let tree = KdTree::build(&boxes, KdBuilder::SahEvents, KdCosts::CHOSEN);
        let depths = tree.node_depths();
        for (k, n) in tree.nodes.iter().enumerate() {
            match n {
                KdNode::Split { axis, plane, above } => println!(
                    "{k} d{} split {axis} at {plane} above {above}",
                    depths[k]
                ),
                KdNode::Leaf { first, count } => println!(
                    "{k} d{} leaf {:?}",
                    depths[k],
                    tree.leaf_objects(*first, *count)
                ),
            }
        }
        println!("{:?}", tree.stats(&KdCosts::CHOSEN));
    }
}
#[cfg(test)]
mod search {
    use super::*;
    #[test]
    fn search_rays() {
        let things = sketch_scene();
        let boxes = sketch_boxes(&things);
        let tree = sketch_tree(&boxes);
        let objects: Vec<Object> = things.iter().map(Thing::object).collect();
        for oyk in 0..50 {
            let oy = 0.5 + 0.12 * oyk as f64;
            for sk in 0..30 {
                let slope = -0.6 + 0.04 * sk as f64;
                let ray = Ray::new(
                    DVec3::new(0.1, oy, 0.0),
                    DVec3::new(1.0, slope, 0.0),
                );
                let mut leaves = Vec::new();
                let mut tested = Vec::new();
                let hit = tree.closest_hit_observed(
                    &objects,
                    &ray,
                    Interval::FORWARD,
                    &mut |v, o| match o {
                        None if v.objects.is_some() => {
                            leaves.push((v.node, v.t_min, v.t_max))
                        }
                        None => {}
                        Some(k) => tested.push((leaves.len(), k)),
                    },
                );
                let Some((h, hit)) = hit else { continue };
                let missed =
                    tested.iter().filter(|t| t.1 as usize != h).count();
                let first =
                    tested.iter().find(|t| t.1 as usize == h).unwrap().0;
                let beyond = first < leaves.len();
                if missed >= 3 || (missed >= 2 && beyond) {
                    println!(
                        "oy {oy} slope {slope}: leaves {} tested {:?} hit {h} at t {:.2} first-test-leaf {first} beyond {beyond}",
                        leaves.len(),
                        tested,
                        hit.t
                    );
                }
            }
        }
    }
}
