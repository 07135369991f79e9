/// Is `value` zero as far as floating point can tell?
///
/// `value` was computed as a sum of products whose absolute values add up
/// to `magnitude` (for a dot product `a·b`, `magnitude = |a|·|b|` taken
/// component-wise: `a.abs().dot(b.abs())`). Rounding can leave an error of
/// a few ε·magnitude, so a result smaller than that has no reliable sign:
/// we call it zero.
// ANCHOR: zero_within_rounding
pub fn zero_within_rounding(value: f64, magnitude: f64) -> bool {
    value.abs() <= 8.0 * f64::EPSILON * magnitude
}
// ANCHOR_END: zero_within_rounding

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounding_noise_is_zero_and_signal_is_not() {
        // 0.1·3 − 0.3 is 5.6e-17 in floating point, not 0
        let noise = 0.1 * 3.0 - 0.3;
        assert_ne!(noise, 0.0);
        assert!(zero_within_rounding(noise, 0.3 + 0.3));
        assert!(!zero_within_rounding(1e-12, 1.0));
        assert!(zero_within_rounding(0.0, 0.0));
    }
}
