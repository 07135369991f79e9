//! Held-out cases of chapter 7 for `raystep grade` (see
//! `raystep_check::held_out`): the pixel centres a triangle covers (on
//! the half-pixel lattice, where edges pass exactly through centres and
//! the fill rule decides; and anywhere, at any scale, away from edges),
//! its barycentric weights, triangles of zero area; the z test over a
//! sequence of surfaces (ties, NaN, +∞) on buffers wider than high; and
//! depth interpolated under perspective.
use std::process::ExitCode;

use ch07::{DVec2, DepthBuffer, barycentric, covers, perspective_depth};
use raystep_check::held_out::{self, Case, Exercise, Rng, short, show2};

fn main() -> ExitCode {
    held_out::main(&[
        Exercise::new("coverage", coverage_case, 1e-9),
        Exercise::new("depth_test", depth_test_case, 1e-9),
    ])
}

fn p(x: f64, y: f64) -> DVec2 {
    DVec2::new(x, y)
}

/// Twice the signed area of (a, b, q), plainly: to judge how clear a
/// case is, not to answer it.
fn cross(a: DVec2, b: DVec2, q: DVec2) -> f64 {
    (b - a).perp_dot(q - a)
}

fn show_triangle(t: &[DVec2; 3]) -> String {
    format!("[{}, {}, {}]", show2(t[0]), show2(t[1]), show2(t[2]))
}

/// The centres of an 8 × 8 grid of pixels of side `unit` from `origin`,
/// covered or not, as one word of 64 letters (`#` covered, `.` not), row
/// by row.
fn coverage_word(t: &[DVec2; 3], origin: DVec2, unit: f64) -> String {
    let mut word = String::with_capacity(64);
    for row in 0..8 {
        for column in 0..8 {
            let centre = p(f64::from(column) + 0.5, f64::from(row) + 0.5);
            word.push(if covers(t, origin + unit * centre) {
                '#'
            } else {
                '.'
            });
        }
    }
    word
}

/// The weights of `q`, or None.
fn weights(case: &mut Case, t: &[DVec2; 3], q: DVec2) {
    match barycentric(t, q) {
        Some(w) => {
            case.num("λa", w[0]);
            case.num("λb", w[1]);
            case.num("λc", w[2]);
        }
        None => case.word("no-weights"),
    }
}

/// A triangle on the half-pixel lattice of an 8 × 8 grid (in either
/// winding, scaled by a power of two and moved by whole pixels): the
/// grid's coverage, exact, the fill rule deciding every centre on an
/// edge; and the weights of a few lattice points.
fn lattice(rng: &mut Rng, case: &mut Case) {
    let half = |rng: &mut Rng| rng.below(17) as f64 / 2.0;
    let t = loop {
        let t = [
            p(half(rng), half(rng)),
            p(half(rng), half(rng)),
            p(half(rng), half(rng)),
        ];
        // at least 4 pixels of area, so that it covers a few centres
        if cross(t[0], t[1], t[2]).abs() >= 8.0 {
            break t;
        }
    };
    let unit = 2f64.powi(rng.below(30) as i32 - 15);
    let origin =
        p(rng.below(9) as f64 - 4.0, rng.below(9) as f64 - 4.0) * 64.0 * unit;
    let t = t.map(|c| origin + unit * c);
    let probes: Vec<DVec2> = (0..3)
        .map(|_| origin + unit * p(half(rng), half(rng)))
        .collect();
    case.ask(format!(
        "covers({}) at the centres of the 8 × 8 pixels of side {} from {}; \
         barycentric at {}, {}, {}",
        show_triangle(&t),
        short(unit),
        show2(origin),
        show2(probes[0]),
        show2(probes[1]),
        show2(probes[2])
    ));
    case.word(coverage_word(&t, origin, unit));
    for q in probes {
        weights(case, &t, q);
    }
}

/// A triangle anywhere (corners in a square of side 20·s, not thin) and
/// points clear of its edges' lines: covered or not, and their weights.
fn anywhere(rng: &mut Rng, case: &mut Case) {
    let s = 10f64.powf(rng.uniform(-100.0, 100.0));
    let t = loop {
        let t = [rng.vec2(10.0 * s), rng.vec2(10.0 * s), rng.vec2(10.0 * s)];
        let longest = (0..3)
            .map(|i| (t[(i + 1) % 3] - t[i]).length())
            .fold(0.0, f64::max);
        if cross(t[0], t[1], t[2]).abs() > 0.05 * longest * longest {
            break t;
        }
    };
    let centroid = (t[0] + t[1] + t[2]) / 3.0;
    let probes: Vec<DVec2> = (0..6)
        .map(|_| {
            loop {
                let q = if rng.chance(0.5) {
                    // inside, by positive weights
                    let w = [rng.unit(), rng.unit(), rng.unit()];
                    let sum = w[0] + w[1] + w[2];
                    (w[0] * t[0] + w[1] * t[1] + w[2] * t[2]) / sum
                } else {
                    centroid + rng.vec2(15.0 * s)
                };
                let clear = (0..3).all(|i| {
                    let (a, b) = (t[i], t[(i + 1) % 3]);
                    let size = (b - a).length() * (q - a).length().max(s);
                    cross(a, b, q).abs() > 1e-6 * size
                });
                if clear {
                    break q;
                }
            }
        })
        .collect();
    let shown: Vec<String> = probes.iter().map(|&q| show2(q)).collect();
    case.ask(format!(
        "covers and barycentric({}) at {}",
        show_triangle(&t),
        shown.join(", ")
    ));
    for q in probes {
        case.word(if covers(&t, q) {
            "covered"
        } else {
            "not-covered"
        });
        weights(case, &t, q);
    }
}

