//! # rcagd-python
//!
//! The `_rcagd` extension module behind the Python package `rcagd`
//! (`crates/python/python/rcagd/__init__.py`). Every function here reads its arguments,
//! calls one library function and wraps the result; there is no geometry in this crate:
//!
//! * [`build`]: a recipe text through the CLI's recipe machinery
//!   ([`rcagd_cli::recipe::Recipe::parse`], [`rcagd_cli::build::build_recipe`]), the
//!   same parser, parameter checks, ops and messages as `rcagd build`;
//! * [`Object`]: one built object ([`rcagd_io::model::Object`]) with its exact JSON
//!   ([`rcagd_io::json::object_to_json`]), exports ([`rcagd_cli::output::render`]), the
//!   exact NURBS of its exchange form ([`rcagd_io::step::exact_sidecar`]), grid
//!   evaluation ([`rcagd_geom::grid::eval_patch_grid_flat`],
//!   [`rcagd_geom::BezierCurve::eval_into`]) and its mesh
//!   ([`rcagd_io::stl::object_mesh`]);
//! * [`read_step`] / [`read_iges`]: [`rcagd_io::step_read::read_step`],
//!   [`rcagd_io::iges_read::read_iges`].
//!
//! Float arrays cross the boundary as native-endian `f64` bytes in a `bytearray`
//! (`numpy.frombuffer` on the Python side: writable, no copy, no Python loop); exact numbers as `"p/q"` strings
//! (`fractions.Fraction` on the Python side). Every error is a Python `ValueError`
//! carrying the library's message.

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyByteArray, PyBytes};
use rcagd_cli::output::OutFormat;
use rcagd_geom::{BezierCurve, BezierPatch};
use rcagd_io::model::Object as IoObject;

/// The size of the blocks of grid rows evaluated at once by `Object::eval_grid`.
const GRID_BLOCK_BYTES: usize = 1 << 20;

/// A `ValueError` with `msg`.
fn value_error(msg: impl std::fmt::Display) -> PyErr {
    PyValueError::new_err(msg.to_string())
}

/// The output format called `name` (the CLI's `--format` names, plus `glb`).
fn out_format(name: &str) -> PyResult<OutFormat> {
    Ok(match name.to_ascii_lowercase().as_str() {
        "json" => OutFormat::Json,
        "step" | "stp" => OutFormat::Step,
        "iges" | "igs" => OutFormat::Iges,
        "obj" => OutFormat::Obj,
        "stl" => OutFormat::Stl,
        "ply" => OutFormat::Ply,
        "gltf" | "glb" => OutFormat::Gltf,
        "svg" => OutFormat::Svg,
        "png" => OutFormat::Png,
        "exact" | "exact.json" => OutFormat::Exact,
        _ => {
            return Err(value_error(format!(
                "unknown format {name:?}: use one of json, step, iges, obj, stl, ply, glb, svg, png, exact"
            )))
        }
    })
}

/// Native-endian `f64`s from bytes (a numpy `float64` array's `tobytes()`).
fn f64s(bytes: &[u8], what: &str) -> PyResult<Vec<f64>> {
    if !bytes.chunks_exact(8).remainder().is_empty() {
        return Err(value_error(format!(
            "{what}: {} bytes is not a whole number of float64 values",
            bytes.len()
        )));
    }
    Ok(bytes
        .chunks_exact(8)
        .map(|c| {
            let mut b = [0u8; 8];
            b.copy_from_slice(c);
            f64::from_ne_bytes(b)
        })
        .collect())
}

/// `f64`s as native-endian bytes in a `bytearray`, written in place (one copy; numpy
/// views it writable with `frombuffer`).
fn f64_bytes<'py>(py: Python<'py>, xs: &[f64]) -> PyResult<Bound<'py, PyByteArray>> {
    PyByteArray::new_with(py, xs.len() * 8, |buf| {
        for (b, x) in buf.chunks_exact_mut(8).zip(xs) {
            b.copy_from_slice(&x.to_ne_bytes());
        }
        Ok(())
    })
}

