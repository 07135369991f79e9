//! Chapter 4's questions worked on paper, with the answers the chapter's
//! code computes from the same numbers (`raystep figures` writes them to
//! the book; `raystep check ch04` judges `exercise/answers.toml`).
use ch03::Sphere;
use ch04::{
    DVec3, Hit, INT_SCALE, Interval, Offset, Ray, World, offset_scale_aware,
    shadow,
};
use raystep_figure::numbers::{trimmed, triple};
use raystep_figure::{ChoiceQuestion, NumberQuestion, Question};

/// Every question, in the order the book asks them.
pub fn all() -> Vec<Question> {
    vec![
        behind_the_ball(),
        under_a_thin_sheet(),
        ulps_along_the_normal(),
    ]
}

/// A number as the worked answers write it: at most 4 decimals.
fn num(x: f64) -> String {
    trimmed(x, 4)
}

/// `m \cdot 10^{e}` with three significant digits (`10^{e}` for m = 1).
fn sci(x: f64) -> String {
    let e = x.abs().log10().floor() as i32;
    let m = num((x / 10f64.powi(e) * 100.0).round() / 100.0);
    if m == "1" {
        format!("10^{{{e}}}")
    } else {
        format!("{m} \\cdot 10^{{{e}}}")
    }
}

/// `(x, y, z)`, as [`num`] writes each.
fn point(v: DVec3) -> String {
    triple(v, 4)
}

/// `[x, y, z]`, for a scene file.
fn toml(v: DVec3) -> String {
    format!("[{}, {}, {}]", v.x, v.y, v.z)
}

/// A scene of one point light, the floor `y = 0` and one more `object`
/// (a line of a scene file), with nothing else to hit.
fn world(light: DVec3, object: &str) -> World {
    let text = format!(
        "[camera]\nlook_from = [0, 2, 8]\nlook_at = [0, 1, 0]\n\n\
         [[lights]]\nposition = {}\n\n\
         [[objects]]\nplane = {{ point = [0, 0, 0], normal = [0, 1, 0] }}\n\n\
         [[objects]]\n{object}\n",
        toml(light)
    );
    ch03::parse(&text, "question.toml").expect("the question's scene builds")
}

/// `"lit"` for S = 1, `"in shadow"` for S = 0.
fn verdict(s: f64) -> &'static str {
    if s == 1.0 { "lit" } else { "in shadow" }
}

/// Question 1: S for a floor point whose shadow ray passes the ball.
fn behind_the_ball() -> Question {
    let ball = Sphere::new(DVec3::new(1.0, 2.0, 0.0), 0.5);
    let light = DVec3::new(3.0, 4.0, 0.0);
    let p = DVec3::new(-0.5, 0.0, 0.0);
    let normal = DVec3::Y;
    let world = world(
        light,
        &format!(
            "sphere = {{ center = {}, radius = {} }}",
            toml(ball.center),
            ball.radius
        ),
    );
    let hit = Hit {
        t: 1.0,
        point: p,
        normal,
    };
    let s = shadow(&world, &hit, normal, &world.lights[0], Offset::ScaleAware);
    let answer = verdict(s);
    // The shadow ray from P itself (t = 1 at the light) against the ball,
    // as the worked answer solves it.
    let d = light - p;
    let f = p - ball.center;
    let (a, b) = (d.dot(d), -f.dot(d));
    let c = f.dot(f) - ball.radius * ball.radius;
    let delta = b * b - a * c;
    let (near, far) = ((b - delta.sqrt()) / a, (b + delta.sqrt()) / a);
    let blocker = ball.intersect(&Ray::new(p, d), Interval::new(0.0, 1.0));
    assert_eq!(
        blocker.is_some(),
        s == 0.0,
        "the ball alone decides question 1"
    );
    ChoiceQuestion {
        id: "q1",
        stars: 2,
        title: "whether a point is in shadow",
        prompt: format!(
            "A side view like the figure's: the floor $y = 0$, a ball with centre $C = {}$ \
             and radius $r = {}$ above it, and a point light at \
             $L_{{\\text{{pos}}}} = {}$. Is the floor point $P = {}$, with \
             $N = {}$, lit by the light ($S = 1$) or in shadow ($S = 0$)?",
            point(ball.center),
            num(ball.radius),
            point(light),
            point(p),
            point(normal)
        ),
        figure: Some("shadow-rays.svg"),
        options: &["lit", "in shadow"],
        answer,
        worked: format!(
            "$N \\cdot (L_{{\\text{{pos}}}} - P) = {} > 0$: the light is in \
             front of the floor, so a shadow ray is needed. It runs along \
             $D = L_{{\\text{{pos}}}} - P = {}$, the light at $t = 1$. \
             Against the ball, as in chapter 3: $f = P - C = {}$, \
             $a = D \\cdot D = {}$, $b = -f \\cdot D = {}$, \
             $c = f \\cdot f - r^2 = {}$, and $\\Delta = b^2 - a c = {}$, \
             positive: the ray's line meets the ball, at \
             $t = (b \\pm \\sqrt{{\\Delta}})/a = {}$ and {}. Both lie between \
             0 and 1, between $P$ and the light, so the ball blocks it: \
             $S = {}$, **{answer}**.",
            num(normal.dot(d)),
            point(d),
            point(f),
            num(a),
            num(b),
            num(c),
            num(delta),
            num(near),
            num(far),
            num(s),
        ),
    }
    .into()
}

