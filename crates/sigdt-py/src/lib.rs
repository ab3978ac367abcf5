//! Python bindings of `sigdt`, built by maturin as `sigdt._core`.
//!
//! This crate only converts types: numpy arrays in (copied once, so that a result depends
//! only on the data at the call while the GIL is released); numpy arrays, dicts with named
//! keys and the `Trace` class out; core errors to Python exceptions, panics to
//! `InternalError`. The user-facing names, defaults and docstrings live in `python/sigdt`.
mod antimeridian;
mod convert;
mod eval;
mod interrupt;
mod replay;

use std::collections::HashMap;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex, OnceLock};

use convert::{err, guarded, points, InternalError, InvalidInputError, ParseError};
use interrupt::interruptible;
use numpy::{IntoPyArray, PyArray2, PyArrayMethods, PyReadonlyArray1, PyReadonlyArray2};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};
use rayon::prelude::*;
use sigdt::{Expect, GraphKind, Method, Options, Phase};

fn options(method: &str, leaf_elimination: bool, expect: &str) -> PyResult<Options> {
    let method: Method = method.parse().map_err(err)?;
    let expect: Expect = expect.parse().map_err(err)?;
    Ok(Options { method, leaf_elimination, expect })
}

/// Why `lon_lat` input is reconstructed in a local plane, in its refusals.
const DEGREES: &str = "the coordinate system is longitude/latitude";

/// The reconstruction of `pts`, in their local plane when they are longitude and latitude
/// (`sigdt_io::reconstruct_in_plane`, as the command line does).
fn run(
    pts: &[sigdt::Point],
    options: &Options,
    lon_lat: bool,
) -> anyhow::Result<sigdt::Reconstruction> {
    match lon_lat {
        true => sigdt_io::reconstruct_in_plane(pts, options, DEGREES),
        false => Ok(sigdt::reconstruct(pts, options)?),
    }
}

/// A failed [`run`] as the Python exception: the kernel's errors as [`err`] maps them, a
/// refusal of the local plane as [`InvalidInputError`].
fn run_err(e: anyhow::Error) -> PyErr {
    match e.downcast::<sigdt::Error>() {
        Ok(e) => err(e),
        Err(e) => InvalidInputError::new_err(e.to_string()),
    }
}

/// `reconstruct(points, method, leaf_elimination, lon_lat=False) -> dict` (see
/// convert::reconstruction).
#[pyfunction]
#[pyo3(signature = (points, method, leaf_elimination, lon_lat=false, expect="curves"))]
fn reconstruct<'py>(
    py: Python<'py>,
    points: PyReadonlyArray2<'py, f64>,
    method: &str,
    leaf_elimination: bool,
    lon_lat: bool,
    expect: &str,
) -> PyResult<Bound<'py, PyDict>> {
    let options = options(method, leaf_elimination, expect)?;
    let method = options.method;
    let pts = convert::points(&points)?;
    let n = pts.len();
    let work = move |_: &Arc<AtomicBool>| {
        guarded(move || match lon_lat {
            true => run(&pts, &options, true),
            // The copy is the call's own: freed once triangulated.
            false => Ok(sigdt::reconstruct_owned(pts, &options)?),
        })
    };
    let rec = interruptible(py, n, work)?.map_err(InternalError::new_err)?.map_err(run_err)?;
    convert::reconstruction(py, &rec, method)
}

/// The thread pool of `threads` threads, built once and kept for later calls.
fn pool(threads: usize) -> Result<Arc<rayon::ThreadPool>, String> {
    static POOLS: OnceLock<Mutex<HashMap<usize, Arc<rayon::ThreadPool>>>> = OnceLock::new();
    let mut pools = POOLS.get_or_init(Default::default).lock().map_err(|e| e.to_string())?;
    if let Some(pool) = pools.get(&threads) {
        return Ok(Arc::clone(pool));
    }
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .map(Arc::new)
        .map_err(|e| e.to_string())?;
    pools.insert(threads, Arc::clone(&pool));
    Ok(pool)
}

