//! Raw declarations of the circlecollide C API (include/circlecollide.h), written by hand.
//!
//! Every item mirrors the header one to one: same names, same field order, same types. The
//! tests in tests/abi.rs compare these declarations with the header's text and with the layout
//! the C compiler gives each struct, so that any drift fails `cargo test`. Use the
//! `circlecollide` crate for a safe API.
#![no_std]
#![allow(non_camel_case_types)]

use core::ffi::{c_char, c_int, c_long, c_uint, c_void};

// ---- version and result codes ------------------------------------------------------------

pub const CC_VERSION_MAJOR: u32 = 1;
pub const CC_VERSION_MINOR: u32 = 2;
pub const CC_VERSION_PATCH: u32 = 0;
pub const CC_VERSION: u32 = (CC_VERSION_MAJOR << 16) | (CC_VERSION_MINOR << 8) | CC_VERSION_PATCH;

pub const CC_MISS: c_int = 0;
pub const CC_OK: c_int = 0;
pub const CC_HIT: c_int = 1;
pub const CC_OVERLAP: c_int = 2;
pub const CC_EVENT_LIMIT: c_int = 3;
pub const CC_ERR_INVALID: c_int = -1;
pub const CC_ERR_NOT_FOUND: c_int = -2;
pub const CC_ERR_FULL: c_int = -3;
pub const CC_ERR_MEMORY: c_int = -4;
pub const CC_ERR_VERSION: c_int = -5;
// 1.2: for a world made from a def past 1.1's (the header's Results)
pub const CC_ERR_RANGE: c_int = -6;
pub const CC_ERR_BUSY: c_int = -7;

// ---- value types -------------------------------------------------------------------------

#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct cc_vec2 {
    pub x: f64,
    pub y: f64,
}

#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct cc_circle {
    pub pos: cc_vec2,
    pub vel: cc_vec2,
    pub radius: f64,
    pub mass: f64,
}

#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct cc_segment {
    pub a: cc_vec2,
    pub b: cc_vec2,
}

#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct cc_contact {
    pub t: f64,
    pub point: cc_vec2,
    pub normal: cc_vec2,
    pub depth: f64,
}

#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct cc_circle_soa {
    pub px: *const f64,
    pub py: *const f64,
    pub vx: *const f64,
    pub vy: *const f64,
    pub radius: *const f64,
}

// ---- the world ---------------------------------------------------------------------------

/// Opaque: lives inside the memory given to `cc_world_init`.
#[repr(C)]
pub struct cc_world {
    _opaque: [u8; 0],
    _not_send_sync: core::marker::PhantomData<(*mut u8, core::marker::PhantomPinned)>,
}

pub type cc_mode = c_int;
pub const CC_MODE_EXACT: cc_mode = 0;
pub const CC_MODE_SWEPT: cc_mode = 1;
pub const CC_MODE_DISCRETE: cc_mode = 2;

#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct cc_contact_event {
    pub a: c_int,
    pub b: c_int,
    pub segment: c_int,
    pub t: f64,
    pub point: cc_vec2,
    pub normal: cc_vec2,
    pub impulse: f64,
}

pub type cc_contact_fn = Option<unsafe extern "C" fn(event: *const cc_contact_event, user: *mut c_void)>;

#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct cc_sensor_event {
    pub sensor: c_int,
    pub visitor: c_int,
    pub begin: c_int,
    pub t: f64,
}

pub type cc_sensor_fn = Option<unsafe extern "C" fn(event: *const cc_sensor_event, user: *mut c_void)>;

pub const CC_MIX_MIN: c_int = 0;
pub const CC_MIX_MAX: c_int = 1;
pub const CC_MIX_PRODUCT: c_int = 2;
pub const CC_MIX_MEAN: c_int = 3;

// cc_world_def.uses bits (1.2): what a world may use; it reserves memory for no more
pub const CC_USES_PROPS: core::ffi::c_uint = 1;
pub const CC_USES_SENSORS: core::ffi::c_uint = 2;
pub const CC_USES_ROLLING: core::ffi::c_uint = 4;
pub const CC_USES_CLOTH: core::ffi::c_uint = 8;
pub const CC_USES_ALL: core::ffi::c_uint = 0xffff;

#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct cc_world_def {
    pub struct_size: usize,
    pub max_circles: c_int,
    pub max_segments: c_int,
    pub mode: c_int,
    pub restitution: f64,
    pub rest_speed: f64,
    pub cell_size: f64,
    pub max_events: u64,
    pub on_contact: cc_contact_fn,
    pub user: *mut c_void,
    // 1.1
    pub rolling_decel: f64,
    pub restitution_mix: c_int,
    pub on_sensor: cc_sensor_fn,
    pub period: cc_vec2,
    // 1.2
    pub uses: core::ffi::c_uint,
}

#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct cc_world_stats {
    pub struct_size: usize,
    pub collisions: u64,
    pub events: u64,
    pub stale_events: u64,
    pub pairs_tested: u64,
    pub cell_crossings: u64,
    pub max_overlap: f64,
    // 1.1
    pub virial: f64,
    pub wall_impulse: f64,
}

