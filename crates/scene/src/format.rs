//! Numbers as error messages show them: as written, in exponent form
//! when very small or large.
use raystep_core::DVec3;

/// `v` as the error messages show numbers: `-1`, `0.5`, `inf`, `nan`.
pub(crate) fn format_number(v: f64) -> String {
    if v.is_nan() {
        "nan".to_owned()
    } else if v != 0.0 && v.is_finite() && !(1e-6..1e16).contains(&v.abs()) {
        format!("{v:e}")
    } else {
        v.to_string()
    }
}

pub(crate) fn format_vec(v: DVec3) -> String {
    format!(
        "[{}, {}, {}]",
        format_number(v.x),
        format_number(v.y),
        format_number(v.z)
    )
}
