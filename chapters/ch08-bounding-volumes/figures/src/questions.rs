//! Chapter 8's questions worked on paper, with the answers the chapter's
//! code computes from the same numbers (`raystep figures` writes them to
//! the book; `raystep check ch08` judges `exercise/answers.toml`). Part 1
//! asks questions 1 and 2, part 2 questions 3 and 4.
use std::sync::{Arc, Mutex};

use ch08::{
    Aabb, Bvh, BvhNode, DVec3, Hit, Interval, Object, Ray, SahCosts, Shape,
    Tightness, near_first_closest_hit, slab_test, split_cost,
};
use raystep_figure::numbers::{trimmed, triple};
use raystep_figure::{ChoiceQuestion, NumberQuestion, Question};

/// Every question, in the order the book asks them (part 1, then part 2).
pub fn all() -> Vec<Question> {
    vec![
        slab_entry(),
        bound_speed_up(),
        sah_split_cost(),
        near_first_child(),
    ]
}

/// A number as the worked answers write it: at most 3 decimals.
fn num(x: f64) -> String {
    trimmed(x, 3)
}

/// `(x, y, z)`, as [`num`] writes each.
fn vector(v: DVec3) -> String {
    triple(v, 3)
}

/// Per axis, the two crossings of the slab's planes, the smaller first,
/// as the worked answers list them: `x: t = 1 \ldots 4`.
fn slabs(b: &Aabb, ray: &Ray) -> String {
    let lines: Vec<String> = (0..3)
        .map(|axis| {
            let name = ["x", "y", "z"][axis];
            let d = ray.direction[axis];
            if d == 0.0 {
                return format!(
                    "${name}$: $D_{name} = 0$, inside for every $t$"
                );
            }
            let t0 = (b.min[axis] - ray.origin[axis]) / d;
            let t1 = (b.max[axis] - ray.origin[axis]) / d;
            format!(
                "${name}$: $t = {} \\ldots {}$",
                num(t0.min(t1)),
                num(t0.max(t1))
            )
        })
        .collect();
    lines.join(", ")
}

/// Question 1 (part 1): where a ray enters a box, by the slab test.
fn slab_entry() -> Question {
    let b = Aabb::new(DVec3::new(3.0, 1.0, -2.0), DVec3::new(9.0, 4.0, 1.0));
    let ray = Ray::new(DVec3::new(1.0, 0.0, 2.0), DVec3::new(2.0, 0.8, -1.0));
    let inside =
        slab_test(&b, &ray, Interval::FORWARD).expect("the ray hits the box");
    // the z slab: entered through its max plane, the ray going toward −z
    let z_near = (b.max.z - ray.origin.z) / ray.direction.z;
    NumberQuestion {
        id: "q1",
        stars: 2,
        title: "where a ray enters a box",
        prompt: format!(
            "The ray $P(t) = P_0 + tD$ with $P_0 = {}$ and $D = {}$ meets \
             the box from $\\text{{min}} = {}$ to $\\text{{max}} = {}$. By \
             the slab test, at what $t$ does it enter the box?",
            vector(ray.origin),
            vector(ray.direction),
            vector(b.min),
            vector(b.max)
        ),
        figure: None,
        quantity: "t_near",
        value: inside.min,
        step: 0.01,
        worked: format!(
            "Per slab, the two crossings $t = (x_{{\\min}} - P_{{0,x}}) / \
             D_x$ and $(x_{{\\max}} - P_{{0,x}}) / D_x$, the smaller first: \
             {}. Going toward $-z$ the ray enters the $z$ slab through its \
             max plane, at $t = ({} - {}) / ({}) = {}$, and leaves it \
             through its min plane at {}: taking the min plane's crossing \
             for the entry would be wrong. The ray is inside the box from the largest \
             entry to the smallest exit: $t_{{near}} =$ **{}**, \
             $t_{{far}} = {}$.",
            slabs(&b, &ray),
            num(b.max.z),
            num(ray.origin.z),
            num(ray.direction.z),
            num(z_near),
            num((b.min.z - ray.origin.z) / ray.direction.z),
            num(inside.min),
            num(inside.max)
        ),
    }
    .into()
}