/// Question 2: a fixed t_min and a blocker closer than it.
fn under_a_thin_sheet() -> Question {
    let epsilon = 1e-4;
    let height = 5e-5;
    let light = DVec3::new(3.0, 4.0, 0.0);
    let p = DVec3::ZERO;
    let normal = DVec3::Y;
    let world = world(
        light,
        &format!("plane = {{ point = [0, {height}, 0], normal = [0, 1, 0] }}"),
    );
    let hit = Hit {
        t: 1.0,
        point: p,
        normal,
    };
    let s = shadow(
        &world,
        &hit,
        normal,
        &world.lights[0],
        Offset::TMin(epsilon),
    );
    let answer = verdict(s);
    let unit = (light - p).normalize();
    let t_sheet = height / normal.dot(unit);
    let truth =
        shadow(&world, &hit, normal, &world.lights[0], Offset::ScaleAware);
    ChoiceQuestion {
        id: "q2",
        stars: 1,
        title: "a fixed minimum t and a thin blocker",
        prompt: format!(
            "A floor point $P = {}$ with $N = {}$, a point light at \
             $L_{{\\text{{pos}}}} = {}$, and \
             a thin sheet lying on the floor: the plane $y = {}$. The shadow \
             ray is strategy 1's, a fixed $t_{{\\min}} = \\varepsilon = {}$ \
             along the unit direction to the light. Does it find $P$ lit or \
             in shadow?",
            point(p),
            point(normal),
            point(light),
            sci(height),
            sci(epsilon),
        ),
        figure: Some("offsets.svg"),
        options: &["lit", "in shadow"],
        answer,
        worked: format!(
            "The unit direction to the light is $D = {}$, and $N \\cdot D = \
             {}$. The floor is met at $t = 0$ and the sheet at \
             $t = {} / {} = {}$: both below $\\varepsilon = {}$, so both \
             are ignored, and nothing else is in the way: **{answer}** \
             ($S = {}$). The sheet really is between $P$ and the light \
             (the scale-aware offset finds it: $S = {}$), so this is a \
             leak, the failure of a fixed $t_{{\\min}}$ in a small scene.",
            point(unit),
            num(normal.dot(unit)),
            sci(height),
            num(normal.dot(unit)),
            sci(t_sheet),
            sci(epsilon),
            num(s),
            num(truth),
        ),
    }
    .into()
}

/// Question 3: how far the scale-aware offset moves one coordinate.
fn ulps_along_the_normal() -> Question {
    let p = DVec3::new(1.5, 3.0, -2.5);
    let normal = DVec3::new(0.0, 0.6, 0.8);
    let moved = offset_scale_aware(p, normal);
    let dy = moved.y - p.y;
    let unit = 1e-14;
    let ulp = f64::from_bits(p.y.to_bits() + 1) - p.y;
    let exponent = p.y.abs().log2().floor() as i32;
    let count = (INT_SCALE * normal.y) as i64;
    NumberQuestion {
        id: "q3",
        stars: 2,
        title: "how far the scale-aware offset moves a point",
        prompt: format!(
            "The scale-aware offset moves the hit point $P = {}$ with normal \
             $N = {}$. How far does its $y$ coordinate move? Give $\\Delta y$ \
             in units of $10^{{-14}}$ (write 1.5 for \
             $1.5 \\cdot 10^{{-14}}$).",
            point(p),
            point(normal)
        ),
        figure: Some("offsets.svg"),
        quantity: "Δy in units of 10⁻¹⁴",
        value: dy / unit,
        step: 0.01,
        worked: format!(
            "$\\lvert y \\rvert = {}$ is not below $1/32$, so $y$ moves by \
             whole ulps of itself. It lies in $[2^{{{exponent}}}, \
             2^{{{}}})$, where an `f64` ulp is \
             $2^{{{exponent}}} \\cdot 2^{{-52}} = 2^{{{}}} \\approx {}$. \
             The count is $256 \\, n_y = {}$, truncated to {count} ulps, \
             toward $+y$ since $n_y > 0$. So \
             $\\Delta y = {count} \\cdot {} \\approx {}$: **{}**.",
            num(p.y.abs()),
            exponent + 1,
            exponent - 52,
            sci(ulp),
            num(INT_SCALE * normal.y),
            sci(ulp),
            sci(dy),
            num((dy / unit * 100.0).round() / 100.0),
        ),
    }
    .into()
}
