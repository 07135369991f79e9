//! A small structured fuzzer for the input cases: valid seed files, and
//! seeded mutations of them. Every choice is drawn from
//! `ch08::SplitMix64`, so a seed gives the same inputs on every machine;
//! it runs on stable Rust and needs no dependency. Each mutation returns
//! the new input and whether the reader must refuse it (`true` only where
//! the file format leaves no doubt).
use std::ops::Range;

use ch08::{Ray32, SplitMix64};

/// The scene files the mutations start from: every field of the format,
/// and the chapters' scenes (spheres, planes, polygons, mirrors, glass,
/// chapter 8's primitives).
pub const SCENES: [&str; 7] = [
    include_str!("../../scene/src/example.toml"),
    include_str!("../../../chapters/ch03-illumination/scenes/spheres.toml"),
    include_str!("../../../chapters/ch04-shadows/scenes/acne.toml"),
    include_str!("../../../chapters/ch05-reflection/scenes/mirrors.toml"),
    include_str!("../../../chapters/ch06-refraction/scenes/materials.toml"),
    include_str!("../../../chapters/ch07-two-methods/scenes/shapes.toml"),
    include_str!(
        "../../../chapters/ch08-bounding-volumes/scenes/primitives.toml"
    ),
];

/// A unit cube: eight corners, twelve triangles.
pub const CUBE: &str = "# a unit cube\n\
    v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n\
    v 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n\
    f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\n\
    f 4 7 3\nf 4 8 7\nf 1 5 8\nf 1 8 4\nf 2 3 7\nf 2 7 6\n";

/// The same cube with texture coordinates, normals and quads
/// (`f v/vt/vn`), split into two objects.
pub const TEXTURED_CUBE: &str = "o front\n\
    v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n\
    v 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n\
    vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n\
    vn 0 0 -1\nvn 0 0 1\nvn 0 -1 0\nvn 0 1 0\nvn -1 0 0\nvn 1 0 0\n\
    f 1/1/1 4/4/1 3/3/1 2/2/1\nf 5/1/2 6/2/2 7/3/2 8/4/2\n\
    f 1/1/3 2/2/3 6/3/3 5/4/3\no back\n\
    f 4/1/4 8/4/4 7/3/4 3/2/4\nf 1/1/5 5/2/5 8/3/5 4/4/5\n\
    f 2/1/6 3/2/6 7/3/6 6/4/6\n";

/// The Stanford bunny of `shared/meshes`, from this crate's folder.
const BUNNY: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../../../shared/meshes/bunny.obj"
);

/// The OBJ seeds: the two cubes, and the bunny's first 200 vertices with
/// the faces among them (if `shared/meshes/bunny.obj` is there).
pub fn obj_seeds() -> Vec<String> {
    let mut seeds = vec![CUBE.to_owned(), TEXTURED_CUBE.to_owned()];
    if let Ok(bunny) = std::fs::read_to_string(BUNNY) {
        let inside = |line: &&str| {
            line.split_whitespace()
                .skip(1)
                .all(|w| w.parse::<usize>().is_ok_and(|i| i <= 200))
        };
        let vertices = bunny.lines().filter(|l| l.starts_with("v ")).take(200);
        let faces =
            bunny.lines().filter(|l| l.starts_with("f ")).filter(inside);
        let lines: Vec<&str> = vertices.chain(faces).collect();
        seeds.push(lines.join("\n") + "\n");
    }
    seeds
}

/// `count` seeded rays as a ray file's bytes (origins on a sphere of
/// radius 3, unit directions).
pub fn ray_seed(random: &mut Mutator, count: usize) -> Vec<u8> {
    let rays: Vec<Ray32> = (0..count)
        .map(|_| Ray32 {
            origin: (random.0.unit_vector() * 3.0).as_vec3(),
            direction: random.0.unit_vector().as_vec3(),
        })
        .collect();
    raystep_bench::ray_bytes(&rays)
}

