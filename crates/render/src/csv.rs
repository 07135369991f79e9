//! The small CSV files behind the charts: `raystep measure` writes them,
//! `raystep figures` draws from them. One header line, the columns'
//! names, then one line per row; every error names the line.
//!
//! A chart's row is a struct deriving serde's `Serialize` and
//! `Deserialize`, one field per column in the file's order, that
//! implements [`Row`]; the csv crate writes ([`to_csv`]) and reads
//! ([`from_csv`]) it. A number's format is its field's `#[serde(with =
//! "…")]`, one of [`Decimals`], [`Exp`], [`Plain`] and [`Flag`]; counts
//! and names are written as they are.
//!
//! ```
//! use raystep_render::csv::{Decimals, Row, from_csv, to_csv};
//! use serde::{Deserialize, Serialize};
//!
//! #[derive(Debug, PartialEq, Serialize, Deserialize)]
//! struct Point {
//!     name: String,
//!     #[serde(with = "Decimals::<2>")]
//!     x: f64,
//! }
//! impl Row for Point {}
//!
//! let text = to_csv(&[Point { name: "a".into(), x: 1.5 }]);
//! assert_eq!(text, "name,x\na,1.50\n");
//! assert_eq!(from_csv::<Point>(&text).unwrap()[0].x, 1.5);
//! ```
mod columns;
mod fields;

use ::csv::{
    DeserializeErrorKind, ErrorKind, ReaderBuilder, StringRecord, Trim,
    WriterBuilder,
};
use serde::Serialize;
use serde::de::DeserializeOwned;

pub use columns::columns;
pub use fields::{Decimals, Exp, Flag, Plain};

/// One row of a measured chart's CSV file: a struct deriving `Serialize`
/// and `Deserialize` whose fields are the columns, in order.
pub trait Row: Serialize + DeserializeOwned {
    /// What a good row is beyond its fields' types (a known method name,
    /// a positive time); an error says what is wrong, and the reader puts
    /// the line in front. Every row is good unless its type says more.
    fn check(&self) -> Result<(), String> {
        Ok(())
    }
}

/// A step of a [`Row::check`]: every one of `values` is positive (times,
/// sizes), or the error "`what` must be positive".
pub fn positive(values: &[f64], what: &str) -> Result<(), String> {
    if values.iter().all(|&x| x > 0.0) {
        Ok(())
    } else {
        Err(format!("{what} must be positive"))
    }
}

/// The header line of `R`'s files: its columns, separated by commas.
pub fn header<R: Row>() -> String {
    columns::<R>().join(",")
}

/// The rows as CSV: the header, then one line per row.
///
/// # Panics
/// If a row does not write one field per column (a programming error: a
/// field that is not a number, a bool or a text).
pub fn to_csv<R: Row>(rows: &[R]) -> String {
    let mut writer = WriterBuilder::new()
        .has_headers(false)
        .from_writer(Vec::new());
    writer
        .write_record(columns::<R>())
        .expect("a header writes to memory");
    for row in rows {
        writer
            .serialize(row)
            .expect("a row writes one field per column");
    }
    let bytes = writer.into_inner().expect("rows write to memory");
    String::from_utf8(bytes).expect("rows of text make text")
}

/// [`from_csv`] of `lines` under `R`'s header: what a test of a
/// [`Row::check`] reads.
pub fn from_lines<R: Row>(lines: &str) -> Result<Vec<R>, String> {
    from_csv(&format!("{}\n{lines}", header::<R>()))
}

/// Reads [`to_csv`]'s output back; blank lines are skipped and fields
/// trimmed. An error names the line and what is wrong: not the header,
/// a line without one field per column, a field that is not a number
/// (`nan` and `inf` are not, in any column: measurements are finite) or
/// not a count, or what [`Row::check`] finds.
pub fn from_csv<R: Row>(text: &str) -> Result<Vec<R>, String> {
    let columns = columns::<R>();
    let mut reader = ReaderBuilder::new()
        .has_headers(false)
        .flexible(true)
        .trim(Trim::All)
        .from_reader(text.as_bytes());
    let mut records = reader.records();
    match records.next() {
        Some(Ok(first)) if first.iter().eq(columns.iter().copied()) => {}
        _ => {
            let header = columns.join(",");
            return Err(format!("line 1: expected the header `{header}`"));
        }
    }
    records
        .filter(|record| {
            !matches!(record, Ok(r) if r.len() == 1 && r[0].is_empty())
        })
        .map(|record| {
            let record = record.map_err(|e| e.to_string())?;
            row(&record, line_of(text, &record), columns)
        })
        .collect()
}

/// The line `record` stands on, from 1. (The csv crate's own line count
/// passes over blank lines, and a record's position is where its reading
/// began: before the blank lines above it.)
fn line_of(text: &str, record: &StringRecord) -> usize {
    let byte = record.position().map_or(0, |p| p.byte() as usize);
    let blank = text.as_bytes()[byte..]
        .iter()
        .take_while(|&&b| b == b'\n' || b == b'\r')
        .count();
    let newlines = text.as_bytes()[..byte + blank].iter();
    1 + newlines.filter(|&&b| b == b'\n').count()
}

