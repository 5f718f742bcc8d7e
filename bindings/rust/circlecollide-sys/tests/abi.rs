//! The hand-written declarations agree with the C header: struct fields (names, order, offsets,
//! sizes, as the C compiler lays them out), function signatures (parsed from the header's
//! text and from src/lib.rs), result codes, modes and the version.

use circlecollide_sys::c_layout::{C_CONSTANTS, C_LAYOUT, C_MODES, C_VERSION, HEADER_PATH};
use circlecollide_sys::*;
use core::mem::{align_of, offset_of, size_of};
use std::collections::BTreeMap;

fn size_of_pointee<T>(_: *const T) -> usize {
    size_of::<T>()
}

/// (struct, field or "", offset or size, size or align) for the Rust types, like C_LAYOUT.
macro_rules! rust_layout {
    ($($t:ident { $($f:ident),* })*) => {{
        let mut v: Vec<(&'static str, &'static str, usize, usize)> = Vec::new();
        $(
            v.push((stringify!($t), "", size_of::<$t>(), align_of::<$t>()));
            $({
                let u = core::mem::MaybeUninit::<$t>::uninit();
                let size = size_of_pointee(unsafe { core::ptr::addr_of!((*u.as_ptr()).$f) });
                v.push((stringify!($t), stringify!($f), offset_of!($t, $f), size));
            })*
        )*
        v
    }};
}

fn rust_table() -> Vec<(&'static str, &'static str, usize, usize)> {
    rust_layout! {
        cc_vec2 { x, y }
        cc_circle { pos, vel, radius, mass }
        cc_segment { a, b }
        cc_contact { t, point, normal, depth }
        cc_circle_soa { px, py, vx, vy, radius }
        cc_contact_event { a, b, segment, t, point, normal, impulse }
        cc_sensor_event { sensor, visitor, begin, t }
        cc_world_def { struct_size, max_circles, max_segments, mode, restitution, rest_speed, cell_size, max_events, on_contact, user, rolling_decel, restitution_mix, on_sensor, period, uses }
        cc_world_stats { struct_size, collisions, events, stale_events, pairs_tested, cell_crossings, max_overlap, virial, wall_impulse }
        cc_circle_props { struct_size, restitution, rolling_decel, category, mask, sensor }
        cc_segment_props { struct_size, restitution, category, mask }
        cc_cast_hit { circle, segment, t, point, normal }
        cc_query_filter { struct_size, mask, ignore }
        cc_vec2f { x, y }
        cc_circlef { pos, vel, radius, mass }
        cc_segmentf { a, b }
        cc_contactf { t, point, normal, depth }
    }
}

fn header() -> String {
    let text = std::fs::read_to_string(HEADER_PATH).expect("the header the library was built from");
    strip_comments(&text)
}

fn strip_comments(s: &str) -> String {
    let mut out = String::new();
    let mut rest = s;
    while let Some(i) = rest.find("/*") {
        out.push_str(&rest[..i]);
        rest = &rest[i + 2..];
        rest = &rest[rest.find("*/").map_or(rest.len(), |j| j + 2)..];
    }
    out.push_str(rest);
    out.lines().map(|l| l.split("//").next().unwrap()).collect::<Vec<_>>().join("\n")
}

fn words(s: &str) -> String {
    s.split_whitespace().collect::<Vec<_>>().join(" ")
}

/// struct name -> field names in order, from `typedef struct X { ... } X;` in the header.
fn header_structs(h: &str) -> BTreeMap<String, Vec<String>> {
    let mut out = BTreeMap::new();
    let mut rest = h;
    while let Some(i) = rest.find("typedef struct") {
        rest = &rest[i + 14..];
        let (Some(open), Some(semi)) = (rest.find('{'), rest.find(';')) else { continue };
        if semi < open {
            continue; // typedef struct cc_world cc_world;
        }
        let close = rest.find('}').unwrap();
        let body = &rest[open + 1..close];
        let name = rest[close + 1..].split(';').next().unwrap().trim().to_string();
        let mut fields = Vec::new();
        for decl in body.split(';').map(words).filter(|d| !d.is_empty()) {
            // "const double *px, *py" -> px, py ; "cc_vec2 a, b" -> a, b
            let first = decl.split(',').next().unwrap();
            let mut names = vec![first.rsplit([' ', '*']).next().unwrap().to_string()];
            names.extend(decl.split(',').skip(1).map(|n| n.trim().trim_start_matches('*').trim().to_string()));
            fields.extend(names);
        }
        out.insert(name, fields);
        rest = &rest[close..];
    }
    out
}

