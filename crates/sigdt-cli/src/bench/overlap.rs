//! The proximity-graph overlap of the paper's §5, averaged over the manifold cases (the
//! graph-based epsilon of each case is computed by a worker, `runner::fill_graph_epsilon`).

use std::path::Path;

use sigdt_lab::eval::{self, Overlap};

use super::record::{Case, OverlapStat};

/// The category the overlap statistics are averaged over, as in the paper.
const OVERLAP_CATEGORY: &str = "manifold";

/// Mean per-set percentages over the manifold cases, with the paper's values (§5).
pub fn overlap_stats(dir: &Path, cases: &[Case]) -> Vec<OverlapStat> {
    // In-process: the graphs are O(n log n) and containment linear, whatever the ground
    // truth (unlike epsilon, which runs in the workers).
    let sets: Vec<Overlap> = cases
        .iter()
        .filter(|c| c.row.category == OVERLAP_CATEGORY)
        .filter_map(|c| labelled(dir, c))
        .filter_map(|(points, gt)| eval::overlap(&points, &gt).ok())
        .collect();
    if sets.is_empty() {
        return Vec::new();
    }
    let count = sets.len() as f64;
    let mean = |f: &dyn Fn(&Overlap) -> f64| 100.0 * sets.iter().map(f).sum::<f64>() / count;
    let share = |f: &dyn Fn(&Overlap) -> bool| {
        Some(100.0 * sets.iter().filter(|s| f(s)).count() as f64 / count)
    };
    let stat =
        |name: &str, mean_percent: f64, contained: Option<f64>, paper: Option<f64>| OverlapStat {
            name: name.to_string(),
            mean_percent,
            sets_contained_percent: contained,
            paper_percent: paper,
        };
    let g = |o: &Overlap| o.gt_in;
    vec![
        stat("SIG edges in DT", mean(&|o| o.sig_in_dt), None, Some(90.9)),
        stat("DT edges in SIG", mean(&|o| o.dt_in_sig), None, Some(47.2)),
        stat(
            "ground truth in SIGDT",
            mean(&|o| g(o).sigdt.fraction),
            share(&|o| g(o).sigdt.contains),
            Some(99.9),
        ),
        stat(
            "ground truth in SIGDT2",
            mean(&|o| g(o).sigdt2.fraction),
            share(&|o| g(o).sigdt2.contains),
            None,
        ),
        stat(
            "ground truth in BC0",
            mean(&|o| g(o).bc0.fraction),
            share(&|o| g(o).bc0.contains),
            Some(99.6),
        ),
        stat(
            "ground truth in 2NN",
            mean(&|o| g(o).knn2.fraction),
            share(&|o| g(o).knn2.contains),
            Some(98.4),
        ),
        stat(
            "ground truth in 3NN",
            mean(&|o| g(o).knn3.fraction),
            share(&|o| g(o).knn3.contains),
            Some(98.5),
        ),
        stat(
            "ground truth in 4NN",
            mean(&|o| g(o).knn4.fraction),
            share(&|o| g(o).knn4.contains),
            Some(98.6),
        ),
        stat("SIGDT edges in ground truth", mean(&|o| o.sigdt_in_gt), None, Some(76.8)),
    ]
}

/// The points and ground truth of `case`, if both can be read (by the lab's reader, which
/// also checks the ground truth against the points).
fn labelled(dir: &Path, case: &Case) -> Option<(Vec<sigdt::Point>, Vec<sigdt::Edge>)> {
    case.row.read(dir).ok()
}
