//! Output files, all or nothing: every file the command line writes (`plot -o`, `boolean
//! --plot`, `intersect --plot`, `lint --html`, `prove --junit`/`--write-readme`, `gallery DIR`)
//! goes through [`write_atomically`]. The library returns bytes; only the binary touches files.

use std::io::Write;
use std::path::{Path, PathBuf};

/// How many symbolic links one output path may pass through (as the kernel's `ELOOP` limit).
const MAX_LINKS: usize = 40;

/// Writes `bytes` to `path` as a plain write would, but all or nothing where the target is a
/// regular file (or does not exist yet):
///
/// - a symbolic link is followed to its target (the link stays; a dangling link's target is
///   created), and the target is written by these rules;
/// - a regular file (or a new one) is written into a temporary file beside it, then renamed
///   over it, keeping its permissions; on any error the temporary file is removed and the
///   target is untouched;
/// - anything else — a character device (`/dev/null`), a FIFO, a socket — is opened and written
///   in place: it is never replaced by a regular file.
pub(crate) fn write_atomically(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let target = resolve_links(path)?;
    match std::fs::metadata(&target) {
        Ok(meta) if !meta.is_file() && !meta.is_dir() => {
            let mut file = std::fs::OpenOptions::new().write(true).truncate(true).open(&target)?;
            file.write_all(bytes)?;
            file.flush()
        }
        existing => {
            let name = target.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
            let tmp = target.with_file_name(format!(".{name}.tmp-{}", std::process::id()));
            let result = std::fs::write(&tmp, bytes)
                .and_then(|()| match &existing {
                    Ok(meta) => std::fs::set_permissions(&tmp, meta.permissions()),
                    Err(_) => Ok(()),
                })
                .and_then(|()| std::fs::rename(&tmp, &target));
            if result.is_err() {
                let _ = std::fs::remove_file(&tmp);
            }
            result
        }
    }
}

/// The path `path` names after following its symbolic links (the last component's, repeatedly;
/// a relative link is read from the link's folder). A path that does not exist is its own
/// target.
fn resolve_links(path: &Path) -> std::io::Result<PathBuf> {
    let mut current = path.to_path_buf();
    for _ in 0..MAX_LINKS {
        match std::fs::symlink_metadata(&current) {
            Ok(meta) if meta.file_type().is_symlink() => {
                let link = std::fs::read_link(&current)?;
                current = match current.parent() {
                    Some(dir) if link.is_relative() => dir.join(link),
                    _ => link,
                };
            }
            _ => return Ok(current),
        }
    }
    Err(std::io::Error::other(format!("more than {MAX_LINKS} symbolic links")))
}

/// Writes the gallery ([`casteljau::plot::gallery::files`]) into `dir` (created if missing):
/// everything is generated first, then each file is written all or nothing. Returns the file
/// names.
pub(crate) fn write_gallery(dir: &Path) -> std::io::Result<Vec<String>> {
    let files = casteljau::plot::gallery::files();
    std::fs::create_dir_all(dir)?;
    for (name, content) in &files {
        write_atomically(&dir.join(name), content.as_bytes())?;
    }
    Ok(files.into_iter().map(|(n, _)| n).collect())
}
