//! An OBJ file checked line by line before the OBJ reader (`tobj`) sees
//! it, so that every error names its line: `tobj` says "face parse
//! error" or "texcoord index out of bounds" without one, and (in a debug
//! build) overflows on a negative index far before the first vertex.
//! The stability catalogue's input cases found these.

use std::fmt;

use raystep_core::DVec3;

/// What is wrong with an OBJ file, and on which line.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct ObjProblem {
    /// The 1-based line.
    pub line: usize,
    /// What is wrong, then the line itself: `what: the line`.
    pub what: String,
}

impl fmt::Display for ObjProblem {
    /// `line N: what: the line`.
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        write!(f, "line {}: {}", self.line, self.what)
    }
}

/// The first problem of `text`; None if every line this reader uses is
/// well formed.
pub(crate) fn check_obj(text: &str) -> Option<ObjProblem> {
    // Step 1: how many of each kind of vertex data came so far (a face
    // may only use those, counting back from the last with −1).
    let (mut v, mut vt, mut vn) = (0usize, 0usize, 0usize);
    let mut coloured: Option<bool> = None;
    // each normal's line and what is wrong with it, if anything (only
    // a normal a face uses must have a direction)
    let mut normals: Vec<(usize, Option<&str>)> = Vec::new();
    let mut corners_with_normals: Option<bool> = None;
    let lines: Vec<&str> = text.lines().collect();
    for (number, line) in lines.iter().enumerate() {
        let problem = |what: &str| {
            Some(ObjProblem {
                line: number + 1,
                what: format!("{what}: {}", line.trim()),
            })
        };
        let mut words = line.split_whitespace();
        let keyword = words.next();
        let values: Vec<&str> = words.collect();
        let numbers: Option<Vec<f32>> =
            values.iter().map(|w| w.parse::<f32>().ok()).collect();
        match keyword {
            // Step 2: a vertex: x y z, x y z w (w ≠ 0) or x y z r g b,
            // finite.
            Some("v") => {
                v += 1;
                let Some(p) = numbers.filter(|p| matches!(p.len(), 3 | 4 | 6))
                else {
                    return problem(
                        "a vertex is 3 numbers (or x y z w, or x y z r g b)",
                    );
                };
                if p.len() == 4 && p[3] == 0.0 {
                    return problem("a vertex's w is 0");
                }
                // (the reader divides by w)
                let w = if p.len() == 4 { p[3] } else { 1.0 };
                if p[..3].iter().any(|x| !(x / w).is_finite()) {
                    return problem(&format!("vertex {v} is not finite"));
                }
                let has_colour = p.len() == 6;
                if *coloured.get_or_insert(has_colour) != has_colour {
                    return problem("vertex colours on some vertices only");
                }
            }
            // Step 3: texture coordinates (u v, or u v w: the reader
            // refuses a lone u) and normals (3).
            Some("vt") => {
                vt += 1;
                if numbers.is_none_or(|t| !(2..=3).contains(&t.len())) {
                    return problem("texture coordinates are 2 or 3 numbers");
                }
            }
            Some("vn") => {
                vn += 1;
                let Some(n) = numbers.filter(|n| n.len() == 3) else {
                    return problem("a normal is 3 numbers");
                };
                let n = DVec3::new(n[0].into(), n[1].into(), n[2].into());
                let fault = if !n.is_finite() {
                    Some("is not finite")
                } else if n.try_normalize().is_none() {
                    Some("has no direction (it is zero)")
                } else {
                    None
                };
                normals.push((number + 1, fault));
            }
            // Step 4: a face: three or more corners v, v/vt, v//vn or
            // v/vt/vn, each index within what came before.
            Some("f") => {
                if values.len() < 3 {
                    return problem("a face has at least 3 corners");
                }
                for corner in &values {
                    let parts: Vec<&str> = corner.split('/').collect();
                    if parts.len() > 3 {
                        return problem(
                            "a corner is v, v/vt, v//vn or v/vt/vn",
                        );
                    }
                    // (the reader lines normals up with vertices only
                    // if every corner has one, or none has)
                    let has_normal =
                        parts.get(2).is_some_and(|n| !n.is_empty());
                    if *corners_with_normals.get_or_insert(has_normal)
                        != has_normal
                    {
                        return problem("normals on some face corners only");
                    }
                    let counts = [v, vt, vn];
                    for (k, part) in parts.iter().enumerate() {
                        if k > 0 && part.is_empty() {
                            continue; // v//vn: no texture coordinate
                        }
                        if !index_ok(part, counts[k]) {
                            let kind = ["vertex", "texture", "normal"][k];
                            return problem(&format!(
                                "{kind} index {part} is not one of the {} \
                                 before it",
                                counts[k]
                            ));
                        }
                    }
                    // Step 5: a normal a face uses has a direction (the
                    // fault is named on the normal's own line).
                    if let Some(k) = parts.get(2).and_then(|p| resolve(p, vn))
                        && let Some(&(at, Some(fault))) = normals.get(k)
                    {
                        return Some(ObjProblem {
                            line: at,
                            what: format!(
                                "normal {} {fault}, and the face on line {} \
                                 uses it: {}",
                                k + 1,
                                number + 1,
                                lines[at - 1].trim()
                            ),
                        });
                    }
                }
            }
            _ => {}
        }
    }
    None
}