pub const CC_MAX_SENSORS: c_int = 64;

#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct cc_circle_props {
    pub struct_size: usize,
    pub restitution: f64,
    pub rolling_decel: f64,
    pub category: u32,
    pub mask: u32,
    pub sensor: c_int,
}

#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct cc_segment_props {
    pub struct_size: usize,
    pub restitution: f64,
    pub category: u32,
    pub mask: u32,
}

#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct cc_cast_hit {
    pub circle: c_int,
    pub segment: c_int,
    pub t: f64,
    pub point: cc_vec2,
    pub normal: cc_vec2,
}

// 1.2
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct cc_query_filter {
    pub struct_size: usize,
    pub mask: u32,
    pub ignore: c_int,
}

// ---- single precision --------------------------------------------------------------------

#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct cc_vec2f {
    pub x: f32,
    pub y: f32,
}

#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct cc_circlef {
    pub pos: cc_vec2f,
    pub vel: cc_vec2f,
    pub radius: f32,
    pub mass: f32,
}

#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct cc_segmentf {
    pub a: cc_vec2f,
    pub b: cc_vec2f,
}

#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct cc_contactf {
    pub t: f32,
    pub point: cc_vec2f,
    pub normal: cc_vec2f,
    pub depth: f32,
}

// ---- functions (one line each: tests/abi.rs reads this block) ----------------------------

extern "C" {
    pub fn cc_version() -> c_uint;
    pub fn cc_version_string() -> *const c_char;
    pub fn cc_result_string(code: c_int) -> *const c_char;

    pub fn cc_detect_static(a: *const cc_circle, b: *const cc_circle, out: *mut cc_contact) -> c_int;
    pub fn cc_separate(a: *mut cc_circle, b: *mut cc_circle) -> c_int;
    pub fn cc_sweep(a: *const cc_circle, b: *const cc_circle, t_max: f64, out: *mut cc_contact) -> c_int;
    pub fn cc_sweep_segment(c: *const cc_circle, s: *const cc_segment, t_max: f64, out: *mut cc_contact) -> c_int;
    pub fn cc_respond(a: *mut cc_circle, b: *mut cc_circle, contact: *const cc_contact, restitution: f64) -> c_int;
    pub fn cc_respond_segment(c: *mut cc_circle, contact: *const cc_contact, restitution: f64) -> c_int;
    pub fn cc_closest_point_on_segment(p: cc_vec2, s: *const cc_segment) -> cc_vec2;
    pub fn cc_sweep_many(
        n: usize,
        a: *const cc_circle_soa,
        b: *const cc_circle_soa,
        t_max: f64,
        t_out: *mut f64,
        result_out: *mut c_int,
    ) -> c_long;
    pub fn cc_sweep_rolling(
        a: *const cc_circle,
        decel_a: f64,
        b: *const cc_circle,
        decel_b: f64,
        t_max: f64,
        out: *mut cc_contact,
    ) -> c_int;
    pub fn cc_sweep_segment_rolling(
        c: *const cc_circle,
        decel: f64,
        s: *const cc_segment,
        t_max: f64,
        out: *mut cc_contact,
    ) -> c_int;
    pub fn cc_rolling_advance(c: *mut cc_circle, decel: f64, t: f64) -> c_int;

    pub fn cc_detect_staticf(a: *const cc_circlef, b: *const cc_circlef, out: *mut cc_contactf) -> c_int;
    pub fn cc_separatef(a: *mut cc_circlef, b: *mut cc_circlef) -> c_int;
    pub fn cc_sweepf(a: *const cc_circlef, b: *const cc_circlef, t_max: f32, out: *mut cc_contactf) -> c_int;
    pub fn cc_sweep_segmentf(c: *const cc_circlef, s: *const cc_segmentf, t_max: f32, out: *mut cc_contactf) -> c_int;
    pub fn cc_respondf(a: *mut cc_circlef, b: *mut cc_circlef, contact: *const cc_contactf, restitution: f32) -> c_int;
    pub fn cc_respond_segmentf(c: *mut cc_circlef, contact: *const cc_contactf, restitution: f32) -> c_int;
    pub fn cc_closest_point_on_segmentf(p: cc_vec2f, s: *const cc_segmentf) -> cc_vec2f;
    pub fn cc_sweep_rollingf(
        a: *const cc_circlef,
        decel_a: f32,
        b: *const cc_circlef,
        decel_b: f32,
        t_max: f32,
        out: *mut cc_contactf,
    ) -> c_int;
    pub fn cc_sweep_segment_rollingf(
        c: *const cc_circlef,
        decel: f32,
        s: *const cc_segmentf,
        t_max: f32,
        out: *mut cc_contactf,
    ) -> c_int;
    pub fn cc_rolling_advancef(c: *mut cc_circlef, decel: f32, t: f32) -> c_int;
}