/// Numbers that break readers: NaN, ∞, overflow, −0, the largest and
/// smallest, integers past i64, empty and garbage. `true`: a scene file
/// must refuse it wherever a number goes (its format says numbers are
/// finite TOML integers or floats).
pub const BAD_NUMBERS: [(&str, bool); 22] = [
    ("nan", true),
    ("-nan", true),
    ("inf", true),
    ("+inf", true),
    ("-inf", true),
    ("1e309", true),
    ("99999999999999999999", true),
    ("-9223372036854775809", true),
    ("", true),
    ("1..2", true),
    ("0x", true),
    ("1e", true),
    ("--1", true),
    ("1 2", true),
    ("1,5", true),
    ("\u{663}", true),
    ("-0", false),
    ("-0.0", false),
    ("1e308", false),
    ("-1e308", false),
    ("5e-324", false),
    ("9223372036854775807", false),
];

/// Finite numbers at the ends of f64's range, and zeros.
const EXTREMES: [&str; 8] = [
    "1e308", "-1e308", "5e-324", "-0", "0", "1e15", "-1e15", "1e-300",
];

/// Values of the wrong type for a number; `[1, 2, 3]` is a colour, so a
/// reader may take it.
const WRONG_TYPES: [(&str, bool); 8] = [
    ("\"1\"", true),
    ("'x'", true),
    ("true", true),
    ("{}", true),
    ("[]", true),
    ("1979-05-27", true),
    ("{ x = 1 }", true),
    ("[1, 2, 3]", false),
];

/// What an OBJ coordinate may become.
const OBJ_NUMBERS: [&str; 18] = [
    "nan", "NaN", "inf", "-inf", "infinity", "1e39", "-1e39", "1e308",
    "3.5e38", "-0", "1e-46", "", "x", "1,5", "0x10", "1e", "1..2", "--1",
];

/// What may follow a vertex's x y z, and whether it must be refused: a
/// `w` of 0, NaN, tiny or 2; two numbers (neither `w` nor a colour); a
/// colour.
const MORE_COORDINATES: [(&str, bool); 6] = [
    ("0", true),
    ("nan", false),
    ("1e-45", false),
    ("2", false),
    ("1 2", true),
    ("0.5 0.5 0.5", false),
];

/// Lines an OBJ file may hold that give no triangle, or that name what is
/// not there.
const STRAY_LINES: [&str; 15] = [
    "f\n",
    "f 1\n",
    "f 1 2\n",
    "l 1 2\n",
    "p 1\n",
    "vp 1 2\n",
    "o\n",
    "g\n",
    "s off\n",
    "usemtl none\n",
    "mtllib missing.mtl\n",
    "v\n",
    "vn\n",
    "\t\n",
    "f 1 2 3 \\\n",
];

/// The bits of NaNs (quiet, signalling, negative, with a payload), ±∞,
/// ±f32::MAX, the smallest subnormal and −0.
const SPECIAL_F32: [u32; 10] = [
    0x7FC0_0000,
    0x7F80_0001,
    0xFFC0_0000,
    0x7FA5_A5A5,
    0x7F80_0000,
    0xFF80_0000,
    0x7F7F_FFFF,
    0xFF7F_FFFF,
    0x0000_0001,
    0x8000_0000,
];

/// Byte sequences that are never UTF-8, or not where they are put.
const BAD_UTF8: [&[u8]; 7] = [
    &[0xFF],
    &[0xC0, 0x80],
    &[0x80],
    &[0xE2, 0x82],
    &[0xED, 0xA0, 0x80],
    &[0xF8, 0x88, 0x80, 0x80, 0x80],
    &[0xFE, 0xFF],
];

/// Draws the choices of every mutation.
pub struct Mutator(SplitMix64);

impl Mutator {
    /// The mutator started from `seed`.
    pub fn new(seed: u64) -> Mutator {
        Mutator(SplitMix64::new(seed))
    }

