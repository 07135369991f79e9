//! Chapter 1's questions worked on paper, with the answers the chapter's
//! code computes from the same numbers (`raystep figures` writes them to
//! the book; `raystep check ch01` judges `exercise/answers.toml`).
use ch01::{Line2, Plane};
use raystep_core::{DVec2, DVec3};
use raystep_figure::{ChoiceQuestion, NumberQuestion, Question};

/// Every question, in the order the book asks them.
pub fn all() -> Vec<Question> {
    vec![side_of_the_line(), distance_of_the_origin()]
}

/// Question 1: the side of the figure's line a point is on.
fn side_of_the_line() -> Question {
    let (p0, p1) = (DVec2::new(1.0, 1.0), DVec2::new(3.0, 2.5));
    // Off the figure (which would show the side), close to the line.
    let s = DVec2::new(9.0, 6.9);
    let line = Line2::through(p0, p1).expect("two distinct points");
    let f = line.eval(s);
    let answer = if f > 0.0 {
        "positive"
    } else if f < 0.0 {
        "negative"
    } else {
        "zero"
    };
    ChoiceQuestion {
        id: "q1",
        stars: 1,
        title: "the side of a line a point is on",
        prompt: format!(
            "Take the figure's line through $P_0 = ({}, {})$ and \
             $P_1 = ({}, {})$. Without drawing, is $f(S)$ for \
             $S = ({}, {})$ positive (the side $N$ points to), negative, \
             or zero (on the line)?",
            p0.x, p0.y, p1.x, p1.y, s.x, s.y
        ),
        figure: Some("line-sign.svg"),
        options: &["positive", "negative", "zero"],
        answer,
        worked: format!(
            "$f(x, y) = -0.6 x + 0.8 y - 0.2$ (worked above), so \
             $f(S) = -0.6 \\cdot {} + 0.8 \\cdot {} - 0.2 = {:.2}$: \
             **{answer}**. $S$ is {:.2} units from the line, on the side \
             $N$ points away from (right of $V$); the point $(9, 7)$ is on \
             the line.",
            s.x,
            s.y,
            f,
            f.abs()
        ),
    }
    .into()
}

/// Question 2: the signed distance of the origin from a plane.
fn distance_of_the_origin() -> Question {
    let p = [
        DVec3::new(1.0, 0.0, 0.0),
        DVec3::new(0.0, 2.0, 0.0),
        DVec3::new(0.0, 0.0, 2.0),
    ];
    let plane = Plane::through(p[0], p[1], p[2]).expect("not collinear");
    let f = plane.eval(DVec3::ZERO);
    let point = |v: DVec3| format!("({}, {}, {})", v.x, v.y, v.z);
    NumberQuestion {
        id: "q2",
        stars: 2,
        title: "the signed distance of a point from a plane",
        prompt: format!(
            "The plane through $P_0 = {}$, $P_1 = {}$, $P_2 = {}$ (in that \
             order): what is $f(O)$, the signed distance of the origin \
             $O$ from it? Mind the sign.",
            point(p[0]),
            point(p[1]),
            point(p[2])
        ),
        figure: Some("plane.svg"),
        quantity: "f(O)",
        value: f,
        step: 0.01,
        worked: format!(
            "$E_1 = (-1, 2, 0)$, $E_2 = (-1, 0, 2)$, \
             $E_1 \\times E_2 = (4, 2, 2)$ of length $\\sqrt{{24}} \\approx \
             4.899$, so $N \\approx (0.816, 0.408, 0.408)$ and \
             $d = -N \\cdot P_0 \\approx -0.816$. At the origin \
             $f(O) = N \\cdot O + d = d \\approx$ **{f:.2}**: the origin \
             lies on the side $N$ points away from, {:.2} units from the \
             plane.",
            f.abs()
        ),
    }
    .into()
}