// The world's functions: declared only when the library built here contains them (the build
// script sets `cc_has_world`), so that a library without them still links.
#[cfg(cc_has_world)]
extern "C" {
    /// Fills 1.0's def only (the symbol a 1.0 program calls); use `cc_world_def_init_sized`.
    pub fn cc_world_def_init(def: *mut cc_world_def);
    /// Defaults for every field of a def of `struct_size` bytes (what the C header's
    /// `cc_world_def_init` macro calls with `sizeof(cc_world_def)`).
    pub fn cc_world_def_init_sized(def: *mut cc_world_def, struct_size: usize);
    pub fn cc_world_size(def: *const cc_world_def) -> usize;
    pub fn cc_world_init(
        memory: *mut c_void,
        bytes: usize,
        def: *const cc_world_def,
        status: *mut c_int,
    ) -> *mut cc_world;
    pub fn cc_world_add_circle(w: *mut cc_world, c: *const cc_circle) -> c_int;
    pub fn cc_world_add_segment(w: *mut cc_world, s: *const cc_segment) -> c_int;
    pub fn cc_world_remove_circle(w: *mut cc_world, id: c_int) -> c_int;
    pub fn cc_world_step(w: *mut cc_world, dt: f64) -> c_int;
    pub fn cc_world_get_circle(w: *const cc_world, id: c_int, out: *mut cc_circle) -> c_int;
    pub fn cc_world_set_circle(w: *mut cc_world, id: c_int, c: *const cc_circle) -> c_int;
    pub fn cc_world_get_circles(w: *const cc_world, ids: *mut c_int, out: *mut cc_circle, capacity: c_int) -> c_int;
    pub fn cc_world_get_segment(w: *const cc_world, id: c_int, out: *mut cc_segment) -> c_int;
    pub fn cc_world_get_unwrapped(w: *const cc_world, id: c_int, out: *mut cc_vec2) -> c_int;
    pub fn cc_world_time(w: *const cc_world) -> f64;
    pub fn cc_world_get_stats(w: *const cc_world, out: *mut cc_world_stats) -> c_int;

    pub fn cc_world_get_circle_props(w: *const cc_world, id: c_int, out: *mut cc_circle_props) -> c_int;
    pub fn cc_world_set_circle_props(w: *mut cc_world, id: c_int, p: *const cc_circle_props) -> c_int;
    pub fn cc_world_get_segment_props(w: *const cc_world, id: c_int, out: *mut cc_segment_props) -> c_int;
    pub fn cc_world_set_segment_props(w: *mut cc_world, id: c_int, p: *const cc_segment_props) -> c_int;

    pub fn cc_world_cast_circle(
        w: *const cc_world,
        p: cc_vec2,
        radius: f64,
        d: cc_vec2,
        mask: u32,
        out: *mut cc_cast_hit,
    ) -> c_int;
    pub fn cc_world_query_circle(
        w: *const cc_world,
        c: cc_vec2,
        radius: f64,
        mask: u32,
        ids: *mut c_int,
        capacity: c_int,
    ) -> c_int;
    pub fn cc_world_query_box(
        w: *const cc_world,
        lo: cc_vec2,
        hi: cc_vec2,
        mask: u32,
        ids: *mut c_int,
        capacity: c_int,
    ) -> c_int;
    pub fn cc_world_hash(w: *const cc_world) -> u64;

    // 1.2
    pub fn cc_world_add_circles(
        w: *mut cc_world,
        c: *const cc_circle,
        n: c_int,
        ids_out: *mut c_int,
        failed: *mut c_int,
    ) -> c_int;
    pub fn cc_world_get_unwrapped_all(w: *const cc_world, ids: *mut c_int, out: *mut cc_vec2, capacity: c_int)
        -> c_int;
    pub fn cc_world_cast_circle_filtered(
        w: *const cc_world,
        p: cc_vec2,
        radius: f64,
        d: cc_vec2,
        filter: *const cc_query_filter,
        out: *mut cc_cast_hit,
    ) -> c_int;
    pub fn cc_world_query_circle_filtered(
        w: *const cc_world,
        c: cc_vec2,
        radius: f64,
        filter: *const cc_query_filter,
        ids: *mut c_int,
        capacity: c_int,
    ) -> c_int;
    pub fn cc_world_query_box_filtered(
        w: *const cc_world,
        lo: cc_vec2,
        hi: cc_vec2,
        filter: *const cc_query_filter,
        ids: *mut c_int,
        capacity: c_int,
    ) -> c_int;
}

/// True when this build of the library contains the world (cc_world_*).
pub const HAS_WORLD: bool = cfg!(cc_has_world);

/// The C layout of every public struct as the C compiler printed it (see native/layout.c),
/// and the header's constants, for the ABI tests.
#[doc(hidden)]
pub mod c_layout {
    include!(concat!(env!("OUT_DIR"), "/layout.rs"));
    pub const HEADER_PATH: &str = include_str!(concat!(env!("OUT_DIR"), "/header_path.txt"));
}
