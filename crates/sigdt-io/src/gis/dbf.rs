//! dBASE `.dbf` tables (dBASE III+ layout, as every Shapefile has one): the attributes of a
//! Shapefile's records, read for `--by`. Record `k` of the table belongs to record `k` of the
//! `.shp`.
//!
//! Field types: `C` (text, trailing blanks dropped), `N` and `F` (numbers: whole when the
//! field has no decimals, else real), `L` (logical: `T`, `Y` true, `F`, `N` false, `?` none)
//! and `D` (date, written `YYYY-MM-DD`); a blank field has no value. Fields of other types
//! (memo, binary) are not attributes. Text is UTF-8 when it decodes so, else Latin-1 (each
//! byte a character), whatever the `.cpg` says. Every size comes from the header and is
//! checked against the bytes there are; the file is read record by record.

use crate::text::quoted;
use std::io::{BufReader, Read};
use std::path::Path;

use anyhow::{anyhow, bail, Result};

use crate::attributes::{Column, ColumnType, Value};

/// A `.dbf` being read: its fields, then its records one by one.
pub struct Dbf {
    reader: BufReader<std::fs::File>,
    shown: String,
    fields: Vec<Field>,
    record_length: usize,
    /// The records the header announces.
    pub records: u32,
    read: u32,
}

struct Field {
    column: Option<Column>,
    kind: u8,
    offset: usize,
    length: usize,
    decimals: u8,
}

impl Dbf {
    /// The `.dbf` beside the `.shp` at `shp` (`a.dbf` or `a.DBF`), opened and its header
    /// read; `None` when there is none.
    pub fn beside(shp: &Path) -> Result<Option<Dbf>> {
        let candidates = [shp.with_extension("dbf"), shp.with_extension("DBF")];
        let Some(path) = candidates.into_iter().find(|p| p.is_file()) else { return Ok(None) };
        let shown = path.display().to_string();
        let file = std::fs::File::open(&path).map_err(|e| anyhow!("{shown}: {e}"))?;
        let mut reader = BufReader::new(file);
        let cut = || anyhow!("{shown}: dBASE: the file ends inside its header");
        let mut head = [0u8; 32];
        reader.read_exact(&mut head).map_err(|_| cut())?;
        let records = u32::from_le_bytes(head[4..8].try_into().expect("4 bytes"));
        let header_length = u16::from_le_bytes([head[8], head[9]]) as usize;
        let record_length = u16::from_le_bytes([head[10], head[11]]) as usize;
        if header_length < 33 {
            bail!("{shown}: dBASE: a header of {header_length} bytes (33 at least)");
        }
        let mut rest = vec![0u8; header_length - 32];
        reader.read_exact(&mut rest).map_err(|_| cut())?;
        let mut fields = Vec::new();
        let mut offset = 1; // the deletion flag
        for descriptor in rest.chunks_exact(32).take_while(|d| d[0] != 0x0d) {
            let end = descriptor[..11].iter().position(|&b| b == 0).unwrap_or(11);
            let name = text(&descriptor[..end]);
            let (kind, length, decimals) =
                (descriptor[11], descriptor[16] as usize, descriptor[17]);
            let column_type = match kind {
                b'C' | b'D' => Some(ColumnType::Text),
                b'N' | b'F' if decimals == 0 && kind == b'N' => Some(ColumnType::Integer),
                b'N' | b'F' => Some(ColumnType::Real),
                b'L' => Some(ColumnType::Bool),
                _ => None,
            };
            let column = column_type.map(|kind| Column { name, kind });
            fields.push(Field { column, kind, offset, length, decimals });
            offset += length;
        }
        if offset > record_length {
            bail!("{shown}: dBASE: fields of {} bytes in records of {record_length}", offset - 1);
        }
        Ok(Some(Dbf { reader, shown, fields, record_length, records, read: 0 }))
    }

    /// The file's name, for messages.
    pub fn name(&self) -> &str {
        &self.shown
    }

