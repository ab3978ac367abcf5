//! Bindings of `sigdt_lab::eval`: metrics against ground truth, as plain dicts and floats.
use numpy::{PyReadonlyArray2, PyUntypedArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::PyDict;
use sigdt::Edge;

use crate::convert::{err, guarded, points as point_slice, InternalError};
use crate::interrupt::interruptible;

/// The edges of an `(m, 2)` int64 array; negative indices are refused, naming the row.
fn edge_list(array: &PyReadonlyArray2<'_, i64>, what: &str) -> PyResult<Vec<Edge>> {
    let shape = array.shape();
    if shape[1] != 2 {
        return Err(PyValueError::new_err(format!(
            "{what} must have shape (m, 2), got ({}, {})",
            shape[0], shape[1]
        )));
    }
    let array = array.as_array();
    (0..shape[0])
        .map(|k| {
            let (i, j) = (array[[k, 0]], array[[k, 1]]);
            if i < 0 || j < 0 {
                return Err(PyValueError::new_err(format!(
                    "{what} row {k} ([{i}, {j}]) has a negative index"
                )));
            }
            Ok([i as usize, j as usize])
        })
        .collect()
}

/// Runs `f` with the GIL released, panics caught, and Ctrl-C raising `KeyboardInterrupt`
/// promptly when its `size` (counted as [`interruptible`] counts points) says it may take
/// long.
fn run<T: Send + 'static>(
    py: Python<'_>,
    size: usize,
    f: impl FnOnce() -> sigdt::Result<T> + Send + 'static,
) -> PyResult<T> {
    interruptible(py, size, move |_| guarded(f))?.map_err(InternalError::new_err)?.map_err(err)
}

/// `evaluate(points, edges, gt) -> dict`: exact, missing, extra, rmse, rmse_to_gt,
/// hausdorff (None without a result), area_difference, area_difference_normalised.
#[pyfunction]
pub fn evaluate<'py>(
    py: Python<'py>,
    points: PyReadonlyArray2<'py, f64>,
    edges: PyReadonlyArray2<'py, i64>,
    gt: PyReadonlyArray2<'py, i64>,
) -> PyResult<Bound<'py, PyDict>> {
    let pts = point_slice(&points)?;
    let (edges, gt) = (edge_list(&edges, "edges")?, edge_list(&gt, "gt")?);
    // The area's overlay splits the rings at every crossing, quadratic in the edges when
    // they cross everywhere (seconds for a few thousand): only calls that would be quick
    // even then run without a thread of their own.
    let size = pts.len().max((edges.len() + gt.len()).saturating_pow(2));
    let m = run(py, size, move || sigdt_lab::eval::evaluate(&pts, &edges, &gt))?;
    let dict = PyDict::new(py);
    dict.set_item("exact", m.exact)?;
    dict.set_item("missing", m.missing)?;
    dict.set_item("extra", m.extra)?;
    dict.set_item("rmse", m.distance.map(|d| d.rmse))?;
    dict.set_item("rmse_to_gt", m.distance.map(|d| d.rmse_to_gt))?;
    dict.set_item("hausdorff", m.distance.map(|d| d.hausdorff))?;
    dict.set_item("area_difference", m.area.area)?;
    dict.set_item("area_difference_normalised", m.area.normalised)?;
    Ok(dict)
}

/// `graph_epsilon(points, gt) -> float`.
#[pyfunction]
pub fn graph_epsilon<'py>(
    py: Python<'py>,
    points: PyReadonlyArray2<'py, f64>,
    gt: PyReadonlyArray2<'py, i64>,
) -> PyResult<f64> {
    let pts = point_slice(&points)?;
    let gt = edge_list(&gt, "gt")?;
    run(py, pts.len() + gt.len(), move || sigdt_lab::eval::graph_epsilon(&pts, &gt))
}

/// `graph_overlap(points, gt) -> dict` of fractions (and `contains_*` booleans).
#[pyfunction]
pub fn graph_overlap<'py>(
    py: Python<'py>,
    points: PyReadonlyArray2<'py, f64>,
    gt: PyReadonlyArray2<'py, i64>,
) -> PyResult<Bound<'py, PyDict>> {
    let pts = point_slice(&points)?;
    let gt = edge_list(&gt, "gt")?;
    let o = run(py, pts.len() + gt.len(), move || sigdt_lab::eval::overlap(&pts, &gt))?;
    let dict = PyDict::new(py);
    dict.set_item("sig_in_dt", o.sig_in_dt)?;
    dict.set_item("dt_in_sig", o.dt_in_sig)?;
    dict.set_item("sigdt_in_gt", o.sigdt_in_gt)?;
    let g = o.gt_in;
    for (name, c) in [
        ("sigdt", g.sigdt),
        ("sigdt2", g.sigdt2),
        ("bc0", g.bc0),
        ("knn2", g.knn2),
        ("knn3", g.knn3),
        ("knn4", g.knn4),
    ] {
        dict.set_item(format!("gt_in_{name}"), c.fraction)?;
        dict.set_item(format!("contains_gt_{name}"), c.contains)?;
    }
    Ok(dict)
}
