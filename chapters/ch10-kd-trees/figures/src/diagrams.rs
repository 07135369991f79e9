//! Chapter 10's lecture figures, each drawn from the chapter's own code:
//! the lecture's sketch of planes splitting space, split by split; one
//! ray's walk through the tree, front to back; and the SAH's cost of
//! every candidate plane at the root.
use std::sync::Arc;

use ch08::TriangleMesh;
use ch10::{
    Aabb, DVec3, Interval, KdBuilder, KdCosts, KdNode, KdTree, Object, Ray,
    Split, Step, split_cost, traversal_step,
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
                    normals: Vec::new(),
                }))
            }
        };
        Object { shape, material: 0 }
    }

    /// Draws it, filled and outlined.
    fn draw(
        &self, page: &mut Page, offset: DVec2, fill: Color, stroke: &Stroke,
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

/// A coordinate as short as it is exact to 3 decimals: `6.625`, `2`.
fn short(x: f64) -> String {
    let s = fixed(x, 3);
    s.trim_end_matches('0').trim_end_matches('.').to_string()
}

/// A number in a small white disc outlined in `color`, centred on `at`.
fn badge(page: &mut Page, at: DVec2, text: &str, color: Color) {
    let r = if text.len() > 1 { 10.0 } else { 8.5 } / page.scale();
    page.circle(
        at,
        r,
        Some(palette::WHITE),
        Some(&Stroke::new(color).width(1.5)),
    );
    page.label_sized(at, text, Anchor::Center, 12.0, color);
}

/// The interior nodes in level order (by depth, then left to right):
/// `number[node]` is the plane's number, 1 for the root's.
fn level_numbers(tree: &KdTree, depths: &[usize]) -> Vec<usize> {
    let mut splits: Vec<usize> = (0..tree.nodes.len())
        .filter(|&n| matches!(tree.nodes[n], KdNode::Split { .. }))
        .collect();
    splits.sort_by_key(|&n| (depths[n], n));
    let mut number = vec![0; tree.nodes.len()];
    for (k, &n) in splits.iter().enumerate() {
        number[n] = k + 1;
    }
    number
}

/// The lecture's sketch, split by split: the planes of depth ≤ 1, ≤ 2
/// and ≤ 3, numbered level by level, each level's new planes in
/// vermilion; then the finished tree.
fn kd_splits() -> Figure {
    let things = sketch_scene();
    let boxes = sketch_boxes(&things);
    let tree = sketch_tree(&boxes);
    let node_boxes = tree.node_boxes();
    let depths = tree.node_depths();
    let number = level_numbers(&tree, &depths);
    let stats = tree.stats(&KdCosts::CHOSEN);
    let root = tree.bounds;
    // the panels: the planes down to this depth (the last: all of them)
    let panels = [1, 2, 3, stats.depth];
    let pad = 0.15;
    let size = DVec2::new(
        root.max.x - root.min.x + 2.0 * pad,
        root.max.y - root.min.y + 2.0 * pad,
    );
    let gap = DVec2::new(0.5, 1.0);
    let mut page = Page::new(900.0, 600.0).view(
        DVec2::new(root.min.x - pad, root.min.y - pad - size.y - gap.y - 0.9),
        DVec2::new(
            root.min.x - pad + 2.0 * size.x + gap.x,
            root.max.y + pad + 0.6,
        ),
    );
    // how many planes the tree has down to a depth
    let planes_to = |deepest: usize| {
        (0..tree.nodes.len())
            .filter(|&n| number[n] > 0 && depths[n] <= deepest)
            .count()
    };
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
        page.polygon(
            &corners(&root, offset),
            None,
            Some(&Stroke::new(palette::BLACK).width(1.0)),
        );
        // earlier planes thin and black, this level's thick and vermilion
        // (the first panel: all three; the finished tree: every plane
        // below depth 3)
        let newest = match k {
            0 => 0,
            _ if last => panels[k - 1] + 1,
            _ => deepest,
        };
        let is_new = |n: usize| depths[n] >= newest;
        let mut badges = Vec::new();
        for (n, node) in tree.nodes.iter().enumerate() {
            let Some((a, b)) = plane_segment(node, &node_boxes[n]) else {
                continue;
            };
            if depths[n] > deepest {
                continue;
            }
            let stroke = match (is_new(n), last) {
                (true, true) => Stroke::new(palette::VERMILION).width(1.5),
                (true, false) => Stroke::new(palette::VERMILION).width(2.5),
                (false, _) => Stroke::new(palette::BLACK).width(1.0),
            };
            page.segment(offset + a, offset + b, &stroke);
            if !last {
                badges.push((offset + 0.5 * (a + b), n));
            }
        }
        // the planes' numbers, on top of every plane
        for (at, n) in badges {
            let color = if is_new(n) {
                palette::VERMILION
            } else {
                palette::BLACK
            };
            badge(&mut page, at, &number[n].to_string(), color);
        }
        let planes = planes_to(deepest);
        let first_new = if newest > 0 {
            planes_to(newest - 1) + 1
        } else {
            1
        };
        let title = if last {
            format!(
                "finished: {planes} planes, {} leaves ({} empty), depth {}",
                stats.leaves, stats.empty_leaves, stats.depth
            )
        } else if k == 0 {
            "depth ≤ 1: the root's plane 1, its children's 2 and 3".to_string()
        } else {
            format!("depth ≤ {deepest}: planes {first_new}–{planes} are new")
        };
        page.label_sized(
            offset + DVec2::new(root.min.x - pad, root.max.y + pad + 0.3),
            &title,
            Anchor::E,
            15.0,
            palette::BLACK,
        );
    }
    page.text_page(
        DVec2::new(14.0, 580.0),
        "vermilion: the planes a level adds, numbered level by level · black: earlier planes · blue: leaves that hold an object",
        Anchor::E,
        14.0,
    );
    // what the caption quotes: the fullest leaf, the objects cut
    let lists: Vec<&[u32]> = tree
        .nodes
        .iter()
        .filter_map(|n| match *n {
            KdNode::Leaf { first, count } => {
                Some(tree.leaf_objects(first, count))
            }
            KdNode::Split { .. } => None,
        })
        .collect();
    let fullest = lists.iter().map(|l| l.len()).max().unwrap_or(0);
    let cut = (0..things.len() as u32)
        .filter(|i| lists.iter().filter(|l| l.contains(i)).count() > 1)
        .count();
    let KdNode::Split {
        plane: root_plane, ..
    } = tree.nodes[0]
    else {
        panic!("the sketch's root is cut");
    };
    Figure::new(
        "kd-splits",
        &format!(
            "Use planes to split space into pieces: the lecture's sketch of {} circles and triangles, and the kd-tree the chapter's SAH builder makes for it (events, costs {}), plane by plane. The planes down to depth 1, 2 and 3, numbered level by level, each level's new ones in vermilion; then the finished tree: {} planes, {} leaves ({} of them empty), depth {}. The root cuts at x = {}, where the SAH is cheapest (see the sweep below). With the empty bonus, a plane that cuts off empty space is cheap, so the builder wraps every object in planes: no leaf holds more than {} objects, and {} objects cut by a plane are listed in two leaves.",
            things.len(),
            KdCosts::CHOSEN.name(),
            stats.nodes - stats.leaves,
            stats.leaves,
            stats.empty_leaves,
            stats.depth,
            short(root_plane),
            fullest,
            cut
        ),
        page,
    )
}

