//! The small CSV files behind the charts: `raystep measure` writes them,
//! `raystep figures` draws from them. Plain comma-separated fields, one
//! header line, no quoting; every error names the line.
//!
//! A chart's data is a list of rows of one type that implements
//! [`CsvRow`]; [`to_csv`] writes them and [`from_csv`] reads them back.

use std::fmt::Display;

/// One row of a measured chart's CSV file.
pub trait CsvRow: Sized {
    /// The header line, the columns' names separated by commas.
    const HEADER: &'static str;

    /// The row as one line of fields in [`CsvRow::HEADER`]'s order,
    /// without the line break.
    fn to_line(&self) -> String;

    /// The row of one data line; an error names the line
    /// ([`Record::error`]).
    fn from_record(record: &Record) -> Result<Self, String>;
}

/// The rows as CSV: the header, then one line per row.
pub fn to_csv<R: CsvRow>(rows: &[R]) -> String {
    let mut csv = format!("{}\n", R::HEADER);
    for row in rows {
        csv.push_str(&row.to_line());
        csv.push('\n');
    }
    csv
}

/// Reads [`to_csv`]'s output back; an error names the line and what is
/// wrong.
pub fn from_csv<R: CsvRow>(text: &str) -> Result<Vec<R>, String> {
    records(text, R::HEADER)?
        .iter()
        .map(R::from_record)
        .collect()
}

/// The data lines of `text`, whose first line must be `header`; blank lines
/// are skipped. An error names the line: a wrong header, or a line without
/// one field per column of the header.
pub fn records<'a>(
    text: &'a str,
    header: &str,
) -> Result<Vec<Record<'a>>, String> {
    let mut lines = text.lines().enumerate();
    match lines.next() {
        Some((_, first)) if first.trim() == header => {}
        _ => return Err(format!("line 1: expected the header `{header}`")),
    }
    let columns = header.split(',').count();
    lines
        .filter(|(_, line)| !line.trim().is_empty())
        .map(|(i, line)| {
            let record = Record {
                line: i + 1,
                fields: line.split(',').map(str::trim).collect(),
            };
            if record.fields.len() == columns {
                Ok(record)
            } else {
                Err(record.error(format!(
                    "expected {columns} fields, got {}",
                    record.fields.len()
                )))
            }
        })
        .collect()
}

/// One data line: its number in the file (from 1) and its trimmed fields,
/// as many as the header has columns.
#[derive(Clone, Debug, PartialEq)]
pub struct Record<'a> {
    /// The line's number in the file, from 1.
    pub line: usize,
    fields: Vec<&'a str>,
}

impl<'a> Record<'a> {
    /// Field `k` as it is written.
    pub fn text(&self, k: usize) -> &'a str {
        self.fields[k]
    }

    /// Field `k` as a finite number; the error calls it `name`.
    pub fn number(&self, k: usize, name: &str) -> Result<f64, String> {
        self.fields[k]
            .parse::<f64>()
            .ok()
            .filter(|x| x.is_finite())
            .ok_or_else(|| {
                self.error(format!(
                    "{name} `{}` is not a number",
                    self.fields[k]
                ))
            })
    }

    /// Field `k` as a count (a whole number ≥ 0); the error calls it `name`.
    pub fn count(&self, k: usize, name: &str) -> Result<u64, String> {
        self.fields[k].parse::<u64>().map_err(|_| {
            self.error(format!("{name} `{}` is not a count", self.fields[k]))
        })
    }

    /// `message` on this line: `line 4: message`.
    pub fn error(&self, message: impl Display) -> String {
        format!("line {}: {message}", self.line)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[derive(Debug, PartialEq)]
    struct Point {
        name: String,
        x: f64,
    }

    impl CsvRow for Point {
        const HEADER: &'static str = "name,x";
        fn to_line(&self) -> String {
            format!("{},{}", self.name, self.x)
        }
        fn from_record(r: &Record) -> Result<Point, String> {
            Ok(Point {
                name: r.text(0).to_string(),
                x: r.number(1, "x")?,
            })
        }
    }

    #[test]
    fn rows_round_trip_through_the_header() {
        let rows = vec![
            Point {
                name: "a".into(),
                x: 1.5,
            },
            Point {
                name: "b".into(),
                x: -2.0,
            },
        ];
        let text = to_csv(&rows);
        assert_eq!(text, "name,x\na,1.5\nb,-2\n");
        assert_eq!(from_csv::<Point>(&text).unwrap(), rows);
        assert_eq!(
            from_csv::<Point>("name,x\na,y\n"),
            Err("line 2: x `y` is not a number".to_string())
        );
    }

    #[test]
    fn fields_numbers_counts_and_errors_name_the_line() {
        let text = "a,b,c\n x , 1.5,7\n\ny,-2e3,0\n";
        let rows = records(text, "a,b,c").unwrap();
        assert_eq!(rows.len(), 2);
        assert_eq!((rows[0].line, rows[0].text(0)), (2, "x"));
        assert_eq!(rows[0].number(1, "b"), Ok(1.5));
        assert_eq!(rows[0].count(2, "c"), Ok(7));
        assert_eq!(rows[1].line, 4);
        assert_eq!(rows[1].number(1, "b"), Ok(-2000.0));
        assert_eq!(
            rows[1].count(1, "b"),
            Err("line 4: b `-2e3` is not a count".to_string())
        );
        assert_eq!(
            records("a,b\n1,nan\n", "a,b").unwrap()[0].number(1, "b"),
            Err("line 2: b `nan` is not a number".to_string())
        );
        assert_eq!(
            records("a,b,c\n1,2\n", "a,b,c"),
            Err("line 2: expected 3 fields, got 2".to_string())
        );
        assert_eq!(
            records("x,y\n", "a,b"),
            Err("line 1: expected the header `a,b`".to_string())
        );
        assert_eq!(
            records("", "a,b"),
            Err("line 1: expected the header `a,b`".to_string())
        );
        assert_eq!(records("a,b\n", "a,b"), Ok(vec![]));
    }
}
