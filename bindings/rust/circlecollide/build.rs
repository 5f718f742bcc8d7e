//! Passes on whether the C library has the world (circlecollide-sys found out when building it).
fn main() {
    println!("cargo::rustc-check-cfg=cfg(cc_has_world)");
    println!("cargo:rerun-if-env-changed=DEP_CIRCLECOLLIDE_WORLD");
    if std::env::var("DEP_CIRCLECOLLIDE_WORLD").as_deref() == Ok("1") {
        println!("cargo:rustc-cfg=cc_has_world");
    }
}
