//! `Scene`: a scene file's text with its overrides, validated by the scene crate on every
//! change (the command's `--set` rules and messages).

use crate::SceneError;
use gdsmc_runner::scene as sc;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyFloat, PyInt, PyList, PyString, PyTuple};
use std::path::{Path, PathBuf};

/// A validated scene: the text of a scene file (docs/scenes.md) and the overrides applied to it.
#[pyclass(frozen, module = "gdsmc._gdsmc")]
#[derive(Clone)]
pub struct Scene {
    pub(crate) source: sc::Sourced,
}

/// A scene error as the Python exception.
fn scene_error(e: sc::Error) -> PyErr {
    SceneError::new_err(e.to_string())
}

impl Scene {
    /// The validated scene.
    pub(crate) fn scene(&self) -> &sc::Scene {
        &self.source.scene
    }

    /// This scene with one more override (validated). An earlier override of the same key
    /// was validated when it was made and is replaced (a scene's `set` of a key set before
    /// changes it), so no key is ever given twice.
    pub(crate) fn with(&self, o: sc::Override) -> PyResult<Self> {
        Ok(Scene {
            source: self.source.with(o).map_err(scene_error)?,
        })
    }
}

/// A Python value as TOML text: numbers, booleans, strings and (nested) lists.
fn toml_value(v: &Bound<'_, PyAny>) -> PyResult<toml::Value> {
    if v.is_instance_of::<PyBool>() {
        return Ok(toml::Value::Boolean(v.extract()?));
    }
    if v.is_instance_of::<PyInt>() {
        return Ok(toml::Value::Integer(v.extract()?));
    }
    if v.is_instance_of::<PyFloat>() {
        return Ok(toml::Value::Float(v.extract()?));
    }
    if v.is_instance_of::<PyString>() {
        return Ok(toml::Value::String(v.extract()?));
    }
    if v.is_instance_of::<PyList>() || v.is_instance_of::<PyTuple>() {
        let items: Vec<Bound<'_, PyAny>> = v.try_iter()?.collect::<PyResult<_>>()?;
        return Ok(toml::Value::Array(
            items.iter().map(toml_value).collect::<PyResult<_>>()?,
        ));
    }
    // numpy scalars and anything else with a float value.
    if let Ok(x) = v.extract::<f64>() {
        return Ok(toml::Value::Float(x));
    }
    Err(pyo3::exceptions::PyTypeError::new_err(format!(
        "a scene value must be a number, bool, string or list, got {}",
        v.get_type().name()?
    )))
}

#[pymethods]
impl Scene {
    /// Reads and validates a scene file (TOML).
    #[staticmethod]
    fn from_file(path: PathBuf) -> PyResult<Self> {
        Ok(Scene {
            source: sc::Sourced::read(&path, Vec::new()).map_err(scene_error)?,
        })
    }

    /// Validates scene text; `name` stands for the file in error messages.
    #[staticmethod]
    #[pyo3(signature = (text, name = "<string>"))]
    fn from_toml(text: String, name: &str) -> PyResult<Self> {
        Ok(Scene {
            source: sc::Sourced::parse(Path::new(name), text, Vec::new()).map_err(scene_error)?,
        })
    }

    /// A copy with `key` (a dotted path, e.g. "collisions.restitution") set to `value`, or
    /// removed when `value` is None, validated as the command's `--set` is.
    #[pyo3(signature = (key, value))]
    fn set(&self, key: &str, value: &Bound<'_, PyAny>) -> PyResult<Self> {
        let text = if value.is_none() {
            String::new()
        } else {
            toml_value(value)?.to_string()
        };
        self.with(sc::Override {
            source: format!("set({key:?})"),
            assignment: format!("{key}={text}"),
        })
    }

    /// The scene's name.
    #[getter]
    fn name(&self) -> String {
        self.scene().name().to_string()
    }

    /// Its description.
    #[getter]
    fn description(&self) -> String {
        self.scene().description().to_string()
    }

    /// Particles per ensemble.
    #[getter]
    fn n(&self) -> usize {
        self.scene().n()
    }

    /// Ensembles.
    #[getter]
    fn ensembles(&self) -> u64 {
        self.scene().ensembles()
    }

    /// Seed.
    #[getter]
    fn seed(&self) -> u64 {
        self.scene().seed()
    }

    /// Observation times.
    #[getter]
    fn times(&self) -> Vec<f64> {
        self.scene().times().to_vec()
    }

    /// The scene file's text (without the overrides).
    #[getter]
    fn text(&self) -> String {
        self.source.text.clone()
    }

    /// The overrides applied, as `key.path=value` strings in order.
    #[getter]
    fn overrides(&self) -> Vec<String> {
        self.source
            .overrides
            .iter()
            .map(|o| o.assignment.clone())
            .collect()
    }

    fn __repr__(&self) -> String {
        format!(
            "Scene({:?}: n={}, ensembles={}, seed={}, {} observation times{})",
            self.scene().name(),
            self.scene().n(),
            self.scene().ensembles(),
            self.scene().seed(),
            self.scene().times().len(),
            if self.source.overrides.is_empty() {
                String::new()
            } else {
                format!(", overrides [{}]", self.overrides().join(", "))
            }
        )
    }
}