/// One built, certified object: its name, op, exact geometry and certificates
/// ([`rcagd_io::model::Object`]), with the `f64` images of its pieces for evaluation.
#[pyclass(module = "rcagd._rcagd", frozen)]
pub struct Object {
    inner: IoObject,
    curves_f64: Vec<BezierCurve<f64>>,
    patches_f64: Vec<BezierPatch<f64>>,
}

impl Object {
    fn new(inner: IoObject) -> PyResult<Self> {
        let curves_f64 = inner.geometry.curves_f64().map_err(value_error)?;
        let patches_f64 = inner.geometry.patches_f64().map_err(value_error)?;
        Ok(Object {
            inner,
            curves_f64,
            patches_f64,
        })
    }
}

#[pymethods]
impl Object {
    /// The object's name.
    #[getter]
    fn name(&self) -> &str {
        &self.inner.name
    }

    /// The op that built it.
    #[getter]
    fn op(&self) -> &str {
        &self.inner.op
    }

    /// `"curve"`, `"curves"`, `"patch"` or `"patches"`.
    #[getter]
    fn kind(&self) -> &'static str {
        self.inner.geometry.kind()
    }

    /// The Euclidean dimension.
    #[getter]
    fn dim(&self) -> usize {
        self.inner.geometry.dim()
    }

    /// The number of curves or patches.
    #[getter]
    fn piece_count(&self) -> usize {
        self.inner.geometry.piece_count()
    }

    /// The object's JSON (`rcagd build` output for one object): exact and `f64`
    /// homogeneous control points, certificates, params, values.
    fn to_json(&self) -> PyResult<String> {
        serde_json::to_string(&rcagd_io::json::object_to_json(&self.inner)).map_err(value_error)
    }

    /// The certificates as `(property, holds, residual, exact)`.
    fn certificates(&self) -> Vec<(String, bool, Option<String>, bool)> {
        self.inner
            .certificates
            .iter()
            .map(|c| (c.property.clone(), c.holds, c.residual.clone(), c.exact))
            .collect()
    }

    /// The file contents in `format` (as `rcagd build --format`).
    fn export<'py>(&self, py: Python<'py>, format: &str) -> PyResult<Bound<'py, PyBytes>> {
        let f = out_format(format)?;
        let bytes = rcagd_cli::output::render(&self.inner, f).map_err(value_error)?;
        Ok(PyBytes::new(py, &bytes))
    }

    /// The exact NURBS of the exchange form (the `.exact.json` sidecar of STEP/IGES):
    /// E3, positive weights, homogeneous control points weight first.
    fn exact_nurbs(&self) -> PyResult<String> {
        let v = rcagd_io::step::exact_sidecar(std::slice::from_ref(&self.inner))
            .map_err(value_error)?;
        serde_json::to_string(&v).map_err(value_error)
    }

    /// The points of patch `piece` on the grid `us × vs` (float64 bytes each), as
    /// float64 bytes of shape `(len(us), len(vs), dim)`.
    fn eval_grid<'py>(
        &self,
        py: Python<'py>,
        piece: usize,
        us: &[u8],
        vs: &[u8],
    ) -> PyResult<Bound<'py, PyByteArray>> {
        let p = self.patches_f64.get(piece).ok_or_else(|| {
            value_error(format!(
                "object {:?} has {} patches; there is no patch {piece}",
                self.inner.name,
                self.patches_f64.len()
            ))
        })?;
        let (us, vs) = (f64s(us, "us")?, f64s(vs, "vs")?);
        let d = p.dim();
        let len = us
            .len()
            .checked_mul(vs.len())
            .and_then(|n| n.checked_mul(d * 8))
            .ok_or_else(|| value_error("the grid is too large"))?;
        // evaluated in blocks of rows straight into the result (a block stays in cache;
        // no second full-size buffer)
        let row = (vs.len() * d * 8).max(1);
        let rows = (GRID_BLOCK_BYTES / row).max(1);
        let mut block = Vec::new();
        PyByteArray::new_with(py, len, |buf| {
            for (dst, u) in buf.chunks_mut(rows * row).zip(us.chunks(rows)) {
                rcagd_geom::grid::eval_patch_grid_flat(p, u, &vs, &mut block)
                    .map_err(value_error)?;
                for (b, x) in dst.chunks_exact_mut(8).zip(&block) {
                    b.copy_from_slice(&x.to_ne_bytes());
                }
            }
            Ok(())
        })
    }

    /// The points of curve `piece` at the parameters `ts` (float64 bytes), as float64
    /// bytes of shape `(len(ts), dim)`.
    fn eval_curve<'py>(
        &self,
        py: Python<'py>,
        piece: usize,
        ts: &[u8],
    ) -> PyResult<Bound<'py, PyByteArray>> {
        let c = self.curves_f64.get(piece).ok_or_else(|| {
            value_error(format!(
                "object {:?} has {} curves; there is no curve {piece}",
                self.inner.name,
                self.curves_f64.len()
            ))
        })?;
        let ts = f64s(ts, "ts")?;
        let d = c.dim();
        let mut out = vec![0.0; ts.len() * d];
        py.detach(|| {
            out.chunks_exact_mut(d.max(1))
                .zip(&ts)
                .try_for_each(|(o, &t)| c.eval_into(t, o))
        })
        .map_err(value_error)?;
        f64_bytes(py, &out)
    }

    /// The triangle mesh of the patches (`rcagd_io::stl::object_mesh`, default options):
    /// `(positions, normals, triangles)` as float64, float64 and uint32 bytes.
    fn mesh<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(
        Bound<'py, PyByteArray>,
        Bound<'py, PyByteArray>,
        Bound<'py, PyByteArray>,
    )> {
        let m = rcagd_io::stl::object_mesh(&self.inner, &rcagd_io::stl::MeshOptions::default())
            .map_err(value_error)?;
        let flat = |v: &[[f64; 3]]| v.iter().flatten().copied().collect::<Vec<f64>>();
        let tri: Vec<u32> = m.triangles.iter().flatten().copied().collect();
        let tri = PyByteArray::new_with(py, tri.len() * 4, |buf| {
            for (b, t) in buf.chunks_exact_mut(4).zip(&tri) {
                b.copy_from_slice(&t.to_ne_bytes());
            }
            Ok(())
        })?;
        Ok((
            f64_bytes(py, &flat(&m.positions))?,
            f64_bytes(py, &flat(&m.normals))?,
            tri,
        ))
    }

    fn __repr__(&self) -> String {
        format!(
            "<rcagd object {:?}: op {}, {}, {}>",
            self.inner.name,
            self.inner.op,
            self.inner.geometry.degree_summary(),
            rcagd_cli::output::certificate_summary(&self.inner)
        )
    }
}