/// The ray of the traversal figure, in the plane z = 0: from outside the
/// root's box, just over the clump, through the long triangle's box.
fn walk_ray() -> Ray {
    Ray::new(DVec3::new(0.1, 1.7, 0.0), DVec3::new(1.0, 0.24, 0.0))
}

/// One node the walk reached: its index, the stretch of the ray inside
/// it, and whether it is a leaf.
#[derive(Clone, Copy, Debug)]
struct Reached {
    node: u32,
    t_min: f64,
    t_max: f64,
    leaf: bool,
}

/// The far children the walk pushed on its stack (at interior nodes
/// whose plane the ray crosses): the chapter's own traversal step, asked
/// again at every interior node the walk reached.
fn pushed(tree: &KdTree, ray: &Ray, reached: &[Reached]) -> Vec<u32> {
    reached
        .iter()
        .filter_map(|r| match tree.nodes[r.node as usize] {
            KdNode::Split { axis, plane, above } => {
                let axis = axis as usize;
                let split = Split {
                    plane,
                    below: r.node + 1,
                    above,
                };
                match traversal_step(
                    split,
                    ray.origin[axis],
                    1.0 / ray.direction[axis],
                    r.t_min,
                    r.t_max,
                ) {
                    Step::Both { far, .. } => Some(far),
                    Step::One(_) => None,
                }
            }
            KdNode::Leaf { .. } => None,
        })
        .collect()
}

