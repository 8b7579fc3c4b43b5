//! Issue #34's cases through the real binary: estimates that tell the truth both ways (cheap
//! work answered at the default budget, dear work refused before it starts, with little
//! memory), finite output or a refusal, `--threads` capped, and output files that replace only
//! regular files. Each case is bounded by its budget, never by a timed assertion.

use crate::common::{TempDir, run, stderr, stdout};
use std::os::unix::fs::FileTypeExt;
use std::process::Command;

/// Refused for its estimated work, naming the option.
fn refused_for_work(o: &std::process::Output) -> bool {
    let all = format!("{}{}", stderr(o), stdout(o));
    o.status.code() == Some(2) && all.contains("estimated work") && all.contains("--max-work")
}

use crate::fuzz::has_non_finite;

/// Runs the binary under an address-space limit (`ulimit -v`, KiB).
fn run_limited(kb: u64, args: &[&str]) -> std::process::Output {
    Command::new("sh")
        .arg("-c")
        .arg(format!("ulimit -v {kb}; exec \"$0\" \"$@\""))
        .arg(env!("CARGO_BIN_EXE_casteljau"))
        .args(args)
        .output()
        .unwrap()
}

#[test]
fn budgets_mixed_magnitudes_are_answered_within_the_default_budget() {
    // once estimated at ~2 s and run past 60 s: the exact images of parameters near 10⁻³⁰⁰ were
    // refined one bisection per root isolation
    let o = run(&["boolean", "difference", "M0 0 C1 1 2 1 3 0 Z", "M1e300 0 L1e300 1e-300 L-1e300 0 Z"], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(stdout(&o).starts_with("M3 0"), "{}", stdout(&o));
    let o = run(
        &["boolean", "difference", "M0 0 C1 1 2 1 3 0 Z", "M1e300 0 L1e300 1e-300 L-1e300 0 Z", "--max-work", "1e6"],
        None,
    );
    assert!(refused_for_work(&o), "{}", stderr(&o));
}

#[test]
fn budgets_arrange_json_writes_tiny_quadratic_roots_at_once() {
    // the canonical interval of 10⁻³⁰⁰·(1 ± √7/14) took a thousand root isolations
    let o = run(&["arrange", "--json", "M0 0 C3 0 -1 0 2 0 Z", "M0 0 H1e300 V1e300 H0 Z"], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let out = stdout(&o);
    assert!(out.contains("1 - 1/14*sqrt(7)") && out.contains("*sqrt(7)\""), "{out}");
}

#[test]
fn budgets_elevation_charges_the_size_of_its_numbers() {
    // 1000-digit coordinates by 9997: estimated 0.05 s, ran 18 s; now estimated from the
    // output's numbers and refused at the default budget
    let digits = |k: usize| format!("{k}{}", "7".repeat(999));
    let cubic = (0..4).map(|k| format!("{} {}", digits(k + 1), digits(k + 5))).collect::<Vec<_>>().join(", ");
    let o = run(&["elevate", "--by", "9997", &cubic], None);
    assert!(refused_for_work(&o), "{}", stderr(&o));
    // the same with small coordinates is answered
    let o = run(&["elevate", "--by", "2000", "0 0, 1 2, 3 1, 4 0"], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
}

#[test]
fn budgets_a_huge_power_in_a_claim_is_refused_before_its_grid_is_evaluated() {
    let dir = TempDir::new("budget-claim");
    dir.write(
        "c.toml",
        "seed = \"x\"\ntitle = \"x\"\n\n[[claim]]\nid = \"big-power\"\nsource = \"x\"\nstatement = \"x\"\n\
         expect = \"holds\"\nkind = \"identity\"\nvars = [\"s\"]\nparams = []\nlhs = \"(1+s)^100000\"\n\
         rhs = \"(1+s)^100000\"\n",
    );
    let o = run(&["prove", dir.path().to_str().unwrap()], None);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("big-power") && stderr(&o).contains("--max-work"), "{}", stderr(&o));
}

#[test]
fn budgets_a_square_traversed_12000_times_is_refused_in_small_memory() {
    // 48,000 segments under the 50,000 limit whose candidate pairs (about 10⁹) were collected
    // before they were priced: 2.5 GB, then an allocation abort. Now counted from the boxes
    // and refused before any is collected.
    let dir = TempDir::new("budget-squares");
    for (name, times) in [("r1000.svg", 1000), ("r12000.svg", 12_000)] {
        let d = format!("M0 0 {}Z", "h10 v10 h-10 v-10 ".repeat(times));
        let file = dir.write(name, &format!("<svg xmlns=\"http://www.w3.org/2000/svg\"><path d=\"{d}\"/></svg>"));
        let o = run_limited(600_000, &["lint", file.to_str().unwrap()]);
        assert_eq!(o.status.code(), Some(2), "{name}: {}", stderr(&o));
        let all = format!("{}{}", stderr(&o), stdout(&o));
        assert!(all.contains("--max-work") && all.contains("candidate pairs"), "{name}: {all}");
        assert!(!all.contains("memory allocation") && !all.contains("panicked"), "{name}: {all}");
        let o = run_limited(600_000, &["arrange", file.to_str().unwrap()]);
        assert!(refused_for_work(&o), "{name}: {}", stderr(&o));
    }
}

#[test]
fn budgets_cheap_arrangements_are_not_refused() {
    // estimated at 14 s (and refused) for 0.56 s of work
    let a = "M2 8 Q1.5 9.5 2 7 C3.5 3 6.5 3 5 0 C4.5 0.5 6.5 2 7 1 L2 8 Z";
    let b = "M7 1 C6.5 2 4.5 0.5 5 0 L5.5 3.75 L4 1.25 L5 0 Z";
    let o = run(&["boolean", "union", a, b, "--direction", "cw"], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let found = stdout(&o).trim().to_string();
    let o = run(&["boolean", "union", a, b, "--direction", "cw", "--against", &found], None);
    assert!(matches!(o.status.code(), Some(0 | 1)), "{}", stderr(&o));
    assert!(!stderr(&o).contains("estimated work"), "{}", stderr(&o));
    // a two-contour cubic check, once estimated at 22 s
    let a = "M0 0 C10 20 30 20 40 0 C30 -20 10 -20 0 0 Z M15 0 C17 5 23 5 25 0 C23 -5 17 -5 15 0 Z";
    let b = "M20 -30 C40 -10 40 10 20 30 C0 10 0 -10 20 -30 Z M20 -8 C24 -4 24 4 20 8 C16 4 16 -4 20 -8 Z";
    let found = stdout(&run(&["boolean", "union", a, b], None)).trim().to_string();
    let o = run(&["boolean", "union", a, b, "--against", &found], None);
    assert!(matches!(o.status.code(), Some(0 | 1)), "{}", stderr(&o));
    // a 2,000-segment glyph (estimated at 356 s, answered in 0.25 s)
    let mut d = String::from("M1000 0");
    for i in 1..=2000 {
        let a = std::f64::consts::TAU * f64::from(i) / 2000.0;
        let r = if i % 2 == 1 { 1037.0 } else { 1000.0 };
        let (x, y) = ((r * a.cos()).round(), (r * a.sin()).round());
        d += &format!(" C{x} {y} {x} {y} {x} {y}");
    }
    d += " Z";
    let o = run(&["boolean", "simplify", &d], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let o = run(&["lint", "--path", &d], None);
    assert!(!stderr(&o).contains("estimated work") && !stdout(&o).contains("estimated work"), "{}", stdout(&o));
}

#[test]
fn budgets_output_beyond_the_f64_range_is_refused_naming_it() {
    for json in [false, true] {
        let mut args = vec!["boolean", "union", "M0 0 H1e400 V1 H0 Z", "M0 0 H2 V2 H0 Z"];
        if json {
            args.push("--json");
        }
        let o = run(&args, None);
        assert_eq!(o.status.code(), Some(2), "{}", stdout(&o));
        let all = format!("{}{}", stderr(&o), stdout(&o));
        assert!(all.contains("beyond the f64 range"), "{all}");
        assert!(!has_non_finite(&stdout(&o)), "{}", stdout(&o));
    }
    let dir = TempDir::new("budget-finite");
    let big = dir.write(
        "big.svg",
        "<svg xmlns=\"http://www.w3.org/2000/svg\"><g transform=\"scale(1e300) scale(1e300)\">\
         <path d=\"M0 0 L2 0 L2 2 Z\"/></g></svg>",
    );
    let nested = dir.write(
        "nested.svg",
        &format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\">{}<path d=\"M0 0 L2 0 L2 2 Z\"/>{}</svg>",
            "<g transform=\"scale(3)\">".repeat(1000),
            "</g>".repeat(1000)
        ),
    );
    for file in [&big, &nested] {
        let f = file.to_str().unwrap();
        for args in [
            vec!["boolean", "simplify", f],
            vec!["boolean", "simplify", "--json", f],
            vec!["arrange", "--json", f],
            vec!["lint", f],
            vec!["lint", "--json", f],
        ] {
            let o = run(&args, None);
            assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stdout(&o));
            let all = format!("{}{}", stderr(&o), stdout(&o));
            assert!(all.contains("beyond the f64 range"), "{args:?}: {all}");
            assert!(!has_non_finite(&stdout(&o)), "{args:?}: {}", stdout(&o));
        }
    }
}

#[test]
fn budgets_threads_are_capped_at_the_work_and_the_cores() {
    // 100,000 threads for one item once took 30 s to start and failed
    let o = run(&["lint", "--threads", "100000", "--path", "M0 0 L2 2 L2 0 L0 2 Z"], None);
    assert!(matches!(o.status.code(), Some(0 | 1)), "{}", stderr(&o));
    assert!(!stderr(&o).contains("cannot start"), "{}", stderr(&o));
    let o = run(&["eval", "--threads", "100000", "--t", "1/2", "0 0, 1 1"], None);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let o = run(&["eval", "--threads", "100000", "--t", "1/2"], Some("0 0, 1 1\n0 0, 2 2\n"));
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    let help = stdout(&run(&["lint", "--help"], None));
    assert!(help.contains("never more than the cores"), "{help}");
}

/// Runs `args` with `{}` replaced by `target`; exit 0.
fn write_to(target: &std::path::Path, args: &[&str]) {
    let t = target.to_str().unwrap();
    let args: Vec<&str> = args.iter().map(|a| if *a == "{}" { t } else { a }).collect();
    let o = run(&args, None);
    assert!(matches!(o.status.code(), Some(0 | 1)), "{args:?}: {}", stderr(&o));
}

/// The writers that replace their file.
fn writers() -> Vec<Vec<&'static str>> {
    vec![
        vec!["plot", "-o", "{}", "0 0, 1 2, 2 0"],
        vec!["boolean", "union", "M0 0 H2 V2 H0 Z", "M1 1 H3 V3 H1 Z", "--plot", "{}"],
        vec!["lint", "--path", "M0 0 L2 2 L2 0 L0 2 Z", "-q", "--html", "{}"],
    ]
}

#[test]
fn budgets_writers_write_through_symbolic_links() {
    let dir = TempDir::new("budget-links");
    for (k, args) in writers().iter().enumerate() {
        let target = dir.join(&format!("target-{k}.svg"));
        std::fs::write(&target, "old").unwrap();
        let link = dir.join(&format!("link-{k}.svg"));
        std::os::unix::fs::symlink(&target, &link).unwrap();
        write_to(&link, args);
        assert!(std::fs::symlink_metadata(&link).unwrap().file_type().is_symlink(), "{args:?}: the link was replaced");
        let written = std::fs::read_to_string(&target).unwrap();
        assert!(written.len() > 100 && written.contains("<svg"), "{args:?}: {written}");
        // a dangling link: its target is created, the link stays
        let missing = dir.join(&format!("missing-{k}.svg"));
        let dangling = dir.join(&format!("dangling-{k}.svg"));
        std::os::unix::fs::symlink(&missing, &dangling).unwrap();
        write_to(&dangling, args);
        assert!(std::fs::symlink_metadata(&dangling).unwrap().file_type().is_symlink());
        assert!(std::fs::read_to_string(&missing).unwrap().contains("<svg"));
    }
    // nothing else is left in the folder (no temporary file)
    let names: Vec<String> =
        std::fs::read_dir(dir.path()).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    assert!(names.iter().all(|n| !n.starts_with('.')), "{names:?}");
}

#[test]
fn budgets_writers_never_replace_a_device() {
    let dir = TempDir::new("budget-devices");
    // /dev/null is written, never replaced; a character device made here too, when allowed
    // (root can mknod)
    let mut devices = vec![std::path::PathBuf::from("/dev/null")];
    let made = dir.join("null-copy");
    let ok = Command::new("mknod").arg(&made).args(["c", "1", "3"]).status().is_ok_and(|s| s.success());
    if ok {
        devices.push(made.clone());
    }
    for device in &devices {
        for args in writers() {
            write_to(device, &args);
            let meta = std::fs::symlink_metadata(device).unwrap();
            assert!(meta.file_type().is_char_device(), "{args:?}: {} is no longer a device", device.display());
        }
    }
    // a link to a device writes the device, and keeps both
    if ok {
        let link = dir.join("to-device");
        std::os::unix::fs::symlink(&made, &link).unwrap();
        write_to(&link, &writers()[0]);
        assert!(std::fs::symlink_metadata(&link).unwrap().file_type().is_symlink());
        assert!(std::fs::symlink_metadata(&made).unwrap().file_type().is_char_device());
    }
}
