//! The shared library's soname, as cargo-c would give it: `libplc_timers.so.0.MINOR` while the
//! version is 0.x (a minor release may change the ABI), `libplc_timers.so.MAJOR` after.
fn main() {
    let major = std::env::var("CARGO_PKG_VERSION_MAJOR").unwrap_or_default();
    let minor = std::env::var("CARGO_PKG_VERSION_MINOR").unwrap_or_default();
    let os = std::env::var("CARGO_CFG_TARGET_OS").unwrap_or_default();
    let sover = if major == "0" {
        format!("0.{minor}")
    } else {
        major
    };
    // ELF platforms only: macOS has install names, Windows no soname.
    if !matches!(os.as_str(), "macos" | "ios" | "windows") {
        println!("cargo:rustc-cdylib-link-arg=-Wl,-soname,libplc_timers.so.{sover}");
    }
    println!("cargo:rerun-if-changed=build.rs");
}
