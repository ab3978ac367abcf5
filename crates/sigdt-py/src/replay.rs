//! The step trace of inflating and sculpting as a Python class: the recorded `sigdt::Trace`
//! with numpy getters for its fields and its replay (`boundary_at`, `inside_at`), which runs
//! in Rust with the GIL released. `python/sigdt/_trace.py` wraps it.
use numpy::{IntoPyArray, PyArray1, PyArray2, PyArrayMethods};
use pyo3::prelude::*;

use crate::convert::{edges, indices};

/// A recorded run of inflating and sculpting (`sigdt::Trace`); see `sigdt.Trace`.
#[pyclass(frozen, module = "sigdt._core")]
pub struct Trace(pub sigdt::Trace);

#[pymethods]
impl Trace {
    /// `(T, 3)` int64: every Delaunay triangle as point indices, counter-clockwise.
    #[getter]
    fn triangles<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<i64>>> {
        let flat: Vec<i64> = self.0.triangles.iter().flatten().map(|&v| v as i64).collect();
        flat.into_pyarray(py).reshape([self.0.triangles.len(), 3])
    }

    /// `(m, 2)` int64: the initial graph, sorted.
    #[getter]
    fn graph<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<i64>>> {
        edges(py, &self.0.graph)
    }

    /// `(T,)` bool: the labels before the first step, True for interior.
    #[getter]
    fn initial_inside<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<bool>> {
        self.0.initial_inside.clone().into_pyarray(py)
    }

    /// `(d, 2)` int64: the initial boundary's edges with exterior on both sides, sorted.
    #[getter]
    fn dangling<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArray2<i64>>> {
        edges(py, &self.0.dangling)
    }

    /// `(S,)` int64: the triangle each step relabels.
    #[getter]
    fn step_triangle<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<i64>> {
        let triangles: Vec<usize> = self.0.steps.iter().map(|s| s.triangle).collect();
        indices(py, &triangles)
    }

    /// `(S,)` bool: each step's new label, True for interior.
    #[getter]
    fn step_inside<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<bool>> {
        self.0.steps.iter().map(|s| s.inside).collect::<Vec<bool>>().into_pyarray(py)
    }

    /// `(S,)` uint8: each step's `Phase::code()`, an index into `PHASES`.
    #[getter]
    fn step_phase<'py>(&self, py: Python<'py>) -> Bound<'py, PyArray1<u8>> {
        self.0.steps.iter().map(|s| s.phase.code()).collect::<Vec<u8>>().into_pyarray(py)
    }

    /// The number of steps when inflating ended and sculpting started.
    #[getter]
    fn inflated_at(&self) -> usize {
        self.0.inflated_at
    }

    /// `boundary_at(step) -> (m, 2) int64`: the boundary after the first `step` steps (all
    /// of them if `step` is larger), sorted (`sigdt::Trace::boundary_at`).
    fn boundary_at<'py>(
        &self,
        py: Python<'py>,
        step: usize,
    ) -> PyResult<Bound<'py, PyArray2<i64>>> {
        let boundary = py.detach(|| self.0.boundary_at(step));
        edges(py, &boundary)
    }

    /// `inside_at(step) -> (T,) bool`: the labels after the first `step` steps (all of them
    /// if `step` is larger), True for interior (`sigdt::Trace::inside_at`).
    fn inside_at<'py>(&self, py: Python<'py>, step: usize) -> Bound<'py, PyArray1<bool>> {
        py.detach(|| self.0.inside_at(step)).into_pyarray(py)
    }
}
