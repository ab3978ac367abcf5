//! Conversions between numpy / Python values and the core's types, and error mapping.
use numpy::{
    IntoPyArray, PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray1, PyReadonlyArray2,
    PyUntypedArrayMethods,
};
use pyo3::exceptions::{PyOSError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use sigdt::{Edge, Point, Reconstruction, Vertices};

// The exception classes are Python's (`python/sigdt/errors.py`), so that they can derive
// from both `SigdtError` and the built-in class a caller expects.
pyo3::import_exception!(sigdt.errors, InvalidInputError);
pyo3::import_exception!(sigdt.errors, ParseError);
pyo3::import_exception!(sigdt.errors, InternalError);

/// The points of an `(n, 2)` C-contiguous float64 array, copied: the calls release the GIL,
/// and another Python thread writing to the array meanwhile must not change the result.
pub fn points(array: &PyReadonlyArray2<'_, f64>) -> PyResult<Vec<Point>> {
    let shape = array.shape();
    if shape[1] != 2 {
        return Err(InvalidInputError::new_err(format!(
            "points must have shape (n, 2), got ({}, {})",
            shape[0], shape[1]
        )));
    }
    let flat = array.as_slice().map_err(|_| {
        InvalidInputError::new_err("points must be a C-contiguous, aligned float64 array")
    })?;
    Ok(bytemuck::cast_slice(flat).to_vec())
}

/// The Python exception for a core error.
pub fn err(e: sigdt::Error) -> PyErr {
    match e {
        sigdt::Error::Parse { .. } => ParseError::new_err(e.to_string()),
        // The subclass Python code expects (FileNotFoundError, PermissionError, ...), with
        // errno and the file name, as `open` raises it.
        sigdt::Error::Io { path, source } => match source.raw_os_error() {
            Some(errno) => {
                let text = source.to_string();
                let suffix = format!(" (os error {errno})");
                let reason = text.strip_suffix(&suffix).unwrap_or(&text).to_string();
                PyOSError::new_err((errno, reason, path))
            }
            None => PyOSError::new_err(format!("{path}: {source}")),
        },
        sigdt::Error::InvalidOption(_) => PyValueError::new_err(e.to_string()),
        _ => InvalidInputError::new_err(e.to_string()),
    }
}

/// Runs `f`, turning a Rust panic into an [`InternalError`] message instead of unwinding
/// into Python.
pub fn guarded<T>(f: impl FnOnce() -> sigdt::Result<T>) -> Result<sigdt::Result<T>, String> {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)).map_err(|panic| {
        let what = panic
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| panic.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "unknown panic".into());
        format!("internal error in sigdt (please report it): {what}")
    })
}

/// `(m, 2)` int64 array of edges.
pub fn edges<'py>(py: Python<'py>, edges: &[Edge]) -> PyResult<Bound<'py, PyArray2<i64>>> {
    let flat: Vec<i64> = edges.iter().flat_map(|&[i, j]| [i as i64, j as i64]).collect();
    flat.into_pyarray(py).reshape([edges.len(), 2])
}

/// int64 vector.
pub fn indices<'py>(py: Python<'py>, values: &[usize]) -> Bound<'py, PyArray1<i64>> {
    values.iter().map(|&v| v as i64).collect::<Vec<i64>>().into_pyarray(py)
}

/// Chains as one flat int64 vector and offsets (chain `k` is `flat[offsets[k]:offsets[k+1]]`).
pub fn chains<'py>(
    py: Python<'py>,
    chains: &[Vec<usize>],
) -> (Bound<'py, PyArray1<i64>>, Bound<'py, PyArray1<i64>>) {
    let mut flat = Vec::with_capacity(chains.iter().map(Vec::len).sum());
    let mut offsets = Vec::with_capacity(chains.len() + 1);
    offsets.push(0i64);
    for c in chains {
        flat.extend(c.iter().map(|&v| v as i64));
        offsets.push(flat.len() as i64);
    }
    (flat.into_pyarray(py), offsets.into_pyarray(py))
}

