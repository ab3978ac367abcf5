//! Points grouped by an attribute as they are read (`--by COLUMN`), each group keeping the
//! attributes that are the same on all of its points.
//!
//! A reader that holds attributes (a GeoPackage layer's columns, a Shapefile's `.dbf`, a
//! FlatGeobuf file's columns, a table's other columns) hands over each record (a feature, a
//! row) with the number of points it gave. Points are grouped by the exact text of the
//! `--by` value (a missing value is a group of its own); per group only one value per
//! column is kept, and forgotten once another differs, so memory is the groups' and not the
//! points' (a table of millions of rows keeps a group number per point).

use std::collections::HashMap;

/// The type of an attribute column.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ColumnType {
    /// Text.
    Text,
    /// A whole number.
    Integer,
    /// A real number.
    Real,
    /// True or false.
    Bool,
}

/// An attribute column.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Column {
    /// Its name.
    pub name: String,
    /// Its type.
    pub kind: ColumnType,
}

/// An attribute's value.
#[derive(Debug, Clone, PartialEq)]
pub enum Value {
    /// No value.
    Null,
    /// Text.
    Text(String),
    /// A whole number.
    Integer(i64),
    /// A real number.
    Real(f64),
    /// True or false.
    Bool(bool),
}

impl Value {
    /// Its text, the key of a group: `None` for no value; numbers as Rust prints them
    /// (`3`, `2.5`, `1.0`).
    pub fn text(&self) -> Option<String> {
        match self {
            Value::Null => None,
            Value::Text(text) => Some(text.clone()),
            Value::Integer(n) => Some(n.to_string()),
            Value::Real(x) => Some(format!("{x:?}")),
            Value::Bool(b) => Some(b.to_string()),
        }
    }

    /// Whether it is the same value as `other` (reals bit for bit).
    fn same(&self, other: &Value) -> bool {
        match (self, other) {
            (Value::Real(a), Value::Real(b)) => a.to_bits() == b.to_bits(),
            _ => self == other,
        }
    }

    /// Whether it fits a column of type `kind`.
    fn fits(&self, kind: ColumnType) -> bool {
        matches!(
            (self, kind),
            (Value::Null, _)
                | (Value::Text(_), ColumnType::Text)
                | (Value::Integer(_), ColumnType::Integer)
                | (Value::Real(_), ColumnType::Real)
                | (Value::Bool(_), ColumnType::Bool)
        )
    }
}

/// One group of points.
#[derive(Debug, Clone, PartialEq)]
pub struct Group {
    /// The text of its `--by` value; `None` for the points without one.
    pub key: Option<String>,
    /// Per column, the value every point of the group has, or `None` where they differ.
    pub values: Vec<Option<Value>>,
}

/// Points grouped by one of their attributes; see the module docs.
#[derive(Debug, Clone, PartialEq)]
pub struct Grouping {
    /// Every attribute column of the file, in its order.
    pub columns: Vec<Column>,
    /// The `--by` column, an index into `columns`.
    pub by: usize,
    /// The groups, in the order of their first point.
    pub groups: Vec<Group>,
    /// The group of each point, in point order.
    pub group_of_point: Vec<u32>,
    index: HashMap<Option<String>, u32>,
}

impl Grouping {
    /// Groups by the column named `by` (exactly, else ignoring case when only one column
    /// matches so) of `columns`; the error names the file `name` and the columns there are.
    pub fn new(columns: Vec<Column>, by: &str, name: &str) -> Result<Grouping, String> {
        let exact = columns.iter().position(|c| c.name == by);
        let loose: Vec<usize> =
            (0..columns.len()).filter(|&k| columns[k].name.eq_ignore_ascii_case(by)).collect();
        let by = match (exact, loose.as_slice()) {
            (Some(k), _) | (None, &[k]) => k,
            _ => {
                let names: Vec<String> =
                    columns.iter().map(|c| crate::text::quoted(&c.name)).collect();
                let there = match names.is_empty() {
                    true => "it has no attribute columns".to_string(),
                    false => format!("the columns: {}", names.join(", ")),
                };
                return Err(format!(
                    "{name}: --by: no column {} ({there})",
                    crate::text::quoted(by)
                ));
            }
        };
        Ok(Grouping {
            columns,
            by,
            groups: Vec::new(),
            group_of_point: Vec::new(),
            index: HashMap::new(),
        })
    }

    /// Adds a record of `points` points whose attributes are `values` (one per column).
    /// A record without points (a feature without geometry) changes nothing.
    pub fn add(&mut self, values: Vec<Value>, points: usize) {
        debug_assert_eq!(values.len(), self.columns.len());
        if points == 0 {
            return;
        }
        let key = values[self.by].text();
        let k = match self.index.get(&key) {
            Some(&k) => {
                let group = &mut self.groups[k as usize];
                for (kept, value) in group.values.iter_mut().zip(&values) {
                    if kept.as_ref().is_some_and(|kept| !kept.same(value)) {
                        *kept = None;
                    }
                }
                k
            }
            None => {
                let k = self.groups.len() as u32;
                self.index.insert(key.clone(), k);
                self.groups.push(Group { key, values: values.into_iter().map(Some).collect() });
                k
            }
        };
        self.group_of_point.extend(std::iter::repeat_n(k, points));
    }

