//! The signals that stop a run (issue 77): a scheduler's SIGTERM (Slurm's time limit,
//! `timeout`, systemd) and SIGHUP stop it as Ctrl-C does, keeping what is finished, with 128
//! plus the signal's number as the exit code. Before, SIGTERM and SIGHUP ended gdsmc at once and
//! nothing was written (the test failed at its first exit code: the signal's, not 143).

use super::command::{root, s};
use super::faults::{holds, long_run, signalled_after_an_ensemble};

/// For each of SIGINT, SIGTERM and SIGHUP: a long run stopped by it once an ensemble is
/// journaled writes a whole partial set (its manifest verifies, its summary says
/// interrupted), leaves its journal for the same command to continue, names the signal, and
/// exits with 128 + the signal's number.
#[test]
fn sigterm_and_sighup_keep_what_is_finished_as_ctrl_c_does() {
    for (signal, code, words) in [
        ("INT", 130, "interrupted"),
        ("TERM", 143, "terminated (SIGTERM)"),
        ("HUP", 129, "hung up (SIGHUP)"),
    ] {
        let r = root(&format!("signal-{signal}"));
        let out = r.join("res");
        let journal = r.join(".res.run.gdsmc-ensembles");
        let o = signalled_after_an_ensemble(long_run(&["--out", s(&out)]), &journal, signal);
        let err = String::from_utf8_lossy(&o.stderr);
        assert_eq!(o.status.code(), Some(code), "SIG{signal}: {err}");
        assert!(err.contains(words), "SIG{signal}: {err}");
        let run = gdsmc_runner::report::set::verify(&out)
            .unwrap_or_else(|e| panic!("SIG{signal}: no whole set: {e}"));
        assert!(
            run["ensembles"].as_u64().unwrap() >= 1,
            "SIG{signal}: {run}"
        );
        let summary: serde_json::Value =
            serde_json::from_slice(&std::fs::read(out.join("summary.json")).unwrap()).unwrap();
        assert_eq!(summary["interrupted"], true, "SIG{signal}");
        assert!(
            holds(&r, ".res.run.gdsmc-ensembles"),
            "SIG{signal}: journal gone"
        );
        assert!(!holds(&r, ".res.partial-"), "SIG{signal}: staging left");
    }
}
