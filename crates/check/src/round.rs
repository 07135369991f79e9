use raystep_core::{DVec2, DVec3};

/// `x` rounded to 4 decimal places, with `-0.0000` written as `0.0000`,
/// and NaN / infinities spelled out.
pub fn num(x: f64) -> String {
    num_places(x, 4)
}

/// `x` rounded to `places` decimal places (see [`num`]).
pub fn num_places(x: f64, places: usize) -> String {
    if x.is_nan() {
        return "NaN".to_string();
    }
    if x.is_infinite() {
        return if x > 0.0 { "inf" } else { "-inf" }.to_string();
    }
    let s = format!("{x:.places$}");
    // "-0.0000" → "0.0000": the sign of a rounded zero is an accident of
    // the operation order.
    match s.strip_prefix('-') {
        Some(rest) if rest.chars().all(|c| c == '0' || c == '.') => {
            rest.to_string()
        }
        _ => s,
    }
}

/// `(x, y)` with each component rounded by [`num`].
pub fn vec2(v: DVec2) -> String {
    format!("({}, {})", num(v.x), num(v.y))
}

/// `(x, y, z)` with each component rounded by [`num`].
pub fn vec3(v: DVec3) -> String {
    format!("({}, {}, {})", num(v.x), num(v.y), num(v.z))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rounds_and_drops_the_sign_of_zero() {
        assert_eq!(num(0.123456), "0.1235");
        assert_eq!(num(-1e-9), "0.0000");
        assert_eq!(num(-0.5), "-0.5000");
        assert_eq!(num(f64::NAN), "NaN");
        assert_eq!(num(f64::NEG_INFINITY), "-inf");
        assert_eq!(vec2(DVec2::new(1.0, -2.0)), "(1.0000, -2.0000)");
    }
}