    /// The columns that are the same on every point of at least one group, as indices into
    /// [`Grouping::columns`] (the `--by` column always, each group's value its key); a value
    /// that does not fit its column's declared type (SQLite stores any) makes the column
    /// text, and so do values of different types with the same text in the `--by` column
    /// (`3` and `'3'`, one group).
    pub fn kept_columns(&mut self) -> Vec<usize> {
        let by = self.by;
        if self.groups.iter().any(|g| g.values[by].is_none()) {
            self.columns[by].kind = ColumnType::Text;
            for group in &mut self.groups {
                group.values[by] = Some(group.key.clone().map_or(Value::Null, Value::Text));
            }
        }
        for (c, column) in self.columns.iter_mut().enumerate() {
            let kept = self.groups.iter().filter_map(|g| g.values[c].as_ref());
            if kept.clone().any(|v| !v.fits(column.kind)) {
                column.kind = ColumnType::Text;
                for group in &mut self.groups {
                    if let Some(value) = &mut group.values[c] {
                        *value = value.text().map_or(Value::Null, Value::Text);
                    }
                }
            }
        }
        (0..self.columns.len())
            .filter(|&c| c == self.by || self.groups.iter().any(|g| g.values[c].is_some()))
            .collect()
    }

    /// The points of each group, as indices in point order.
    pub fn members(&self) -> Vec<Vec<usize>> {
        let mut members = vec![Vec::new(); self.groups.len()];
        for (i, &k) in self.group_of_point.iter().enumerate() {
            members[k as usize].push(i);
        }
        members
    }

    /// How the group `k` is named in messages: its `--by` value quoted, or `(no NAME)`.
    pub fn group_name(&self, k: usize) -> String {
        match &self.groups[k].key {
            Some(key) => crate::text::quoted(key),
            None => format!("(no {})", self.columns[self.by].name),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn columns() -> Vec<Column> {
        ["island", "Area", "id"]
            .map(|name| Column {
                name: name.into(),
                kind: if name == "island" { ColumnType::Text } else { ColumnType::Integer },
            })
            .to_vec()
    }

    #[test]
    fn points_group_by_the_exact_text_and_keep_what_is_constant() {
        let mut g = Grouping::new(columns(), "island", "a.csv").unwrap();
        let text = |s: &str| Value::Text(s.into());
        g.add(vec![text("a"), Value::Integer(5), Value::Integer(1)], 2);
        g.add(vec![text("b"), Value::Integer(6), Value::Integer(2)], 1);
        g.add(vec![text("a"), Value::Integer(5), Value::Integer(3)], 1);
        g.add(vec![text("A"), Value::Integer(5), Value::Integer(4)], 1);
        g.add(vec![Value::Null, Value::Text("x".into()), Value::Integer(5)], 1);
        assert_eq!(g.group_of_point, [0, 0, 1, 0, 2, 3]);
        assert_eq!(g.members(), vec![vec![0, 1, 3], vec![2], vec![4], vec![5]]);
        assert_eq!(g.groups[0].values, vec![Some(text("a")), Some(Value::Integer(5)), None]);
        assert_eq!(g.group_name(3), "(no island)");
        assert_eq!(g.group_name(2), "'A'");
        // `id` is the same within groups of one record; a text in the integer column `Area`
        // makes it text.
        assert_eq!(g.kept_columns(), [0, 1, 2]);
        assert_eq!(g.columns[1].kind, ColumnType::Text);
        assert_eq!(g.groups[0].values[1], Some(text("5")));
    }

    #[test]
    fn a_number_and_its_text_are_one_group_of_a_text_column() {
        let mut g = Grouping::new(columns(), "Area", "a.gpkg").unwrap();
        let row = |area: Value| vec![Value::Text("a".into()), area, Value::Integer(1)];
        g.add(row(Value::Integer(3)), 1);
        g.add(row(Value::Text("3".into())), 1);
        g.add(row(Value::Integer(4)), 1);
        assert_eq!(g.groups.len(), 2);
        g.kept_columns();
        assert_eq!(g.columns[1].kind, ColumnType::Text);
        let keys: Vec<_> = g.groups.iter().map(|g| g.values[1].clone()).collect();
        assert_eq!(keys, [Some(Value::Text("3".into())), Some(Value::Text("4".into()))]);
    }

    #[test]
    fn an_unknown_column_names_those_there_are() {
        let err = Grouping::new(columns(), "isle", "a.gpkg").unwrap_err();
        assert_eq!(err, "a.gpkg: --by: no column 'isle' (the columns: 'island', 'Area', 'id')");
        assert_eq!(Grouping::new(columns(), "area", "a").unwrap().by, 1, "case aside");
        let err = Grouping::new(Vec::new(), "x", "a.shp").unwrap_err();
        assert!(err.ends_with("(it has no attribute columns)"), "{err}");
    }
}