/// Builds a recipe (TOML or JSON text; `file_name` chooses the format by its extension,
/// else it is sniffed) with the CLI's machinery: the same ops, checks and messages as
/// `rcagd build`. Relative file parameters are taken relative to `file_name`'s directory.
/// `float = true` builds as `rcagd build --float` ([`rcagd_cli::build::Arithmetic::Float`]:
/// the ops' `f64` instantiation, tolerance certificates, objects marked
/// `arithmetic = "f64"`; an op without a float path is an error).
#[pyfunction]
#[pyo3(signature = (text, file_name, float = false))]
fn build(py: Python<'_>, text: &str, file_name: &str, float: bool) -> PyResult<Vec<Object>> {
    let recipe = rcagd_cli::recipe::Recipe::parse(file_name, text, None)
        .map_err(|d| value_error(rcagd_cli::source::render_all(&d).trim_end()))?;
    let arithmetic = if float {
        rcagd_cli::build::Arithmetic::Float
    } else {
        rcagd_cli::build::Arithmetic::Exact
    };
    let objects = py
        .detach(|| rcagd_cli::build::build_recipe_with(&recipe, arithmetic, |_| {}))
        .map_err(|d| value_error(rcagd_cli::source::render_all(&d).trim_end()))?;
    objects.into_iter().map(Object::new).collect()
}