/// `reconstruct_many(point_sets, method, leaf_elimination, n_jobs) -> list[dict]`, in
/// parallel with the GIL released; an error names the failing set.
///
/// `_panic_in_set` is a test hook (not exposed by `sigdt.reconstruct_many`): the set with
/// that index panics inside its worker instead of being reconstructed, so the tests can
/// check that a Rust panic in one parallel task becomes an `InternalError` naming the set.
#[pyfunction]
#[pyo3(signature = (point_sets, method, leaf_elimination, n_jobs=None, lon_lat=false, _panic_in_set=None, expect="curves"))]
// The Python signature's arguments, one each: the binding stays thin.
#[allow(clippy::too_many_arguments)]
fn reconstruct_many<'py>(
    py: Python<'py>,
    point_sets: Vec<Bound<'py, PyAny>>,
    method: &str,
    leaf_elimination: bool,
    n_jobs: Option<usize>,
    lon_lat: bool,
    _panic_in_set: Option<usize>,
    expect: &str,
) -> PyResult<Bound<'py, PyList>> {
    let options = options(method, leaf_elimination, expect)?;
    let method = options.method;
    // One array borrowed at a time, copied and released: rust-numpy checks each new borrow
    // against every live one of the same base array, so holding them all (views of one
    // array, as Python's grouping passes) cost O(sets²).
    let sets = point_sets
        .iter()
        .enumerate()
        .map(|(k, a)| {
            a.extract::<PyReadonlyArray2<'py, f64>>()
                .and_then(|array| points(&array))
                .map_err(|e| InvalidInputError::new_err(format!("point set {k}: {}", e.value(py))))
        })
        .collect::<PyResult<Vec<_>>>()?;
    let total: usize = sets.iter().map(Vec::len).sum();
    let work = move |cancel: &Arc<AtomicBool>| {
        let all = || -> Vec<Result<anyhow::Result<sigdt::Reconstruction>, String>> {
            sets.par_iter()
                .enumerate()
                .map(|(k, pts)| {
                    if cancel.load(Ordering::Relaxed) {
                        return Err("interrupted".to_string()); // the caller has gone
                    }
                    guarded(|| {
                        if _panic_in_set == Some(k) {
                            panic!("test hook: panic in point set {k}");
                        }
                        run(pts, &options, lon_lat)
                    })
                })
                .collect()
        };
        match n_jobs {
            None => Ok(all()),
            Some(threads) => pool(threads).map(|pool| pool.install(all)),
        }
    };
    let results =
        interruptible(py, total, work)?.map_err(pyo3::exceptions::PyRuntimeError::new_err)?;
    let list = PyList::empty(py);
    for (k, result) in results.into_iter().enumerate() {
        let rec = result
            .map_err(|msg| InternalError::new_err(format!("point set {k}: {msg}")))?
            .map_err(|e| {
                let py_err = run_err(e);
                let message = format!("point set {k}: {}", py_err.value(py));
                match () {
                    _ if py_err.is_instance_of::<ParseError>(py) => ParseError::new_err(message),
                    _ if py_err.is_instance_of::<InvalidInputError>(py) => {
                        InvalidInputError::new_err(message)
                    }
                    _ => pyo3::exceptions::PyValueError::new_err(message),
                }
            })?;
        list.append(convert::reconstruction(py, &rec, method)?)?;
    }
    Ok(list)
}

/// `trace(points, method, leaf_elimination) -> Trace | None`: the steps of inflating and
/// sculpting, `None` for graph filters and degenerate input.
#[pyfunction]
fn trace(
    py: Python<'_>,
    points: PyReadonlyArray2<'_, f64>,
    method: &str,
    leaf_elimination: bool,
) -> PyResult<Option<replay::Trace>> {
    let options = options(method, leaf_elimination, "curves")?;
    let pts = convert::points(&points)?;
    let (_, trace) = py
        .detach(|| guarded(|| sigdt::reconstruct_traced(&pts, &options)))
        .map_err(InternalError::new_err)?
        .map_err(err)?;
    Ok(trace.map(replay::Trace))
}

