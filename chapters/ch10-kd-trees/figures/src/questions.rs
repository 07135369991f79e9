//! Chapter 10's questions worked on paper, with the answers the chapter's
//! code computes from the same numbers (`raystep figures` writes them to
//! the book; `raystep check ch10` judges `exercise/answers.toml`).
use ch08::slab_test;
use ch10::{
    Aabb, DVec3, Interval, KdCosts, Ray, Split, Step, split_cost,
    traversal_step,
};
use raystep_figure::numbers::{trimmed, triple};
use raystep_figure::{ChoiceQuestion, NumberQuestion, Question};

/// Every question, in the order the book asks them.
pub fn all() -> Vec<Question> {
    vec![plane_cost(), empty_bonus(), walk_order()]
}

/// A number as the worked answers write it: at most 3 decimals.
fn num(x: f64) -> String {
    trimmed(x, 3)
}

/// `(x, y, z)`, as [`num`] writes each.
fn vector(v: DVec3) -> String {
    triple(v, 3)
}

/// The node both cost questions cut, and its objects.
fn node() -> (Aabb, usize) {
    (Aabb::new(DVec3::ZERO, DVec3::new(6.0, 2.0, 2.0)), 10)
}

/// The node cut at `x = plane`: the boxes below and above.
fn halves(node: &Aabb, plane: f64) -> (Aabb, Aabb) {
    let (mut below, mut above) = (*node, *node);
    below.max.x = plane;
    above.min.x = plane;
    (below, above)
}

/// `a × b × c`, a box's sides.
fn sides(b: &Aabb) -> String {
    let d = b.max - b.min;
    format!("{} \\times {} \\times {}", num(d.x), num(d.y), num(d.z))
}

/// The constants, as the prompts state them.
fn constants(c: &KdCosts) -> String {
    format!(
        "$C_{{trav}} = {}$, $C_{{isect}} = {}$, $b = {}$",
        num(c.traversal),
        num(c.intersection),
        num(c.empty_bonus)
    )
}

/// Question 1: the SAH cost of one split plane.
fn plane_cost() -> Question {
    let (node, objects) = node();
    let (plane, n_below) = (2.0, 4);
    let n_above = objects - n_below;
    let costs = KdCosts::CHOSEN;
    let cost = split_cost(&node, 0, plane, n_below, n_above, &costs);
    let (below, above) = halves(&node, plane);
    let area = |b: &Aabb| num(b.surface_area());
    let weighted = (below.surface_area() * n_below as f64
        + above.surface_area() * n_above as f64)
        / node.surface_area();
    let leaf = objects as f64 * costs.intersection;
    NumberQuestion {
        id: "q1",
        stars: 1,
        title: "the SAH cost of a split plane",
        prompt: format!(
            "A node's box runs from ${}$ to ${}$ and holds {objects} \
             objects. The plane $x = {}$ leaves {n_below} of them below it \
             and {n_above} above (none cut). With the chapter's constants \
             ({}), what does the split cost?",
            vector(node.min),
            vector(node.max),
            num(plane),
            constants(&costs)
        ),
        figure: None,
        quantity: "C",
        value: cost,
        step: 1.0,
        worked: format!(
            "The node (${}$) has area $A = {}$, the child below (${}$) \
             $A_b = {}$, the one above (${}$) $A_a = {}$. No child is \
             empty, so no bonus: $C = {} + {} \\cdot \\frac{{{} \\cdot \
             {n_below} + {} \\cdot {n_above}}}{{{}}} = {} + {} \\cdot {} =$ \
             **{}**, against ${objects} \\cdot {} = {}$ for a leaf.",
            sides(&node),
            area(&node),
            sides(&below),
            area(&below),
            sides(&above),
            area(&above),
            num(costs.traversal),
            num(costs.intersection),
            area(&below),
            area(&above),
            area(&node),
            num(costs.traversal),
            num(costs.intersection),
            num(weighted),
            num(cost),
            num(costs.intersection),
            num(leaf)
        ),
    }
    .into()
}