    /// A number in `0..n` (`n ≥ 1`).
    pub fn below(&mut self, n: usize) -> usize {
        crate::trials::below(&mut self.0, n)
    }

    /// One of `items`, uniformly.
    pub fn pick<T: Copy>(&mut self, items: &[T]) -> T {
        items[self.below(items.len())]
    }

    /// `text` cut at a random character.
    pub fn truncated(&mut self, text: &str) -> String {
        let mut end = self.below(text.len() + 1);
        while !text.is_char_boundary(end) {
            end -= 1;
        }
        text[..end].to_owned()
    }

    /// `bytes` cut at a random byte.
    pub fn truncated_bytes(&mut self, bytes: &[u8]) -> Vec<u8> {
        bytes[..self.below(bytes.len() + 1)].to_vec()
    }

    /// One to three lines deleted, duplicated or swapped.
    pub fn lines_edited(&mut self, text: &str) -> String {
        let mut lines: Vec<&str> = text.split_inclusive('\n').collect();
        for _ in 0..1 + self.below(3) {
            if lines.is_empty() {
                break;
            }
            let (i, j) = (self.below(lines.len()), self.below(lines.len()));
            match self.below(3) {
                0 => drop(lines.remove(i)),
                1 => lines.insert(j, lines[i]),
                _ => lines.swap(i, j),
            }
        }
        lines.concat()
    }

    /// One number of a TOML file replaced by one of [`BAD_NUMBERS`].
    pub fn bad_number(&mut self, text: &str) -> (String, bool) {
        let (by, reject) = self.pick(&BAD_NUMBERS);
        self.replace_number(text, by, reject)
    }

    /// One number of a TOML file replaced by a finite extreme (±1e308,
    /// the smallest subnormal, −0, 0, 10¹⁵): a scene a reader may take.
    pub fn extreme_number(&mut self, text: &str) -> String {
        let by = self.pick(&EXTREMES);
        self.replace_number(text, by, false).0
    }

    /// A key or table name renamed, a number of the wrong type, or an
    /// `[x, y, z]` with two or four numbers: each is refused.
    pub fn wrong_key_or_type(&mut self, text: &str) -> (String, bool) {
        match self.below(3) {
            0 => {
                let keys = keys(text);
                if keys.is_empty() {
                    return (text.to_owned(), false);
                }
                let key = keys[self.below(keys.len())].clone();
                let name = &text[key.clone()];
                let renamed = match self.below(4) {
                    0 => format!("zz_{name}"),
                    1 => format!("{name}_"),
                    2 => name[..1].to_uppercase() + &name[1..],
                    _ => format!("{name}{}", &name[name.len() - 1..]),
                };
                (splice(text, key, &renamed), true)
            }
            1 => {
                let (by, reject) = self.pick(&WRONG_TYPES);
                self.replace_number(text, by, reject)
            }
            _ => {
                let arrays = number_arrays(text);
                if arrays.is_empty() {
                    return (text.to_owned(), false);
                }
                let inner = arrays[self.below(arrays.len())].clone();
                let items: Vec<&str> = text[inner.clone()].split(',').collect();
                let changed = if self.below(2) == 0 {
                    items[..items.len() - 1].join(",")
                } else {
                    items.join(",") + ", 0"
                };
                (splice(text, inner, &changed), true)
            }
        }
    }

    /// Bytes that are not UTF-8 put at a random place (or over a byte);
    /// whether the result is still UTF-8 decides `reject`.
    pub fn invalid_utf8(&mut self, bytes: &[u8]) -> (Vec<u8>, bool) {
        let mut out = bytes.to_vec();
        let at = self.below(out.len() + 1);
        let bad = self.pick(&BAD_UTF8);
        if self.below(4) == 0 && at < out.len() {
            out.splice(at..at + 1, bad.iter().copied());
        } else {
            out.splice(at..at, bad.iter().copied());
        }
        let reject = std::str::from_utf8(&out).is_err();
        (out, reject)
    }