/// The 0-based position of `word`, an OBJ index into `count` items
/// (None where [`index_ok`] would refuse it).
fn resolve(word: &str, count: usize) -> Option<usize> {
    let i = word.parse::<i64>().ok()?;
    let k = i.unsigned_abs() as usize;
    match i {
        1.. => Some(k - 1).filter(|&k| k < count),
        ..0 => count.checked_sub(k),
        0 => None,
    }
}

/// Is `word` an OBJ index into `count` items: 1 to `count`, or −1 (the
/// last) to −`count`?
fn index_ok(word: &str, count: usize) -> bool {
    match word.parse::<i64>() {
        Ok(i) if i > 0 => i.unsigned_abs() as usize <= count,
        Ok(i) if i < 0 => i.unsigned_abs() as usize <= count,
        _ => false,
    }
}

#[cfg(test)]
mod tests {
    use super::check_obj;

    const CUBE_CORNER: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n";

    #[test]
    fn a_good_file_passes() {
        let text = format!("{CUBE_CORNER}f 1 2 3\nf 1/1 2/1 3/1\n");
        assert_eq!(check_obj(&text), None);
        // normals at every corner (and a zero one no face uses)
        let text = format!(
            "{CUBE_CORNER}vn 0 0 0\nf 1//1 2//1 3//1\nf -3/1/-2 -2/1/1 -1/1/1\n"
        );
        assert_eq!(check_obj(&text), None);
        // colours on every vertex, and w
        assert_eq!(
            check_obj("v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nf 1 2 3\n"),
            None
        );
        assert_eq!(
            check_obj("v 0 0 0 1\nv 1 0 0 2\nv 0 1 0 1\nf 1 2 3\n"),
            None
        );
    }

    #[test]
    fn each_problem_names_its_line() {
        let cases = [
            ("f 1/-3 2/1 3/1", "line 6: texture index -3"),
            ("f 1/5 2/1 3/1", "line 6: texture index 5"),
            ("f 1//2 2//1 3//1", "line 6: normal index 2"),
            ("f 1/x 2 3", "line 6: texture index x"),
            ("f 1 2", "line 6: a face has at least 3 corners"),
            ("f 0 1 2", "line 6: vertex index 0"),
            ("f 1 2 4", "line 6: vertex index 4"),
            ("v 0 0 1e39", "line 6: vertex 4 is not finite"),
            ("v 0 0 0 0", "line 6: a vertex's w is 0"),
            ("v 1e30 0 0 1e-30", "line 6: vertex 4 is not finite"),
            ("v 0 0", "line 6: a vertex is 3 numbers"),
            (
                "v 0 0 0 1 2 3",
                "line 6: vertex colours on some vertices only",
            ),
            (
                "vt 1 2 3 4",
                "line 6: texture coordinates are 2 or 3 numbers",
            ),
            ("vt 1", "line 6: texture coordinates are 2 or 3 numbers"),
            ("vn 1 x 3", "line 6: a normal is 3 numbers"),
            (
                "f 1//1 2 3",
                "line 6: normals on some face corners only: f 1//1 2 3",
            ),
            (
                "vn 0 0 0\nf 1 2 3\nf 1//2 2//2 3//2",
                "line 8: normals on some face corners only",
            ),
            (
                "vn 0 0 0\nf 1//1 2//1 3//-1",
                "line 6: normal 2 has no direction (it is zero), and the \
                 face on line 7 uses it: vn 0 0 0",
            ),
            (
                "vn nan 0 1\nf 1//1 2//2 3//1",
                "line 6: normal 2 is not finite, and the face on line 7 \
                 uses it: vn nan 0 1",
            ),
            (
                "vn 1e39 0 0\nf 1//2 2//2 3//2",
                "line 6: normal 2 is not finite",
            ),
        ];
        for (line, expected) in cases {
            let text = format!("{CUBE_CORNER}{line}\n");
            let message =
                check_obj(&text).map(|p| p.to_string()).unwrap_or_default();
            assert!(message.starts_with(expected), "{line}: {message}");
        }
    }
}