#[test]
fn structs_match_the_header_and_the_c_layout() {
    assert!(!C_LAYOUT.is_empty(), "no C layout (cross-compiling?)");
    let h = header_structs(&header());
    assert!(h.len() >= 16, "{h:?}");
    let rust = rust_table();
    for (name, fields) in &h {
        let listed = |t: &[(&str, &str, usize, usize)]| -> Vec<String> {
            t.iter().filter(|r| r.0 == name && !r.1.is_empty()).map(|r| r.1.to_string()).collect()
        };
        assert_eq!(&listed(C_LAYOUT), fields, "native/layout.c lists other fields of {name} than the header");
        assert_eq!(&listed(&rust), fields, "the Rust {name} has other fields than the header");
    }
    let structs: Vec<_> = rust.iter().filter(|r| r.1.is_empty()).map(|r| r.0).collect();
    assert_eq!(structs.len(), h.len(), "a struct of the header is not declared in Rust");
    let diff: Vec<_> = rust.iter().zip(C_LAYOUT).filter(|(r, c)| r != c).collect();
    assert!(
        diff.is_empty() && rust.len() == C_LAYOUT.len(),
        "Rust and C disagree, (struct, field, offset or size, size or align) as (Rust, C): {diff:?}"
    );
}

/// Normalised C signature "ret name(type, type)" from the header.
fn header_functions(h: &str) -> BTreeMap<String, String> {
    let mut out = BTreeMap::new();
    for decl in h.split("CC_API").skip(1) {
        let decl = words(decl.split(';').next().unwrap());
        let Some(open) = decl.find('(') else { continue };
        if !decl.contains("cc_") || decl.starts_with('_') {
            continue; // the macro's own definition lines
        }
        let head = decl[..open].replace('*', " * ");
        let mut head: Vec<&str> = head.split_whitespace().collect();
        let name = head.pop().unwrap().to_string();
        let ret = c_type(&head.join(" "));
        let args = decl[open + 1..decl.rfind(')').unwrap()].trim();
        let args: Vec<String> = if args == "void" || args.is_empty() {
            vec![]
        } else {
            args.split(',')
                .map(|a| {
                    let a = a.replace('*', " * ");
                    let mut t: Vec<&str> = a.split_whitespace().collect();
                    t.pop(); // the parameter's name
                    c_type(&t.join(" "))
                })
                .collect()
        };
        out.insert(name.clone(), format!("{ret} {name}({})", args.join(", ")));
    }
    out
}

fn c_type(t: &str) -> String {
    words(t).replace(" *", "*")
}

fn rust_to_c(t: &str) -> String {
    let t = t.trim();
    if let Some(p) = t.strip_prefix("*const ") {
        return format!("const {}*", rust_to_c(p));
    }
    if let Some(p) = t.strip_prefix("*mut ") {
        return format!("{}*", rust_to_c(p));
    }
    match t {
        "f64" => "double",
        "f32" => "float",
        "c_int" => "int",
        "c_uint" => "unsigned",
        "c_long" => "long",
        "usize" => "size_t",
        "u64" => "uint64_t",
        "u32" => "uint32_t",
        "c_char" => "char",
        "c_void" => "void",
        other => other,
    }
    .to_string()
}