/// A triangle of zero area (three corners in line, a corner repeated, one
/// point three times), at its corners and on its line: never covered, no
/// weights.
fn degenerate(rng: &mut Rng, case: &mut Case) {
    let unit = 2f64.powi(rng.below(30) as i32 - 15);
    let a = p(rng.below(17) as f64, rng.below(17) as f64) * 0.5 * unit;
    let step = p(rng.below(9) as f64 - 4.0, rng.below(9) as f64 - 4.0) * unit;
    let t = match rng.below(3) {
        0 => [a, a + 2.0 * step, a + step],
        1 => [a, a + step, a],
        _ => [a, a, a],
    };
    let t = if rng.chance(0.5) {
        [t[0], t[2], t[1]]
    } else {
        t
    };
    let probes = [t[0], t[1], t[2], (t[0] + t[1]) / 2.0, a + 0.5 * step];
    case.ask(format!(
        "a triangle of zero area {} at its corners and on its line",
        show_triangle(&t)
    ));
    for q in probes {
        case.word(if covers(&t, q) {
            "covered"
        } else {
            "not-covered"
        });
    }
    weights(case, &t, a + 0.5 * step);
}

fn coverage_case(rng: &mut Rng, case: &mut Case) {
    match rng.below(5) {
        0 | 1 => lattice(rng, case),
        2 | 3 => anywhere(rng, case),
        _ => degenerate(rng, case),
    }
}

/// A depth drawn at a pixel: anything finite, the same as the pixel
/// holds (a tie), an ulp either side of it, NaN, +∞.
fn depth(rng: &mut Rng, held: f64, s: f64) -> f64 {
    match rng.below(10) {
        0 => held,
        1 => held.next_up(),
        2 => held.next_down(),
        3 => f64::NAN,
        4 => f64::INFINITY,
        _ => s * rng.uniform(0.1, 10.0),
    }
}

/// Surfaces drawn one after another on a small buffer (often wider than
/// high): which the z test keeps, and every depth the buffer then holds;
/// or depth under perspective from screen weights.
fn depth_test_case(rng: &mut Rng, case: &mut Case) {
    if rng.chance(0.4) {
        return perspective(rng, case);
    }
    let (width, height) = (1 + rng.below(6) as u32, 1 + rng.below(6) as u32);
    let s = 10f64.powf(rng.uniform(-3.0, 6.0));
    let mut holds = vec![f64::INFINITY; (width * height) as usize];
    let mut draws = Vec::new();
    for _ in 0..4 + rng.below(14) {
        let (column, row) = (
            rng.below(width as usize) as u32,
            rng.below(height as usize) as u32,
        );
        // what the pixel holds, by the rule, to draw ties against
        let held = holds[(row * width + column) as usize];
        let held = if held.is_finite() { held } else { s };
        let z = depth(rng, held, s);
        let i = (row * width + column) as usize;
        if z < holds[i] {
            holds[i] = z;
        }
        draws.push((column, row, z));
    }
    let shown: Vec<String> = draws
        .iter()
        .map(|&(c, r, z)| format!("({c}, {r}) {}", short(z)))
        .collect();
    case.ask(format!(
        "a {width} × {height} buffer, drawn at (column, row) depth: {}",
        shown.join("; ")
    ));
    let mut buffer = DepthBuffer::new(width, height);
    for (column, row, z) in draws {
        let kept = buffer.test_and_set(column, row, z);
        case.word(if kept { "kept" } else { "rejected" });
    }
    for row in 0..height {
        for column in 0..width {
            case.num("z/s", buffer.get(column, row) / s);
        }
    }
}

/// 1 / (λa/za + λb/zb + λc/zc): weights inside the triangle (a corner, an
/// edge, anywhere), corner depths from s/10 to 100·s.
fn perspective(rng: &mut Rng, case: &mut Case) {
    let s = 10f64.powf(rng.uniform(-3.0, 6.0));
    let z = [0; 3].map(|_| s * 10f64.powf(rng.uniform(-1.0, 2.0)));
    let lambda = match rng.below(4) {
        0 => {
            let mut l = [0.0; 3];
            l[rng.below(3)] = 1.0;
            l
        }
        1 => {
            let a = rng.unit();
            let k = rng.below(3);
            let mut l = [0.0; 3];
            l[k] = a;
            l[(k + 1) % 3] = 1.0 - a;
            l
        }
        _ => {
            let (a, b) = (rng.unit(), rng.unit());
            let (a, b) = if a + b > 1.0 {
                (1.0 - a, 1.0 - b)
            } else {
                (a, b)
            };
            [1.0 - a - b, a, b]
        }
    };
    case.ask(format!(
        "perspective_depth(λ = [{}, {}, {}], z = [{}, {}, {}])",
        short(lambda[0]),
        short(lambda[1]),
        short(lambda[2]),
        short(z[0]),
        short(z[1]),
        short(z[2])
    ));
    case.num("z/s", perspective_depth(lambda, z) / s);
}