    /// A line of 10³ to 10⁵ characters (a comment, a key, a number, a
    /// string) or a value nested 10² to 10⁴ deep.
    pub fn overlong(&mut self, text: &str) -> (String, bool) {
        let long = [1_000, 10_000, 100_000][self.below(3)];
        let deep = [100, 1_000, 10_000][self.below(3)];
        match self.below(6) {
            0 => (format!("# {}\n{text}", "x".repeat(long)), false),
            1 => (format!("{} = 1\n{text}", "k".repeat(long)), true),
            2 => self.replace_number(text, &"9".repeat(long), true),
            3 => self.replace_number(
                text,
                &format!("0.{}", "1".repeat(long)),
                false,
            ),
            4 => {
                let value = format!("\"{}\"", "s".repeat(long));
                self.replace_number(text, &value, true)
            }
            _ => {
                let (open, close) = if self.below(2) == 0 {
                    ("[", "]")
                } else {
                    ("{a=", "}")
                };
                let value = open.repeat(deep) + "1" + &close.repeat(deep);
                self.replace_number(text, &value, true)
            }
        }
    }

    /// One index of an `f` line made bad: 0, −0, past the last vertex,
    /// before the first (negative), past u32 or i64, not an integer; in
    /// the `v` part (refused) or the `vt`/`vn` part (refused if not an
    /// integer).
    pub fn bad_index(&mut self, text: &str) -> (String, bool) {
        let lines: Vec<&str> = text.split_inclusive('\n').collect();
        let starts =
            |k: &str| lines.iter().filter(|l| l.starts_with(k)).count();
        let faces: Vec<usize> = (0..lines.len())
            .filter(|&k| lines[k].starts_with("f "))
            .collect();
        if faces.is_empty() {
            return (text.to_owned(), false);
        }
        let k = self.pick(&faces);
        let words: Vec<&str> = lines[k].split_whitespace().collect();
        let w = 1 + self.below(words.len() - 1);
        let mut parts: Vec<&str> = words[w].split('/').collect();
        let part = self.below(parts.len());
        let kind = ["v ", "vt ", "vn "][part.min(2)];
        let count = starts(kind);
        let before = lines[..k].iter().filter(|l| l.starts_with(kind)).count();
        let bad = match self.below(10) {
            0 => "0".to_owned(),
            1 => "-0".to_owned(),
            2 => (count + 1).to_string(),
            3 => (count + 2 + self.below(1000)).to_string(),
            4 => format!("-{}", before + 1 + self.below(3)),
            5 => (1u64 << 32).to_string(),
            6 => "99999999999999999999".to_owned(),
            7 => i64::MIN.to_string(),
            8 => i64::MAX.to_string(),
            _ => self.pick(&["x", "1.0", "1e3", "0x1"]).to_owned(),
        };
        let integer = bad.parse::<isize>().is_ok();
        parts[part] = &bad;
        let face = parts.join("/");
        let mut words = words;
        words[w] = &face;
        let line = words.join(" ") + "\n";
        let edited: String =
            lines[..k].concat() + &line + &lines[k + 1..].concat();
        (edited, part == 0 || !integer)
    }

    /// One coordinate of a `v`, `vt` or `vn` line made NaN, ∞, too large
    /// for f32, −0, tiny, empty or garbage; or a coordinate dropped (refused),
    /// or one to three more (a `w` of 0 and five numbers are refused).
    pub fn bad_vertex(&mut self, text: &str) -> (String, bool) {
        let mut lines: Vec<String> = text.lines().map(str::to_owned).collect();
        let vertices: Vec<usize> = (0..lines.len())
            .filter(|&k| {
                ["v ", "vt ", "vn "].iter().any(|p| lines[k].starts_with(p))
            })
            .collect();
        if vertices.is_empty() {
            return (text.to_owned(), false);
        }
        let k = self.pick(&vertices);
        let mut words: Vec<String> =
            lines[k].split_whitespace().map(str::to_owned).collect();
        let need = if words[0] == "vt" { 2 } else { 3 };
        let reject = match self.below(4) {
            0 | 1 => {
                let by = self.pick(&OBJ_NUMBERS);
                words[1 + self.below(need)] = by.to_owned();
                by.parse::<f32>().is_err()
            }
            2 => {
                words.truncate(need);
                true
            }
            _ if words[0] == "v" => {
                let (more, reject) = self.pick(&MORE_COORDINATES);
                words.push(more.to_owned());
                reject
            }
            _ => {
                words.push("7".to_owned());
                false
            }
        };
        lines[k] = words.join(" ");
        (lines.join("\n") + "\n", reject)
    }

