//! Chapter 6's questions worked on paper, with the answers the chapter's
//! code computes from the same numbers (`raystep figures` writes them to
//! the book; `raystep check ch06` judges `exercise/answers.toml`).
use ch06::{critical_angle, fresnel, index_of_refraction, refract, schlick};
use raystep_core::DVec3;
use raystep_figure::{ChoiceQuestion, NumberQuestion, Question};

/// Every question, in the order the book asks them.
pub fn all() -> Vec<Question> {
    vec![
        refraction_angle(),
        refracts_or_reflects(),
        schlick_leaving_glass(),
    ]
}

/// The index of a material of the lecture's table.
fn index_of(material: &str) -> f64 {
    index_of_refraction(material).expect("a material of the table")
}

/// The surface's normal N, and the unit direction D of a ray meeting it
/// at `degrees` to N, in the plane z = 0.
fn ray_at(degrees: f64) -> (DVec3, DVec3) {
    let theta = degrees.to_radians();
    let d = DVec3::new(theta.sin(), -theta.cos(), 0.0);
    (d, DVec3::Y)
}

/// φ in degrees: the angle between T and −N.
fn phi_of(t: DVec3, n: DVec3) -> f64 {
    (-t.dot(n)).clamp(-1.0, 1.0).acos().to_degrees()
}

/// Question 1: Snell's law, from air into glass.
fn refraction_angle() -> Question {
    let (from, into, degrees) = ("air", "glass", 30.0_f64);
    let (n_theta, n_phi) = (index_of(from), index_of(into));
    let (d, n) = ray_at(degrees);
    let t = refract(d, n, n_theta, n_phi)
        .expect("into a denser medium every ray refracts");
    let phi = phi_of(t, n);
    let sin_phi = n_theta / n_phi * degrees.to_radians().sin();
    NumberQuestion {
        id: "q1",
        stars: 1,
        title: "the refraction angle from air into glass",
        prompt: format!(
            "A ray in {from} ($n_\\theta = {n_theta}$) meets a flat piece of \
             {into} ($n_\\varphi = {n_phi}$) at $\\theta = {degrees}°$ to the \
             normal. At what angle $\\varphi$ to $-N$ does the refracted ray \
             go on in the {into}, in degrees?"
        ),
        figure: Some("snell.svg"),
        quantity: "φ (degrees)",
        value: phi,
        step: 0.1,
        worked: format!(
            "Snell's law: $\\sin\\varphi = (n_\\theta / n_\\varphi) \
             \\sin\\theta = ({n_theta} / {n_phi}) \\cdot \\sin {degrees}° = \
             {:.4} \\cdot {:.1} = {sin_phi:.4}$, so \
             $\\varphi = \\arcsin {sin_phi:.4} \\approx$ **{phi:.2}°**: the \
             ray bends toward the normal, by {:.1}°. (From vacuum it would \
             be {:.2}°: air is nearly vacuum.)",
            n_theta / n_phi,
            degrees.to_radians().sin(),
            degrees - phi,
            phi_of(
                refract(d, n, index_of("vacuum"), n_phi)
                    .expect("into a denser medium every ray refracts"),
                n
            )
        ),
    }
    .into()
}

