//! Numbers that must not be split at a line end: `3.7 %`, `4.9 ns`,
//! `160 × 90`, `39 171`. In running text the space inside them becomes a
//! no-break space (a narrow one between digit groups), so the browser
//! never leaves `%` or `ns` alone at the start of a line.

/// No-break space: between a number and its unit, and around `×`.
const NBSP: char = '\u{a0}';
/// Narrow no-break space: between the digit groups of `39 171`.
const NNBSP: char = '\u{202f}';

/// Units written after a number with a space.
const UNITS: &[&str] = &[
    "%", "ms", "ns", "µs", "s", "px", "rad", "°", "GB", "MB", "KB", "bytes",
];

/// `text` (running text, no code and no math) with the spaces inside its
/// numbers made unbreakable.
pub fn tie_numbers(text: &str) -> String {
    let chars: Vec<char> = text.chars().collect();
    let mut out = String::with_capacity(text.len());
    for (i, &c) in chars.iter().enumerate() {
        let after_digit = i > 0 && chars[i - 1].is_ascii_digit();
        out.push(if c == ' ' && after_digit && ties(&chars[i + 1..]) {
            if group_follows(&chars[i + 1..]) {
                NNBSP
            } else {
                NBSP
            }
        } else if c == ' ' && chars.get(i.wrapping_sub(1)) == Some(&'×') {
            // `160 × 90`: the space after the sign, before the number
            if chars.get(i + 1).is_some_and(char::is_ascii_digit) {
                NBSP
            } else {
                c
            }
        } else {
            c
        });
    }
    out
}

/// Whether what follows a space after a digit belongs to the number: a
/// unit, `×` and a number, or a group of three digits.
fn ties(rest: &[char]) -> bool {
    group_follows(rest)
        || (rest.first() == Some(&'×')
            && rest.get(1) == Some(&' ')
            && rest.get(2).is_some_and(char::is_ascii_digit))
        || UNITS.iter().any(|unit| {
            let unit: Vec<char> = unit.chars().collect();
            rest.starts_with(&unit)
                && !rest.get(unit.len()).is_some_and(|c| c.is_alphanumeric())
        })
}

/// Three digits and then no more digits: the next group of `39 171`.
fn group_follows(rest: &[char]) -> bool {
    rest.len() >= 3
        && rest[..3].iter().all(char::is_ascii_digit)
        && !rest.get(3).is_some_and(|c| c.is_ascii_digit() || *c == '.')
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units_signs_and_digit_groups_stay_with_their_number() {
        assert_eq!(
            tie_numbers("3.7 % and 4.9 ns at 160 × 90, 39 171 rays"),
            "3.7\u{a0}% and 4.9\u{a0}ns at 160\u{a0}×\u{a0}90, \
             39\u{202f}171 rays"
        );
    }

    #[test]
    fn other_spaces_after_numbers_stay_breakable() {
        for text in [
            "depth 4 is exact",
            "in 2013 the test",
            "3 sides",
            "12 1234",
            "1 1.25",
        ] {
            assert_eq!(tie_numbers(text), text);
        }
    }
}
