//! `sigdt reconstruct --by COLUMN`: the points reconstructed group by group, and the groups
//! as GIS layers, one feature per group per layer carrying the attributes that are the same
//! on all of its points ([`sigdt_io::attributes`]).
//!
//! Groups run in parallel on the threads of `--threads` (the pool `run` installs), each in
//! its own local plane when the points are longitude and latitude, as one whole input would.
//! A group that fails (spread over more than a hemisphere, ...) does not fail the run: its
//! `areas` feature has no geometry, status `error` and the message as its diagnosis; one
//! warning line names the groups without a curve, failed or with too few points.

use anyhow::Result;
use rayon::prelude::*;
use sigdt::{Options, Point, Reconstruction};
use sigdt_io::attributes::{Grouping, Value};
use sigdt_io::gis::layers::Layers;
use sigdt_io::gis::local::reconstruct_in_plane;

use crate::messages::one_line;

/// The results of every group, as layers, and what a user must be told about them.
pub struct Groups {
    /// One feature per group per layer.
    pub layers: Layers,
    /// The names of the groups without a curve, each with why: its error, or its status
    /// (`too-few-points: fewer than three distinct points`).
    pub without_curves: Vec<(String, String)>,
    /// The names of the groups whose result warns ([`Reconstruction::warns`]).
    pub warned: Vec<String>,
    /// How many groups ended in each status, in order of first appearance.
    pub statuses: Vec<(&'static str, usize)>,
    /// How many points were left out, per reason, in name order.
    pub left_out: std::collections::BTreeMap<&'static str, usize>,
}

/// Reconstructs each group of `grouping` (its points among `points`) with `options`; in a
/// local plane when `degrees` says why the points are longitude and latitude.
pub fn reconstruct(
    points: &[Point],
    mut grouping: Grouping,
    options: &Options,
    degrees: Option<&str>,
) -> Groups {
    let kept = grouping.kept_columns();
    let columns = kept.iter().map(|&c| grouping.columns[c].clone()).collect();
    let mut layers = Layers::with_columns(columns);
    let members = grouping.members();
    let results: Vec<Result<Reconstruction>> = members
        .par_iter()
        .map(|rows| {
            let group: Vec<Point> = rows.iter().map(|&i| points[i]).collect();
            match degrees {
                Some(why) => reconstruct_in_plane(&group, options, why),
                None => Ok(sigdt::reconstruct_owned(group, options)?),
            }
        })
        .collect();
    let mut groups = Groups {
        layers: Layers::default(),
        without_curves: Vec::new(),
        warned: Vec::new(),
        statuses: Vec::new(),
        left_out: Default::default(),
    };
    for (k, (rows, result)) in members.iter().zip(results).enumerate() {
        let group = &grouping.groups[k];
        let values: Vec<Value> =
            kept.iter().map(|&c| group.values[c].clone().unwrap_or(Value::Null)).collect();
        let name = grouping.group_name(k);
        match result {
            Ok(rec) => {
                let group_points: Vec<Point> = rows.iter().map(|&i| points[i]).collect();
                let lon_lat = degrees.is_some();
                layers.add(values, options.method, &group_points, &rec, lon_lat, Some(rows));
                if rec.loops.is_empty() && rec.paths.is_empty() {
                    let why = format!("{}: {}", rec.status.name(), rec.status);
                    groups.without_curves.push((name, why));
                } else if rec.warns() {
                    groups.warned.push(name);
                }
                let status = rec.status.name();
                match groups.statuses.iter_mut().find(|(s, _)| *s == status) {
                    Some((_, count)) => *count += 1,
                    None => groups.statuses.push((status, 1)),
                }
                for l in &rec.left_out {
                    *groups.left_out.entry(l.reason.name()).or_default() += 1;
                }
            }
            Err(err) => {
                let message = one_line(&err);
                layers.add_failed(values, options.method, message.clone());
                groups.without_curves.push((name, message));
            }
        }
    }
    groups.layers = layers;
    groups
}

/// `names` for a message: all of them up to ten, then how many more.
pub fn listed(names: impl ExactSizeIterator<Item = String>) -> String {
    let total = names.len();
    let shown: Vec<String> = names.take(10).collect();
    match total - shown.len() {
        0 => shown.join(", "),
        more => format!("{} and {more} more", shown.join(", ")),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use sigdt_io::attributes::{Column, ColumnType};

    #[test]
    fn each_group_is_reconstructed_alone_and_a_failure_is_a_feature() {
        // Two squares apart, two points, one point, and one that is no longitude.
        let square = |dx: f64| [[dx, 0.0], [dx + 1.0, 0.0], [dx + 1.0, 1.0], [dx, 1.0]];
        let rest = [[50.0, 50.0], [51.0, 50.0], [60.0, 60.0], [400.0, 0.0]];
        let points: Vec<Point> = [&square(0.0)[..], &square(10.0), &rest].concat();
        let keys = ["a", "a", "a", "a", "b", "b", "b", "b", "c", "c", "d", "e"];
        let column = |name: &str| Column { name: name.into(), kind: ColumnType::Text };
        let mut grouping =
            Grouping::new(vec![column("island"), column("id")], "island", "t").expect("a column");
        let text = |s: &str| Value::Text(s.into());
        for (k, key) in keys.iter().enumerate() {
            grouping.add(vec![text(key), text(&k.to_string())], 1);
        }
        let degrees = Some("the test says degrees");
        let groups = reconstruct(&points, grouping, &Options::default(), degrees);
        let layers = &groups.layers;
        assert_eq!(layers.groups.len(), 5);
        assert_eq!(layers.columns.len(), 2, "`id` is the same within the one-point groups");
        assert_eq!(layers.groups[2].values, [text("c"), Value::Null]);
        assert_eq!(layers.areas.len(), 4, "two squares, and d and e without geometry");
        assert_eq!(layers.paths.len(), 1, "two points give their edge");
        assert_eq!(layers.groups[4].run.status, "error");
        assert_eq!(groups.statuses, [("polygon", 2), ("too-few-points", 2)]);
        let without: Vec<&str> = groups.without_curves.iter().map(|(n, _)| n.as_str()).collect();
        assert_eq!(without, ["'d'", "'e'"]);
        assert!(groups.without_curves[1].1.contains("is not a longitude and a latitude"));
        assert_eq!(
            listed((0..12).map(|k| k.to_string())),
            "0, 1, 2, 3, 4, 5, 6, 7, 8, 9 and 2 more"
        );
    }
}
