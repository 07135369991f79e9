//! Chapter 2's questions worked on paper, with the answers the chapter's
//! code computes from the same numbers (`raystep figures` writes them to
//! the book; `raystep check ch02` judges `exercise/answers.toml`).
use ch01::rotate90;
use ch02::{
    DVec2, DVec3, Interval, Plane, Ray, RayPlane, edge_function, inside_convex,
    ray_plane,
};
use raystep_figure::numbers::{trimmed, triple};
use raystep_figure::{ChoiceQuestion, NumberQuestion, Question};

/// Every question, in the order the book asks them.
pub fn all() -> Vec<Question> {
    vec![
        t_of_a_plane_hit(),
        a_ray_along_the_plane(),
        inside_the_house(),
    ]
}

/// The plane of questions 1 and 2: $0.6 y + 0.8 z = 4$.
fn tilted_plane() -> Plane {
    Plane {
        normal: DVec3::new(0.0, 0.6, 0.8),
        d: -4.0,
    }
}

/// A number as the worked answers write it: at most 4 decimals.
fn num(x: f64) -> String {
    trimmed(x, 4)
}

/// A number as a factor: in parentheses if negative.
fn factor(x: f64) -> String {
    if x < 0.0 {
        format!("({})", num(x))
    } else {
        num(x)
    }
}

/// ` + x` or ` - |x|`: a number added to a sum.
fn plus(x: f64) -> String {
    if x < 0.0 {
        format!(" - {}", num(-x))
    } else {
        format!(" + {}", num(x))
    }
}

/// `(x, y, z)`, as [`num`] writes each.
fn point(v: DVec3) -> String {
    triple(v, 4)
}

/// `a \cdot x + b \cdot y + …`: the products of `n · v`, a zero component
/// of `n` left out.
fn dot_terms(n: DVec3, v: DVec3) -> String {
    let terms: Vec<String> = n
        .to_array()
        .into_iter()
        .zip(v.to_array())
        .filter(|(a, _)| *a != 0.0)
        .map(|(a, b)| format!("{} \\cdot {}", factor(a), factor(b)))
        .collect();
    terms.join(" + ")
}

/// `N = (…)`, `d = …` of a plane, for a prompt.
fn plane_text(plane: &Plane) -> String {
    format!(
        "$N \\cdot P + d = 0$ with $N = {}$ and $d = {}$",
        point(plane.normal),
        num(plane.d)
    )
}

/// Question 1: t of a ray and a tilted plane, by the formula.
fn t_of_a_plane_hit() -> Question {
    let plane = tilted_plane();
    let ray = Ray::new(DVec3::new(1.0, 2.0, -1.0), DVec3::new(1.0, 0.0, 2.0));
    let RayPlane::Hit(t) = ray_plane(&plane, &ray, Interval::FORWARD) else {
        panic!("the ray of question 1 hits its plane in front");
    };
    let distance = plane.eval(ray.origin);
    let approach = plane.normal.dot(ray.direction);
    let hit = ray.at(t);
    NumberQuestion {
        id: "q1",
        stars: 1,
        title: "t where a ray meets a plane",
        prompt: format!(
            "The plane {}, and the ray from $P_0 = {}$ along $D = {}$ (not a \
             unit vector). At what $t$ does the ray meet the plane?",
            plane_text(&plane),
            point(ray.origin),
            point(ray.direction)
        ),
        figure: Some("ray-plane.svg"),
        quantity: "t",
        value: t,
        step: 0.02,
        worked: format!(
            "The distance of the origin: $N \\cdot P_0 + d = {}{} = {}$. \
             The rate: $N \\cdot D = {} = {}$. So \
             $t = -(N \\cdot P_0 + d) / (N \\cdot D) = -({}) / {} =$ \
             **{}**, in front of the origin. Check: $P(t) = P_0 + tD = {}$, \
             and $N \\cdot P(t) = {} = {}$, which is $-d$: the point is on \
             the plane. ($D$ has length {:.2}, so the hit is {:.2} units \
             from $P_0$, not $t$.)",
            dot_terms(plane.normal, ray.origin),
            plus(plane.d),
            num(distance),
            dot_terms(plane.normal, ray.direction),
            num(approach),
            num(distance),
            num(approach),
            num(t),
            point(hit),
            dot_terms(plane.normal, hit),
            num(plane.normal.dot(hit)),
            ray.direction.length(),
            t * ray.direction.length(),
        ),
    }
    .into()
}