/// `polygons(points, loop_vertices, loop_offsets) -> list[(shell, holes)]`: the loops (flat,
/// as `reconstruct` returns them) grouped into polygons with holes by
/// `sigdt::Reconstruction::polygons`, with exact predicates; indices into the loops.
#[pyfunction]
fn polygons(
    py: Python<'_>,
    points: PyReadonlyArray2<'_, f64>,
    loop_vertices: PyReadonlyArray1<'_, i64>,
    loop_offsets: PyReadonlyArray1<'_, i64>,
) -> PyResult<Vec<(usize, Vec<usize>)>> {
    let pts = convert::points(&points)?;
    let loops = convert::chains_from(&loop_vertices, &loop_offsets, pts.len())?;
    let rec = sigdt::Reconstruction { loops, ..Default::default() };
    let polygons = py
        .detach(|| guarded(|| Ok(rec.polygons(&pts))))
        .map_err(InternalError::new_err)?
        .map_err(err)?;
    Ok(polygons.into_iter().map(|p| (p.shell, p.holes)).collect())
}

/// `write_reconstruction(points, fields, format) -> str`: the result of `reconstruct` (the
/// dict `fields`, from `points`) as text in `format` (`wkt`, `geojson`, `loops`, `edges`), by
/// the writer of `sigdt reconstruct --format` (`sigdt_io::text::write_reconstruction`), so that
/// `to_wkt` and `to_geojson` write what the CLI writes.
#[pyfunction]
fn write_reconstruction(
    py: Python<'_>,
    points: PyReadonlyArray2<'_, f64>,
    fields: &Bound<'_, PyDict>,
    format: &str,
) -> PyResult<String> {
    let format: sigdt_io::text::OutputFormat = format.parse().map_err(err)?;
    let pts = convert::points(&points)?;
    let rec = convert::reconstruction_from(fields, pts.len())?;
    // Results pickled before the method was recorded have none.
    let method = match fields.get_item("method")? {
        Some(name) => Some(name.extract::<String>()?.parse::<Method>().map_err(err)?),
        None => None,
    };
    let options = sigdt_io::text::WriteOptions { method, legacy_crs: None };
    let write = || {
        let mut out = Vec::new();
        sigdt_io::text::write_reconstruction_with(&mut out, format, &pts, &rec, &options)
            .map(|()| out)
    };
    let out = py
        .detach(|| guarded(|| Ok(write())))
        .map_err(InternalError::new_err)?
        .map_err(err)?
        .map_err(|e| InternalError::new_err(format!("writing the result: {e}")))?;
    String::from_utf8(out).map_err(|e| InternalError::new_err(e.to_string()))
}

/// `proximity_graph(points, kind, k) -> (m, 2) int64 array`.
#[pyfunction]
#[pyo3(signature = (points, kind, k=None))]
fn proximity_graph<'py>(
    py: Python<'py>,
    points: PyReadonlyArray2<'py, f64>,
    kind: &str,
    k: Option<usize>,
) -> PyResult<Bound<'py, PyArray2<i64>>> {
    let kind = GraphKind::from_name(kind, k).map_err(err)?;
    let pts = convert::points(&points)?;
    let edges = py
        .detach(|| guarded(|| sigdt::proximity_graph(&pts, kind)))
        .map_err(InternalError::new_err)?
        .map_err(err)?;
    convert::edges(py, &edges)
}

