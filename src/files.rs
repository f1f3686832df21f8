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

/// Write every `(name, text)` into `dir` as a set, replacing what is there: the old set or
/// the new one, never a mix. Every target is checked first without following links (a link
/// or a folder at a name is refused before anything is written); the temporaries are written;
/// then, under an advisory lock on the folder held across processes, each is renamed onto its
/// name, and should one rename fail the files already replaced are put back.
pub fn write_all_atomic(dir: &Path, files: &[(String, String)]) -> Result<()> {
    write_set(dir, files, true, None)
}

/// Write every `(name, text)` into `dir` as a set of new files: refused, with nothing
/// written, when any name exists (a dangling link included); on a failure half-way the files
/// already written are removed.
pub fn write_new_set(dir: &Path, files: &[(String, String)]) -> Result<()> {
    write_set(dir, files, false, None)
}

/// A target renamed in place, and the old file's backup (none when there was no old file).
type Replaced = (PathBuf, Option<PathBuf>);

/// [`write_all_atomic`] (`clobber`) or [`write_new_set`]; `fail_at` makes the rename of that
/// file fail, as a full disk would (the tests' fault).
fn write_set(
    dir: &Path,
    files: &[(String, String)],
    clobber: bool,
    fail_at: Option<usize>,
) -> Result<()> {
    let fail = |path: &Path, message: String| Error::Write {
        path: path.to_path_buf(),
        message,
    };
    for (name, _) in files {
        let target = dir.join(name);
        if let Some(why) = refused(&target, clobber) {
            return Err(fail(&target, why.into()));
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
    let _folder =
        folder_lock(dir).map_err(|e| fail(dir, format!("cannot lock the folder: {e}")))?;
    let mut done: Vec<Replaced> = Vec::new();
    for (i, (t, target)) in written.into_iter().enumerate() {
        let step = backup(&target, clobber).and_then(|old| {
            let renamed = match fail_at {
                Some(k) if k == i => Err(std::io::Error::other("the rename failed (injected)")),
                _ => t.persist(&target, clobber),
            };
            match renamed {
                Ok(()) => Ok(old),
                Err(e) => {
                    if let Some(b) = &old {
                        let _ = std::fs::remove_file(b);
                    }
                    Err(e)
                }
            }
        });
        match step {
            Ok(old) => done.push((target, old)),
            Err(e) => {
                undo(done);
                return Err(fail(
                    &target,
                    format!("{e}; the files already replaced were put back"),
                ));
            }
        }
    }
    for (_, old) in done {
        if let Some(b) = old {
            let _ = std::fs::remove_file(b);
        }
    }
    Ok(())
}

/// Why `target` may not be written, if it may not: a link (even dangling) or a folder at its
/// name, or any file there when nothing may be replaced.
fn refused(target: &Path, clobber: bool) -> Option<&'static str> {
    let m = std::fs::symlink_metadata(target).ok()?;
    if m.file_type().is_symlink() {
        Some("is a symbolic link; not followed, and nothing was written")
    } else if m.is_dir() {
        Some("is a folder; nothing was written")
    } else if !clobber {
        Some("the file exists and is not overwritten; nothing was written (choose an empty folder)")
    } else {
        None
    }
}

/// An exclusive advisory lock on `dir` (flock on the folder itself: no file is added to it),
/// held until the returned handle is dropped; another process writing a set there waits.
fn folder_lock(dir: &Path) -> std::io::Result<std::fs::File> {
    let f = std::fs::File::open(dir)?;
    match f.lock() {
        // a file system without advisory locks: the set is still whole within this process
        Err(e) if e.kind() == std::io::ErrorKind::Unsupported => Ok(f),
        r => r.map(|()| f),
    }
}

/// A hard link to the old file at `target` under a hidden name beside it, to put back should
/// the set fail; none when there is nothing to keep.
fn backup(target: &Path, clobber: bool) -> std::io::Result<Option<PathBuf>> {
    if !clobber || std::fs::symlink_metadata(target).is_err() {
        return Ok(None);
    }
    let name = target
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    for n in 0..1000u32 {
        let b = target.with_file_name(format!(".{name}.{}.{n}.old", std::process::id()));
        match std::fs::hard_link(target, &b) {
            Ok(()) => return Ok(Some(b)),
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => continue,
            // a file system without hard links: a copy under the same unused name
            Err(_) if std::fs::symlink_metadata(&b).is_err() => {
                std::fs::copy(target, &b)?;
                return Ok(Some(b));
            }
            Err(e) => return Err(e),
        }
    }
    Err(std::io::Error::other(
        "no free name for the old file's backup",
    ))
}

/// Put back what a failed set replaced: each old file onto its name, a new file removed.
fn undo(done: Vec<Replaced>) {
    for (target, old) in done.into_iter().rev() {
        let _ = match old {
            Some(b) => std::fs::rename(&b, &target),
            None => std::fs::remove_file(&target),
        };
    }
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

#[cfg(test)]
mod tests {
    use super::*;

    fn set(tag: &str) -> Vec<(String, String)> {
        ["a.json", "b.html", "c.svg"]
            .iter()
            .map(|n| (n.to_string(), format!("{tag} {n}")))
            .collect()
    }

    fn contents(dir: &Path) -> Vec<String> {
        let mut names: Vec<String> = std::fs::read_dir(dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        names.sort();
        names
            .iter()
            .map(|n| {
                format!(
                    "{n}: {}",
                    std::fs::read_to_string(dir.join(n)).unwrap_or_default()
                )
            })
            .collect()
    }

    #[test]
    fn a_failure_after_the_first_rename_puts_the_old_set_back() {
        let dir = tempfile::tempdir().unwrap();
        write_all_atomic(dir.path(), &set("old")).unwrap();
        let before = contents(dir.path());
        let e = write_set(dir.path(), &set("new"), true, Some(2)).unwrap_err();
        assert!(e.to_string().contains("put back"), "{e}");
        assert_eq!(contents(dir.path()), before);
        // a set into an empty folder that fails leaves it empty
        let empty = tempfile::tempdir().unwrap();
        assert!(write_set(empty.path(), &set("new"), true, Some(1)).is_err());
        assert!(contents(empty.path()).is_empty());
    }

    #[test]
    fn a_folder_or_a_dangling_link_at_a_name_refuses_before_anything_is_written() {
        let dir = tempfile::tempdir().unwrap();
        write_all_atomic(dir.path(), &set("old")).unwrap();
        std::fs::remove_file(dir.path().join("c.svg")).unwrap();
        std::fs::create_dir(dir.path().join("c.svg")).unwrap();
        let e = write_all_atomic(dir.path(), &set("new")).unwrap_err();
        assert!(e.to_string().contains("is a folder"), "{e}");
        assert!(std::fs::read_to_string(dir.path().join("a.json"))
            .unwrap()
            .starts_with("old"));
        let fresh = tempfile::tempdir().unwrap();
        std::os::unix::fs::symlink(fresh.path().join("nowhere"), fresh.path().join("b.html"))
            .unwrap();
        assert!(write_new_set(fresh.path(), &set("new")).is_err());
        assert_eq!(contents(fresh.path()), ["b.html: "]);
    }

    /// Run as a child process by the tests below: write a set of 40 files tagged
    /// `ORTHOCHECK_SET_WRITER` into `ORTHOCHECK_SET_DIR`, `ORTHOCHECK_SET_ROUNDS` times.
    #[test]
    #[ignore = "a child process of the tests of the folder lock"]
    fn set_writer() {
        let (Ok(tag), Ok(dir)) = (
            std::env::var("ORTHOCHECK_SET_WRITER"),
            std::env::var("ORTHOCHECK_SET_DIR"),
        ) else {
            return;
        };
        let rounds: usize = std::env::var("ORTHOCHECK_SET_ROUNDS")
            .ok()
            .and_then(|r| r.parse().ok())
            .unwrap_or(1);
        for _ in 0..rounds {
            write_all_atomic(Path::new(&dir), &many(&tag)).unwrap();
        }
    }

    fn many(tag: &str) -> Vec<(String, String)> {
        (0..40)
            .map(|i| (format!("f{i:02}.svg"), format!("{tag} {i}")))
            .collect()
    }

    fn writer(dir: &Path, tag: &str, rounds: usize) -> std::process::Child {
        std::process::Command::new(std::env::current_exe().unwrap())
            .args([
                "files::tests::set_writer",
                "--exact",
                "--ignored",
                "--quiet",
            ])
            .env("ORTHOCHECK_SET_WRITER", tag)
            .env("ORTHOCHECK_SET_DIR", dir)
            .env("ORTHOCHECK_SET_ROUNDS", rounds.to_string())
            .stdout(std::process::Stdio::null())
            .spawn()
            .unwrap()
    }

    /// The tags of the visible files of `dir` (temporaries and backups are hidden).
    fn tags(dir: &Path) -> std::collections::BTreeSet<String> {
        contents(dir)
            .iter()
            .filter(|l| !l.starts_with('.'))
            .filter_map(|l| Some(l.split(": ").nth(1)?.split(' ').next()?.to_string()))
            .collect()
    }

    /// While another process holds the folder's lock, a writer renames nothing: it waits,
    /// then writes its whole set.
    #[test]
    fn a_writer_waits_for_the_folder_lock_of_another_process() {
        let dir = tempfile::tempdir().unwrap();
        write_all_atomic(dir.path(), &many("old")).unwrap();
        let held = folder_lock(dir.path()).unwrap();
        let mut child = writer(dir.path(), "new", 1);
        // its temporaries written, the writer would rename next: it must wait instead
        let temporaries = || {
            contents(dir.path())
                .iter()
                .filter(|l| l.contains(".tmp"))
                .count()
        };
        let start = std::time::Instant::now();
        while temporaries() < 40 && start.elapsed() < std::time::Duration::from_secs(30) {
            std::thread::sleep(std::time::Duration::from_millis(5));
        }
        assert_eq!(temporaries(), 40);
        std::thread::sleep(std::time::Duration::from_millis(300));
        assert!(
            child.try_wait().unwrap().is_none(),
            "the writer did not wait"
        );
        assert_eq!(tags(dir.path()), ["old".to_string()].into());
        drop(held);
        assert!(child.wait().unwrap().success());
        assert_eq!(tags(dir.path()), ["new".to_string()].into());
    }

    #[test]
    fn two_processes_writing_one_folder_leave_one_whole_set() {
        let dir = tempfile::tempdir().unwrap();
        let (mut x, mut y) = (writer(dir.path(), "x", 100), writer(dir.path(), "y", 100));
        // a reader holding the folder's lock sees one whole set at every look
        let mut looks = 0;
        while x.try_wait().unwrap().is_none() || y.try_wait().unwrap().is_none() {
            let _held = folder_lock(dir.path()).unwrap();
            let seen = tags(dir.path());
            assert!(seen.len() <= 1, "a mix of sets: {seen:?}");
            looks += 1;
        }
        assert!(x.wait().unwrap().success() && y.wait().unwrap().success());
        assert!(looks > 0);
        assert_eq!(tags(dir.path()).len(), 1);
        assert_eq!(contents(dir.path()).len(), 40, "{:?}", contents(dir.path()));
    }
}
