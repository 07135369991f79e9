//! Chapter 9's questions worked on paper, with the answers the chapter's
//! code computes from the same numbers (`raystep figures` writes them to
//! the book; `raystep check ch09` judges `exercise/answers.toml`).
use std::ops::ControlFlow;

use ch09::{
    Aabb, DVec3, Interval, Lattice, RULE_FACTOR, Ray, Resolution, dda_setup,
    rule_cells, walk,
};
use raystep_figure::numbers::{trimmed, triple};
use raystep_figure::{ChoiceQuestion, NumberQuestion, Question};

/// Every question, in the order the book asks them.
pub fn all() -> Vec<Question> {
    vec![rule_cell_count(), second_row_crossing(), cells_visited()]
}

/// A number as the worked answers write it: at most 3 decimals.
fn num(x: f64) -> String {
    trimmed(x, 3)
}

/// `(x, y, z)`, as [`num`] writes each.
fn vector(v: DVec3) -> String {
    triple(v, 3)
}

/// Question 1: how many cells the resolution rule gives.
fn rule_cell_count() -> Question {
    let objects = 5000;
    let bounds = Aabb::new(DVec3::ZERO, DVec3::new(12.0, 8.0, 5.0));
    let cells = Resolution::Rule.cells(&bounds, objects);
    let total: usize = cells.iter().product();
    let longest = rule_cells(objects);
    let extent = bounds.max - bounds.min;
    let per_unit = longest as f64 / extent.max_element();
    NumberQuestion {
        id: "q1",
        stars: 1,
        title: "how many cells the rule gives",
        prompt: format!(
            "A scene of {objects} small objects fills the box from ${}$ to \
             ${}$. How many cells does the chapter's rule give the grid in \
             all ($n_x \\cdot n_y \\cdot n_z$)?",
            vector(bounds.min),
            vector(bounds.max)
        ),
        figure: None,
        quantity: "cells",
        value: total as f64,
        step: 1.0,
        worked: format!(
            "Along the longest axis ($x$, {} units) the rule gives \
             ${} \\sqrt[3]{{{objects}}} \\approx {} \\cdot {:.2} = {:.1}$, \
             rounded {longest} cells: {} cells a unit. Along $y$: \
             ${} \\cdot {} = {}$, rounded {}; along $z$: ${} \\cdot {} = {}$, \
             rounded {}. In all ${} \\cdot {} \\cdot {} =$ **{total}** cells, \
             about {:.1} an object (27 in a cube-shaped scene).",
            num(extent.x),
            num(RULE_FACTOR),
            num(RULE_FACTOR),
            (objects as f64).cbrt(),
            RULE_FACTOR * (objects as f64).cbrt(),
            num(per_unit),
            num(extent.y),
            num(per_unit),
            num(extent.y * per_unit),
            cells[1],
            num(extent.z),
            num(per_unit),
            num(extent.z * per_unit),
            cells[2],
            cells[0],
            cells[1],
            cells[2],
            total as f64 / objects as f64
        ),
    }
    .into()
}

/// Question 2: the DDA's `t_max` and `t_delta` for a ray going down.
fn second_row_crossing() -> Question {
    let lattice = Lattice::new(
        Aabb::new(DVec3::new(0.0, 0.0, -0.5), DVec3::new(10.0, 6.0, 0.5)),
        [5, 3, 1],
    );
    let ray = Ray::new(DVec3::new(0.6, 5.2, 0.0), DVec3::new(1.0, -0.4, 0.0));
    let dda =
        dda_setup(&lattice, &ray, Interval::FORWARD).expect("inside the grid");
    let t = dda.t_max.y + dda.t_delta.y;
    let plane = lattice.plane(1, dda.cell[1]);
    NumberQuestion {
        id: "q2",
        stars: 2,
        title: "the DDA's setup for a ray going down",
        prompt: format!(
            "A grid of {} × {} cells (one cell deep) fills the box from ${}$ \
             to ${}$. The ray starts inside it at $P_0 = {}$ with direction \
             $D = {}$. From the DDA's setup, at what $t$ does the ray cross \
             its second plane between rows of cells ($y$ = const)?",
            lattice.cells[0],
            lattice.cells[1],
            vector(lattice.bounds.min),
            vector(lattice.bounds.max),
            vector(ray.origin),
            vector(ray.direction)
        ),
        figure: Some("dda-setup.svg"),
        quantity: "t",
        value: t,
        step: 0.05,
        worked: format!(
            "The cells are {} × {} units; the origin lies in cell $({}, {})$, \
             which runs from $y = {}$ to ${}$. Going down ($D_y < 0$) the \
             next plane is the cell's own lower one, $y = {}$: \
             $t_{{\\max,y}} = ({} - {}) / ({}) = {}$, and \
             $t_{{\\delta,y}} = {} / {} = {}$. The second crossing comes one \
             $t_{{\\delta,y}}$ later: ${} + {} =$ **{}**, at \
             $y = {}$.",
            num(lattice.size.x),
            num(lattice.size.y),
            dda.cell[0],
            dda.cell[1],
            num(plane),
            num(lattice.plane(1, dda.cell[1] + 1)),
            num(plane),
            num(plane),
            num(ray.origin.y),
            num(ray.direction.y),
            num(dda.t_max.y),
            num(lattice.size.y),
            num(ray.direction.y.abs()),
            num(dda.t_delta.y),
            num(dda.t_max.y),
            num(dda.t_delta.y),
            num(t),
            num(ray.at(t).y)
        ),
    }
    .into()
}

