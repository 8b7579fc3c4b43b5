//! Output files, all or nothing: every file the command line writes (`plot -o`, `boolean
//! --plot`, `intersect --plot`, `lint --html`, `prove --junit`/`--write-readme`, `gallery DIR`)
//! goes through [`write_atomically`]. The library returns bytes; only the binary touches files.

use std::path::Path;

/// Writes `bytes` to `path` all or nothing: into a temporary file beside it, then renamed over
/// `path`; on any error the temporary file is removed and `path` is untouched.
pub(crate) fn write_atomically(path: &Path, bytes: &[u8]) -> std::io::Result<()> {
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_default();
    let tmp = path.with_file_name(format!(".{name}.tmp-{}", std::process::id()));
    let result = std::fs::write(&tmp, bytes).and_then(|()| std::fs::rename(&tmp, path));
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
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