    /// The attribute columns, in field order.
    pub fn columns(&self) -> Vec<Column> {
        self.fields.iter().filter_map(|f| f.column.clone()).collect()
    }

    /// The attributes of the next record, one per column; an error past the last one.
    pub fn next_record(&mut self) -> Result<Vec<Value>> {
        let shown = &self.shown;
        if self.read == self.records {
            bail!("{shown}: dBASE: {} records, fewer than the Shapefile's", self.records);
        }
        self.read += 1;
        let mut record = vec![0u8; self.record_length];
        self.reader.read_exact(&mut record).map_err(|_| {
            anyhow!("{shown}: dBASE: the file ends inside record {} of {}", self.read, self.records)
        })?;
        let number = self.read;
        let fields = self.fields.iter().filter(|f| f.column.is_some());
        fields
            .map(|f| {
                let raw = &record[f.offset..f.offset + f.length];
                value(raw, f).map_err(|why| {
                    let name = f.column.as_ref().map_or("", |c| c.name.as_str());
                    let name = crate::text::quoted(name);
                    anyhow!("{shown}: dBASE record {number}, field {name}: {why}")
                })
            })
            .collect()
    }
}

/// The value of field `f` stored as `raw` (input quoted in messages, control characters
/// escaped, as every reader quotes it).
fn value(raw: &[u8], f: &Field) -> Result<Value, String> {
    let trimmed = text(raw).trim().to_string();
    if trimmed.is_empty() {
        return Ok(Value::Null);
    }
    Ok(match f.kind {
        b'C' => Value::Text(text(raw).trim_end().to_string()),
        b'D' if trimmed.len() == 8 && trimmed.bytes().all(|b| b.is_ascii_digit()) => {
            Value::Text(format!("{}-{}-{}", &trimmed[..4], &trimmed[4..6], &trimmed[6..]))
        }
        b'D' => return Err(format!("{} is not a date YYYYMMDD", quoted(&trimmed))),
        b'L' => match trimmed.as_bytes()[0].to_ascii_uppercase() {
            b'T' | b'Y' => Value::Bool(true),
            b'F' | b'N' => Value::Bool(false),
            b'?' => Value::Null,
            _ => return Err(format!("{} is not a logical value", quoted(&trimmed))),
        },
        // Overflow is written as asterisks.
        _ if trimmed.bytes().all(|b| b == b'*') => Value::Null,
        b'N' if f.decimals == 0 => match trimmed.parse::<i64>() {
            Ok(n) => Value::Integer(n),
            Err(_) => return Err(format!("{} is not a whole number", quoted(&trimmed))),
        },
        _ => match trimmed.parse::<f64>() {
            Ok(x) if x.is_finite() => Value::Real(x),
            _ => return Err(format!("{} is not a number", quoted(&trimmed))),
        },
    })
}

