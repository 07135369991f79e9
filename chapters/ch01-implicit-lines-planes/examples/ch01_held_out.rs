//! Held-out cases of chapter 1 for `raystep grade` (see
//! `raystep_check::held_out`): lines and planes through points drawn at
//! grading time, at every scale from 1e-300 to 1e300, degenerate ones
//! among them.
use std::process::ExitCode;

use ch01::{DVec3, Degenerate, Line2, Plane, rotate90};
use raystep_check::held_out::{self, Case, Exercise, Rng, show2, show3};

fn main() -> ExitCode {
    held_out::main(&[
        Exercise::new("line_through_points", line, 1e-7),
        Exercise::new("plane_through_points", plane, 1e-7),
    ])
}

/// A size for a case's coordinates: 1e-3 … 1e6 or any decade from 1e-300
/// to 1e300 (where |P1 − P0|² over- or underflows).
fn scale(rng: &mut Rng) -> f64 {
    if rng.chance(0.4) {
        10f64.powf(rng.uniform(-300.0, 300.0))
    } else {
        rng.magnitude(1e-3, 1e6).abs()
    }
}

/// A point that breaks a line or plane through `p`, as often as not:
/// `p` itself (coincident points), or with a coordinate that is NaN, ±∞
/// or ±1e308 (whose differences overflow).
fn spoiled(rng: &mut Rng, p: DVec3) -> Option<DVec3> {
    let mut q = p;
    q[rng.below(3)] = match rng.below(12) {
        0 => f64::NAN,
        1 => f64::INFINITY,
        2 => f64::NEG_INFINITY,
        3 => 1e308,
        4 => -1e308,
        5 | 6 => return Some(p),
        _ => return None,
    };
    Some(q)
}

/// The answer to a line or plane that could not be made.
fn error_word(case: &mut Case, error: Degenerate) {
    case.word("error");
    case.word(format!("{error:?}"));
}

/// rotate90 of a vector; the line through two distinct points, with f
/// at a third; now and then a degenerate line.
fn line(rng: &mut Rng, case: &mut Case) {
    let s = scale(rng);
    let v = rng.vec2(s);
    let p0 = rng.vec2(s);
    let p1 = p0 + rng.vec2(s);
    let probe = p0 + rng.vec2(s);
    let bad = spoiled(rng, p0.extend(0.0)).map(|q| q.truncate());
    case.ask(format!(
        "rotate90{}, Line2::through({}, {}), eval at {}{}",
        show2(v),
        show2(p0),
        show2(p1),
        show2(probe),
        bad.map_or(String::new(), |q| format!(
            ", Line2::through({}, {})",
            show2(p0),
            show2(q)
        ))
    ));
    case.vec2("R", rotate90(v));
    match Line2::through(p0, p1) {
        Ok(l) => {
            case.vec2("V", l.direction);
            case.vec2("N", l.normal);
            case.num("c", l.c);
            case.num("f", l.eval(probe));
        }
        Err(e) => error_word(case, e),
    }
    if let Some(q) = bad {
        match Line2::through(p0, q) {
            Ok(l) => case.vec2("N", l.normal),
            Err(e) => error_word(case, e),
        }
    }
}

/// The plane through three points, with f at a fourth; now and then a
/// degenerate plane (two points coincide, collinear, not finite).
fn plane(rng: &mut Rng, case: &mut Case) {
    let s = scale(rng);
    let p0 = rng.vec3(s);
    let (mut p1, mut p2);
    loop {
        p1 = p0 + rng.vec3(s);
        p2 = p0 + rng.vec3(s);
        // No case near the collinear threshold (1e-12), where a correct
        // solution in another order may decide either way.
        let (e1, e2) = ((p1 - p0) / s, (p2 - p0) / s);
        let sine = e1.cross(e2).length() / (e1.length() * e2.length());
        if sine > 1e-6 {
            break;
        }
    }
    let probe = p0 + rng.vec3(s);
    let bad = if rng.chance(0.15) {
        Some(p0 + 2.0 * (p1 - p0)) // collinear
    } else {
        spoiled(rng, p2)
    };
    case.ask(format!(
        "Plane::through({}, {}, {}), eval at {}{}",
        show3(p0),
        show3(p1),
        show3(p2),
        show3(probe),
        bad.map_or(String::new(), |q| format!(
            "; Plane::through({}, {}, {})",
            show3(p0),
            show3(p1),
            show3(q)
        ))
    ));
    match Plane::through(p0, p1, p2) {
        Ok(plane) => {
            case.vec3("N", plane.normal);
            case.num("d", plane.d);
            case.num("f", plane.eval(probe));
        }
        Err(e) => error_word(case, e),
    }
    if let Some(q) = bad {
        match Plane::through(p0, p1, q) {
            Ok(plane) => case.vec3("N", plane.normal),
            Err(e) => error_word(case, e),
        }
    }
}