    /// A file cut at a random byte, lines edited, a stray line (`f` with
    /// fewer than three indices, `vp`, `o`, `mtllib` of a missing file),
    /// bytes that are not UTF-8 (refused), or a line of 10⁴–10⁵ characters.
    pub fn obj_garbage(&mut self, text: &str) -> (Vec<u8>, bool) {
        match self.below(5) {
            0 => (self.truncated_bytes(text.as_bytes()), false),
            1 => (self.lines_edited(text).into_bytes(), false),
            2 => {
                let mut lines: Vec<&str> = text.split_inclusive('\n').collect();
                let stray = self.pick(&STRAY_LINES);
                lines.insert(self.below(lines.len() + 1), stray);
                (lines.concat().into_bytes(), false)
            }
            3 => self.invalid_utf8(text.as_bytes()),
            _ => {
                let long = [10_000, 100_000][self.below(2)];
                let line = match self.below(4) {
                    0 => format!("v 1{} 0 0\n", "0".repeat(long)),
                    1 => format!("# {}\n", "x".repeat(long)),
                    2 => format!("f{}\n", " 1 2 3".repeat(long / 6)),
                    _ => format!("{}\n", "x".repeat(long)),
                };
                (format!("{text}{line}").into_bytes(), false)
            }
        }
    }

    /// A ray file cut at a random byte, lengthened by 1 to 23 bytes (or by
    /// whole rays and some), or emptied.
    pub fn ray_length(&mut self, bytes: &[u8]) -> Vec<u8> {
        let mut out = bytes.to_vec();
        match self.below(4) {
            0 => out.truncate(self.below(bytes.len() + 1)),
            1 => out
                .extend((0..1 + self.below(23)).map(|_| self.below(256) as u8)),
            2 => out.extend(
                (0..24 * (1 + self.below(3)) + self.below(24)).map(|i| i as u8),
            ),
            _ => out.clear(),
        }
        out
    }

    /// One to three floats of a ray file replaced by NaN (quiet,
    /// signalling, negative, with a payload), ±∞, ±f32::MAX, the smallest
    /// subnormal or −0; or a ray's direction made zero.
    pub fn ray_special(&mut self, bytes: &[u8]) -> Vec<u8> {
        let mut out = bytes.to_vec();
        let floats = out.len() / 4;
        if self.below(5) == 0 {
            let ray = self.below(floats / 6);
            out[24 * ray + 12..24 * ray + 24].fill(0);
            return out;
        }
        for _ in 0..1 + self.below(3) {
            let k = self.below(floats);
            let bits: u32 = self.pick(&SPECIAL_F32);
            out[4 * k..4 * k + 4].copy_from_slice(&bits.to_le_bytes());
        }
        out
    }

    /// A random number of `text` replaced by `by`.
    fn replace_number(
        &mut self, text: &str, by: &str, reject: bool,
    ) -> (String, bool) {
        let numbers = numbers(text);
        if numbers.is_empty() {
            return (text.to_owned(), false);
        }
        let at = numbers[self.below(numbers.len())].clone();
        (splice(text, at, by), reject)
    }
}

/// `text` with `range` replaced by `by`.
fn splice(text: &str, range: Range<usize>, by: &str) -> String {
    format!("{}{by}{}", &text[..range.start], &text[range.end..])
}

