//! Roots by bracketing: isolate each root in an interval, then close in.
//!
//! Between two neighbouring roots of p′, p is monotone: it crosses zero
//! once or not at all, and a sign change at the ends of such a piece
//! proves a root inside. The roots of p′ come from the same method one
//! degree lower, down to a constant, which has none.
//!
//! This is what finds the two close roots of a ray that grazes a torus's
//! silhouette. Between them p′ has a root, the bottom of the dip where
//! the ray is deepest inside; it is a simple root of p′, found
//! accurately, and p there is clearly negative (about the depth times
//! |∇f|), so both pieces show a sign change. The closed form asks the
//! same question through a discriminant, a difference of large rounded
//! numbers near 0, and merges or loses the pair when it rounds the wrong
//! way. Here a root is lost only if p at the bottom of the dip is smaller
//! than the rounding of p itself.

use crate::{derivative, horner};

// ANCHOR: roots_in
/// The real roots of the polynomial `c` (lowest degree first) in
/// `[a, b]`, sorted: isolated between the roots of its derivative, each
/// found by Newton's method kept inside a bracket with a sign change.
pub fn roots_in(c: &[f64], a: f64, b: f64) -> Vec<f64> {
    // Step 1: drop zero leading coefficients; a constant has no roots.
    let degree = c.iter().rposition(|&ci| ci != 0.0).unwrap_or(0);
    let c = &c[..=degree];
    if degree == 0 || a.is_nan() || b.is_nan() || a > b {
        return Vec::new();
    }
    // Step 2: the derivative's roots cut [a, b] into monotone pieces.
    let dc = derivative(c);
    let mut ends = vec![a];
    ends.extend(roots_in(&dc, a, b).into_iter().filter(|&x| a < x && x < b));
    ends.push(b);
    // Step 3: one root in each piece whose ends have opposite signs.
    let mut roots: Vec<f64> = Vec::new();
    for piece in ends.windows(2) {
        let (lo, hi) = (piece[0], piece[1]);
        let (p_lo, p_hi) = (horner(c, lo), horner(c, hi));
        if p_lo == 0.0 {
            roots.push(lo); // a root on the cut itself
        } else if p_hi != 0.0 && (p_lo < 0.0) != (p_hi < 0.0) {
            roots.push(newton_in_bracket(c, &dc, lo, hi, p_lo));
        }
    }
    if horner(c, b) == 0.0 {
        roots.push(b);
    }
    roots.dedup();
    roots
}
// ANCHOR_END: roots_in

// ANCHOR: newton_in_bracket
/// The root of `c` in `[lo, hi]`, where p(lo) = `p_lo` and p(hi) have
/// opposite signs: Newton's steps t − p(t)/p′(t) while they stay inside
/// the bracket and shrink it fast, else bisection. Each step keeps the
/// root bracketed, so the answer is never lost, only refined.
fn newton_in_bracket(
    c: &[f64], dc: &[f64], mut lo: f64, mut hi: f64, p_lo: f64,
) -> f64 {
    let mut t = 0.5 * (lo + hi);
    let mut step = hi - lo;
    for _ in 0..200 {
        // Step 1: shrink the bracket to the side with the sign change.
        let p = horner(c, t);
        if p == 0.0 {
            return t;
        }
        if (p < 0.0) == (p_lo < 0.0) {
            lo = t;
        } else {
            hi = t;
        }
        // Step 2: Newton's step if it lands inside and at least halves
        // the last step; else bisect.
        let newton = t - p / horner(dc, t);
        let previous = step;
        let next = if lo < newton && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
        let next = if (next - t).abs() * 2.0 > previous {
            0.5 * (lo + hi)
        } else {
            next
        };
        step = (next - t).abs();
        // Step 3: done when the step is below the spacing of doubles.
        if step <= 2.0 * f64::EPSILON * t.abs() || next == lo || next == hi {
            return next;
        }
        t = next;
    }
    t
}
// ANCHOR_END: newton_in_bracket

#[cfg(test)]
mod tests {
    use super::*;
    use crate::multiply;

    #[test]
    fn finds_each_root_in_the_interval() {
        // (t − 1)(t − 2)(t + 3)
        let p = [6.0, -7.0, 0.0, 1.0];
        let roots = roots_in(&p, -10.0, 10.0);
        assert_eq!(roots.len(), 3, "{roots:?}");
        for (got, want) in roots.iter().zip([-3.0, 1.0, 2.0]) {
            assert!((got - want).abs() < 1e-14, "{roots:?}");
        }
        assert_eq!(roots_in(&p, 0.0, 1.5).len(), 1);
        assert!(roots_in(&p, 3.0, 4.0).is_empty());
        assert!(roots_in(&[1.0, 0.0, 1.0], -5.0, 5.0).is_empty());
    }

    #[test]
    fn keeps_two_roots_1e_minus_7_apart() {
        // (t − 1)(t − 1 − h)(t − 3)(t + 2), h = 2⁻²³ ≈ 1.2e-7: exact
        // coefficients. Close roots are ill-conditioned: p′ there is only
        // about 6h, so a rounding of 1e-15 in p moves them by about 1e-9;
        // what matters is that both are found, in order.
        let h = 2f64.powi(-23);
        let pair = multiply(&[-1.0, 1.0], &[-(1.0 + h), 1.0]);
        let p = multiply(&multiply(&pair, &[-3.0, 1.0]), &[2.0, 1.0]);
        let roots = roots_in(&p, -5.0, 5.0);
        assert_eq!(roots.len(), 4, "{roots:?}");
        assert!((roots[1] - 1.0).abs() < 1e-8, "{roots:?}");
        assert!((roots[2] - (1.0 + h)).abs() < 1e-8, "{roots:?}");
        assert!(roots[1] < roots[2]);
    }

    #[test]
    fn a_root_on_an_end_or_at_a_double_root() {
        // t(t − 1) on [0, 1]: both ends are roots, each reported once
        assert_eq!(roots_in(&[0.0, -1.0, 1.0], 0.0, 1.0), vec![0.0, 1.0]);
        // (t − 2)²: the double root is the cut between the pieces
        assert_eq!(roots_in(&[4.0, -4.0, 1.0], 0.0, 5.0), vec![2.0]);
    }
}
