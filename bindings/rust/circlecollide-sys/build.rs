//! Builds the repository's C library (static) with CMake, links it, and runs the small C program
//! native/layout.c to record the C layout of every public struct for the ABI tests.

use std::env;
use std::fs;
use std::path::{Path, PathBuf};
use std::process::Command;

fn main() {
    let manifest = PathBuf::from(env::var("CARGO_MANIFEST_DIR").unwrap());
    // The C sources: the repository this crate lives in, unless told otherwise.
    let root = env::var_os("CIRCLECOLLIDE_SOURCE_DIR").map(PathBuf::from).unwrap_or_else(|| manifest.join("../../.."));
    let root =
        root.canonicalize().unwrap_or_else(|e| panic!("circlecollide sources not found at {}: {e}", root.display()));
    for p in ["include", "src", "CMakeLists.txt"] {
        println!("cargo:rerun-if-changed={}", root.join(p).display());
    }
    println!("cargo:rerun-if-changed=native");
    println!("cargo:rerun-if-env-changed=CIRCLECOLLIDE_SOURCE_DIR");
    println!("cargo::rustc-check-cfg=cfg(cc_has_world)");

    let dst = cmake::Config::new(manifest.join("native"))
        .define("CC_ROOT", &root)
        .profile("Release")
        .build_target("cc_layout") // depends on circlecollide_static: builds both, installs nothing
        .build();
    let build = dst.join("build");

    let lib = find(&build.join("circlecollide").join("src"), &["libcirclecollide.a", "circlecollide.lib"])
        .expect("the CMake build produced no static circlecollide library");
    println!("cargo:rustc-link-search=native={}", lib.parent().unwrap().display());
    println!("cargo:rustc-link-lib=static=circlecollide");
    let target_os = env::var("CARGO_CFG_TARGET_OS").unwrap_or_default();
    if target_os == "linux" || target_os == "android" || target_os.ends_with("bsd") {
        println!("cargo:rustc-link-lib=m");
    }
    println!("cargo:root={}", root.display());
    println!("cargo:include={}", root.join("include").display());

    // The world is declared in the header before it is built: expose it only when it is in the
    // library (dependents read DEP_CIRCLECOLLIDE_WORLD).
    let has_world = fs::read(&lib).map(|b| contains(&b, b"cc_world_init")).unwrap_or(false);
    if has_world {
        println!("cargo:rustc-cfg=cc_has_world");
    }
    println!("cargo:world={}", has_world as u8);

    // The C layout, printed by the C compiler's own program (only when it can run here).
    let out = PathBuf::from(env::var("OUT_DIR").unwrap());
    let layout = if env::var("HOST") == env::var("TARGET") {
        let exe = find(&build, &["cc_layout", "cc_layout.exe"]).expect("cc_layout was not built");
        let o = Command::new(&exe).output().expect("cc_layout did not run");
        assert!(o.status.success(), "cc_layout failed");
        String::from_utf8(o.stdout).unwrap()
    } else {
        // cross-compiling: the layout test has nothing to compare and says so
        "pub const C_LAYOUT: &[(&str, &str, usize, usize)] = &[];\npub const C_MODES: [i32; 3] = [0, 1, 2];\n\
         pub const C_VERSION: u32 = 0;\npub const C_CODES: [(&str, i32); 0] = [];\n\
         pub const C_CONSTANTS: &[(&str, i64)] = &[];\n"
            .to_string()
    };
    fs::write(out.join("layout.rs"), layout).unwrap();
    fs::write(out.join("header_path.txt"), root.join("include/circlecollide.h").display().to_string()).unwrap();
}

/// The first file named one of `names` under `dir` (any depth: multi-config generators add one).
fn find(dir: &Path, names: &[&str]) -> Option<PathBuf> {
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in fs::read_dir(&d).ok()?.flatten() {
            let p = e.path();
            if p.is_dir() {
                stack.push(p);
            } else if names.iter().any(|n| p.file_name().is_some_and(|f| f == *n)) {
                return Some(p);
            }
        }
    }
    None
}

fn contains(hay: &[u8], needle: &[u8]) -> bool {
    hay.windows(needle.len()).any(|w| w == needle)
}
