//! The committed header `include/plc_timers.h` is the one cbindgen generates from the sources
//! now (macro-expanded): this test regenerates it and fails on any difference (CI runs it). To update the header
//! after changing the API: `PLC_TIMERS_BLESS=1 cargo test -p plc-timers-c --test header`.

use std::path::Path;

#[test]
fn committed_header_is_fresh() {
    let crate_dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let config = cbindgen::Config::from_file(crate_dir.join("cbindgen.toml"))
        .expect("bindings/c/cbindgen.toml is readable and valid");
    // The exported functions are written by the macro `export!` (src/export.rs), so cbindgen
    // reads the crate macro-expanded (`[parse.expand]` in cbindgen.toml): it runs `cargo rustc
    // -- -Zunpretty=expanded`, which a stable compiler accepts with RUSTC_BOOTSTRAP=1 (set for
    // that child process only; the crate itself builds without it). Its own target directory,
    // as this test's cargo holds the lock on the main one.
    std::env::set_var("RUSTC_BOOTSTRAP", "1");
    std::env::set_var(
        "CARGO_EXPAND_TARGET_DIR",
        Path::new(env!("CARGO_TARGET_TMPDIR")).join("cbindgen-expand"),
    );
    let bindings = cbindgen::Builder::new()
        .with_crate(crate_dir)
        .with_config(config)
        .generate()
        .expect("cbindgen generates the header from bindings/c/src");
    let mut fresh = Vec::new();
    bindings.write(&mut fresh);
    let path = crate_dir.join("include/plc_timers.h");
    if std::env::var_os("PLC_TIMERS_BLESS").is_some() {
        std::fs::write(&path, &fresh).expect("include/plc_timers.h is writable");
        return;
    }
    let committed = std::fs::read(&path).unwrap_or_default();
    if committed != fresh {
        let committed = String::from_utf8_lossy(&committed);
        let fresh = String::from_utf8_lossy(&fresh);
        let first = committed
            .lines()
            .zip(fresh.lines())
            .position(|(a, b)| a != b)
            .unwrap_or(committed.lines().count().min(fresh.lines().count()));
        panic!(
            "include/plc_timers.h differs from the header cbindgen generates now (first at line \
             {}): committed {:?}, fresh {:?}.\nRegenerate it with \
             `PLC_TIMERS_BLESS=1 cargo test -p plc-timers-c --test header` and commit it.",
            first + 1,
            committed.lines().nth(first).unwrap_or("<end of file>"),
            fresh.lines().nth(first).unwrap_or("<end of file>"),
        );
    }
}
