//! The `main` of every chapter's diagram binary.

use std::path::PathBuf;
use std::process::ExitCode;

use crate::Chapter;
use crate::output::{Format, check_all, write_all};

/// What the command line asked for.
#[derive(Debug, PartialEq)]
struct Args {
    out: PathBuf,
    format: Format,
    check: bool,
}

/// Parses the arguments after the program name. `Ok(None)` means `--help`.
fn parse_args(
    args: impl IntoIterator<Item = String>,
) -> Result<Option<Args>, String> {
    let mut out = None;
    let mut format = Format::Both;
    let mut check = false;
    let mut args = args.into_iter();
    while let Some(arg) = args.next() {
        let (flag, inline) = match arg.split_once('=') {
            Some((flag, value)) if flag.starts_with("--") => {
                (flag.to_string(), Some(value.to_string()))
            }
            _ => (arg.clone(), None),
        };
        let mut value = |name: &str| {
            inline
                .clone()
                .or_else(|| args.next())
                .ok_or_else(|| format!("{name} needs a value"))
        };
        match flag.as_str() {
            "--out" => out = Some(PathBuf::from(value("--out")?)),
            "--format" => format = value("--format")?.parse()?,
            "--check" if inline.is_none() => check = true,
            "-h" | "--help" if inline.is_none() => return Ok(None),
            _ => return Err(format!("unknown argument {arg:?}")),
        }
    }
    let out = out.ok_or("--out DIR is required")?;
    Ok(Some(Args { out, format, check }))
}

/// The whole `main` of a chapter's diagram binary: draws `chapter`'s
/// figures (and charts).
///
/// Usage: `<bin> --out DIR [--format svg|png|both] [--check]` (format defaults to both).
/// Writes the figures of `figures()` into DIR and prints one line per file written. With
/// `--check` it writes nothing and prints one line per file that differs, is missing or is
/// extra, failing if there is any. On an error it prints one line to stderr and fails; bad
/// arguments print a one-line usage error and exit with status 2.
pub fn diagram_main(chapter: &Chapter) -> ExitCode {
    let (program, chapter, figures) =
        (format!("{}-figures", chapter.id), chapter.id, chapter);
    let usage =
        format!("usage: {program} --out DIR [--format svg|png|both] [--check]");
    let args = match parse_args(std::env::args().skip(1)) {
        Ok(Some(args)) => args,
        Ok(None) => {
            println!("{usage}");
            println!(
                "Draws the {chapter} lecture figures into DIR as SVG and/or PNG files."
            );
            return ExitCode::SUCCESS;
        }
        Err(message) => {
            eprintln!("{program}: {message}; {usage}");
            return ExitCode::from(2);
        }
    };
    let figures = figures.all_figures();
    if args.check {
        return match check_all(&figures, &args.out, args.format) {
            Ok(mismatches) if mismatches.is_empty() => ExitCode::SUCCESS,
            Ok(mismatches) => {
                for m in &mismatches {
                    println!("{m}");
                }
                eprintln!(
                    "{program}: {} figure file(s) out of date in {}; rerun without --check",
                    mismatches.len(),
                    args.out.display()
                );
                ExitCode::FAILURE
            }
            Err(e) => {
                eprintln!("{program}: error: {e}");
                ExitCode::FAILURE
            }
        };
    }
    match write_all(&figures, &args.out, args.format) {
        Ok(paths) => {
            for path in paths {
                println!("{}", path.display());
            }
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("{program}: error: {e}");
            ExitCode::FAILURE
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(args: &[&str]) -> Result<Option<Args>, String> {
        parse_args(args.iter().map(|s| s.to_string()))
    }

    #[test]
    fn parses_out_and_format() {
        let args = parse(&["--out", "figs", "--format", "svg"])
            .unwrap()
            .unwrap();
        assert_eq!(args.out, PathBuf::from("figs"));
        assert_eq!(args.format, Format::Svg);
        let args = parse(&["--format=png", "--out=x", "--check"])
            .unwrap()
            .unwrap();
        assert_eq!((args.format, args.check), (Format::Png, true));
        assert_eq!(
            parse(&["--out", "x"]).unwrap().unwrap().format,
            Format::Both
        );
        assert_eq!(parse(&["--help"]), Ok(None));
    }

    #[test]
    fn rejects_bad_arguments() {
        assert!(parse(&[]).is_err());
        assert!(parse(&["--out"]).is_err());
        assert!(parse(&["--out", "x", "--format", "jpg"]).is_err());
        assert!(parse(&["--out", "x", "--verbose"]).is_err());
    }
}