/// The row of data line `line`, or the error on that line.
fn row<R: Row>(
    record: &StringRecord, line: usize, columns: &[&str],
) -> Result<R, String> {
    let on_line = |message: String| format!("line {line}: {message}");
    if record.len() != columns.len() {
        let (expected, got) = (columns.len(), record.len());
        return Err(on_line(format!("expected {expected} fields, got {got}")));
    }
    let infinite =
        |field: &str| field.parse().is_ok_and(|x: f64| !x.is_finite());
    if let Some(k) = record.iter().position(infinite) {
        let (name, field) = (columns[k], &record[k]);
        return Err(on_line(format!("{name} `{field}` is not a number")));
    }
    let row: R = record
        .deserialize(None)
        .map_err(|e| on_line(field_error(&e, record, columns)))?;
    row.check().map_err(on_line)?;
    Ok(row)
}

/// A field that does not read as its column's type, named by its column.
fn field_error(
    error: &::csv::Error, record: &StringRecord, columns: &[&str],
) -> String {
    let ErrorKind::Deserialize { err, .. } = error.kind() else {
        return error.to_string();
    };
    let what = match err.kind() {
        DeserializeErrorKind::ParseInt(_) => "is not a count",
        DeserializeErrorKind::ParseFloat(_) => "is not a number",
        _ => return err.to_string(),
    };
    match err.field().map(|k| k as usize) {
        Some(k) if k < columns.len() => {
            format!("{} `{}` {what}", columns[k], &record[k])
        }
        _ => err.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde::Deserialize;

    #[derive(Debug, PartialEq, Serialize, Deserialize)]
    struct Point {
        name: String,
        #[serde(with = "Plain")]
        x: f64,
        count: u64,
        #[serde(rename = "on", with = "Flag")]
        chosen: bool,
    }

    impl Row for Point {
        fn check(&self) -> Result<(), String> {
            match self.name.as_str() {
                "" => Err("no name".into()),
                _ => Ok(()),
            }
        }
    }

    fn point(name: &str, x: f64, count: u64, chosen: bool) -> Point {
        Point {
            name: name.into(),
            x,
            count,
            chosen,
        }
    }

    #[test]
    fn rows_round_trip_under_their_header() {
        assert_eq!(columns::<Point>(), ["name", "x", "count", "on"]);
        assert_eq!(header::<Point>(), "name,x,count,on");
        let rows = vec![point("a b", 1.5, 7, true), point("c", -2.0, 0, false)];
        let text = to_csv(&rows);
        assert_eq!(text, "name,x,count,on\na b,1.5,7,1\nc,-2,0,0\n");
        assert_eq!(from_csv::<Point>(&text).unwrap(), rows);
        // no rows: the header alone
        assert_eq!(to_csv::<Point>(&[]), "name,x,count,on\n");
        assert_eq!(from_csv::<Point>("name,x,count,on\n"), Ok(vec![]));
    }

    #[test]
    fn each_format_writes_as_its_format_string() {
        #[derive(Debug, PartialEq, Serialize, Deserialize)]
        struct Formats {
            #[serde(with = "Decimals::<0>")]
            d0: f64,
            #[serde(with = "Decimals::<3>")]
            d3: f64,
            #[serde(with = "Exp")]
            e: f64,
            #[serde(with = "Plain")]
            p: f64,
        }
        impl Row for Formats {}
        let x = 1234.56789;
        let row = Formats {
            d0: x,
            d3: x,
            e: 1e-3,
            p: 0.1,
        };
        let line = format!("{x:.0},{x:.3},{:e},{}", 1e-3, 0.1);
        assert_eq!(line, "1235,1234.568,1e-3,0.1");
        assert_eq!(to_csv(&[row]), format!("d0,d3,e,p\n{line}\n"));
        let back = from_csv::<Formats>(&format!("d0,d3,e,p\n{line}\n"));
        assert_eq!(back.unwrap()[0].e, 1e-3);
    }

    #[test]
    fn fields_are_trimmed_and_blank_lines_skipped() {
        let text = "name,x,count,on\n x , 1.5,7,1\n\n  \ny,-2e3,0,2\n";
        let rows = from_csv::<Point>(text).unwrap();
        assert_eq!(
            rows,
            [point("x", 1.5, 7, true), point("y", -2e3, 0, false)]
        );
    }

    #[test]
    fn a_check_may_ask_for_positive_values() {
        assert_eq!(positive(&[1.0, 1e-9], "times"), Ok(()));
        let error = Err("times must be positive".to_string());
        assert_eq!(positive(&[1.0, 0.0], "times"), error);
        assert_eq!(positive(&[-1.0], "times"), error);
    }

    #[test]
    fn errors_name_the_line_and_the_column() {
        let read = |body: &str| {
            from_lines::<Point>(&format!("a,1,1,1\n{body}")).map(|_| ())
        };
        for (body, error) in [
            ("b,y,1,1\n", "line 3: x `y` is not a number"),
            ("b,nan,1,1\n", "line 3: x `nan` is not a number"),
            ("b,1,inf,1\n", "line 3: count `inf` is not a number"),
            ("\nb,1,-2e3,1\n", "line 4: count `-2e3` is not a count"),
            ("b,1,1,x\n", "line 3: on `x` is not a count"),
            ("b,1,1\n", "line 3: expected 4 fields, got 3"),
            (" ,1,1,1\n", "line 3: no name"),
        ] {
            assert_eq!(read(body), Err(error.to_string()), "{body:?}");
        }
        assert_eq!(
            from_csv::<Point>("name,x\n"),
            Err("line 1: expected the header `name,x,count,on`".into())
        );
        assert_eq!(
            from_csv::<Point>(""),
            Err("line 1: expected the header `name,x,count,on`".into())
        );
    }
}