/// The same normalised signatures from the extern blocks of src/lib.rs.
fn rust_functions() -> BTreeMap<String, String> {
    let src = include_str!("../src/lib.rs");
    let mut out = BTreeMap::new();
    for block in src.split("extern \"C\" {").skip(1) {
        let block = &block[..block.find("\n}").unwrap()];
        for decl in block.split(';').map(words).filter(|d| d.contains("pub fn ")) {
            let decl = &decl[decl.find("pub fn ").unwrap() + 7..];
            let open = decl.find('(').unwrap();
            let close = decl.rfind(')').unwrap();
            let name = decl[..open].trim().to_string();
            let args: Vec<String> = decl[open + 1..close]
                .split(',')
                .filter(|a| !a.trim().is_empty())
                .map(|a| rust_to_c(a.split_once(':').unwrap().1))
                .collect();
            let ret = decl[close + 1..].trim().strip_prefix("->").map_or("void".to_string(), rust_to_c);
            out.insert(name.clone(), format!("{ret} {name}({})", args.join(", ")));
        }
    }
    out
}

#[test]
fn functions_match_the_header_signature_for_signature() {
    let h = header_functions(&header());
    assert!(h.len() >= 40, "{h:?}");
    let r = rust_functions();
    let only_h: Vec<_> = h.keys().filter(|k| !r.contains_key(*k)).collect();
    let only_r: Vec<_> = r.keys().filter(|k| !h.contains_key(*k)).collect();
    assert!(only_h.is_empty() && only_r.is_empty(), "header only: {only_h:?}; Rust only: {only_r:?}");
    for (name, sig) in &h {
        assert_eq!(&r[name], sig, "signature of {name}");
    }
}

/// The names of the header's integer macros (`#define CC_X value`), CC_API and initializers
/// (`#define CC_X {...}`, which Rust spells as a struct's Default) aside.
fn header_defines(h: &str) -> Vec<String> {
    h.lines()
        .filter_map(|l| l.trim().strip_prefix("#"))
        .filter_map(|l| l.trim().strip_prefix("define"))
        .filter_map(|l| {
            let mut w = l.split_whitespace();
            let name = w.next()?;
            (!w.next().is_some_and(|v| v.starts_with('{'))).then_some(name)
        })
        .filter(|n| n.starts_with("CC_") && *n != "CC_API")
        .map(str::to_string)
        .collect()
}

#[test]
fn constants_match_the_header() {
    let rust: [(&str, i64); 26] = [
        ("CC_VERSION_MAJOR", CC_VERSION_MAJOR.into()),
        ("CC_VERSION_MINOR", CC_VERSION_MINOR.into()),
        ("CC_VERSION_PATCH", CC_VERSION_PATCH.into()),
        ("CC_VERSION", CC_VERSION.into()),
        ("CC_MISS", CC_MISS.into()),
        ("CC_OK", CC_OK.into()),
        ("CC_HIT", CC_HIT.into()),
        ("CC_OVERLAP", CC_OVERLAP.into()),
        ("CC_EVENT_LIMIT", CC_EVENT_LIMIT.into()),
        ("CC_ERR_INVALID", CC_ERR_INVALID.into()),
        ("CC_ERR_NOT_FOUND", CC_ERR_NOT_FOUND.into()),
        ("CC_ERR_FULL", CC_ERR_FULL.into()),
        ("CC_ERR_MEMORY", CC_ERR_MEMORY.into()),
        ("CC_ERR_VERSION", CC_ERR_VERSION.into()),
        ("CC_ERR_RANGE", CC_ERR_RANGE.into()),
        ("CC_ERR_BUSY", CC_ERR_BUSY.into()),
        ("CC_MIX_MIN", CC_MIX_MIN.into()),
        ("CC_MIX_MAX", CC_MIX_MAX.into()),
        ("CC_MIX_PRODUCT", CC_MIX_PRODUCT.into()),
        ("CC_MIX_MEAN", CC_MIX_MEAN.into()),
        ("CC_MAX_SENSORS", CC_MAX_SENSORS.into()),
        ("CC_USES_PROPS", CC_USES_PROPS.into()),
        ("CC_USES_SENSORS", CC_USES_SENSORS.into()),
        ("CC_USES_ROLLING", CC_USES_ROLLING.into()),
        ("CC_USES_CLOTH", CC_USES_CLOTH.into()),
        ("CC_USES_ALL", CC_USES_ALL.into()),
    ];
    assert_eq!(&rust[..], C_CONSTANTS, "(Rust, C)");
    // every integer macro of the header is among them (a new one must be added here and to
    // native/layout.c)
    let mut names: Vec<_> = rust.iter().map(|r| r.0.to_string()).collect();
    let mut defined = header_defines(&header());
    names.sort();
    defined.sort();
    assert_eq!(names, defined, "the header's CC_ macros and the Rust constants differ");
    assert_eq!([CC_MODE_EXACT, CC_MODE_SWEPT, CC_MODE_DISCRETE], C_MODES);
    assert_eq!(CC_VERSION, C_VERSION);
    // and the library linked is the one of this header
    assert_eq!(unsafe { cc_version() }, C_VERSION);
}