/// Question 2: a ray whose direction is perpendicular to the plane's
/// normal, off the plane.
fn a_ray_along_the_plane() -> Question {
    let plane = tilted_plane();
    let ray = Ray::new(DVec3::new(1.0, 2.0, -1.0), DVec3::new(0.0, 4.0, -3.0));
    let case = ray_plane(&plane, &ray, Interval::FORWARD);
    let answer = match case {
        RayPlane::Hit(_) => "hit",
        RayPlane::Outside(_) => "outside",
        RayPlane::Parallel => "parallel",
        RayPlane::InPlane => "in plane",
    };
    let distance = plane.eval(ray.origin);
    ChoiceQuestion {
        id: "q2",
        stars: 1,
        title: "the case of a ray and a plane",
        prompt: format!(
            "The same plane, {}, and the ray from $P_0 = {}$ along \
             $D = {}$, with the interval $[0, \\infty]$. Which of \
             `ray_plane`'s four cases is it: a hit, outside the interval, \
             parallel, or in the plane?",
            plane_text(&plane),
            point(ray.origin),
            point(ray.direction)
        ),
        figure: Some("parallel-and-behind.svg"),
        options: &["hit", "outside", "parallel", "in plane"],
        answer,
        worked: format!(
            "The rate first: $N \\cdot D = {} = {}$, so the ray runs \
             parallel to the plane, and the formula for $t$ would divide by \
             0. Parallel or in the plane? The origin decides: \
             $N \\cdot P_0 + d = {}{} = {}$, not 0, so the ray stays {} \
             units from the plane and never meets it: **{answer}**.",
            dot_terms(plane.normal, ray.direction),
            num(plane.normal.dot(ray.direction)),
            dot_terms(plane.normal, ray.origin),
            plus(plane.d),
            num(distance),
            num(distance.abs()),
        ),
    }
    .into()
}

/// The convex house of the figure `inside-test.svg`, counter-clockwise.
const HOUSE: [DVec2; 5] = [
    DVec2::new(0.0, 0.0),
    DVec2::new(4.0, 0.0),
    DVec2::new(4.0, 3.0),
    DVec2::new(2.0, 5.0),
    DVec2::new(0.0, 3.0),
];

/// Question 3: the edge test at a point just beyond the house's roof.
fn inside_the_house() -> Question {
    let p = DVec2::new(3.5, 3.9);
    let inside = inside_convex(&HOUSE, p);
    let answer = if inside { "inside" } else { "outside" };
    let n = HOUSE.len();
    let values: Vec<String> = (0..n)
        .map(|i| {
            let (a, b) = (HOUSE[i], HOUSE[(i + 1) % n]);
            format!("$f_{} = {}$", i + 1, num(edge_function(a, b, p)))
        })
        .collect();
    let negative: Vec<usize> = (0..n)
        .filter(|&i| edge_function(HOUSE[i], HOUSE[(i + 1) % n], p) < 0.0)
        .collect();
    let [k] = negative[..] else {
        panic!("question 3's point is outside exactly one edge");
    };
    let (a, b) = (HOUSE[k], HOUSE[(k + 1) % n]);
    let v = b - a;
    let normal = rotate90(v);
    let pa = p - a;
    let vertices: Vec<String> = HOUSE
        .iter()
        .map(|v| format!("({}, {})", num(v.x), num(v.y)))
        .collect();
    ChoiceQuestion {
        id: "q3",
        stars: 2,
        title: "whether a point is inside a convex polygon",
        prompt: format!(
            "The figure's house, counter-clockwise: ${}$. Is the point \
             $P = ({}, {})$ inside or outside it? Decide with the edge test, \
             not by eye.",
            vertices.join(", "),
            num(p.x),
            num(p.y)
        ),
        figure: Some("inside-test.svg"),
        options: &["inside", "outside"],
        answer,
        worked: format!(
            "For each edge $a \\to b$, $N = R\\,(b - a)$ and \
             $f = N \\cdot (P - a)$. Edge {} runs from $({}, {})$ to \
             $({}, {})$: $N = R\\,({}, {}) = ({}, {})$ and \
             $P - a = ({}, {})$, so $f_{} = {} \\cdot {} + {} \\cdot {} = \
             {}$. All five: {}. One is negative, so $P$ is on the outer \
             side of edge {}: **{answer}**.",
            k + 1,
            num(a.x),
            num(a.y),
            num(b.x),
            num(b.y),
            num(v.x),
            num(v.y),
            num(normal.x),
            num(normal.y),
            num(pa.x),
            num(pa.y),
            k + 1,
            factor(normal.x),
            factor(pa.x),
            factor(normal.y),
            factor(pa.y),
            num(normal.dot(pa)),
            values.join(", "),
            k + 1,
        ),
    }
    .into()
}
