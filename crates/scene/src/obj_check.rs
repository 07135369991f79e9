//! An OBJ file checked line by line before the OBJ reader (`tobj`) sees
//! it, so that every error names its line: `tobj` says "face parse
//! error" or "texcoord index out of bounds" without one, and (in a debug
//! build) overflows on a negative index far before the first vertex.
//! The stability catalogue's input cases found these.

/// The first problem of `text`, as `line N: what: the line`; None if
/// every line this reader uses is well formed.
pub(crate) fn check_obj(text: &str) -> Option<String> {
    // Step 1: how many of each kind of vertex data came so far (a face
    // may only use those, counting back from the last with −1).
    let (mut v, mut vt, mut vn) = (0usize, 0usize, 0usize);
    let mut coloured: Option<bool> = None;
    for (number, line) in text.lines().enumerate() {
        let problem = |what: &str| {
            Some(format!("line {}: {what}: {}", number + 1, line.trim()))
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
                if numbers.is_none_or(|n| n.len() != 3) {
                    return problem("a normal is 3 numbers");
                }
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
                }
            }
            _ => {}
        }
    }
    None
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
        let text = format!(
            "{CUBE_CORNER}f 1 2 3\nf 1/1 2/1 3/1\nf -3//1 -2//1 -1//1\n"
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
        ];
        for (line, expected) in cases {
            let text = format!("{CUBE_CORNER}{line}\n");
            let message = check_obj(&text).unwrap_or_default();
            assert!(message.starts_with(expected), "{line}: {message}");
        }
    }
}
