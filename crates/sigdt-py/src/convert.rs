//! Conversions between numpy / Python values and the core's types, and error mapping.
use numpy::{
    IntoPyArray, PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray2, PyUntypedArrayMethods,
};
use pyo3::exceptions::{PyOSError, PyRuntimeError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyTuple};
use sigdt::{Edge, Phase, Point, Reconstruction, Status, Trace};

pyo3::create_exception!(
    sigdt,
    InvalidInputError,
    PyValueError,
    "The points are unusable: wrong shape, non-finite values, or an impossible range."
);
pyo3::create_exception!(sigdt, ParseError, PyValueError, "A point file could not be parsed.");
pyo3::create_exception!(
    sigdt,
    InternalError,
    PyRuntimeError,
    "A bug inside sigdt (a Rust panic), reported instead of crashing."
);

/// The points of an `(n, 2)` C-contiguous float64 array, borrowed without copying.
pub fn points<'a>(array: &'a PyReadonlyArray2<'_, f64>) -> PyResult<&'a [Point]> {
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
    Ok(bytemuck::cast_slice(flat))
}

/// The Python exception for a core error.
pub fn err(e: sigdt::Error) -> PyErr {
    match e {
        sigdt::Error::Parse { .. } => ParseError::new_err(e.to_string()),
        sigdt::Error::Io { .. } => PyOSError::new_err(e.to_string()),
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

/// The tuple `python/sigdt/_result.py` builds a `Reconstruction` from:
/// `(edges, loop_vertices, loop_offsets, path_vertices, path_offsets, status, left_out,
/// duplicates, stats)`.
pub fn reconstruction<'py>(py: Python<'py>, rec: &Reconstruction) -> PyResult<Bound<'py, PyTuple>> {
    let (loop_vertices, loop_offsets) = chains(py, &rec.loops);
    let (path_vertices, path_offsets) = chains(py, &rec.paths);
    let left_out: &[usize] = match &rec.status {
        Status::SculptingStuck { left_out } => left_out,
        _ => &[],
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
    PyTuple::new(
        py,
        [
            edges(py, &rec.edges)?.into_any(),
            loop_vertices.into_any(),
            loop_offsets.into_any(),
            path_vertices.into_any(),
            path_offsets.into_any(),
            rec.status.name().into_pyobject(py)?.into_any(),
            indices(py, left_out).into_any(),
            edges(py, &rec.duplicates)?.into_any(),
            stats.into_any(),
        ],
    )
}

/// The tuple `python/sigdt/_trace.py` builds a `Trace` from: `(triangles (T, 3) int64,
/// graph (m, 2) int64, initial_inside (T,) bool, dangling (d, 2) int64, step_triangle (S,)
/// int64, step_inside (S,) bool, step_phase (S,) uint8, inflated_at)`; phase codes index
/// `Phase::ALL` (0 inflate, 1 pocket, 2 sculpt).
pub fn trace<'py>(py: Python<'py>, trace: &Trace) -> PyResult<Bound<'py, PyTuple>> {
    let flat: Vec<i64> = trace.triangles.iter().flatten().map(|&v| v as i64).collect();
    let triangles = flat.into_pyarray(py).reshape([trace.triangles.len(), 3])?;
    let steps = &trace.steps;
    let step_triangle: Vec<usize> = steps.iter().map(|s| s.triangle).collect();
    let step_inside: Vec<bool> = steps.iter().map(|s| s.inside).collect();
    let code = |p: Phase| Phase::ALL.iter().position(|&q| q == p).unwrap_or(0) as u8;
    let step_phase: Vec<u8> = steps.iter().map(|s| code(s.phase)).collect();
    PyTuple::new(
        py,
        [
            triangles.into_any(),
            edges(py, &trace.graph)?.into_any(),
            trace.initial_inside.clone().into_pyarray(py).into_any(),
            edges(py, &trace.dangling)?.into_any(),
            indices(py, &step_triangle).into_any(),
            step_inside.into_pyarray(py).into_any(),
            step_phase.into_pyarray(py).into_any(),
            trace.inflated_at.into_pyobject(py)?.into_any(),
        ],
    )
}