/// Question 2 (part 1): what a bound saves, by its expected cost.
fn bound_speed_up() -> Question {
    let counts = Tightness {
        rays: 4000,
        bound_hits: 640,
        object_hits: 400,
        wasted: 240,
        lost: 0,
    };
    let (c_bound, c_object) = (27.0, 240.0);
    let cost = counts.expected_cost(c_bound, c_object);
    let speed_up = counts.speed_up(c_bound, c_object);
    NumberQuestion {
        id: "q2",
        stars: 1,
        title: "what a bound saves",
        prompt: format!(
            "An object costs {} ns a test, and its box {} ns. Of {} random \
             lines, {} hit the box and {} the object. How many times faster \
             is a ray behind the box than one that tests the object alone \
             ($C_{{\\text{{object}}}} / C_{{\\text{{bounded}}}}$)?",
            num(c_object),
            num(c_bound),
            counts.rays,
            counts.bound_hits,
            counts.object_hits
        ),
        figure: None,
        quantity: "speed-up",
        value: speed_up,
        step: 0.02,
        worked: format!(
            "Only the lines that hit the box pay for the object's test: \
             $P(\\text{{bound hit}}) = {} / {} = {}$ (the {} lines that \
             hit the object play no part). $C_{{\\text{{bounded}}}} = {} + {} \\cdot \
             {} = {}$ ns against $C_{{\\text{{object}}}} = {}$ ns, so the \
             box makes a ray **{:.2}** times faster. It {}, as \
             $P(\\text{{bound hit}}) = {}$ is {} $1 - {} / {} = {:.4}$.",
            counts.bound_hits,
            counts.rays,
            num(counts.p_bound()),
            counts.object_hits,
            num(c_bound),
            num(counts.p_bound()),
            num(c_object),
            num(cost),
            num(c_object),
            speed_up,
            if speed_up > 1.0 {
                "pays"
            } else {
                "does not pay"
            },
            num(counts.p_bound()),
            if speed_up > 1.0 { "below" } else { "not below" },
            num(c_bound),
            num(c_object),
            1.0 - c_bound / c_object
        ),
    }
    .into()
}

/// Question 3 (part 2): the SAH cost of one split.
fn sah_split_cost() -> Question {
    let parent =
        Aabb::new(DVec3::new(0.0, 0.0, 0.0), DVec3::new(4.0, 2.0, 2.0));
    let left = Aabb::new(DVec3::new(0.0, 0.0, 0.0), DVec3::new(1.0, 2.0, 2.0));
    let right = Aabb::new(DVec3::new(1.0, 0.0, 0.0), DVec3::new(4.0, 2.0, 1.0));
    let (n_left, n_right) = (6, 10);
    let costs = SahCosts::CHOSEN;
    let cost = split_cost(&parent, &left, n_left, &right, n_right, &costs);
    let leaf = (n_left + n_right) as f64 * costs.intersection;
    let area = |b: &Aabb| num(b.surface_area());
    let sides = |b: &Aabb| {
        let d = b.max - b.min;
        format!("{} \\times {} \\times {}", num(d.x), num(d.y), num(d.z))
    };
    NumberQuestion {
        id: "q3",
        stars: 2,
        title: "the SAH cost of a split",
        prompt: format!(
            "A node's box runs from ${}$ to ${}$. A split puts {} objects in \
             a left child with box ${}$ to ${}$ and {} in a right child with \
             box ${}$ to ${}$ (each child a leaf). With \
             the chapter's costs ($C_{{\\text{{trav}}}} = {}$, \
             $C_{{\\text{{isect}}}} = {}$), what does the surface area \
             heuristic say the split costs?",
            vector(parent.min),
            vector(parent.max),
            n_left,
            vector(left.min),
            vector(left.max),
            n_right,
            vector(right.min),
            vector(right.max),
            num(costs.traversal),
            num(costs.intersection)
        ),
        figure: None,
        quantity: "C(split)",
        value: cost,
        step: 0.1,
        worked: format!(
            "A box of sides $a \\times b \\times c$ has area \
             $2(ab + bc + ca)$: the parent (${}$) {}, the left child \
             (${}$) {}, the right child (${}$) {}. \
             $C = {} + \\frac{{{} \\cdot {} + {} \\cdot {}}}{{{}}} \\cdot {} \
             =$ **{}**, against {} for keeping the node a leaf of {} \
             objects: the split {}.",
            sides(&parent),
            area(&parent),
            sides(&left),
            area(&left),
            sides(&right),
            area(&right),
            num(costs.traversal),
            area(&left),
            n_left,
            area(&right),
            n_right,
            area(&parent),
            num(costs.intersection),
            num(cost),
            num(leaf),
            n_left + n_right,
            if cost < leaf { "pays" } else { "does not pay" }
        ),
    }
    .into()
}

