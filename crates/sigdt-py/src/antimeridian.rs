//! Splitting longitude/latitude rings and lines at ±180° for Python's layers
//! (`sigdt._layers`), by the code the command line writes GIS files with
//! (`sigdt_io::gis::antimeridian`), so that both give the same geometries.

use numpy::{IntoPyArray, PyArray2, PyArrayMethods, PyReadonlyArray2};
use pyo3::prelude::*;
use sigdt::Point;
use sigdt_io::gis::antimeridian;

use crate::convert::points;

fn array<'py>(py: Python<'py>, ring: &[Point]) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let flat: Vec<f64> = ring.iter().flatten().copied().collect();
    flat.into_pyarray(py).reshape([ring.len(), 2])
}

/// `split_polygon_at_antimeridian(rings) -> list[list[array]]`: one polygon (shell, then
/// holes; rings not closed) as polygons valid in EPSG:4326.
#[pyfunction]
pub fn split_polygon_at_antimeridian<'py>(
    py: Python<'py>,
    rings: Vec<PyReadonlyArray2<'py, f64>>,
) -> PyResult<Vec<Vec<Bound<'py, PyArray2<f64>>>>> {
    let rings = rings.iter().map(points).collect::<PyResult<Vec<_>>>()?;
    antimeridian::split_polygon(&rings)
        .iter()
        .map(|polygon| polygon.iter().map(|ring| array(py, ring)).collect())
        .collect()
}

/// `split_line_at_antimeridian(line) -> list[array]`: one line cut where it crosses ±180°.
#[pyfunction]
pub fn split_line_at_antimeridian<'py>(
    py: Python<'py>,
    line: PyReadonlyArray2<'py, f64>,
) -> PyResult<Vec<Bound<'py, PyArray2<f64>>>> {
    let line = points(&line)?;
    antimeridian::split_line(&line).iter().map(|piece| array(py, piece)).collect()
}