/// `bytes` as text: UTF-8 when they are, else Latin-1; NUL padding dropped.
fn text(bytes: &[u8]) -> String {
    let bytes = match bytes.iter().position(|&b| b == 0) {
        Some(end) => &bytes[..end],
        None => bytes,
    };
    match std::str::from_utf8(bytes) {
        Ok(text) => text.to_string(),
        Err(_) => bytes.iter().map(|&b| char::from(b)).collect(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A `.dbf` of the fields `(name, type, length, decimals)` and the records' raw fields.
    fn dbf(fields: &[(&str, u8, u8, u8)], records: &[&[&str]]) -> Vec<u8> {
        let record_length: usize = 1 + fields.iter().map(|f| f.2 as usize).sum::<usize>();
        let header_length = 32 + 32 * fields.len() + 1;
        let mut b = vec![3u8, 124, 1, 1];
        b.extend_from_slice(&(records.len() as u32).to_le_bytes());
        b.extend_from_slice(&(header_length as u16).to_le_bytes());
        b.extend_from_slice(&(record_length as u16).to_le_bytes());
        b.resize(32, 0);
        for &(name, kind, length, decimals) in fields {
            let mut d = [0u8; 32];
            d[..name.len()].copy_from_slice(name.as_bytes());
            (d[11], d[16], d[17]) = (kind, length, decimals);
            b.extend_from_slice(&d);
        }
        b.push(0x0d);
        for record in records {
            b.push(b' ');
            for (value, field) in record.iter().zip(fields) {
                let mut cell = value.as_bytes().to_vec();
                cell.resize(field.2 as usize, b' ');
                b.extend_from_slice(&cell);
            }
        }
        b.push(0x1a);
        b
    }

    #[test]
    fn each_field_type_reads_as_its_value() {
        let dir = tempfile::tempdir().unwrap();
        let fields =
            [("name", b'C', 8, 0), ("n", b'N', 5, 0), ("x", b'N', 8, 2), ("ok", b'L', 1, 0)];
        let fields = [&fields[..], &[("day", b'D', 8, 0), ("m", b'M', 10, 0)]].concat();
        let records: [&[&str]; 2] = [
            &["Fidži", "  42", "  -1.50", "T", "20240131", "memo"],
            &["", "", "*****", "?", "", ""],
        ];
        std::fs::write(dir.path().join("a.dbf"), dbf(&fields, &records)).unwrap();
        let mut table = Dbf::beside(&dir.path().join("a.shp")).unwrap().unwrap();
        let names: Vec<String> = table.columns().into_iter().map(|c| c.name).collect();
        assert_eq!(names, ["name", "n", "x", "ok", "day"], "the memo is not an attribute");
        let first = table.next_record().unwrap();
        assert_eq!(
            first,
            [
                Value::Text("Fidži".into()),
                Value::Integer(42),
                Value::Real(-1.5),
                Value::Bool(true),
                Value::Text("2024-01-31".into())
            ]
        );
        assert!(table.next_record().unwrap().iter().all(|v| *v == Value::Null));
        let err = table.next_record().unwrap_err().to_string();
        assert!(err.ends_with("a.dbf: dBASE: 2 records, fewer than the Shapefile's"), "{err}");
        assert!(Dbf::beside(&dir.path().join("none.shp")).unwrap().is_none());
    }

    #[test]
    fn a_bad_field_or_a_short_file_names_the_record() {
        let dir = tempfile::tempdir().unwrap();
        // A control character in a field is escaped in the message, as every reader's is.
        let bytes = dbf(&[("day", b'D', 8, 0)], &[&["\x1b[2J0101"]]);
        std::fs::write(dir.path().join("a.dbf"), &bytes).unwrap();
        let mut table = Dbf::beside(&dir.path().join("a.shp")).unwrap().unwrap();
        let err = table.next_record().unwrap_err().to_string();
        assert!(err.ends_with(r"field 'day': '\u{1b}[2J0101' is not a date YYYYMMDD"), "{err}");
        let bytes = dbf(&[("n", b'N', 4, 0)], &[&["12"], &["x1"]]);
        std::fs::write(dir.path().join("a.dbf"), &bytes).unwrap();
        let mut table = Dbf::beside(&dir.path().join("a.shp")).unwrap().unwrap();
        assert_eq!(table.next_record().unwrap(), [Value::Integer(12)]);
        let err = table.next_record().unwrap_err().to_string();
        assert!(err.ends_with("dBASE record 2, field 'n': 'x1' is not a whole number"), "{err}");
        std::fs::write(dir.path().join("a.dbf"), &bytes[..bytes.len() - 4]).unwrap();
        let mut table = Dbf::beside(&dir.path().join("a.shp")).unwrap().unwrap();
        table.next_record().unwrap();
        let err = table.next_record().unwrap_err().to_string();
        assert!(err.ends_with("the file ends inside record 2 of 2"), "{err}");
        std::fs::write(dir.path().join("a.dbf"), &bytes[..20]).unwrap();
        let err = Dbf::beside(&dir.path().join("a.shp")).err().unwrap().to_string();
        assert!(err.ends_with("dBASE: the file ends inside its header"), "{err}");
    }
}