/// `place(points, width) -> (height, (n, 2) float64 array)`: where `sigdt render` puts the
/// points on a page `width` pixels wide (`sigdt_lab::render::place`), NaN for a point it
/// cannot place; `Reconstruction.to_svg` draws with it.
#[pyfunction]
fn place<'py>(
    py: Python<'py>,
    points: PyReadonlyArray2<'py, f64>,
    width: f64,
) -> PyResult<(f64, Bound<'py, PyArray2<f64>>)> {
    let pts = convert::points(&points)?;
    let (height, at) = py
        .detach(|| guarded(|| Ok(sigdt_lab::render::place(&pts, width))))
        .map_err(InternalError::new_err)?
        .map_err(err)?;
    let flat: Vec<f64> = at.iter().flat_map(|p| p.unwrap_or([f64::NAN; 2])).collect();
    Ok((height, flat.into_pyarray(py).reshape([pts.len(), 2])?))
}

/// `read_points(path, columns, max_points) -> (n, 2) float64 array`, in any format the CLI
/// reads, by its reader (`sigdt_io`).
#[pyfunction]
#[pyo3(signature = (path, columns=None, max_points=None, layer=None))]
fn read_points<'py>(
    py: Python<'py>,
    path: std::path::PathBuf,
    columns: Option<String>,
    max_points: Option<usize>,
    layer: Option<String>,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let max_points = max_points.unwrap_or(usize::MAX);
    let read = move |cancel: &Arc<AtomicBool>| {
        sigdt_io::cancel::cancellable(Arc::clone(cancel), || {
            sigdt_io::read_points_file(&path, columns.as_deref(), layer.as_deref(), max_points)
        })
    };
    // On a thread of its own (as many points as a file may hold), so that Ctrl-C raises at
    // once and the reader, told by the flag, stops (a GeoPackage view may not end).
    let pts = interruptible(py, usize::MAX, read)?.map_err(|e| match e {
        sigdt_io::Error::Io(io) => err(io),
        sigdt_io::Error::Usage(message) => PyValueError::new_err(message),
        sigdt_io::Error::Data(message) => ParseError::new_err(message),
    })?;
    let n = pts.len();
    let flat: Vec<f64> = pts.iter().flatten().copied().collect();
    flat.into_pyarray(py).reshape([n, 2])
}

/// The extension module.
#[pymodule]
fn _core(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(reconstruct, m)?)?;
    m.add_function(wrap_pyfunction!(reconstruct_many, m)?)?;
    m.add_function(wrap_pyfunction!(trace, m)?)?;
    m.add_function(wrap_pyfunction!(polygons, m)?)?;
    m.add_function(wrap_pyfunction!(write_reconstruction, m)?)?;
    m.add_function(wrap_pyfunction!(proximity_graph, m)?)?;
    m.add_function(wrap_pyfunction!(read_points, m)?)?;
    m.add_function(wrap_pyfunction!(place, m)?)?;
    m.add_function(wrap_pyfunction!(antimeridian::split_polygon_at_antimeridian, m)?)?;
    m.add_function(wrap_pyfunction!(antimeridian::split_line_at_antimeridian, m)?)?;
    m.add_function(wrap_pyfunction!(eval::evaluate, m)?)?;
    m.add_function(wrap_pyfunction!(eval::graph_epsilon, m)?)?;
    m.add_function(wrap_pyfunction!(eval::graph_overlap, m)?)?;
    m.add_class::<replay::Trace>()?;
    m.add("METHODS", Method::ALL.iter().map(|m| m.name()).collect::<Vec<_>>())?;
    m.add("GRAPH_KINDS", GraphKind::NAMES.to_vec())?;
    m.add("PHASES", Phase::ALL.iter().map(|p| p.name()).collect::<Vec<_>>())?;
    // The colours of every picture, shared with `sigdt render` and `sigdt view`.
    let palette: std::collections::HashMap<&str, &str> =
        sigdt_lab::render::palette::PALETTE.into_iter().collect();
    m.add("PALETTE", palette)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
