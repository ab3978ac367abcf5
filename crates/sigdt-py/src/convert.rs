//! Conversions between numpy / Python values and the core's types, and error mapping.
use numpy::{
    IntoPyArray, PyArray1, PyArray2, PyArrayMethods, PyReadonlyArray1, PyReadonlyArray2,
    PyUntypedArrayMethods,
};
use pyo3::exceptions::{PyKeyError, PyOSError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use sigdt::{
    Edge, Finding, FindingKind, LeftOut, LeftOutReason, Method, Point, Reconstruction, Status,
    Vertices,
};

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
pub fn guarded<T, E>(f: impl FnOnce() -> Result<T, E>) -> Result<Result<T, E>, String> {
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
pub fn reconstruction<'py>(
    py: Python<'py>,
    rec: &Reconstruction,
    method: Method,
) -> PyResult<Bound<'py, PyDict>> {
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
    dict.set_item("method", method.name())?;
    dict.set_item("status_warns", rec.warns())?;
    dict.set_item("status_is_warning", rec.status.is_warning())?;
    let diagnosis = PyList::empty(py);
    for f in &rec.diagnosis {
        let finding = PyDict::new(py);
        finding.set_item("kind", f.kind.name())?;
        finding.set_item("count", f.count)?;
        finding.set_item("worst", f.worst)?;
        finding.set_item("at", f.at)?;
        finding.set_item("point", f.point.to_vec())?;
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

/// The value of `key` in `fields`; a `KeyError` naming it when it is missing.
fn item<'py>(fields: &Bound<'py, PyDict>, key: &str) -> PyResult<Bound<'py, PyAny>> {
    fields.get_item(key)?.ok_or_else(|| PyKeyError::new_err(key.to_string()))
}

/// The `[i, j]` rows of an `(m, 2)` int64 array, each index below `n`.
fn pairs_from(array: &Bound<'_, PyAny>, what: &str, n: usize) -> PyResult<Vec<Edge>> {
    let array = array.extract::<PyReadonlyArray2<'_, i64>>()?;
    let view = array.as_array();
    if view.ncols() != 2 && view.nrows() > 0 {
        return Err(PyValueError::new_err(format!("{what} must have shape (m, 2)")));
    }
    view.rows()
        .into_iter()
        .map(|row| {
            let index = |v: i64| {
                usize::try_from(v).ok().filter(|&v| v < n).ok_or_else(|| {
                    PyValueError::new_err(format!("{what}: {v} is not an index below {n}"))
                })
            };
            Ok([index(row[0])?, index(row[1])?])
        })
        .collect()
}

/// The status named `name`; `SculptingStuck` lists the points left out as inside.
fn status_from(name: &str, left_out: &[LeftOut]) -> PyResult<Status> {
    let inside = left_out.iter().filter(|l| l.reason == LeftOutReason::Inside).map(|l| l.index);
    [
        Status::Polygon,
        Status::Polygons,
        Status::SculptingStuck { left_out: inside.collect() },
        Status::Curves,
        Status::Network,
        Status::Branching,
        Status::Noisy,
        Status::Crossing,
        Status::Unfinished,
        Status::Collinear,
        Status::TooFewPoints,
    ]
    .into_iter()
    .find(|s| s.name() == name)
    .ok_or_else(|| PyValueError::new_err(format!("unknown status {name:?}")))
}