/// The chains of a flat int64 vector and its offsets, the inverse of [`chains`]: the offsets
/// must run from 0 to the vector's length without decreasing, and every vertex must be a
/// point index below `n`.
pub fn chains_from(
    vertices: &PyReadonlyArray1<'_, i64>,
    offsets: &PyReadonlyArray1<'_, i64>,
    n: usize,
) -> PyResult<Vec<Vec<usize>>> {
    let vertices: Vec<i64> = vertices.as_array().iter().copied().collect();
    let offsets: Vec<i64> = offsets.as_array().iter().copied().collect();
    if let Some(v) = vertices.iter().find(|&&v| !(0..n as i64).contains(&v)) {
        return Err(PyValueError::new_err(format!("vertex {v} is not a point index (0..{n})")));
    }
    let runs = offsets.first() == Some(&0)
        && offsets.last() == Some(&(vertices.len() as i64))
        && offsets.windows(2).all(|w| w[0] <= w[1]);
    if !runs {
        return Err(PyValueError::new_err(format!(
            "offsets must rise from 0 to {} (the number of vertices)",
            vertices.len()
        )));
    }
    Ok(offsets
        .windows(2)
        .map(|w| vertices[w[0] as usize..w[1] as usize].iter().map(|&v| v as usize).collect())
        .collect())
}

/// The dict `python/sigdt/_result.py` builds a `Reconstruction` from (the `_Reconstruction`
/// TypedDict of `_core.pyi`): `edges`, `loop_vertices`, `loop_offsets`, `path_vertices`,
/// `path_offsets` (int64 arrays, chains as by [`chains`]), `status` (its name) with
/// `status_message` (what it means) and `status_warns` (whether it says the result is not a
/// faithful curve: `Status::is_warning`), `left_out`
/// (int64 indices) with `left_out_reasons` (their reasons' names, same order), `vertices`
/// (`"input"`, `"moved"` or `"new"`) with `positions` (the `(k, 2)` float64 coordinates the
/// edges index, or `None` for the input points), `duplicates` (int64 array) and `stats` (a
/// dict of counts).
pub fn reconstruction<'py>(py: Python<'py>, rec: &Reconstruction) -> PyResult<Bound<'py, PyDict>> {
    let (loop_vertices, loop_offsets) = chains(py, &rec.loops);
    let (path_vertices, path_offsets) = chains(py, &rec.paths);
    let left_out: Vec<usize> = rec.left_out.iter().map(|l| l.index).collect();
    let reasons: Vec<&str> = rec.left_out.iter().map(|l| l.reason.name()).collect();
    let (kind, positions) = match &rec.vertices {
        Vertices::Input => ("input", None),
        Vertices::Moved(p) => ("moved", Some(p)),
        Vertices::New(p) => ("new", Some(p)),
    };
    let positions = match positions {
        Some(p) => {
            let flat: Vec<f64> = p.iter().flat_map(|q| [q[0], q[1]]).collect();
            Some(flat.into_pyarray(py).reshape([p.len(), 2])?)
        }
        None => None,
    };
    let s = &rec.stats;
    let stats = PyDict::new(py);
    for (name, value) in [
        ("points", s.points),
        ("distinct_points", s.distinct_points),
        ("graph_edges", s.graph_edges),
        ("leaf_edges_added", s.leaf_edges_added),
        ("non_manifold_before", s.non_manifold_before),
        ("inflated_triangles", s.inflated_triangles),
        ("pockets", s.pockets),
        ("interior_before_sculpting", s.interior_before_sculpting),
        ("sculpted_triangles", s.sculpted_triangles),
    ] {
        stats.set_item(name, value)?;
    }
    let dict = PyDict::new(py);
    dict.set_item("edges", edges(py, &rec.edges)?)?;
    dict.set_item("loop_vertices", loop_vertices)?;
    dict.set_item("loop_offsets", loop_offsets)?;
    dict.set_item("path_vertices", path_vertices)?;
    dict.set_item("path_offsets", path_offsets)?;
    dict.set_item("status", rec.status.name())?;
    dict.set_item("status_message", rec.status.to_string())?;
    dict.set_item("status_warns", rec.warns())?;
    dict.set_item("status_is_warning", rec.status.is_warning())?;
    let diagnosis = PyList::empty(py);
    for f in &rec.diagnosis {
        let finding = PyDict::new(py);
        finding.set_item("kind", f.kind.name())?;
        finding.set_item("count", f.count)?;
        finding.set_item("worst", f.worst)?;
        finding.set_item("at", f.at)?;
        finding.set_item("message", f.to_string())?;
        diagnosis.append(finding)?;
    }
    dict.set_item("diagnosis", diagnosis)?;
    dict.set_item("left_out", indices(py, &left_out))?;
    dict.set_item("left_out_reasons", reasons)?;
    dict.set_item("vertices", kind)?;
    dict.set_item("positions", positions)?;
    dict.set_item("duplicates", edges(py, &rec.duplicates)?)?;
    dict.set_item("stats", stats)?;
    Ok(dict)
}