/// Per byte of a TOML text: whether it is code (outside strings and
/// comments).
fn code(text: &str) -> Vec<bool> {
    let bytes = text.as_bytes();
    let mut mask = vec![true; bytes.len()];
    let (mut quote, mut comment, mut escaped) = (None, false, false);
    for (i, &b) in bytes.iter().enumerate() {
        if comment {
            comment = b != b'\n';
            mask[i] = !comment;
        } else if let Some(q) = quote {
            mask[i] = false;
            if escaped {
                escaped = false;
            } else if b == b'\\' && q == b'"' {
                escaped = true;
            } else if b == q || b == b'\n' {
                quote = None;
            }
        } else if b == b'#' {
            (comment, mask[i]) = (true, false);
        } else if b == b'"' || b == b'\'' {
            (quote, mask[i]) = (Some(b), false);
        }
    }
    mask
}

/// The last code byte before `i` that is not white space.
fn code_before(text: &[u8], mask: &[bool], i: usize) -> Option<u8> {
    (0..i)
        .rev()
        .find(|&k| mask[k] && !text[k].is_ascii_whitespace())
        .map(|k| text[k])
}

/// The spans of the numbers that are values (after `=`, `[` or `,`).
fn numbers(text: &str) -> Vec<Range<usize>> {
    let (b, mask) = (text.as_bytes(), code(text));
    let part = |c: u8| c.is_ascii_alphanumeric() || b"._+-".contains(&c);
    let mut spans = Vec::new();
    let mut i = 0;
    while i < b.len() {
        let signed = b"+-".contains(&b[i])
            && b.get(i + 1).is_some_and(u8::is_ascii_digit);
        let start = mask[i]
            && (b[i].is_ascii_digit() || signed)
            && code_before(b, &mask, i).is_some_and(|c| b"=[,".contains(&c));
        if start {
            let end = (i..b.len()).find(|&k| !part(b[k])).unwrap_or(b.len());
            spans.push(i..end);
            i = end;
        } else {
            i += 1;
        }
    }
    spans
}

/// The spans of the bare keys before `=` and of each table header's
/// first name (`materials` of `[materials.red]`, never the material's
/// own name, which a scene chooses freely).
fn keys(text: &str) -> Vec<Range<usize>> {
    let (b, mask) = (text.as_bytes(), code(text));
    let bare = |c: u8| c.is_ascii_alphanumeric() || c == b'_' || c == b'-';
    let mut spans = Vec::new();
    let mut i = 0;
    while i < b.len() {
        if !(mask[i] && bare(b[i])) || (i > 0 && bare(b[i - 1])) {
            i += 1;
            continue;
        }
        let end = (i..b.len()).find(|&k| !bare(b[k])).unwrap_or(b.len());
        let line_start = text[..i].rfind('\n').map_or(0, |k| k + 1);
        let before = text[line_start..i].trim();
        let after = text[end..].trim_start_matches([' ', '\t']);
        let is_key = (after.starts_with('=') && !after.starts_with("=="))
            && (before.is_empty() || before.ends_with(['{', ',']));
        let is_header = before == "[" || before == "[[";
        if is_key || is_header {
            spans.push(i..end);
        }
        i = end;
    }
    spans
}

/// The inside of each `[…]` that holds only numbers (`[0, 1, 5]`).
fn number_arrays(text: &str) -> Vec<Range<usize>> {
    let mask = code(text);
    let mut spans = Vec::new();
    for (open, _) in text.match_indices('[').filter(|(i, _)| mask[*i]) {
        let Some(close) = text[open + 1..].find(['[', ']']) else {
            continue;
        };
        let inner = open + 1..open + 1 + close;
        let all_numbers = text[inner.clone()].split(',').all(|item| {
            let item = item.trim();
            !item.is_empty() && item.parse::<f64>().is_ok()
        });
        if text.as_bytes()[inner.end] == b']' && all_numbers {
            spans.push(inner);
        }
    }
    spans
}
