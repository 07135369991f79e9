//! Roots by formula: the quadratic, Cardano's cubic and Ferrari's quartic.
//!
//! Coefficients are lowest degree first (`c[i]` multiplies tⁱ, as in
//! [`horner`](crate::horner)). Each function returns the real roots,
//! sorted; a double root may come out once or as two nearly equal roots.
//!
//! The quartic is the textbook method, written carefully, but it is a
//! chain of formulas: each step rounds, and nothing afterwards checks the
//! result against the polynomial. Where two roots nearly meet (a ray that
//! grazes a torus) a discriminant near 0 can round to the wrong sign, and
//! where the coefficients are huge and cancel (a ray from far away) the
//! rounding swamps the answer. `tests/torus_solvers.rs` counts the roots
//! it loses; [`roots_in`](crate::roots_in) is the robust method.
use ch02::zero_within_rounding;

// ANCHOR: quadratic
/// The real roots of c₀ + c₁t + c₂t², in the stable form.
///
/// The school formula (−b ± √(b² − 4ac)) / 2a subtracts two nearly equal
/// numbers for one of the roots when b² ≫ 4ac. Instead, take the root
/// where the signs agree, q = −(b + sign(b)·√(b² − 4ac)) / 2, and get
/// the two roots as q/a and c/q (their product is c/a).
pub fn quadratic_roots(c: [f64; 3]) -> Vec<f64> {
    let [c0, b, a] = c;
    // Step 1: a linear equation if the square term is missing.
    if a == 0.0 {
        return if b == 0.0 { Vec::new() } else { vec![-c0 / b] };
    }
    // Step 2: no real roots below a zero discriminant.
    let discriminant = b * b - 4.0 * a * c0;
    if discriminant < 0.0 {
        return Vec::new();
    }
    // Step 3: the root without cancellation, then the other from it.
    let q = -0.5 * (b + discriminant.sqrt().copysign(b));
    if q == 0.0 {
        return vec![0.0]; // b = 0 and c₀ = 0: a double root at 0
    }
    sorted(vec![q / a, c0 / q])
}
// ANCHOR_END: quadratic

// ANCHOR: cubic
/// The real roots of c₀ + c₁t + c₂t² + c₃t³: Cardano's formula when
/// there is one real root, the trigonometric form when there are three.
pub fn cubic_roots(c: [f64; 4]) -> Vec<f64> {
    if c[3] == 0.0 {
        return quadratic_roots([c[0], c[1], c[2]]);
    }
    // Step 1: divide by c₃: t³ + a·t² + b·t + d.
    let (a, b, d) = (c[2] / c[3], c[1] / c[3], c[0] / c[3]);
    // Step 2: depress it, t = y − a/3: y³ + p·y + q.
    let p = b - a * a / 3.0;
    let q = 2.0 * a * a * a / 27.0 - a * b / 3.0 + d;
    let shift = a / 3.0;
    // Step 3: the discriminant decides between one and three real roots.
    let discriminant = (q / 2.0).powi(2) + (p / 3.0).powi(3);
    let ys = if discriminant >= 0.0 {
        // Cardano: y = u + v with u³ and v³ the roots of z² + qz − p³/27.
        // u from the root without cancellation, v = −p / 3u.
        let u = (-q / 2.0 - discriminant.sqrt().copysign(q)).cbrt();
        let v = if u == 0.0 { 0.0 } else { -p / (3.0 * u) };
        vec![u + v]
    } else {
        // Three real roots (p < 0): y = 2√(−p/3)·cos(φ/3 − 2πk/3).
        let m = 2.0 * (-p / 3.0).sqrt();
        let cos_phi = (3.0 * q / (p * m)).clamp(-1.0, 1.0);
        let phi = cos_phi.acos();
        (0..3)
            .map(|k| {
                let angle = (phi - 2.0 * std::f64::consts::PI * k as f64) / 3.0;
                m * angle.cos()
            })
            .collect()
    };
    sorted(ys.into_iter().map(|y| y - shift).collect())
}
// ANCHOR_END: cubic