/// One ray through the sketch's tree, front to back: the leaves it
/// visits, the objects it tests there, the hit, and the far children
/// left on the stack when the hit ends the walk.
fn kd_traversal() -> Figure {
    let things = sketch_scene();
    let boxes = sketch_boxes(&things);
    let tree = sketch_tree(&boxes);
    let objects: Vec<Object> = things.iter().map(Thing::object).collect();
    let node_boxes = tree.node_boxes();
    let ray = walk_ray();
    // Step 1–4 of the walk, observed: every node reached, every test
    let mut reached: Vec<Reached> = Vec::new();
    let mut tested: Vec<(usize, u32)> = Vec::new();
    let hit = tree.closest_hit_observed(
        &objects,
        &ray,
        Interval::FORWARD,
        |visit: &ch10::KdVisit, object| match object {
            None => reached.push(Reached {
                node: visit.node,
                t_min: visit.t_min,
                t_max: visit.t_max,
                leaf: visit.objects.is_some(),
            }),
            Some(k) => tested.push((reached.len() - 1, k)),
        },
    );
    let (hit_object, hit) = hit.expect("the ray hits an object");
    let leaves: Vec<Reached> =
        reached.iter().copied().filter(|r| r.leaf).collect();
    // the far children still on the stack when the walk stops: they
    // begin after the hit
    let left_over: Vec<u32> = pushed(&tree, &ray, &reached)
        .into_iter()
        .filter(|&far| reached.iter().all(|r| r.node != far))
        .collect();
    let root = tree.bounds;
    let mut page = Page::new(900.0, 560.0).view(
        DVec2::new(root.min.x - 0.45, root.min.y - 1.1),
        DVec2::new(root.max.x + 0.2, root.max.y + 0.2),
    );
    // the far children never visited: hatched grey
    for &far in &left_over {
        page.polygon_alpha(
            &corners(&node_boxes[far as usize], DVec2::ZERO),
            Some(palette::LIGHT_GREY.with_alpha(0.5)),
            None,
        );
    }
    // the leaves visited, front to back
    for (k, r) in leaves.iter().enumerate() {
        let last = k + 1 == leaves.len();
        let fill = if last {
            palette::ORANGE.with_alpha(0.4)
        } else {
            palette::SKY_BLUE.with_alpha(0.3)
        };
        page.polygon_alpha(
            &corners(&node_boxes[r.node as usize], DVec2::ZERO),
            Some(fill),
            None,
        );
    }
    for (n, node) in tree.nodes.iter().enumerate() {
        if let Some((a, b)) = plane_segment(node, &node_boxes[n]) {
            page.segment(a, b, &Stroke::new(palette::GREY).width(1.0));
        }
    }
    for &far in &left_over {
        page.polygon(
            &corners(&node_boxes[far as usize], DVec2::ZERO),
            None,
            Some(&Stroke::new(palette::NOTE).width(1.5).dashed()),
        );
    }
    page.polygon(
        &corners(&root, DVec2::ZERO),
        None,
        Some(&Stroke::new(palette::BLACK).width(1.0)),
    );
    let was_tested = |i: usize| tested.iter().any(|&(_, k)| k as usize == i);
    for (i, thing) in things.iter().enumerate() {
        let (fill, stroke) = if i == hit_object {
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
    // the ray up to the hit, and dashed beyond it: never walked
    let exit = ch08::slab_test(&root, &ray, Interval::FORWARD)
        .map_or(hit.t, |inside| inside.max);
    page.segment(
        flat(ray.at(hit.t)),
        flat(ray.at(exit)),
        &Stroke::new(palette::BLUE).width(1.5).dashed(),
    );
    page.arrow(
        flat(ray.origin),
        flat(ray.at(hit.t)),
        &Stroke::new(palette::BLUE).width(2.5),
    );
    page.cross(flat(hit.point));
    page.point(flat(ray.origin), palette::BLUE);
    // each leaf's number on the ray, halfway through the leaf
    for (k, r) in leaves.iter().enumerate() {
        let at = flat(ray.at(0.5 * (r.t_min + r.t_max)));
        badge(&mut page, at, &(k + 1).to_string(), palette::BLUE);
    }
    let lines = [
        format!(
            "blue: the {} leaves the ray visits, numbered in order · orange: the leaf that holds the hit; the walk stops there",
            leaves.len()
        ),
        format!(
            "orange objects: tested, missed ({}) · vermilion: the hit · dashed: far children left on the stack ({}), never visited",
            tested.len() - 1,
            left_over.len()
        ),
    ];
    for (k, line) in lines.iter().enumerate() {
        page.text_page(
            DVec2::new(14.0, 512.0 + 26.0 * k as f64),
            line,
            Anchor::E,
            14.0,
        );
    }
    let empty = leaves
        .iter()
        .filter(|r| {
            matches!(tree.nodes[r.node as usize], KdNode::Leaf { count: 0, .. })
        })
        .count();
    Figure::new(
        "kd-traversal",
        &format!(
            "One ray through the same tree, front to back, as the chapter's walk takes it (kd_walk, observed through closest_hit_observed). At each plane it crosses, the near child comes first and the far one goes on the stack. It visits {} of the {} leaves (blue, numbered in order; {} of them empty, which cost nothing but the steps down to them) and tests {} objects: {} miss (orange), the last is hit (vermilion). The leaf that holds the hit (orange) ends the walk: the {} far children still on the stack (dashed) begin after the hit and are never visited, nor is the rest of the ray.",
            leaves.len(),
            tree.stats(&KdCosts::CHOSEN).leaves,
            empty,
            tested.len(),
            tested.len() - 1,
            left_over.len()
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

/// The candidate planes across the root on `axis`: every box's start and
/// end strictly inside the root, in order.
fn candidates(boxes: &[Aabb], root: &Aabb, axis: usize) -> Vec<f64> {
    let mut planes: Vec<f64> = boxes
        .iter()
        .flat_map(|b| [b.min[axis], b.max[axis]])
        .filter(|&p| root.min[axis] < p && p < root.max[axis])
        .collect();
    planes.sort_by(f64::total_cmp);
    planes.dedup();
    planes
}

/// The SAH cost of every candidate plane across the root on `axis`:
/// exercise 1's formula, with the objects counted as the builder counts.
fn root_sweep(boxes: &[Aabb], root: &Aabb, axis: usize) -> Vec<(f64, f64)> {
    candidates(boxes, root, axis)
        .into_iter()
        .map(|p| {
            let (below, above) = counts_at(boxes, axis, p);
            (p, split_cost(root, axis, p, below, above, &KdCosts::CHOSEN))
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

/// The SAH cost along x at the sketch's root: every candidate plane's
/// cost, the cost of a leaf, and the cheapest plane, which is the one the
/// builder takes.
fn sah_sweep() -> Figure {
    let things = sketch_scene();
    let boxes = sketch_boxes(&things);
    let tree = sketch_tree(&boxes);
    let root = tree.bounds;
    let costs = KdCosts::CHOSEN;
    // Step 1: every candidate plane's cost, exercise 1's formula
    let sweep = root_sweep(&boxes, &root, 0);
    let (best_x, best_cost) = cheapest(&sweep);
    // Step 2: the builder's own choice is the same plane (y has no
    // cheaper one)
    let (best_y, best_y_cost) = cheapest(&root_sweep(&boxes, &root, 1));
    let KdNode::Split { axis: 0, plane, .. } = tree.nodes[0] else {
        panic!("the sketch's root is cut along x");
    };
    assert!(
        plane == best_x && best_cost < best_y_cost,
        "the figure's sweep finds the builder's plane"
    );
    // Step 3: a leaf instead: test every object
    let leaf_cost = boxes.len() as f64 * costs.intersection;
    // the cost chart below the scene: cost c at world y = chart_y(c)
    let (top, height, max_cost) = (root.min.y - 0.7, 3.6, 300.0);
    let chart_y = |c: f64| top - height + height * c / max_cost;
    let (width, tall) = (800.0, 720.0);
    let mut page = Page::new(width, tall).view(
        DVec2::new(root.min.x - 1.25, top - height - 1.3),
        DVec2::new(root.max.x + 0.15, root.max.y + 0.45),
    );
    // the scene and the root's box; each box's sides are candidates
    page.polygon(
        &corners(&root, DVec2::ZERO),
        None,
        Some(&Stroke::new(palette::BLACK).width(1.0)),
    );
    for (thing, b) in things.iter().zip(&boxes) {
        page.polygon(
            &corners(b, DVec2::ZERO),
            None,
            Some(&Stroke::new(palette::GREY).width(1.0).dashed()),
        );
        thing.draw(
            &mut page,
            DVec2::ZERO,
            palette::GREY,
            &Stroke::new(palette::GREY).width(1.0),
        );
    }
    // the chart's axes, grid and ticks
    let x0 = root.min.x;
    let ink = Stroke::new(palette::BLACK).width(1.0);
    page.segment(
        DVec2::new(x0, chart_y(0.0)),
        DVec2::new(x0, chart_y(max_cost)),
        &ink,
    );
    for c in (0..=300).step_by(50) {
        let y = chart_y(f64::from(c));
        if c > 0 {
            page.segment(
                DVec2::new(x0, y),
                DVec2::new(root.max.x, y),
                &Stroke::new(palette::LIGHT_GREY).width(1.0),
            );
        }
        page.label_sized(
            DVec2::new(x0, y),
            &c.to_string(),
            Anchor::W,
            13.0,
            palette::BLACK,
        );
    }
    page.segment(
        DVec2::new(x0, chart_y(0.0)),
        DVec2::new(root.max.x, chart_y(0.0)),
        &ink,
    );
    for x in (x0.ceil() as i32)..=(root.max.x.floor() as i32) {
        let at = DVec2::new(f64::from(x), chart_y(0.0));
        page.segment(at, at - DVec2::new(0.0, 0.08), &ink);
        page.label_sized(at, &x.to_string(), Anchor::S, 13.0, palette::BLACK);
    }
    page.label_sized(
        DVec2::new(0.5 * (x0 + root.max.x), chart_y(0.0) - 0.45),
        "x: where the plane cuts",
        Anchor::S,
        14.0,
        palette::BLACK,
    );
    page.label_sized(
        DVec2::new(x0 - 0.75, chart_y(max_cost) + 0.25),
        "SAH cost",
        Anchor::NE,
        14.0,
        palette::BLACK,
    );
    // the leaf's cost: test every object
    page.segment(
        DVec2::new(x0, chart_y(leaf_cost)),
        DVec2::new(root.max.x, chart_y(leaf_cost)),
        &Stroke::new(palette::GREEN).width(2.0).dashed(),
    );
    page.label_sized(
        DVec2::new(0.5 * (x0 + best_x), chart_y(leaf_cost)),
        &format!(
            "leaf: N·C_{{isect}} = {} · {} = {}",
            boxes.len(),
            costs.intersection,
            leaf_cost
        ),
        Anchor::N,
        16.0,
        palette::GREEN,
    );
    // the cost at every candidate plane
    let points: Vec<DVec2> = sweep
        .iter()
        .map(|&(x, c)| DVec2::new(x, chart_y(c)))
        .collect();
    page.polyline(&points, &Stroke::new(palette::BLUE).width(1.5));
    for &p in &points {
        page.circle(p, 0.055, Some(palette::BLUE), None);
    }
    // the chosen plane, through the scene and the chart
    page.segment(
        DVec2::new(best_x, chart_y(0.0)),
        DVec2::new(best_x, root.max.y),
        &Stroke::new(palette::VERMILION).width(2.5).dashed(),
    );
    page.circle(
        DVec2::new(best_x, chart_y(best_cost)),
        0.09,
        Some(palette::VERMILION),
        None,
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
        &format!("{below} objects below · {above} above"),
        Anchor::N,
        15.0,
        palette::VERMILION,
    );
    page.text_page(
        DVec2::new(14.0, tall - 16.0),
        &format!(
            "C(x) = C_{{trav}} + C_{{isect}}·(N_{{below}}·A_{{below}} + N_{{above}}·A_{{above}}) / A,   C_{{trav}} = {}, C_{{isect}} = {}",
            costs.traversal, costs.intersection
        ),
        Anchor::E,
        16.0,
    );
    Figure::new(
        "sah-sweep",
        &format!(
            "The surface area heuristic at the sketch's root, along x: exercise 1's split_cost at each of the {} candidate planes, the sides of the objects' boxes (dashed) strictly inside the root, with the objects counted as the builder counts them (a box ending at the plane is below it, one starting there above it, one across it on both sides). The cheapest, x = {}, costs {:.1} ({below} objects below, {above} above) against {} for a leaf that tests all {} objects; the best plane on y, y = {}, costs {:.1}, so the builder cuts the root at x = {}. Near the root's sides a plane cuts off little and leaves nearly every object on its other side: it costs about as much as the leaf.",
            sweep.len(),
            short(best_x),
            best_cost,
            leaf_cost,
            boxes.len(),
            short(best_y),
            best_y_cost,
            short(best_x)
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
        let (x, cost) = cheapest(&root_sweep(&boxes, &tree.bounds, 0));
        let (_, y_cost) = cheapest(&root_sweep(&boxes, &tree.bounds, 1));
        assert!(cost < y_cost);
        assert!(
            matches!(tree.nodes[0], KdNode::Split { axis: 0, plane, .. } if plane == x),
            "{:?} vs x = {x}",
            tree.nodes[0]
        );
    }

    /// The tree over the flat boxes finds, for rays in the plane z = 0,
    /// the same closest hit as testing every object: the spheres and
    /// prisms cut by the plane are the circles and triangles drawn.
    #[test]
    fn the_tree_finds_what_testing_everything_finds() {
        let things = sketch_scene();
        let tree = sketch_tree(&sketch_boxes(&things));
        let objects: Vec<Object> = things.iter().map(Thing::object).collect();
        let mut random = ch08::SplitMix64::new(10);
        let mut hits = 0;
        for _ in 0..2000 {
            let origin = DVec3::new(
                12.0 * random.next_f64(),
                7.0 * random.next_f64(),
                0.0,
            );
            let angle = std::f64::consts::TAU * random.next_f64();
            let ray =
                Ray::new(origin, DVec3::new(angle.cos(), angle.sin(), 0.0));
            let brute = objects
                .iter()
                .enumerate()
                .filter_map(|(k, o)| {
                    o.shape.intersect(&ray, Interval::FORWARD).map(|h| (k, h))
                })
                .min_by(|a, b| a.1.t.total_cmp(&b.1.t));
            let found = tree.closest_hit_observed(
                &objects,
                &ray,
                Interval::FORWARD,
                |_, _| {},
            );
            assert_eq!(
                found.map(|(k, h)| (k, h.t)),
                brute.map(|(k, h)| (k, h.t)),
                "{ray:?}"
            );
            if let Some((_, h)) = found {
                assert!(h.point.z.abs() < 1e-9);
                hits += 1;
            }
        }
        assert!(hits > 500, "{hits} hits");
    }
}