/// The finding of a dict made by [`reconstruction`] (its `message` is the finding's text, so
/// it is not read back).
fn finding_from(finding: &Bound<'_, PyAny>) -> PyResult<Finding> {
    let finding = finding.cast::<PyDict>()?;
    let name: String = item(finding, "kind")?.extract()?;
    let kind = [
        FindingKind::PassesOverSamples,
        FindingKind::DoublesBack,
        FindingKind::SmallLoops,
        FindingKind::OpenEnds,
        FindingKind::OutliersOnCurve,
        FindingKind::EndsMeet,
        FindingKind::NoisyArea,
        FindingKind::OpenOutlines,
    ]
    .into_iter()
    .find(|k| k.name() == name)
    .ok_or_else(|| PyValueError::new_err(format!("unknown finding kind {name:?}")))?;
    Ok(Finding {
        kind,
        count: item(finding, "count")?.extract()?,
        worst: item(finding, "worst")?.extract()?,
        at: item(finding, "at")?.extract()?,
        // Results kept from before findings had coordinates have none.
        point: match finding.get_item("point")? {
            Some(point) => match point.extract::<Vec<f64>>()?[..] {
                [x, y] => [x, y],
                _ => return Err(PyValueError::new_err("a finding's point is not [x, y]")),
            },
            None => [f64::NAN; 2],
        },
    })
}

/// The core's result of a dict made by [`reconstruction`] from `n` points (as
/// `python/sigdt/_result.py` keeps it, maybe pickled and back): everything the writers of
/// `sigdt_io::text` read (not `stats`). Every index is checked against the points or vertices
/// it refers to; an unknown name or a missing key raises.
pub fn reconstruction_from(fields: &Bound<'_, PyDict>, n: usize) -> PyResult<Reconstruction> {
    let positions = item(fields, "positions")?;
    let positions = if positions.is_none() {
        None
    } else {
        Some(points(&positions.extract::<PyReadonlyArray2<'_, f64>>()?)?)
    };
    let kind: String = item(fields, "vertices")?.extract()?;
    let vertices = match (kind.as_str(), positions) {
        ("input", None) => Vertices::Input,
        ("moved", Some(p)) if p.len() == n => Vertices::Moved(p),
        ("new", Some(p)) => Vertices::New(p),
        (kind, _) => {
            return Err(PyValueError::new_err(format!(
                "vertices {kind:?} do not match the positions given"
            )))
        }
    };
    let k = match &vertices {
        Vertices::Input => n,
        Vertices::Moved(p) | Vertices::New(p) => p.len(),
    };
    let chains = |name: &str| -> PyResult<Vec<Vec<usize>>> {
        let flat = item(fields, &format!("{name}_vertices"))?;
        let offsets = item(fields, &format!("{name}_offsets"))?;
        chains_from(&flat.extract()?, &offsets.extract()?, k)
    };
    let (loops, paths) = (chains("loop")?, chains("path")?);
    let indices = item(fields, "left_out")?.extract::<PyReadonlyArray1<'_, i64>>()?;
    let reasons: Vec<String> = item(fields, "left_out_reasons")?.extract()?;
    if indices.len() != reasons.len() {
        return Err(PyValueError::new_err("left_out and left_out_reasons differ in length"));
    }
    let left_out = indices
        .as_array()
        .iter()
        .zip(&reasons)
        .map(|(&index, reason)| {
            let index = usize::try_from(index).ok().filter(|&i| i < n).ok_or_else(|| {
                PyValueError::new_err(format!("left_out: {index} is not a point index"))
            })?;
            let reason =
                LeftOutReason::ALL.into_iter().find(|r| r.name() == reason).ok_or_else(|| {
                    PyValueError::new_err(format!("unknown left-out reason {reason:?}"))
                })?;
            Ok(LeftOut { index, reason })
        })
        .collect::<PyResult<Vec<_>>>()?;
    let status: String = item(fields, "status")?.extract()?;
    let diagnosis = item(fields, "diagnosis")?
        .try_iter()?
        .map(|f| finding_from(&f?))
        .collect::<PyResult<Vec<_>>>()?;
    Ok(Reconstruction {
        edges: pairs_from(&item(fields, "edges")?, "edges", k)?,
        loops,
        paths,
        status: status_from(&status, &left_out)?,
        duplicates: pairs_from(&item(fields, "duplicates")?, "duplicates", n)?,
        left_out,
        vertices,
        stats: Default::default(),
        diagnosis,
    })
}
