//! Polynomials in t, as the slow primitives give them.
//!
//! A polynomial is a slice of coefficients, **lowest degree first**:
//! `c[i]` multiplies tⁱ, so `[c₀, c₁, c₂]` is c₀ + c₁t + c₂t². The torus
//! gives five of them (a quartic), the monkey saddle four, a blob seven.

// ANCHOR: horner
/// p(t) = c₀ + c₁t + … + cₙtⁿ by Horner's rule,
/// (…(cₙt + cₙ₋₁)t + …)t + c₀: n multiplications and n additions, and
/// no powers of t that could overflow before they are scaled down.
pub fn horner(c: &[f64], t: f64) -> f64 {
    c.iter().rev().fold(0.0, |sum, &ci| sum * t + ci)
}
// ANCHOR_END: horner

/// The derivative p′: `[c₁, 2c₂, 3c₃, …]` (empty for a constant).
pub fn derivative(c: &[f64]) -> Vec<f64> {
    c.iter()
        .enumerate()
        .skip(1)
        .map(|(i, &ci)| i as f64 * ci)
        .collect()
}

/// The product p·q (empty if either is empty).
pub fn multiply(p: &[f64], q: &[f64]) -> Vec<f64> {
    if p.is_empty() || q.is_empty() {
        return Vec::new();
    }
    let mut product = vec![0.0; p.len() + q.len() - 1];
    for (i, &pi) in p.iter().enumerate() {
        for (j, &qj) in q.iter().enumerate() {
            product[i + j] += pi * qj;
        }
    }
    product
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn horner_derivative_and_product() {
        // (t − 1)(t − 2)(t + 3) = t³ − 7t + 6
        let p = multiply(&multiply(&[-1.0, 1.0], &[-2.0, 1.0]), &[3.0, 1.0]);
        assert_eq!(p, vec![6.0, -7.0, 0.0, 1.0]);
        for t in [1.0, 2.0, -3.0] {
            assert_eq!(horner(&p, t), 0.0);
        }
        assert_eq!(horner(&p, 0.0), 6.0);
        assert_eq!(derivative(&p), vec![-7.0, 0.0, 3.0]);
        assert!(derivative(&[5.0]).is_empty());
        assert_eq!(horner(&[], 2.0), 0.0);
    }
}
