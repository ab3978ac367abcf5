//! A FlatGeobuf feature's properties as attributes (`--by`): the header's columns, and each
//! feature's property bytes, a sequence of a little-endian `u16` column index and the value
//! in the column's type (fixed-size numbers, or a `u32` length and UTF-8 text for strings,
//! JSON and date-times). Every length is checked against the bytes there are.

use flatgeobuf::{ColumnType as FgbColumnType, Header};

use crate::attributes::{Column, ColumnType, Value};

/// The header's attribute columns: every column but binary ones, with its position in the
/// header.
pub struct Columns {
    /// The attribute columns.
    pub columns: Vec<Column>,
    /// Per header column, its type and its position among `columns` (`None`: not one).
    header: Vec<(FgbColumnType, Option<usize>)>,
}

impl Columns {
    /// The columns of `header`.
    pub fn of(header: &Header<'_>) -> Columns {
        let mut columns = Vec::new();
        let mut positions = Vec::new();
        for column in header.columns().iter().flatten() {
            let kind = match column.type_() {
                FgbColumnType::Bool => Some(ColumnType::Bool),
                FgbColumnType::Float | FgbColumnType::Double => Some(ColumnType::Real),
                FgbColumnType::String | FgbColumnType::Json | FgbColumnType::DateTime => {
                    Some(ColumnType::Text)
                }
                FgbColumnType::Binary => None,
                _ => Some(ColumnType::Integer),
            };
            let at = kind.map(|kind| {
                columns.push(Column { name: column.name().to_string(), kind });
                columns.len() - 1
            });
            positions.push((column.type_(), at));
        }
        Columns { columns, header: positions }
    }

    /// The attributes in the property bytes `bytes` of a feature, one per column (no value
    /// where the feature has none).
    pub fn values(&self, bytes: &[u8]) -> Result<Vec<Value>, String> {
        let mut values = vec![Value::Null; self.columns.len()];
        let mut at = 0;
        let take = |at: &mut usize, n: usize| -> Result<&[u8], String> {
            let end = at.checked_add(n).filter(|&end| end <= bytes.len());
            let end = end.ok_or_else(|| format!("its properties end inside a value at {at}"))?;
            let slice = &bytes[*at..end];
            *at = end;
            Ok(slice)
        };
        while at < bytes.len() {
            let index = u16::from_le_bytes(take(&mut at, 2)?.try_into().expect("2 bytes"));
            let &(kind, position) = self.header.get(index as usize).ok_or_else(|| {
                format!("a property of column {index}, but the header has {}", self.header.len())
            })?;
            let mut fixed = |n: usize| take(&mut at, n).map(|b| b.to_vec());
            let value = match kind {
                FgbColumnType::Bool => Value::Bool(fixed(1)?[0] != 0),
                FgbColumnType::Byte => Value::Integer(i64::from(fixed(1)?[0] as i8)),
                FgbColumnType::UByte => Value::Integer(i64::from(fixed(1)?[0])),
                FgbColumnType::Short => {
                    Value::Integer(i64::from(i16::from_le_bytes(array(&fixed(2)?))))
                }
                FgbColumnType::UShort => {
                    Value::Integer(i64::from(u16::from_le_bytes(array(&fixed(2)?))))
                }
                FgbColumnType::Int => {
                    Value::Integer(i64::from(i32::from_le_bytes(array(&fixed(4)?))))
                }
                FgbColumnType::UInt => {
                    Value::Integer(i64::from(u32::from_le_bytes(array(&fixed(4)?))))
                }
                FgbColumnType::Long => Value::Integer(i64::from_le_bytes(array(&fixed(8)?))),
                FgbColumnType::ULong => {
                    let n = u64::from_le_bytes(array(&fixed(8)?));
                    // Past i64: its text (the column becomes text).
                    i64::try_from(n).map_or_else(|_| Value::Text(n.to_string()), Value::Integer)
                }
                FgbColumnType::Float => {
                    Value::Real(f64::from(f32::from_le_bytes(array(&fixed(4)?))))
                }
                FgbColumnType::Double => Value::Real(f64::from_le_bytes(array(&fixed(8)?))),
                _ => {
                    let n = u32::from_le_bytes(array(&fixed(4)?)) as usize;
                    let text = take(&mut at, n)?;
                    Value::Text(String::from_utf8_lossy(text).into_owned())
                }
            };
            if let Some(position) = position {
                values[position] = value;
            }
        }
        Ok(values)
    }
}

/// The first `N` bytes of `bytes` (which has them).
fn array<const N: usize>(bytes: &[u8]) -> [u8; N] {
    bytes[..N].try_into().expect("N bytes")
}
