//! `gdsmc._gdsmc`: the Python extension. Scenes go through the scene crate's validation (the
//! same messages as the command, naming file, line and key), runs through the runner's
//! ensemble loop (the same numbers as `gdsmc run` for the same scene and seed), and results
//! come back as the same tables the command writes (parsed into numpy arrays by the Python
//! layer, `gdsmc/__init__.py`).

mod result;
mod scene;
mod state;
mod sweep;
mod theory;

use pyo3::prelude::*;

pyo3::create_exception!(
    _gdsmc,
    SceneError,
    pyo3::exceptions::PyValueError,
    "A scene that cannot be read, parsed or validated; the message names the file, line and key."
);
pyo3::create_exception!(
    _gdsmc,
    RunError,
    pyo3::exceptions::PyRuntimeError,
    "A run that stopped (an engine error, a refused size, an unwritable output place)."
);

/// The command's flags a runner message may name, and the keyword arguments that are their
/// Python words.
const KEYWORDS: [(&str, &str); 7] = [
    ("--save-state", "save_state="),
    ("--initial-state", "initial_state="),
    ("--allow-long", "allow_long=True"),
    ("--threads", "threads="),
    ("--ensembles", "ensembles="),
    ("--seed", "seed="),
    ("--vary", "vary="),
];

/// A runner message in Python's words: each command flag it names as the keyword argument.
pub(crate) fn python_words(message: &str) -> String {
    KEYWORDS
        .iter()
        .fold(message.to_string(), |m, (flag, word)| m.replace(flag, word))
}

/// Maps a runner error to the Python exception that says what went wrong, in Python's words.
pub(crate) fn to_py(e: gdsmc_runner::Error) -> PyErr {
    match e {
        gdsmc_runner::Error::Scene(s) => SceneError::new_err(python_words(&s.to_string())),
        gdsmc_runner::Error::Argument { .. } => {
            pyo3::exceptions::PyValueError::new_err(python_words(&e.to_string()))
        }
        other => RunError::new_err(python_words(&other.to_string())),
    }
}

/// Says each of the runner's warnings `notes` (a note of a state file, a directory a claim
/// named and gdsmc left) as a Python `UserWarning`.
pub(crate) fn warn_all(py: Python<'_>, notes: &[String]) -> PyResult<()> {
    let category = py.get_type::<pyo3::exceptions::PyUserWarning>();
    for n in notes {
        let text = std::ffi::CString::new(python_words(n)).unwrap_or_default();
        PyErr::warn(py, &category, &text, 1)?;
    }
    Ok(())
}

/// The extension module.
#[pymodule]
fn _gdsmc(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("SceneError", m.py().get_type::<SceneError>())?;
    m.add("RunError", m.py().get_type::<RunError>())?;
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add("STREAM_VERSION", gdsmc_runner::STREAM_VERSION)?;
    m.add_class::<scene::Scene>()?;
    m.add_class::<result::RunResult>()?;
    m.add_function(wrap_pyfunction!(result::run, m)?)?;
    m.add_function(wrap_pyfunction!(state::read_state, m)?)?;
    m.add_function(wrap_pyfunction!(result::reproduce, m)?)?;
    m.add_function(wrap_pyfunction!(sweep::sweep, m)?)?;
    m.add_function(wrap_pyfunction!(theory::references, m)?)?;
    Ok(())
}
