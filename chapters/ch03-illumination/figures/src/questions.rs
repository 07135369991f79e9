//! Chapter 3's questions worked on paper, with the answers the chapter's
//! code computes from the same numbers (`raystep figures` writes them to
//! the book; `raystep check ch03` judges `exercise/answers.toml`).
use ch03::{
    DVec3, Interval, LightSample, Material, Ray, Sphere, reflect_light,
    shading_terms,
};
use raystep_figure::numbers::{trimmed, triple};
use raystep_figure::{NumberQuestion, Question};

/// Every question, in the order the book asks them.
pub fn all() -> Vec<Question> {
    vec![
        t_of_a_sphere_hit(),
        the_specular_factor(),
        the_local_model(),
    ]
}

/// A number as the worked answers write it: at most 4 decimals.
fn num(x: f64) -> String {
    trimmed(x, 4)
}

/// `(x, y, z)`, as [`num`] writes each.
fn point(v: DVec3) -> String {
    triple(v, 4)
}

/// Question 1: the nearer root of a ray and a sphere off its axis.
fn t_of_a_sphere_hit() -> Question {
    let sphere = Sphere::new(DVec3::new(1.0, 0.0, -6.0), 2.0);
    let ray = Ray::new(DVec3::ZERO, DVec3::new(0.0, 0.0, -1.0));
    let hit = sphere
        .intersect(&ray, Interval::FORWARD)
        .expect("the ray of question 1 hits its sphere");
    // The quantities of the lecture's steps, for the worked answer.
    let f = ray.origin - sphere.center;
    let d = ray.direction;
    let (a, b) = (d.dot(d), -f.dot(d));
    let c = f.dot(f) - sphere.radius * sphere.radius;
    // The textbook roots (the code computes them in a rounding-safe
    // order, the exercise; by hand the textbook form is enough).
    let delta = b * b - a * c;
    let (near, far) = ((b - delta.sqrt()) / a, (b + delta.sqrt()) / a);
    assert!(near > 0.0 && far > near, "both roots in front");
    NumberQuestion {
        id: "q1",
        stars: 2,
        title: "t where a ray meets a sphere",
        prompt: format!(
            "The ray from $P_0 = {}$ along $D = {}$ and the sphere with \
             centre $C = {}$ and radius $r = {}$. At what $t$ does the ray \
             first meet the sphere?",
            point(ray.origin),
            point(d),
            point(sphere.center),
            num(sphere.radius)
        ),
        figure: None,
        quantity: "t",
        value: hit.t,
        step: 0.05,
        worked: format!(
            "$f = P_0 - C = {}$, so $a = D \\cdot D = {}$, \
             $b = -f \\cdot D = {}$ and $c = f \\cdot f - r^2 = {}$. \
             The discriminant: $\\Delta = b^2 - a c = {}$ $> 0$, so the \
             line meets the sphere twice, at $t = (b \\mp \\sqrt{{\\Delta}})/a$ \
             $= {}$ and ${}$. Both are in front of $P_0$; the nearer one is \
             the first hit: $t \\approx$ **{:.2}**. The hit point is \
             $P_0 + tD \\approx {}$.",
            point(f),
            num(a),
            num(b),
            num(c),
            num(delta),
            num(near),
            num(far),
            hit.t,
            point(hit.point),
        ),
    }
    .into()
}

