//! Passes on whether the C library has the world (circlecollide-sys found out when building it),
//! and extracts the Rust examples of the repository README for a doc test.
fn main() {
    let readme = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../README.md");
    println!("cargo:rerun-if-changed={}", readme.display());
    let text = std::fs::read_to_string(&readme).unwrap_or_default();
    let mut blocks = String::new();
    let mut inside = false;
    for line in text.lines() {
        if inside {
            blocks.push_str(line);
            blocks.push('\n');
            inside = line.trim() != "```";
        } else if line.trim() == "```rust" {
            blocks.push_str(line);
            blocks.push('\n');
            inside = true;
        }
    }
    if blocks.is_empty() {
        println!("cargo:warning=no ```rust block in {}: its doc test is empty", readme.display());
    }
    let out = std::path::PathBuf::from(std::env::var("OUT_DIR").unwrap());
    std::fs::write(out.join("readme_rust.md"), blocks).unwrap();

    println!("cargo::rustc-check-cfg=cfg(cc_has_world)");
    println!("cargo:rerun-if-env-changed=DEP_CIRCLECOLLIDE_WORLD");
    if std::env::var("DEP_CIRCLECOLLIDE_WORLD").as_deref() == Ok("1") {
        println!("cargo:rustc-cfg=cc_has_world");
    }
}
