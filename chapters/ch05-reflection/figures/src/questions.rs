//! Chapter 5's questions worked on paper, with the answers the chapter's
//! code computes from the same numbers (`raystep figures` writes them to
//! the book; `raystep check ch05` judges `exercise/answers.toml`).
use ch05::{DEFAULT_STOP, Path, Stop, pixel_tree, reflect_ray, trace_counted};
use raystep_core::DVec3;
use raystep_figure::{NumberQuestion, Question};

use crate::measurements::{REFERENCE, chart_world};

/// Every question, in the order the book asks them.
pub fn all() -> Vec<Question> {
    vec![
        reflected_direction(),
        bounces_before_the_cut(),
        rays_of_a_chain(),
    ]
}

/// Question 1: a component of R = D − 2(D·N)N on a tilted mirror.
fn reflected_direction() -> Question {
    let (d, n) = (DVec3::new(1.0, -2.0, 0.0), DVec3::new(0.6, 0.8, 0.0));
    let r = reflect_ray(d, n);
    let dn = d.dot(n);
    let vector = |v: DVec3| format!("({}, {}, {})", v.x, v.y, v.z);
    NumberQuestion {
        id: "q1",
        stars: 1,
        title: "the reflected direction on a tilted mirror",
        prompt: format!(
            "A ray with direction $D = {}$ meets a tilted mirror whose unit \
             normal is $N = {}$. What is the $y$ component of the reflected \
             direction $R = D - 2 (D \\cdot N) N$? Mind the sign.",
            vector(d),
            vector(n)
        ),
        figure: Some("reflection.svg"),
        quantity: "R_y",
        value: r.y,
        step: 0.005,
        worked: format!(
            "$D \\cdot N = {} \\cdot {} + ({}) \\cdot {} = {dn:.1}$, so \
             $R = D - 2 \\cdot ({dn:.1}) N = D + {:.1} N = ({:.1}, {:.1}, \
             {})$ and $R_y =$ **{:.1}**. The reflected ray still runs \
             downwards in $y$, yet it leaves the mirror: \
             $R \\cdot N = {:.1} = -D \\cdot N$. $R$ keeps the length of \
             $D$, $\\sqrt{{{}}}$, since $D$ was not a unit vector.",
            d.x,
            n.x,
            d.y,
            n.y,
            -2.0 * dn,
            r.x,
            r.y,
            r.z,
            r.y,
            r.dot(n),
            d.length_squared()
        ),
    }
    .into()
}

/// Question 2: how many bounces the contribution rule lets through
/// between two grey mirrors.
fn bounces_before_the_cut() -> Question {
    let kr = 0.6;
    let stop = DEFAULT_STOP;
    // The chain of reflected rays between the two mirrors, each one
    // weighing kr more, until the rule cuts one.
    let mut path = Path::PRIMARY;
    let mut shot = 0;
    loop {
        let next = path.then(DVec3::splat(kr));
        if stop.cut(next).is_some() {
            break;
        }
        shot += 1;
        path = next;
    }
    let cut = path.then(DVec3::splat(kr));
    let exact = stop.min_contribution.ln() / f64::ln(kr);
    NumberQuestion {
        id: "q2",
        stars: 2,
        title: "bounces before the contribution rule cuts",
        prompt: format!(
            "Two grey mirrors face each other, both with $k_r = {kr}$, and \
             a ray bounces between them forever. The tracer stops by rule 2 \
             at {} (`DEFAULT_STOP`). How many reflected rays does it shoot \
             for this ray?",
            stop.min_contribution
        ),
        figure: None,
        quantity: "reflected rays",
        value: f64::from(shot),
        step: 0.5,
        worked: format!(
            "The reflected ray at depth $k$ weighs $k_r^k = {kr}^k$. \
             ${kr}^{{{}}} \\approx {:.5}$ is still at least {}, but \
             ${kr}^{{{}}} \\approx {:.6}$ is below it (by logarithms: \
             $k = \\ln {} / \\ln {kr} \\approx {exact:.1}$), so rule 2 cuts \
             the ray at depth {} and the tracer shoots the {shot} rays at \
             depths 1 to {shot}: **{shot}**.",
            path.depth,
            path.contribution(),
            stop.min_contribution,
            cut.depth,
            cut.contribution(),
            stop.min_contribution,
            cut.depth,
        ),
    }
    .into()
}

/// Question 3: every ray of the figure's pixel under a depth limit.
fn rays_of_a_chain() -> Question {
    let world = chart_world("facing-mirrors");
    let (column, row) = (0, 35);
    let longest = pixel_tree(&world, column, row, &REFERENCE)
        .iter()
        .map(|r| r.path.depth)
        .max()
        .unwrap_or(0);
    let max_depth = 5;
    let stop = Stop::depth(max_depth);
    let ray = world
        .camera
        .pixel_ray(column, row, world.width, world.height);
    let (_, counts) = trace_counted(&world, &ray, &stop);
    assert!(
        longest > max_depth
            && counts.shadow == counts.primary + counts.secondary
            && counts.cut_by_depth == 1,
        "the question says: the chain goes deeper than the limit, and every \
         hit sends one shadow ray"
    );
    let hits = counts.primary + counts.secondary;
    // the figure's top panel: the same chain under Stop::depth(2)
    let (_, two) = trace_counted(&world, &ray, &Stop::depth(2));
    NumberQuestion {
        id: "q3",
        stars: 2,
        title: "the rays of one pixel under a depth limit",
        prompt: format!(
            "Take the figure's pixel ({column}, {row}) of the facing \
             mirrors: its ray bounces between the two mirror walls, {longest} \
             times when no rule cuts it, and every hit on a wall sends one \
             shadow ray to the scene's one light. Under `Stop::depth({})` \
             (rule 1 alone), how many rays does the pixel's trace shoot in \
             all, primary, reflected and shadow rays counted?",
            max_depth
        ),
        figure: Some("ray-tree.svg"),
        quantity: "rays",
        value: counts.total() as f64,
        step: 0.5,
        worked: format!(
            "Rule 1 lets rays down to depth {max_depth} be shot: the primary \
             ray (depth 0) and {} reflected rays (depths 1 to {max_depth}); \
             the ray at depth {} is cut. Each of these {hits} rays hits a \
             wall and sends one shadow ray: {} shadow rays. In all \
             $1 + {} + {} =$ **{}** rays. (The top of the figure shows the \
             same chain under `Stop::depth(2)`: $1 + {} + {} = {}$ rays.)",
            counts.secondary,
            max_depth + 1,
            counts.shadow,
            counts.secondary,
            counts.shadow,
            counts.total(),
            two.secondary,
            two.shadow,
            two.total()
        ),
    }
    .into()
}
