//! Rendering and the files: determinism, outlined text, atomic writes and the check.

use std::fs;
use std::path::Path;

use raystep_figure::{
    Anchor, DVec2, Figure, FigureError, Format, Mismatch, Page, Stroke,
    check_all, palette, render, smallest_text_comment, write_all,
};

fn sample(name: &str) -> Figure {
    let mut page = Page::new(240.0, 160.0)
        .view(DVec2::new(-2.0, -1.0), DVec2::new(2.0, 1.5));
    page.scalar_field(|p| p.y - 0.5 * p.x, 1.0, 8.0);
    page.axes(palette::GREY);
    page.line(
        DVec2::ZERO,
        DVec2::new(2.0, 1.0),
        &Stroke::new(palette::BLACK),
    );
    page.point(DVec2::new(1.0, 1.0), palette::VERMILION);
    page.label(DVec2::new(1.0, 1.0), "P_0, θ < φ", Anchor::NE);
    Figure::new(name, "A sample.", page)
}

/// A fresh empty directory under the system temp dir, removed when the
/// test ends.
fn scratch(test: &str) -> tempfile::TempDir {
    tempfile::Builder::new()
        .prefix(&format!("raystep-figure-{test}-"))
        .tempdir()
        .unwrap()
}

fn png_size(png: &[u8]) -> (u32, u32) {
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
    assert_eq!(&png[12..16], b"IHDR");
    let be = |b: &[u8]| u32::from_be_bytes([b[0], b[1], b[2], b[3]]);
    (be(&png[16..20]), be(&png[20..24]))
}

fn names(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

#[test]
fn render_is_deterministic_with_text_outlined() {
    let a = render(&sample("a")).unwrap();
    let b = render(&sample("a")).unwrap();
    assert_eq!(a, b);
    let svg = String::from_utf8(a.svg).unwrap();
    assert!(!svg.contains("<text"), "text was not outlined");
    assert!(svg.contains("<path"));
    assert_eq!(png_size(&a.png), (480, 320));
}

#[test]
fn the_smallest_text_is_measured_and_recorded_after_the_svg_element() {
    // "P_0, θ < φ" at 16 px: its subscript is 0.7 × 16 = 11.2 px
    let rendered = render(&sample("small")).unwrap();
    assert_eq!(rendered.width, 240.0);
    let size = rendered.smallest_text.unwrap();
    assert!((size - 11.2).abs() < 1e-4, "{size}");
    let svg = String::from_utf8(rendered.svg).unwrap();
    let svg_end = svg.find('>').unwrap() + 1;
    assert!(svg[..svg_end].starts_with("<svg"), "{svg}");
    assert!(
        svg[svg_end..]
            .starts_with("\n<!-- raystep: smallest text 11.2 px -->\n"),
        "{svg}"
    );

    // a label inside a scaled group counts at its drawn size
    let mut page = Page::new(200.0, 100.0);
    page.label(DVec2::new(10.0, 50.0), "big", Anchor::E);
    page.raw_svg(
        r#"<g transform="rotate(30) scale(0.5)"><text x="20" y="40" font-size="20">small</text></g>"#,
    );
    let rendered = render(&Figure::new("scaled", "", page)).unwrap();
    assert!((rendered.smallest_text.unwrap() - 10.0).abs() < 1e-4);

    // a page without text
    let rendered = render(&Figure::new("blank", "", Page::new(10.0, 10.0)));
    assert_eq!(rendered.unwrap().smallest_text, None);
}

#[test]
fn the_recorded_size_is_rounded_down() {
    assert_eq!(
        smallest_text_comment(Some(11.2f32.into())),
        "<!-- raystep: smallest text 11.2 px -->"
    );
    assert_eq!(
        smallest_text_comment(Some(10.99)),
        "<!-- raystep: smallest text 10.9 px -->"
    );
    assert_eq!(
        smallest_text_comment(Some(16.0)),
        "<!-- raystep: smallest text 16.0 px -->"
    );
    assert_eq!(smallest_text_comment(None), "<!-- raystep: no text -->");
}

#[test]
fn write_all_writes_both_files_and_no_temporaries() {
    let scratch_dir = scratch("write");
    let dir = scratch_dir.path().join("nested");
    let written =
        write_all(&[sample("one"), sample("two")], &dir, Format::Both).unwrap();
    assert_eq!(
        written,
        ["one.svg", "one.png", "two.svg", "two.png"].map(|n| dir.join(n))
    );
    assert_eq!(names(&dir), ["one.png", "one.svg", "two.png", "two.svg"]);
    let rendered = render(&sample("one")).unwrap();
    assert_eq!(fs::read(dir.join("one.png")).unwrap(), rendered.png);

    let svg_only = scratch("write-svg");
    write_all(&[sample("one")], svg_only.path(), Format::Svg).unwrap();
    assert_eq!(names(svg_only.path()), ["one.svg"]);
}

#[test]
fn check_all_finds_differing_missing_and_extra_files() {
    let scratch_dir = scratch("check");
    let dir = scratch_dir.path();
    let figures = [sample("one"), sample("two")];
    write_all(&figures, dir, Format::Both).unwrap();
    assert_eq!(check_all(&figures, dir, Format::Both).unwrap(), []);

    fs::write(dir.join("one.svg"), "<svg/>").unwrap();
    fs::remove_file(dir.join("two.png")).unwrap();
    fs::write(dir.join("stray.svg"), "<svg/>").unwrap();
    fs::write(dir.join("notes.txt"), "not a figure").unwrap();
    let found = check_all(&figures, dir, Format::Both).unwrap();
    assert_eq!(
        found,
        [
            Mismatch::Differs(dir.join("one.svg")),
            Mismatch::Missing(dir.join("two.png")),
            Mismatch::Extra(dir.join("stray.svg")),
        ]
    );
    assert_eq!(
        found[1].to_string(),
        format!("missing: {}", dir.join("two.png").display())
    );
    // checking PNGs only ignores the SVG files
    assert_eq!(
        check_all(&figures, dir, Format::Png).unwrap(),
        [Mismatch::Missing(dir.join("two.png"))]
    );
}

#[test]
fn unwritable_directory_is_an_error_naming_the_path() {
    let scratch_dir = scratch("unwritable");
    let dir = scratch_dir.path();
    let file = dir.join("plain-file");
    fs::write(&file, "").unwrap();
    let target = file.join("figures");
    let err = write_all(&[sample("one")], &target, Format::Both).unwrap_err();
    assert!(matches!(err, FigureError::CreateDir { .. }), "{err:?}");
    let message = err.to_string();
    assert!(
        message.starts_with(&format!(
            "cannot create directory {}: ",
            target.display()
        )),
        "{message}"
    );
}

#[test]
fn bad_and_duplicate_names_are_errors() {
    let scratch_dir = scratch("names");
    let dir = scratch_dir.path();
    let err = write_all(&[sample("../up")], dir, Format::Svg).unwrap_err();
    assert!(err.to_string().contains("../up"), "{err}");
    let err =
        write_all(&[sample("x"), sample("x")], dir, Format::Svg).unwrap_err();
    assert_eq!(err.to_string(), "two figures are named x");
}
