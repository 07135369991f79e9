//! Numbers as figures print them: a real minus sign (−, not -), thin
//! spaces between thousands, powers of ten as superscripts.

/// `x` with `digits` decimals and a real minus sign.
pub fn fixed(x: f64, digits: usize) -> String {
    format!("{x:.digits$}").replace('-', "−")
}

/// `x` with its sign always shown, as short as it is exact if that takes
/// at most `width` characters, else with 2 decimals: `+8`, `−4.5`, `0`.
pub fn signed(x: f64, width: usize) -> String {
    let short = format!("{}", x.abs());
    let s = if short.len() <= width {
        short
    } else {
        format!("{:.2}", x.abs())
    };
    if x > 0.0 {
        format!("+{s}")
    } else if x < 0.0 {
        format!("−{s}")
    } else {
        s
    }
}

/// `x` in scientific notation with one decimal, as label markup
/// (`2.0×10^{−15}`) or, with `markup` false, in plain Unicode (`2.0 × 10⁻¹⁵`).
pub fn scientific(x: f64, markup: bool) -> String {
    if x == 0.0 {
        return "0".to_string();
    }
    let exponent = x.abs().log10().floor() as i32;
    let mantissa = x / 10f64.powi(exponent);
    let (mantissa, exponent) = if (mantissa.abs() * 10.0).round() >= 100.0 {
        (mantissa / 10.0, exponent + 1)
    } else {
        (mantissa, exponent)
    };
    let m = fixed(mantissa, 1);
    let e = exponent.to_string().replace('-', "−");
    if markup {
        format!("{m}×10^{{{e}}}")
    } else {
        const SUPERSCRIPTS: [char; 10] = ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
        let e: String = e
            .chars()
            .map(|c| match c.to_digit(10) {
                Some(d) => SUPERSCRIPTS[d as usize],
                None => '⁻',
            })
            .collect();
        format!("{m} × 10{e}")
    }
}

/// A number with a thin space between thousands: 14 400.
pub fn grouped(n: u64) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (k, c) in digits.chars().enumerate() {
        if k > 0 && (digits.len() - k) % 3 == 0 {
            out.push('\u{2009}');
        }
        out.push(c);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_print_with_real_minus_signs() {
        assert_eq!(fixed(-0.25, 3), "−0.250");
        assert_eq!(signed(8.0, 5), "+8");
        assert_eq!(signed(-4.5, 5), "−4.5");
        assert_eq!(signed(0.0, 5), "0");
        assert_eq!(signed(25.0625, 5), "+25.06");
        assert_eq!(signed(25.0625, 7), "+25.0625");
        assert_eq!(scientific(2.0e-15, true), "2.0×10^{−15}");
        assert_eq!(scientific(2.0e-15, false), "2.0 × 10⁻¹⁵");
        assert_eq!(scientific(9.96e3, false), "1.0 × 10⁴");
        assert_eq!(scientific(0.0, false), "0");
        assert_eq!(grouped(14_400), "14\u{2009}400");
        assert_eq!(grouped(999), "999");
        assert_eq!(grouped(1_179_792_000), "1\u{2009}179\u{2009}792\u{2009}000");
    }
}
