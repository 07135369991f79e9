//! Chapter 7's questions worked on paper, with the answers the chapter's
//! code computes from the same numbers (`raystep figures` writes them to
//! the book; `raystep check ch07` judges `exercise/answers.toml`).
use ch02::edge_function;
use ch07::{
    DVec2, DepthBuffer, SHAPES, Stage, covers, perspective_depth, rasterize,
    shapes,
};
use raystep_figure::numbers::grouped;
use raystep_figure::{ChoiceQuestion, NumberQuestion, Question};

/// Every question, in the order the book asks them.
pub fn all() -> Vec<Question> {
    vec![centres_covered(), the_z_test(), what_grows()]
}

/// Question 1: the pixel centres a small triangle covers, fill rule
/// included.
fn centres_covered() -> Question {
    let corners = [
        DVec2::new(0.5, 0.5),
        DVec2::new(4.5, 0.5),
        DVec2::new(0.5, 4.5),
    ];
    let size = 6;
    let [a, b, c] = corners;
    // the top, left and slanted edges, each walked with the inside on
    // its positive side (as `covers` walks them)
    let edges = if edge_function(a, b, c) > 0.0 {
        [(a, b), (c, a), (b, c)]
    } else {
        [(b, a), (a, c), (c, b)]
    };
    let (mut inside, mut on_edge, mut on) = (0, 0, [0; 3]);
    let mut rows = Vec::new();
    for row in 0..size {
        let mut in_row = 0;
        for column in 0..size {
            let p = DVec2::new(column as f64 + 0.5, row as f64 + 0.5);
            in_row += u32::from(covers(&corners, p));
            let f = edges.map(|(from, to)| edge_function(from, to, p));
            if f.iter().all(|&f| f > 0.0) {
                inside += 1;
            } else if f.iter().all(|&f| f >= 0.0) {
                on_edge += 1;
                for (k, f) in f.iter().enumerate() {
                    on[k] += u32::from(*f == 0.0);
                }
            }
        }
        if in_row > 0 {
            rows.push(in_row);
        }
    }
    let covered: u32 = rows.iter().sum();
    let rows: Vec<String> = rows.iter().map(u32::to_string).collect();
    let point = |p: DVec2| format!("({}, {})", p.x, p.y);
    NumberQuestion {
        id: "q1",
        stars: 2,
        title: "the pixel centres a triangle covers",
        prompt: format!(
            "On a {size} × {size} pixel grid (pixel $(c, r)$ has its centre \
             at $(c + \\tfrac12, r + \\tfrac12)$, $y$ pointing down), a \
             triangle has its corners on the pixel centres $a = {}$, \
             $b = {}$ and $c = {}$. How many pixel centres does `covers` \
             give it, with the fill rule for the centres on its edges?",
            point(a),
            point(b),
            point(c)
        ),
        figure: Some("coverage.svg"),
        quantity: "centres",
        value: f64::from(covered),
        step: 0.5,
        worked: format!(
            "Each edge passes through pixel centres: the top edge $a b$ \
             ($y = {}$) through {}, the left edge $c a$ ($x = {}$) through \
             {} and the slanted edge $b c$ ($x + y = {}$) through {}, the \
             corners shared. Strictly inside lie only the {inside} centres \
             with $x, y > {}$ and $x + y < {}$; {on_edge} lie on an edge. \
             The fill rule gives the triangle the centres of its top and \
             left edges (inward normals $+y$ and $+x$), not those of the \
             slanted edge, whose inward normal points up and to the left: \
             of the {on_edge}, the {} with $x + y < {}$. So **{covered}** \
             centres, ${}$ by rows; the {} on the slanted edge belong to \
             whatever lies beyond it.",
            a.y,
            on[0],
            a.x,
            on[1],
            b.x + b.y,
            on[2],
            a.x,
            b.x + b.y,
            covered - inside,
            b.x + b.y,
            rows.join(" + "),
            on[2],
        ),
    }
    .into()
}

