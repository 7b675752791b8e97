//! What proves a staging directory gdsmc's, so that the next run at a place may remove the one
//! a killed run left. A claim file is only a file: anyone who can write beside the output
//! directory can plant one naming `.`, a sibling, or a directory of the user's that happens to
//! be called `.res.partial-77`. So a recorded name is never enough. The directory is removed
//! only when every one of these holds, and otherwise it is left and named in a warning:
//!
//! 1. its name is this place's exact staging name, `.NAME.partial-PID` or
//!    `.NAME.partial-PID-K` (digits only), beside the output directory;
//! 2. it is a directory itself, not a symbolic link;
//! 3. it belongs to the user running gdsmc (Linux; elsewhere no directory is removed: the
//!    owner cannot be told, so the warning names it instead);
//! 4. it holds the marker file [`MARKER`], a regular file whose token equals the random token
//!    (128 bits from the operating system) the claim recorded when the directory was made.
//!
//! A process writes the token into its claim (flushed) before it creates the directory, and
//! the marker into the directory at once after: a killed run leaves a claim and a directory
//! whose tokens agree. The marker is no file of the set: the manifest does not list it. When
//! the set is swapped in, the previous set gets a marker of the same token before the two
//! directories are exchanged (so the staging name, now holding the previous set, still proves
//! itself if a kill comes before it is removed), and the new set's marker is removed after.
//! A marker left in an output set by a kill at that moment is recognized ([`is_marker`]) and
//! not taken for a user's file.

use std::path::Path;

/// The file in a staging directory that holds the token its claim recorded.
pub const MARKER: &str = ".gdsmc-staging";

/// The marker's first line, before the token.
const SIGNATURE: &str = "gdsmc staging";

/// Hexadecimal digits of a token (128 bits).
const TOKEN_DIGITS: usize = 32;

/// A fresh random token from the operating system's generator, as 32 hexadecimal digits, or
/// the reason there is none (then no staging directory can be proven, and none is removed).
pub fn token() -> Result<String, String> {
    let mut bytes = [0u8; TOKEN_DIGITS / 2];
    getrandom::fill(&mut bytes).map_err(|e| format!("no random token: {e}"))?;
    Ok(bytes.iter().map(|b| format!("{b:02x}")).collect())
}

/// Whether `text` is a token as [`token`] writes it.
pub fn is_token(text: &str) -> bool {
    text.len() == TOKEN_DIGITS && text.bytes().all(|b| b.is_ascii_hexdigit())
}

/// The marker file's contents for `token`.
pub fn marker_text(token: &str) -> String {
    format!("{SIGNATURE}\ntoken {token}\n")
}

/// Whether the directory entry `name` in `dir` is a marker file of gdsmc's: named [`MARKER`],
/// a regular file (not a link) holding a marker's text for some token. An output set may hold
/// one for a moment while it is swapped in (the previous set carries it to the staging name,
/// so that a kill there leaves a directory the next run can prove); it is no file of the set.
pub fn is_marker(dir: &Path, name: &str) -> bool {
    name == MARKER && marker_token(dir).is_ok()
}

/// The token of the marker file in `dir`: a regular file (not a link), a few bytes, holding a
/// marker's text ([`marker_text`]); `Err` says what is there instead, in words for the warning.
fn marker_token(dir: &Path) -> Result<String, String> {
    let path = dir.join(MARKER);
    if std::fs::symlink_metadata(&path).is_ok_and(|m| !m.is_file()) {
        return Err(format!("its {MARKER} is not a regular file"));
    }
    let f = super::open_regular(&path).map_err(|_| format!("it holds no {MARKER}"))?;
    let mut text = String::new();
    std::io::Read::read_to_string(&mut std::io::Read::take(f, 256), &mut text)
        .map_err(|e| format!("its {MARKER} cannot be read: {e}"))?;
    text.strip_prefix(SIGNATURE)
        .and_then(|t| t.strip_prefix("\ntoken "))
        .and_then(|t| t.strip_suffix('\n'))
        .filter(|t| is_token(t))
        .map(str::to_string)
        .ok_or_else(|| format!("its {MARKER} does not hold the claim's token"))
}

/// Writes the marker of `token` into `dir` (a new file: an existing one is refused).
pub fn mark(dir: &Path, token: &str) -> std::io::Result<()> {
    let mut f = std::fs::OpenOptions::new()
        .write(true)
        .create_new(true)
        .open(dir.join(MARKER))?;
    std::io::Write::write_all(&mut f, marker_text(token).as_bytes())?;
    f.sync_data()
}

/// Removes the staging directory `dir` with its marker last: everything else first, so that
/// a kill in the middle leaves a directory that still proves itself gdsmc's and the next run
/// removes (`remove_dir_all` takes the entries in any order, the marker perhaps first).
pub fn remove_marked(dir: &Path) {
    if let Ok(entries) = std::fs::read_dir(dir) {
        for e in entries.flatten() {
            if e.file_name() == MARKER {
                continue;
            }
            let p = e.path();
            match e.file_type() {
                Ok(t) if t.is_dir() => {
                    let _ = std::fs::remove_dir_all(&p);
                }
                _ => {
                    let _ = std::fs::remove_file(&p);
                }
            }
        }
    }
    let _ = std::fs::remove_dir_all(dir);
}

/// Whether `name` is a staging name of the place whose staging names begin with `prefix`
/// (`.NAME.partial-`): the prefix, then a process id, then at most one `-K`, digits only.
pub fn is_staging_name(name: &str, prefix: &str) -> bool {
    let Some(rest) = name.strip_prefix(prefix) else {
        return false;
    };
    let digits = |s: &str| !s.is_empty() && s.len() <= 20 && s.bytes().all(|b| b.is_ascii_digit());
    match rest.split_once('-') {
        None => digits(rest),
        Some((pid, k)) => digits(pid) && digits(k),
    }
}

