//! Running the real `casteljau` binary from the integration tests.

#![allow(dead_code)] // each test file uses its own subset

#[cfg(feature = "cli")]
use std::io::Write;
use std::process::Output;
#[cfg(feature = "cli")]
use std::process::{Child, Command, Stdio};

/// Starts the binary with `args` and all three streams piped.
#[cfg(feature = "cli")]
pub fn spawn<S: AsRef<std::ffi::OsStr>>(args: &[S]) -> Child {
    Command::new(env!("CARGO_BIN_EXE_casteljau"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary starts")
}

/// Runs the binary with `args`, feeding `stdin` when given.
#[cfg(feature = "cli")]
pub fn run(args: &[&str], stdin: Option<&str>) -> Output {
    let mut child = spawn(args);
    if let Some(s) = stdin {
        child.stdin.take().unwrap().write_all(s.as_bytes()).unwrap();
    }
    drop(child.stdin.take());
    child.wait_with_output().unwrap()
}
pub fn stdout(o: &Output) -> String {
    String::from_utf8(o.stdout.clone()).unwrap()
}
pub fn stderr(o: &Output) -> String {
    String::from_utf8(o.stderr.clone()).unwrap()
}

/// A fresh directory under the system's temporary directory, removed with everything in it
/// when the guard is dropped — also when the test fails (the panic unwinds through the drop),
/// so no run leaves files behind.
pub struct TempDir(std::path::PathBuf);

impl TempDir {
    /// `casteljau-<name>-<pid>-<k>`, created empty (`k` counts the guards of this process, so
    /// tests running in parallel never share a directory).
    pub fn new(name: &str) -> TempDir {
        static COUNTER: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
        let k = COUNTER.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let dir = std::env::temp_dir().join(format!("casteljau-{name}-{}-{k}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).expect("the temporary directory can be created");
        TempDir(dir)
    }

    /// The directory.
    pub fn path(&self) -> &std::path::Path {
        &self.0
    }

    /// A path inside the directory.
    pub fn join(&self, name: &str) -> std::path::PathBuf {
        self.0.join(name)
    }

    /// Writes `text` to `name` inside the directory and returns its path.
    pub fn write(&self, name: &str, text: &str) -> std::path::PathBuf {
        let p = self.join(name);
        std::fs::write(&p, text).expect("the temporary file can be written");
        p
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}