/// Question 2: the empty bonus decides between two planes.
fn empty_bonus() -> Question {
    let (node, objects) = node();
    let costs = KdCosts::CHOSEN;
    let (even, n_below) = (2.0, 4);
    let (wrap, n_wrap) = (5.0, objects);
    let c_even = split_cost(&node, 0, even, n_below, objects - n_below, &costs);
    let c_wrap = split_cost(&node, 0, wrap, n_wrap, 0, &costs);
    let no_bonus = KdCosts {
        empty_bonus: 0.0,
        ..costs
    };
    let c_wrap_plain = split_cost(&node, 0, wrap, n_wrap, 0, &no_bonus);
    let leaf = objects as f64 * costs.intersection;
    // the worked answer's point: the bonus, and only the bonus, decides
    assert!(
        c_wrap < c_even && c_even < c_wrap_plain,
        "the bonus decides"
    );
    let options = [
        format!("x = {}", num(even)),
        format!("x = {}", num(wrap)),
        "the leaf".to_string(),
    ];
    let cheapest = [c_even, c_wrap, leaf]
        .iter()
        .enumerate()
        .min_by(|a, b| a.1.total_cmp(b.1))
        .map(|(k, _)| k)
        .expect("three costs");
    let (below, _) = halves(&node, wrap);
    let option_refs: Vec<&str> = options.iter().map(String::as_str).collect();
    ChoiceQuestion {
        id: "q2",
        stars: 3,
        title: "the empty bonus",
        prompt: format!(
            "A node's box runs from ${}$ to ${}$ and holds {objects} \
             objects; the constants are the chapter's ({}). The plane \
             $x = {}$ leaves {n_below} objects below it and {} above; the \
             plane $x = {}$ leaves all {objects} below and none above. If these are its only candidate planes, which does the builder choose: the plane $x = {}$, the plane \
             $x = {}$, or no plane (the leaf)?",
            vector(node.min),
            vector(node.max),
            constants(&costs),
            num(even),
            objects - n_below,
            num(wrap),
            num(even),
            num(wrap)
        ),
        figure: Some("sah-sweep.svg"),
        options: &option_refs,
        answer: option_refs[cheapest],
        worked: format!(
            "$x = {}$ costs {} (question 1). $x = {}$ leaves the child \
             above empty, so the bonus applies: the child below (${}$) has \
             area {} of the node's {}, and $C = {} + (1 - {}) \\cdot {} \\cdot \
             \\frac{{{}}}{{{}}} \\cdot {objects} \\approx {:.1}$. \
             The leaf costs ${objects} \\cdot {} = {}$. The cheapest is \
             **{}**. Without the bonus $x = {}$ would cost {:.1}: cutting off \
             the empty space pays only because a ray that finds an empty \
             child skips it for free.",
            num(even),
            num(c_even),
            num(wrap),
            sides(&below),
            num(below.surface_area()),
            num(node.surface_area()),
            num(costs.traversal),
            num(costs.empty_bonus),
            num(costs.intersection),
            num(below.surface_area()),
            num(node.surface_area()),
            c_wrap,
            num(costs.intersection),
            num(leaf),
            options[cheapest],
            num(wrap),
            c_wrap_plain
        ),
    }
    .into()
}

/// The traversal's answers, as question 3 names them.
const ORDERS: [&str; 4] = [
    "below only",
    "above only",
    "below, then above",
    "above, then below",
];

/// Question 3: which children the walk visits, in which order.
fn walk_order() -> Question {
    let node = Aabb::new(DVec3::ZERO, DVec3::splat(4.0));
    let split = Split {
        plane: 2.0,
        below: 1,
        above: 2,
    };
    let ray = Ray::new(DVec3::new(5.0, 1.0, 1.0), DVec3::new(-2.0, 1.0, 0.5));
    let inside = slab_test(&node, &ray, Interval::FORWARD)
        .expect("the ray hits the node");
    let (t_min, t_max) = (inside.min, inside.max);
    let inverse = 1.0 / ray.direction.x;
    let step = traversal_step(split, ray.origin.x, inverse, t_min, t_max);
    let name = |child: u32| {
        if child == split.below {
            "below"
        } else {
            "above"
        }
    };
    let answer = match step {
        Step::One(child) if child == split.below => ORDERS[0],
        Step::One(_) => ORDERS[1],
        Step::Both { near, .. } if near == split.below => ORDERS[2],
        Step::Both { .. } => ORDERS[3],
    };
    // The question's ray crosses the plane inside the node: the walk's
    // own answer names the near child, the far one and where it crosses.
    let Step::Both {
        near,
        far,
        near_until: t_plane,
        ..
    } = step
    else {
        panic!("question 3's ray crosses the plane inside the node")
    };
    let verdict = if t_plane > t_max {
        "after $t_{max}$: the ray leaves the node before it reaches the plane"
    } else if t_plane < t_min {
        "before $t_{min}$: the ray crossed the plane before it entered the node"
    } else {
        "inside $[t_{min}, t_{max}]$: the ray passes through both children"
    };
    let tail = match step {
        Step::Both {
            near_until,
            far_from,
            ..
        } => format!(
            " (the near child over $[{}, {}]$ now, the far one over \
             $[{}, {}]$ pushed for later)",
            num(t_min),
            num(near_until),
            num(far_from),
            num(t_max)
        ),
        Step::One(_) => String::new(),
    };
    ChoiceQuestion {
        id: "q3",
        stars: 2,
        title: "which child the walk visits first",
        prompt: format!(
            "A node's box runs from ${}$ to ${}$; its plane $x = {}$ has one \
             child below and one above. The ray starts at $P_0 = {}$ with \
             direction $D = {}$, and the walk reaches the node over \
             $[t_{{min}}, t_{{max}}] = [{}, {}]$. Which children does the \
             walk visit, and in which order?",
            vector(node.min),
            vector(node.max),
            num(split.plane),
            vector(ray.origin),
            vector(ray.direction),
            num(t_min),
            num(t_max)
        ),
        figure: Some("kd-traversal.svg"),
        options: &ORDERS,
        answer,
        worked: format!(
            "The ray goes toward ${}x$ ($D_x = {}$), so it comes from {} \
             the plane: the child {} it is near, the one {} it far. It \
             crosses the plane at $t_{{plane}} = ({} - {}) / ({}) = {}$, \
             {}. So: **{}**{}.",
            if ray.direction.x < 0.0 { "-" } else { "+" },
            num(ray.direction.x),
            name(near),
            name(near),
            name(far),
            num(split.plane),
            num(ray.origin.x),
            num(ray.direction.x),
            num(t_plane),
            verdict,
            answer,
            tail
        ),
    }
    .into()
}