/// Checks that `dir`, a staging directory a claim recorded with `token`, is one gdsmc made
/// (the module's four conditions, `prefix` the place's staging prefix); `Err` says which one
/// fails, in words for the warning.
pub fn proven(dir: &Path, prefix: &str, token: Option<&str>) -> Result<(), String> {
    proven_for(dir, prefix, token, this_user())
}

/// [`proven`] for the user `user` (`None`: the owner cannot be told here).
fn proven_for(
    dir: &Path,
    prefix: &str,
    token: Option<&str>,
    user: Option<u32>,
) -> Result<(), String> {
    let name = dir
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    if !is_staging_name(&name, prefix) {
        return Err(format!(
            "its name is not this place's staging name ({prefix}PID)"
        ));
    }
    let meta = std::fs::symlink_metadata(dir).map_err(|e| format!("it cannot be read: {e}"))?;
    if meta.file_type().is_symlink() {
        return Err("it is a symbolic link".into());
    }
    if !meta.is_dir() {
        return Err("it is not a directory".into());
    }
    owned(&meta, user)?;
    let token = token
        .filter(|t| is_token(t))
        .ok_or("the claim records no token for it")?;
    if marker_token(dir)? != token {
        return Err(format!("its {MARKER} does not hold the claim's token"));
    }
    Ok(())
}

/// The user running gdsmc (its effective user id), where it can be told.
fn this_user() -> Option<u32> {
    #[cfg(target_os = "linux")]
    return Some(rustix::process::geteuid().as_raw());
    #[cfg(not(target_os = "linux"))]
    None
}

/// Whether the directory whose metadata is `meta` belongs to `user`.
fn owned(meta: &std::fs::Metadata, user: Option<u32>) -> Result<(), String> {
    #[cfg(unix)]
    if let Some(me) = user {
        use std::os::unix::fs::MetadataExt;
        if meta.uid() != me {
            return Err(format!(
                "it belongs to user {}, not to this user ({me})",
                meta.uid()
            ));
        }
        return Ok(());
    }
    let _ = (meta, user);
    Err("its owner cannot be told on this system".into())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn staging_names_are_the_prefix_and_digits_only() {
        let p = ".res.partial-";
        for good in [".res.partial-77", ".res.partial-123-4"] {
            assert!(is_staging_name(good, p), "{good}");
        }
        for bad in [
            ".",
            "..",
            "thesis",
            ".res.partial-",
            ".res.partial-7x",
            ".res.partial-1-2-3",
            ".res.partial--1",
            ".res.partial-1-",
            ".other.partial-7",
            ".res.partial-7/..",
        ] {
            assert!(!is_staging_name(bad, p), "{bad}");
        }
    }

    #[test]
    fn tokens_are_fresh_and_recognized() {
        let (a, b) = (token().unwrap(), token().unwrap());
        assert!(is_token(&a) && is_token(&b));
        assert_ne!(a, b);
        assert!(!is_token("") && !is_token(&a[1..]) && !is_token(&a.replace(&a[..1], "g")));
    }

    /// Each condition refuses on its own: a directory gdsmc made (its marker with the claim's
    /// token) is proven, and changing any one thing about it refuses it.
    #[cfg(target_os = "linux")]
    #[test]
    fn every_condition_refuses_by_itself() {
        let root = std::env::temp_dir().join(format!("gdsmc-staging-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&root);
        std::fs::create_dir_all(&root).unwrap();
        let p = ".res.partial-";
        let t = token().unwrap();
        let dir = root.join(".res.partial-9");
        std::fs::create_dir(&dir).unwrap();
        std::fs::write(dir.join(MARKER), marker_text(&t)).unwrap();
        assert_eq!(proven(&dir, p, Some(&t)), Ok(()));
        // Another user's directory, or a system where the owner cannot be told.
        let me = this_user().unwrap();
        let e = proven_for(&dir, p, Some(&t), Some(me + 1)).unwrap_err();
        assert!(e.contains("belongs to user"), "{e}");
        let e = proven_for(&dir, p, Some(&t), None).unwrap_err();
        assert!(e.contains("owner cannot be told"), "{e}");
        // Another token, no token, a token of the wrong form.
        let other = token().unwrap();
        assert!(proven(&dir, p, Some(&other)).unwrap_err().contains("token"));
        assert!(proven(&dir, p, None).unwrap_err().contains("no token"));
        assert!(proven(&dir, p, Some("x")).unwrap_err().contains("no token"));
        // Another name, the place itself, a link to the directory.
        assert!(proven(&root, p, Some(&t)).unwrap_err().contains("name"));
        let link = root.join(".res.partial-10");
        std::os::unix::fs::symlink(&dir, &link).unwrap();
        assert!(proven(&link, p, Some(&t)).unwrap_err().contains("link"));
        // A file by the name, a marker that is a link to a file holding the token.
        let file = root.join(".res.partial-11");
        std::fs::write(&file, "x").unwrap();
        assert!(
            proven(&file, p, Some(&t))
                .unwrap_err()
                .contains("not a directory")
        );
        let linked = root.join(".res.partial-12");
        std::fs::create_dir(&linked).unwrap();
        std::os::unix::fs::symlink(dir.join(MARKER), linked.join(MARKER)).unwrap();
        assert!(
            proven(&linked, p, Some(&t))
                .unwrap_err()
                .contains("regular")
        );
        // No marker.
        std::fs::remove_file(dir.join(MARKER)).unwrap();
        assert!(proven(&dir, p, Some(&t)).unwrap_err().contains("holds no"));
        let _ = std::fs::remove_dir_all(&root);
    }
}
