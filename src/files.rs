//! Writing the user's files safely: every temporary file is created exclusively, under an
//! unpredictable name, without following a link planted under it (`tempfile`), and removed on
//! every exit: on an error or a panic when it is dropped, on Ctrl-C or SIGTERM by
//! [`remove_temporaries`], which the signal handler calls. Output reaches its name whole, by a
//! rename (or a link, where nothing may be overwritten).

use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

use tempfile::NamedTempFile;

use crate::error::{Error, Result};

/// The temporary files alive now, for the signal handler.
static LIVE: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// Held while temporaries reach their names: the signal handler waits for it, so a set of
/// files is renamed whole or not at all, never half of it.
static COMMIT: Mutex<()> = Mutex::new(());

/// The mode a file the user asked for is created with: read and write for all, less the
/// umask (as any new file), not the owner-only mode of a temporary file.
fn user_file_mode() -> std::fs::Permissions {
    use std::os::unix::fs::PermissionsExt as _;
    std::fs::Permissions::from_mode(0o666)
}

/// A temporary file in the folder of its target, registered while it lives (`file` is taken
/// when it reaches its name).
struct Temporary {
    path: PathBuf,
    file: Option<NamedTempFile>,
}

impl Temporary {
    /// A new temporary file beside `target`, holding `text` (flushed to the disk).
    fn with(target: &Path, text: &str) -> std::io::Result<Temporary> {
        let dir = target
            .parent()
            .filter(|d| !d.as_os_str().is_empty())
            .unwrap_or(Path::new("."));
        let name = target
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        // registered under the lock it is created in, so the signal handler sees every one
        let mut live = lock();
        let file = tempfile::Builder::new()
            .prefix(&format!(".{name}."))
            .suffix(".tmp")
            .permissions(user_file_mode())
            .tempfile_in(dir)?;
        let path = file.path().to_path_buf();
        live.push(path.clone());
        drop(live);
        let mut t = Temporary {
            path,
            file: Some(file),
        };
        if let Some(f) = t.file.as_mut() {
            f.write_all(text.as_bytes())?;
            f.as_file().sync_all()?;
        }
        Ok(t)
    }

    /// Rename onto `target` (replacing it), or link to it when `clobber` is false (refusing
    /// an existing name).
    fn persist(mut self, target: &Path, clobber: bool) -> std::io::Result<()> {
        let Some(file) = self.file.take() else {
            return Err(std::io::Error::other("the temporary file is gone"));
        };
        let done = if clobber {
            file.persist(target).map(drop)
        } else {
            file.persist_noclobber(target).map(drop)
        };
        done.map_err(|e| e.error)
    }
}

impl Drop for Temporary {
    fn drop(&mut self) {
        forget(&self.path);
    }
}

fn lock() -> std::sync::MutexGuard<'static, Vec<PathBuf>> {
    LIVE.lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
}

fn commit() -> std::sync::MutexGuard<'static, ()> {
    COMMIT
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner)
}

fn forget(path: &Path) {
    lock().retain(|p| p != path);
}

/// Remove every temporary file still alive (the signal handler's clean-up; the process ends
/// right after, so no drop runs).
pub fn remove_temporaries() {
    let _commit = commit();
    for p in lock().drain(..) {
        let _ = std::fs::remove_file(p);
    }
}

/// Make sure `dir` exists and can be written to, before anything is computed for it: a
/// temporary file is created in it and removed. A folder that cannot be used (a file of that
/// name, no permission) is the command's usage, not a failed check: an input error (exit 2).
pub fn prepare_output_dir(dir: &Path) -> Result<()> {
    let fail = |e: std::io::Error| Error::Input {
        location: crate::error::InputLocation::file(dir),
        message: format!("cannot be used as the output folder: {e}"),
    };
    std::fs::create_dir_all(dir).map_err(fail)?;
    let probe = tempfile::Builder::new()
        .prefix(".orthocheck-probe.")
        .tempfile_in(dir)
        .map_err(fail)?;
    probe.close().map_err(fail)
}

/// Write every `(name, text)` into `dir` as a set: every temporary file first, then the
/// renames; a name that is a symbolic link is refused before anything is written.
pub fn write_all_atomic(dir: &Path, files: &[(String, String)]) -> Result<()> {
    let fail = |path: &Path, message: String| Error::Write {
        path: path.to_path_buf(),
        message,
    };
    for (name, _) in files {
        let target = dir.join(name);
        if let Ok(m) = std::fs::symlink_metadata(&target)
            && m.file_type().is_symlink()
        {
            return Err(fail(&target, "is a symbolic link; not followed".into()));
        }
    }
    let mut written = Vec::new();
    for (name, text) in files {
        let target = dir.join(name);
        // on an error the temporaries written so far are dropped, so removed
        written.push((
            Temporary::with(&target, text).map_err(|e| fail(&target, e.to_string()))?,
            target,
        ));
    }
    let _commit = commit();
    for (t, target) in written {
        t.persist(&target, true)
            .map_err(|e| fail(&target, e.to_string()))?;
    }
    Ok(())
}

/// Write `text` to `path`, which must not exist: written whole under a temporary name, then
/// linked to its name (a link fails if the name exists, so nothing is overwritten).
/// `exists` is the error for an existing name.
pub fn write_new(path: &Path, text: &str, exists: impl Fn(&Path) -> Error) -> Result<()> {
    let failed = |e: std::io::Error| Error::Write {
        path: path.to_path_buf(),
        message: e.to_string(),
    };
    // refuse an existing file (or a link, even a dangling one) before writing anything
    if std::fs::symlink_metadata(path).is_ok() {
        return Err(exists(path));
    }
    let t = Temporary::with(path, text).map_err(failed)?;
    let _commit = commit();
    t.persist(path, false).map_err(|e| match e.kind() {
        // the name appeared while the file was being written
        std::io::ErrorKind::AlreadyExists => exists(path),
        _ => failed(e),
    })
}