/// Question 2: which of two fragments the z-buffer keeps, the second at a
/// depth from perspective interpolation.
fn the_z_test() -> Question {
    let first = 1.8;
    let (lambda, z) = ([0.5, 0.25, 0.25], [1.0, 3.0, 3.0]);
    let mut buffer = DepthBuffer::new(1, 1);
    assert!(buffer.test_and_set(0, 0, first), "the buffer starts at +∞");
    let second = perspective_depth(lambda, z);
    let answer = if buffer.test_and_set(0, 0, second) {
        "A"
    } else {
        "B"
    };
    let linear: f64 = lambda.iter().zip(z).map(|(l, z)| l * z).sum();
    ChoiceQuestion {
        id: "q2",
        stars: 2,
        title: "which fragment the z-buffer keeps",
        prompt: format!(
            "Triangle B is drawn first and covers a pixel at view depth \
             $z = {first}$. Then triangle A covers the same pixel; its \
             corners lie at depths $z_a = {}$, $z_b = {}$, $z_c = {}$, and \
             the pixel's centre has the screen weights \
             $\\lambda = ({}, {}, {})$ in it. Which triangle does the pixel \
             show after the z test?",
            z[0], z[1], z[2], lambda[0], lambda[1], lambda[2]
        ),
        figure: None,
        options: &["A", "B"],
        answer,
        worked: format!(
            "Interpolate $1/z$, not $z$: $z = 1 / ({} / {} + {} / {} + {} / \
             {}) = 1 / {:.4} = {second:.2}$. That is closer than B's \
             {first}, so the z test keeps **{answer}** (and the buffer now \
             holds {second:.2}). Interpolating $z$ itself would give \
             ${} \\cdot {} + {} \\cdot {} + {} \\cdot {} = {linear:.1}$, \
             behind B: the wrong triangle.",
            lambda[0],
            z[0],
            lambda[1],
            z[1],
            lambda[2],
            z[2],
            1.0 / second,
            lambda[0],
            z[0],
            lambda[1],
            z[1],
            lambda[2],
            z[2],
        ),
    }
    .into()
}

/// Question 3: whose work grows with the number of triangles, for a
/// fixed image.
fn what_grows() -> Question {
    let (width, height) = (160, 90);
    let pixels = u64::from(width) * u64::from(height);
    let (small, large) = (shapes(2, width, height), shapes(3, width, height));
    // The ray caster's loop: every ray tests every polygon.
    let ray_tests = |stage: &Stage| pixels * stage.world.objects.len() as u64;
    let (ray_small, ray_large) = (ray_tests(&small), ray_tests(&large));
    let (raster_small, raster_large) =
        (rasterize(&small).1.tested, rasterize(&large).1.tested);
    let alone = raystep_scene::parse(SHAPES, "shapes.toml")
        .expect("the chapter's scene parses")
        .objects
        .len();
    let ball_small = small.world.objects.len() - alone;
    let ball_large = large.world.objects.len() - alone;
    assert_eq!(ball_large, 4 * ball_small, "the ball's triangles, × 4");
    let growth = |from: u64, to: u64| to as f64 / from as f64;
    let (ray_growth, raster_growth) = (
        growth(ray_small, ray_large),
        growth(raster_small, raster_large),
    );
    assert!(
        ray_growth > 2.0 && raster_growth < 1.5,
        "the ray caster's work grows, the rasterizer's hardly"
    );
    NumberQuestion {
        id: "q3",
        stars: 1,
        title: "how the ray caster's work grows with the triangles",
        prompt: format!(
            "The shapes scene at {width} × {height}: its ball goes from \
             {ball_small} triangles to {ball_large}, covering about the same \
             pixels as before, beside the scene's other {alone} polygons. By \
             what factor does the ray caster's count of ray–polygon tests \
             grow? (Then think about the rasterizer's pixel tests.)"
        ),
        figure: None,
        quantity: "the factor",
        value: ray_growth,
        step: 0.02,
        worked: format!(
            "The ray caster tests every polygon with each of its {} rays: \
             {} × {} = {} tests before, {} × {} = {} after, \
             **{ray_growth:.2}** times as many. The rasterizer tests the \
             pixel centres in each triangle's box, and the smaller triangles \
             have smaller boxes that cover the same pixels between them: {} \
             tests before, {} after, {raster_growth:.2} times as many.",
            grouped(pixels),
            grouped(pixels),
            small.world.objects.len(),
            grouped(ray_small),
            grouped(pixels),
            grouped(large.world.objects.len() as u64),
            grouped(ray_large),
            grouped(raster_small),
            grouped(raster_large),
        ),
    }
    .into()
}