/// `typedef ret (*name)(args);` of the header, normalised as "ret name(type, type)".
fn header_fn_types(h: &str) -> BTreeMap<String, String> {
    let mut out = BTreeMap::new();
    for decl in h.split(';').map(words) {
        let Some(rest) = decl.strip_prefix("typedef ") else { continue };
        let Some(star) = rest.find("(*") else { continue };
        let ret = c_type(&rest[..star]);
        let close = star + rest[star..].find(')').unwrap();
        let name = rest[star + 2..close].trim().to_string();
        let args = &rest[close + 1..];
        let args = args.trim().trim_start_matches('(').trim_end_matches(')');
        let args: Vec<String> = args
            .split(',')
            .map(|a| {
                let a = a.replace('*', " * ");
                let mut t: Vec<&str> = a.split_whitespace().collect();
                t.pop();
                c_type(&t.join(" "))
            })
            .collect();
        out.insert(name.clone(), format!("{ret} {name}({})", args.join(", ")));
    }
    out
}

/// The same from `pub type name = Option<unsafe extern "C" fn(args) -> ret>;` in src/lib.rs.
fn rust_fn_types() -> BTreeMap<String, String> {
    let src = include_str!("../src/lib.rs");
    let mut out = BTreeMap::new();
    for decl in src.split(';').map(words) {
        let Some(p) = decl.find("pub type ") else { continue };
        let decl = &decl[p + 9..];
        let Some((name, ty)) = decl.split_once(" = Option<unsafe extern \"C\" fn(") else { continue };
        let ty = ty.strip_suffix('>').unwrap();
        let close = ty.rfind(')').unwrap();
        let args: Vec<String> = ty[..close]
            .split(',')
            .filter(|a| !a.trim().is_empty())
            .map(|a| rust_to_c(a.split_once(':').unwrap().1))
            .collect();
        let ret = ty[close + 1..].trim().strip_prefix("->").map_or("void".to_string(), rust_to_c);
        out.insert(name.to_string(), format!("{ret} {name}({})", args.join(", ")));
    }
    out
}

#[test]
fn callback_types_match_the_header() {
    let h = header_fn_types(&header());
    assert_eq!(h.len(), 2, "{h:?}");
    assert_eq!(h, rust_fn_types());
}

#[test]
fn the_c_layout_fields_are_those_of_the_header() {
    // the parser itself: a struct with a multi-name pointer declaration
    let h = header_structs("typedef struct s { const double *px, *py; int n; } s;");
    assert_eq!(h["s"], ["px", "py", "n"]);
    let f = header_functions("CC_API const char *cc_x(int code, const cc_circle *a);");
    assert_eq!(f["cc_x"], "const char* cc_x(int, const cc_circle*)");
    let t = header_fn_types("typedef void (*cc_f)(const cc_e *event, void *user);");
    assert_eq!(t["cc_f"], "void cc_f(const cc_e*, void*)");
    assert_eq!(header_defines("#define CC_API x\n#  define CC_A (-1) /* c */\n#define X 1"), ["CC_A"]);
}