/// The counts a student may answer question 3 with.
const COUNTS: [&str; 7] = ["6", "7", "8", "9", "10", "11", "12"];

/// Question 3: how many cells a ray visits.
fn cells_visited() -> Question {
    let (w, h) = (6, 4);
    let lattice = Lattice::new(
        Aabb::new(
            DVec3::new(0.0, 0.0, -0.5),
            DVec3::new(w as f64, h as f64, 0.5),
        ),
        [w, h, 1],
    );
    let ray = Ray::new(DVec3::new(0.5, 0.25, 0.0), DVec3::new(1.0, 0.6, 0.0));
    let mut visits = Vec::new();
    walk(&lattice, &ray, Interval::FORWARD, |visit| {
        visits.push(visit);
        ControlFlow::Continue(())
    });
    let count = visits.len().to_string();
    let answer = COUNTS
        .iter()
        .find(|&&c| c == count)
        .expect("the count is one of the options");
    // the walls crossed, per axis: where the walk steps along x and y
    let steps = |axis: usize| {
        visits
            .windows(2)
            .filter(|pair| pair[0].cell[axis] != pair[1].cell[axis])
            .count()
    };
    // where the ray crosses the planes y = const, and no two walls at once
    let rows: Vec<String> = visits
        .windows(2)
        .filter(|pair| pair[0].cell[1] != pair[1].cell[1])
        .map(|pair| {
            format!(
                "$y = {}$ at $t = {}$",
                num(lattice.plane(1, pair[1].cell[1])),
                num(pair[1].t_in)
            )
        })
        .collect();
    let mut walls: Vec<f64> = visits[1..].iter().map(|v| v.t_in).collect();
    walls.dedup();
    assert_eq!(walls.len(), visits.len() - 1, "two walls at the same t");
    let last = visits.last().expect("the ray is inside");
    let cells: Vec<String> = visits
        .iter()
        .map(|v| format!("({}, {})", v.cell[0], v.cell[1]))
        .collect();
    ChoiceQuestion {
        id: "q3",
        stars: 2,
        title: "how many cells a ray visits",
        prompt: format!(
            "A grid of {w} × {h} unit cells (one cell deep) fills the box \
             from ${}$ to ${}$. The ray starts inside it at $P_0 = {}$ with \
             direction $D = {}$. How many cells does the walk visit before \
             the ray leaves the grid?",
            vector(lattice.bounds.min),
            vector(lattice.bounds.max),
            vector(ray.origin),
            vector(ray.direction)
        ),
        figure: Some("dda-setup.svg"),
        options: &COUNTS,
        answer,
        worked: format!(
            "Each wall the ray crosses inside the grid takes it into one more \
             cell. It leaves at $t = {}$, at $({}, {})$; before that it \
             crosses {} planes $x$ = const and {} planes $y$ = const \
             ({}), never two at the same $t$. So \
             $1 + {} + {} =$ **{count}** cells: {}.",
            num(last.t_out),
            num(ray.at(last.t_out).x),
            num(ray.at(last.t_out).y),
            steps(0),
            steps(1),
            rows.join(", "),
            steps(0),
            steps(1),
            cells.join(", ")
        ),
    }
    .into()
}
