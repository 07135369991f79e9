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
        let e: String = e.chars().map(superscript).collect();
        format!("{m} × 10{e}")
    }
}

/// `x` as a power of ten, as label markup: `10^{−4}`, or with one
/// decimal of mantissa where it is not 1: `1.1·10^{−16}`, `−2.5·10^{3}`.
pub fn power(x: f64) -> String {
    if x == 0.0 {
        return "0".to_string();
    }
    let exponent = x.abs().log10().floor() as i32;
    let mantissa = x / 10f64.powi(exponent);
    let mut m = format!("{mantissa:.1}");
    // 9.96 rounds up to 10.0: one more power of ten
    let exponent = if m.trim_start_matches('-') == "10.0" {
        m = format!("{:.1}", mantissa / 10.0);
        exponent + 1
    } else {
        exponent
    };
    let power = if exponent < 0 {
        format!("10^{{−{}}}", -exponent)
    } else {
        format!("10^{{{exponent}}}")
    };
    match m.as_str() {
        "1.0" => power,
        "-1.0" => format!("−{power}"),
        _ => format!("{}·{power}", m.replace('-', "−")),
    }
}

/// [`power`] in plain Unicode, for captions: `1.1·10⁻¹⁶`.
pub fn power_text(x: f64) -> String {
    let markup = power(x);
    let Some((mantissa, exponent)) = markup.split_once("^{") else {
        return markup;
    };
    let raised: String = exponent
        .trim_end_matches('}')
        .chars()
        .map(superscript)
        .collect();
    format!("{mantissa}{raised}")
}

/// A digit or minus sign raised: `−` → `⁻`, `4` → `⁴`; anything else as it is.
pub fn superscript(c: char) -> char {
    const SUPERSCRIPTS: [char; 10] =
        ['⁰', '¹', '²', '³', '⁴', '⁵', '⁶', '⁷', '⁸', '⁹'];
    match c {
        '−' | '-' => '⁻',
        _ => c.to_digit(10).map_or(c, |d| SUPERSCRIPTS[d as usize]),
    }
}

/// An axis label on a log axis that draws zeros at `floor`: "0" at or
/// below it, whole numbers from 1 up, the rest as they are (`0.1`).
pub fn floored(y: f64, floor: f64) -> String {
    if y <= floor {
        "0".to_string()
    } else if y >= 1.0 {
        format!("{y:.0}")
    } else {
        format!("{y}")
    }
}

/// A number with a thin space between thousands: 14 400.
pub fn grouped(n: u64) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (k, c) in digits.chars().enumerate() {
        if k > 0 && (digits.len() - k).is_multiple_of(3) {
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
        assert_eq!(floored(0.01, 0.01), "0");
        assert_eq!(floored(0.1, 0.01), "0.1");
        assert_eq!(floored(12.0, 0.01), "12");
        assert_eq!(power(1e-4), "10^{−4}");
        assert_eq!(power(1.1e-16), "1.1·10^{−16}");
        assert_eq!(power(-9.96e2), "−10^{3}");
        assert_eq!(power(2.5e3), "2.5·10^{3}");
        assert_eq!(power_text(1.1e-16), "1.1·10⁻¹⁶");
        assert_eq!(power_text(1e4), "10⁴");
        assert_eq!(
            grouped(1_179_792_000),
            "1\u{2009}179\u{2009}792\u{2009}000"
        );
    }
}

/// `x` with at most `decimals` decimals, trailing zeros dropped and never
/// `-0`, with the ASCII minus (for LaTeX and TOML text, not for drawing):
/// `0.5`, `12`, `-0.25`.
pub fn trimmed(x: f64, decimals: usize) -> String {
    let text = format!("{x:.decimals$}");
    let text = text.trim_end_matches('0').trim_end_matches('.');
    if text == "-0" {
        "0".into()
    } else {
        text.into()
    }
}

/// `(x, y, z)`, each [`trimmed`] to `decimals`.
pub fn triple(v: raystep_core::DVec3, decimals: usize) -> String {
    let [x, y, z] = v.to_array().map(|c| trimmed(c, decimals));
    format!("({x}, {y}, {z})")
}

#[cfg(test)]
mod trimmed_tests {
    use super::*;

    #[test]
    fn trimmed_numbers_drop_zeros_and_the_sign_of_zero() {
        assert_eq!(trimmed(0.5, 4), "0.5");
        assert_eq!(trimmed(12.0, 3), "12");
        assert_eq!(trimmed(-0.00001, 3), "0");
        assert_eq!(trimmed(-0.8165, 2), "-0.82");
        let v = raystep_core::DVec3::new(1.0, -2.5, 0.125);
        assert_eq!(triple(v, 2), "(1, -2.5, 0.12)");
    }
}