/// A box that notes when the walk tests it and is never hit: the order of
/// its notes is the order in which the walk reaches the leaves.
#[derive(Debug)]
struct Probe {
    /// The node whose leaf holds it.
    node: u32,
    bounds: Aabb,
    log: Arc<Mutex<Vec<u32>>>,
}

impl Shape for Probe {
    fn intersect(&self, _: &Ray, _: Interval) -> Option<Hit> {
        self.log.lock().expect("one thread").push(self.node);
        None
    }

    fn bounds(&self) -> Aabb {
        self.bounds
    }
}

/// Question 4 (part 2): which child the near-first walk visits first.
fn near_first_child() -> Question {
    let flat = |x0: f64, y0: f64, x1: f64, y1: f64| {
        Aabb::new(DVec3::new(x0, y0, -1.0), DVec3::new(x1, y1, 1.0))
    };
    let boxes = [flat(3.0, 0.0, 5.0, 4.0), flat(1.0, 1.2, 9.0, 2.0)];
    let ray = Ray::new(DVec3::ZERO, DVec3::new(1.0, 0.5, 0.0));
    // the tree by hand: a root and two leaves, nodes 1 and 2, one probe
    // in each, so that the chapter's walk itself shows its order
    let log = Arc::new(Mutex::new(Vec::new()));
    let objects: Vec<Object> = (0..2)
        .map(|k| Object {
            shape: Arc::new(Probe {
                node: k as u32 + 1,
                bounds: boxes[k],
                log: log.clone(),
            }),
            material: 0,
        })
        .collect();
    let leaf = |k: usize| BvhNode {
        bounds: boxes[k],
        first: k as u32,
        count: 1,
    };
    let root = BvhNode {
        bounds: boxes[0].union(boxes[1]),
        first: 1,
        count: 0,
    };
    let bvh = Bvh {
        nodes: vec![root, leaf(0), leaf(1)],
        order: vec![0, 1],
        unbounded: Vec::new(),
    };
    near_first_closest_hit(&bvh, &objects, &ray, Interval::FORWARD);
    let order = log.lock().expect("one thread").clone();
    let answer = match order.first() {
        Some(1) => "node 1",
        Some(2) => "node 2",
        _ => "neither",
    };
    let entry = |k: usize| {
        slab_test(&boxes[k], &ray, Interval::FORWARD).map(|i| (i.min, i.max))
    };
    let (a, b) = (entry(0).expect("hits"), entry(1).expect("hits"));
    // the one entered first, and the other (node numbers are k + 1)
    let (first, second) = if order.first() == Some(&2) {
        (1, 0)
    } else {
        (0, 1)
    };
    let t_in = [a.0, b.0];
    // a box whose centre is nearer the origin is not always entered first
    let distance = |k: usize| ((boxes[k].min + boxes[k].max) / 2.0).length();
    let remark = if distance(second) < distance(first) {
        format!(
            ", though node {}'s centre is nearer the origin ({} against {}): \
             the order is where the ray enters a box, not where the box lies",
            second + 1,
            num(distance(second)),
            num(distance(first))
        )
    } else {
        String::new()
    };
    let rect = |k: usize| {
        format!(
            "$[{}, {}] \\times [{}, {}]$",
            num(boxes[k].min.x),
            num(boxes[k].max.x),
            num(boxes[k].min.y),
            num(boxes[k].max.y)
        )
    };
    ChoiceQuestion {
        id: "q4",
        stars: 3,
        title: "which child the near-first walk visits first",
        prompt: format!(
            "An interior node's children are node 1, with box {} in $x$ \
             and $y$, and node 2, with box {} (both from $z = -1$ to \
             $z = 1$). The ray starts at $P_0 = {}$ with direction $D = {}$. \
             Which child does the near-first walk visit first?",
            rect(0),
            rect(1),
            vector(ray.origin),
            vector(ray.direction)
        ),
        figure: None,
        options: &["node 1", "node 2", "neither"],
        answer,
        worked: format!(
            "The walk compares where the ray enters the two boxes (the slab \
             test's $t_{{near}}$). Node 1: {}, so the ray is inside it over \
             $[{}, {}]$. Node 2: {}, inside over $[{}, {}]$. Node {} is \
             entered first, at $t = {}$ against {}, so the walk pushes node \
             {} and pops **{}** first{}.",
            slabs(&boxes[0], &ray),
            num(a.0),
            num(a.1),
            slabs(&boxes[1], &ray),
            num(b.0),
            num(b.1),
            first + 1,
            num(t_in[first]),
            num(t_in[second]),
            second + 1,
            answer,
            remark
        ),
    }
    .into()
}