/// The files of several objects in one format: STEP, IGES and glb hold them all in one
/// file ([`rcagd_io::step::write_step`], [`rcagd_io::iges::write_iges`],
/// [`rcagd_io::gltf::objects_to_glb`]); the exact sidecar likewise.
#[pyfunction]
fn export_many<'py>(
    py: Python<'py>,
    objects: Vec<PyRef<'py, Object>>,
    format: &str,
) -> PyResult<Bound<'py, PyBytes>> {
    let objs: Vec<IoObject> = objects.iter().map(|o| o.inner.clone()).collect();
    let bytes = match out_format(format)? {
        OutFormat::Step => rcagd_io::step::write_step(&objs).map(String::into_bytes),
        OutFormat::Iges => rcagd_io::iges::write_iges(&objs).map(String::into_bytes),
        OutFormat::Gltf => {
            rcagd_io::gltf::objects_to_glb(&objs, &rcagd_io::stl::MeshOptions::default())
        }
        OutFormat::Json => rcagd_io::json::objects_to_json_string(&objs).map(String::into_bytes),
        OutFormat::Exact => rcagd_io::step::exact_sidecar(&objs).and_then(|v| {
            serde_json::to_string(&v)
                .map(String::into_bytes)
                .map_err(Into::into)
        }),
        _ => {
            return Err(value_error(format!(
                "format {format:?} holds one object per file: use Object.export"
            )))
        }
    }
    .map_err(value_error)?;
    Ok(PyBytes::new(py, &bytes))
}

/// The objects of a STEP file as exact JSON (`[{name, curves, surfaces}]`, the sidecar
/// format of [`rcagd_io::step_read::imported_to_json`]).
#[pyfunction]
fn read_step(text: &str) -> PyResult<String> {
    let objs = rcagd_io::step_read::read_step(text).map_err(value_error)?;
    imported_json(&objs)
}

/// The objects of an IGES file as exact JSON (as [`read_step`]).
#[pyfunction]
fn read_iges(text: &str) -> PyResult<String> {
    let objs = rcagd_io::iges_read::read_iges(text).map_err(value_error)?;
    imported_json(&objs)
}

fn imported_json(objs: &[rcagd_io::step_read::ImportedObject]) -> PyResult<String> {
    let v: Vec<serde_json::Value> = objs
        .iter()
        .map(rcagd_io::step_read::imported_to_json)
        .collect();
    serde_json::to_string(&v).map_err(value_error)
}

/// An op's parameter: `(name, type, requirement, doc)`.
type ParamRow = (String, String, String, String);

/// Every op: `(name, summary, [(parameter, type, requirement, doc)])`.
#[pyfunction]
fn ops() -> Vec<(String, String, Vec<ParamRow>)> {
    rcagd_cli::ops::all()
        .map(|op| {
            let params = op
                .params
                .iter()
                .map(|p| {
                    (
                        p.name.to_string(),
                        p.kind.type_name(),
                        p.requirement(),
                        p.doc.to_string(),
                    )
                })
                .collect();
            (op.name.to_string(), op.summary.to_string(), params)
        })
        .collect()
}

/// The extension module.
#[pymodule]
fn _rcagd(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Object>()?;
    m.add_function(wrap_pyfunction!(build, m)?)?;
    m.add_function(wrap_pyfunction!(export_many, m)?)?;
    m.add_function(wrap_pyfunction!(read_step, m)?)?;
    m.add_function(wrap_pyfunction!(read_iges, m)?)?;
    m.add_function(wrap_pyfunction!(ops, m)?)?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    Ok(())
}