/// Question 2: total internal reflection or not, from glass into water.
fn refracts_or_reflects() -> Question {
    let (from, into, degrees) = ("glass", "water", 60.0_f64);
    let (n_theta, n_phi) = (index_of(from), index_of(into));
    let (d, n) = ray_at(degrees);
    let t = refract(d, n, n_theta, n_phi);
    let answer = if t.is_some() {
        "refracts"
    } else {
        "total internal reflection"
    };
    let critical = critical_angle(n_theta, n_phi)
        .expect("out of a denser medium there is a critical angle")
        .to_degrees();
    let into_air = critical_angle(n_theta, index_of("air"))
        .expect("glass is denser than air")
        .to_degrees();
    let sin_phi = n_theta / n_phi * degrees.to_radians().sin();
    let outcome = match t {
        Some(t) => format!(
            "$\\sin\\varphi < 1$: the ray **refracts**, at \
             $\\varphi = \\arcsin {sin_phi:.3} \\approx {:.1}°$, bent away \
             from the normal",
            phi_of(t, n)
        ),
        None => "$\\sin\\varphi > 1$: there is no $\\varphi$, **total \
                 internal reflection**"
            .to_string(),
    };
    ChoiceQuestion {
        id: "q2",
        stars: 2,
        title: "total internal reflection, or not",
        prompt: format!(
            "A ray inside {from} ($n_\\theta = {n_theta}$) meets the surface \
             to {into} ($n_\\varphi = {n_phi}$) at $\\theta = {degrees}°$ to \
             the normal. Does it refract into the {into}, or is it totally \
             reflected?"
        ),
        figure: Some("critical-angles.svg"),
        options: &["refracts", "total internal reflection"],
        answer,
        worked: format!(
            "Snell's law asks for $\\sin\\varphi = (n_\\theta / n_\\varphi) \
             \\sin\\theta = ({n_theta} / {n_phi}) \\cdot {:.3} = \
             {sin_phi:.3}$. {outcome}. The critical angle from {from} into \
             {into} is $\\arcsin({n_phi} / {n_theta}) \\approx \
             {critical:.1}°$, larger than the ray's {degrees}°. Into air the same ray would \
             be trapped: there the critical angle is {into_air:.1}°.",
            degrees.to_radians().sin()
        ),
    }
    .into()
}

/// Question 3: Schlick's R leaving glass, where α is the refracted angle.
fn schlick_leaving_glass() -> Question {
    let (from, into, degrees) = ("glass", "vacuum", 30.0_f64);
    let (n_theta, n_phi) = (index_of(from), index_of(into));
    let cos_theta = degrees.to_radians().cos();
    let r = schlick(cos_theta, n_theta, n_phi);
    let r0 = ((n_theta - n_phi) / (n_theta + n_phi)).powi(2);
    let sin_phi = n_theta / n_phi * degrees.to_radians().sin();
    let (d, n) = ray_at(degrees);
    let t = refract(d, n, n_theta, n_phi).expect("below the critical angle");
    let cos_alpha = -t.dot(n);
    let rise = (1.0 - cos_alpha).powi(5);
    // the same curve with θ in place of α: Schlick's R entering the glass
    let with_theta = schlick(cos_theta, n_phi, n_theta);
    let exact = fresnel(cos_theta, n_theta, n_phi);
    NumberQuestion {
        id: "q3",
        stars: 3,
        title: "Schlick's R leaving glass",
        prompt: format!(
            "A ray inside {from} ($n_\\theta = {n_theta}$) meets the surface \
             to {into} ($n_\\varphi = {n_phi}$) at $\\theta = {degrees}°$. \
             What fraction $R$ of its light does Schlick's approximation \
             reflect? Mind which angle goes into Schlick's curve."
        ),
        figure: Some("reflectance.svg"),
        quantity: "R",
        value: r,
        step: 0.0005,
        worked: format!(
            "$R_0 = (({n_theta} - {n_phi}) / ({n_theta} + {n_phi}))^2 = \
             {r0:.2}$. The ray leaves the denser medium, so $\\alpha$ is the \
             refracted angle: $\\sin\\varphi = {n_theta} \\cdot \\sin \
             {degrees}° = {sin_phi:.2}$, $\\cos\\alpha = \\cos\\varphi = \
             \\sqrt{{1 - {sin_phi:.2}^2}} = {cos_alpha:.4}$. Then \
             $(1 - {cos_alpha:.4})^5 = {:.4}^5 \\approx {rise:.5}$ and \
             $R = {r0:.2} + {:.2} \\cdot {rise:.5} \\approx$ **{r:.4}**. \
             With $\\theta$ in place of $\\alpha$ the rise would be \
             $(1 - \\cos {degrees}°)^5 = {:.3}^5$, nearly nothing, and $R$ \
             only {with_theta:.4}. (The exact Fresnel equations give \
             {exact:.4}.)",
            1.0 - cos_alpha,
            1.0 - r0,
            1.0 - cos_theta
        ),
    }
    .into()
}