// ANCHOR: quartic
/// The real roots of c₀ + c₁t + c₂t² + c₃t³ + c₄t⁴ by Ferrari's method.
///
/// Depress the quartic to y⁴ + p·y² + q·y + r, then add a square to both
/// sides: y⁴ + p·y² + q·y + r = (y² + p/2 + m)² − (√(2m)·y − q/(2√(2m)))²
/// holds when m solves the resolvent cubic
/// 8m³ + 8p·m² + (2p² − 8r)·m − q² = 0, which has a root m > 0. The
/// difference of two squares factors into two quadratics.
pub fn quartic_roots(c: [f64; 5]) -> Vec<f64> {
    if c[4] == 0.0 {
        return cubic_roots([c[0], c[1], c[2], c[3]]);
    }
    // Step 1: divide by c₄: t⁴ + a·t³ + b·t² + d·t + e.
    let (a, b, d, e) = (c[3] / c[4], c[2] / c[4], c[1] / c[4], c[0] / c[4]);
    // Step 2: depress it, t = y − a/4: y⁴ + p·y² + q·y + r.
    let a2 = a * a;
    let p = b - 3.0 * a2 / 8.0;
    let q = d - a * b / 2.0 + a2 * a / 8.0;
    let r = e - a * d / 4.0 + a2 * b / 16.0 - 3.0 * a2 * a2 / 256.0;
    let mut ys = Vec::new();
    // q is zero when its rounding error is as large as it (chapter 2's
    // test): then the resolvent's root m is about 0 and the division by
    // √2m in step 4 would blow the rounding up.
    let q_terms = d.abs() + (a * b).abs() / 2.0 + (a2 * a).abs() / 8.0;
    if zero_within_rounding(q, q_terms) {
        // Step 3a: no odd term: a quadratic in z = y².
        for z in quadratic_roots([r, p, 1.0]) {
            if z >= 0.0 {
                ys.extend([-z.sqrt(), z.sqrt()]);
            }
        }
    } else {
        // Step 3b: the resolvent cubic's largest root m (> 0 in exact
        // arithmetic, since the cubic is −q² < 0 at m = 0).
        let resolvent = [-q * q, 2.0 * p * p - 8.0 * r, 8.0 * p, 8.0];
        let m = cubic_roots(resolvent).into_iter().fold(0.0, f64::max);
        if m <= 0.0 {
            return Vec::new();
        }
        // Step 4: the two quadratics y² ± s·y + (p/2 + m ∓ q/2s), s = √2m.
        let s = (2.0 * m).sqrt();
        ys.extend(quadratic_roots([p / 2.0 + m - q / (2.0 * s), s, 1.0]));
        ys.extend(quadratic_roots([p / 2.0 + m + q / (2.0 * s), -s, 1.0]));
    }
    // Step 5: back from y to t.
    sorted(ys.into_iter().map(|y| y - a / 4.0).collect())
}
// ANCHOR_END: quartic

/// The roots in increasing order, exact repeats dropped.
fn sorted(mut roots: Vec<f64>) -> Vec<f64> {
    roots.sort_by(f64::total_cmp);
    roots.dedup();
    roots
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(got: &[f64], want: &[f64]) -> bool {
        got.len() == want.len()
            && got.iter().zip(want).all(|(g, w)| (g - w).abs() < 1e-9)
    }

    #[test]
    fn simple_roots_of_each_degree() {
        // (t − 1)(t − 3)
        assert!(close(&quadratic_roots([3.0, -4.0, 1.0]), &[1.0, 3.0]));
        assert!(quadratic_roots([1.0, 0.0, 1.0]).is_empty());
        assert!(close(&quadratic_roots([2.0, -1.0, 0.0]), &[2.0]));
        // tiny root beside a large one: c/q keeps it exact
        let tiny = quadratic_roots([1.0, -1e9, 1.0]);
        assert!((tiny[0] - 1e-9).abs() < 1e-24, "{tiny:?}");
        // (t − 1)(t − 2)(t + 3) and (t − 2)(t² + 1)
        assert!(close(
            &cubic_roots([6.0, -7.0, 0.0, 1.0]),
            &[-3.0, 1.0, 2.0]
        ));
        assert!(close(&cubic_roots([-2.0, 1.0, -2.0, 1.0]), &[2.0]));
        // (t − 1)(t − 2)(t − 3)(t − 4) = t⁴ − 10t³ + 35t² − 50t + 24
        let four = quartic_roots([24.0, -50.0, 35.0, -10.0, 1.0]);
        assert!(close(&four, &[1.0, 2.0, 3.0, 4.0]), "{four:?}");
        // (t² − 1)(t² − 4): the biquadratic branch
        let even = quartic_roots([4.0, 0.0, -5.0, 0.0, 1.0]);
        assert!(close(&even, &[-2.0, -1.0, 1.0, 2.0]), "{even:?}");
        // (t² + 1)(t² + 2): no real root
        assert!(quartic_roots([2.0, 0.0, 3.0, 0.0, 1.0]).is_empty());
    }
}