/// Question 2: Rᵢ and the highlight's factor (Rᵢ·V)^p.
fn the_specular_factor() -> Question {
    let n = DVec3::new(0.0, 1.0, 0.0);
    let l = DVec3::new(0.6, 0.8, 0.0);
    let v = DVec3::new(-0.8, 0.6, 0.0);
    let p: f64 = 8.0;
    let r = reflect_light(l, n);
    let r_dot_v = r.dot(v);
    let value = r_dot_v.max(0.0).powf(p);
    // p = 2^k: the power by k squarings, as by hand.
    let k = p.log2() as usize;
    assert_eq!(2f64.powi(k as i32), p, "p is a power of two");
    let squares: Vec<String> =
        std::iter::successors(Some(r_dot_v), |x| Some(x * x))
            .take(k + 1)
            .map(num)
            .collect();
    NumberQuestion {
        id: "q2",
        stars: 1,
        title: "the mirror direction and the highlight",
        prompt: format!(
            "At a surface point with normal $N = {}$, the light lies in the \
             direction $L = {}$ and the eye in the direction $V = {}$ (unit \
             vectors, as in the figure). Compute $R = 2 (N \\cdot L) N - L$, \
             then the specular factor $(R \\cdot V)^p$ for $p = {}$.",
            point(n),
            point(l),
            point(v),
            num(p)
        ),
        figure: Some("vectors.svg"),
        quantity: "(R·V)^p",
        value,
        step: 0.01,
        worked: format!(
            "$N \\cdot L = {}$, so $R = 2 \\cdot {} \\, N - L = {}$: the \
             light's direction mirrored about $N$. Then $R \\cdot V = {}$ \
             ($\\cos\\alpha$, positive: no clamp), and $p = {}$ is {} \
             squarings: ${}$, so $(R \\cdot V)^{{{}}} \\approx$ **{:.2}**.",
            num(n.dot(l)),
            num(n.dot(l)),
            point(r),
            num(r_dot_v),
            num(p),
            k,
            squares.join(" \\to "),
            num(p),
            value,
        ),
    }
    .into()
}

/// Question 3: the local model with two lights, one of them behind the
/// surface.
fn the_local_model() -> Question {
    let n = DVec3::new(0.0, 0.0, 1.0);
    let l = DVec3::new(0.0, 0.6, 0.8);
    let v = DVec3::new(0.0, -0.28, 0.96);
    let behind = DVec3::new(0.6, 0.0, -0.8);
    let material = Material {
        ka: DVec3::splat(0.2),
        kd: DVec3::splat(0.6),
        ks: DVec3::splat(0.4),
        p: 4.0,
        ..Material::default()
    };
    let ambient = DVec3::splat(0.5);
    let lights = [
        LightSample {
            direction: l,
            intensity: DVec3::splat(1.0),
            visibility: 1.0,
        },
        LightSample {
            direction: behind,
            intensity: DVec3::splat(0.5),
            visibility: 1.0,
        },
    ];
    let terms = shading_terms(&material, n, v, ambient, &lights);
    let value = terms.sum().x;
    let r = reflect_light(l, n);
    NumberQuestion {
        id: "q3",
        stars: 3,
        title: "the local model at one point",
        prompt: format!(
            "A grey material with $k_a = {}$, $k_d = {}$, $k_s = {}$ and \
             $p = {}$, under the ambient light $I_a = {}$. At a point with \
             normal $N = {}$ seen from the direction $V = {}$, two lights: \
             light 1 of intensity $I_1 = {}$ in the direction $L_1 = {}$, \
             and light 2 of intensity $I_2 = {}$ in the direction \
             $L_2 = {}$. Every light is seen ($S_i = 1$). What is $L$ (one \
             channel: all three are the same)?",
            num(material.ka.x),
            num(material.kd.x),
            num(material.ks.x),
            num(material.p),
            num(ambient.x),
            point(n),
            point(v),
            num(lights[0].intensity.x),
            point(l),
            num(lights[1].intensity.x),
            point(behind),
        ),
        figure: Some("vectors.svg"),
        quantity: "L",
        value,
        step: 0.01,
        worked: format!(
            "Ambient: $k_a I_a = {} \\cdot {} = {}$. Light 2 has \
             $N \\cdot L_2 = {}$: it is behind the surface and adds \
             nothing, not even a highlight. Light 1: $N \\cdot L_1 = {}$, \
             so the diffuse term is $I_1 k_d (N \\cdot L_1) = {}$. \
             $R_1 = 2 (N \\cdot L_1) N - L_1 = {}$, $R_1 \\cdot V = {}$, \
             and the specular term is $I_1 k_s (R_1 \\cdot V)^{{{}}} = \
             {} \\cdot {} = {}$. Together \
             $L = {} + {} + {} \\approx$ **{:.2}**.",
            num(material.ka.x),
            num(ambient.x),
            num(terms.ambient.x),
            num(n.dot(behind)),
            num(n.dot(l)),
            num(terms.diffuse.x),
            point(r),
            num(r.dot(v)),
            num(material.p),
            num(material.ks.x),
            num(r.dot(v).powf(material.p)),
            num(terms.specular.x),
            num(terms.ambient.x),
            num(terms.diffuse.x),
            num(terms.specular.x),
            value,
        ),
    }
    .into()
}
