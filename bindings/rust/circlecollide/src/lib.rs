//! Exact continuous collision of moving circles: a safe Rust API over the circlecollide C library.
//!
//! Value types ([`Vec2`], [`Circle`], [`Segment`], [`Contact`]) are generic over the precision,
//! `f64` (the default) or `f32` (the C library's single-precision twins). [`Vec2`] is a vector
//! (`a + b`, `a - b`, `-a`, `a * 2.0`, `2.0 * a`, `a / 2.0`, [`Vec2::dot`], [`Vec2::length`],
//! [`Vec2::normalized`]) and converts from `(x, y)` and `[x, y]`. Every call returns a
//! [`Result`] whose [`Error`] names the call, the cause and the argument where the library's
//! code alone would not (`sweep: a.radius must be finite and > 0, got NaN (CC_ERR_INVALID)`).
//!
//! ```
//! use circlecollide::{sweep, respond, Circle, ContactKind, Vec2};
//! let a = Circle::new((0.0, 0.0), 1.0).with_vel((1.0, 0.0)); // radius 1, mass 1
//! let b = Circle::new((10.0, 0.0), 1.0).with_vel((-1.0, 0.0));
//! let c = sweep(&a, &b, 10.0).unwrap().expect("they meet");
//! assert_eq!((c.kind, c.t), (ContactKind::Hit, 4.0)); // a gap of 8 closing at speed 2
//! let (mut a, mut b) = (a.at(c.t), b.at(c.t));
//! assert!(respond(&mut a, &mut b, &c, 1.0).unwrap()); // elastic, equal masses: they swap
//! assert_eq!((a.vel.x, b.vel.x), (-1.0, 1.0));
//! ```
//!
//! [`World`] (when the C library has it) simulates many circles and walls in memory it owns.
#![deny(missing_docs)]

use core::ffi::{c_int, CStr};
use core::fmt;
use core::mem::{offset_of, size_of};
use core::ops;

pub use circlecollide_sys as sys;

mod batch;
mod cause;
pub use batch::{sweep_many, Columns};

#[cfg(cc_has_world)]
mod world;
#[cfg(cc_has_world)]
pub use world::{
    CastHit, CircleId, CircleProps, ContactEvent, Mode, Other, QueryFilter, RestitutionMix, SegmentId, SegmentProps,
    SensorEvent, Stats, StepOutcome, World, WorldDef, MAX_CAPACITY, MAX_SENSORS, USES_ALL, USES_CLOTH, USES_PROPS,
    USES_ROLLING, USES_SENSORS,
};

// ---- errors ------------------------------------------------------------------------------

/// What kind of error the library reported.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ErrorKind {
    /// `CC_ERR_INVALID`: NaN or infinite input, radius or mass <= 0, restitution outside [0, 1], ...
    Invalid,
    /// `CC_ERR_NOT_FOUND`: a world id not in use.
    NotFound,
    /// `CC_ERR_FULL`: the world holds as many circles (or walls) as it can.
    Full,
    /// `CC_ERR_MEMORY`: the world's memory is too small or misaligned.
    Memory,
    /// `CC_ERR_VERSION`: a struct_size the library does not know.
    Version,
    /// `CC_ERR_RANGE` (1.2): a value beyond a documented limit (a capacity above 2^26, a circle
    /// too wide for the world's period, a step past what the world allows).
    Range,
    /// `CC_ERR_BUSY` (1.2): a change of the world from inside its own callback.
    Busy,
    /// A code newer than these bindings.
    Other,
}

/// An error code of the C library with its cause: the call that failed and, where the binding
/// could tell from the arguments, what was wrong with which of them.
#[derive(Clone, PartialEq, Eq)]
pub struct Error {
    code: c_int,
    call: &'static str,
    detail: Option<String>,
}

impl Error {
    /// The library's code for a call, without a cause named (the library's own text says it).
    pub(crate) fn from_code(code: c_int, call: &'static str) -> Self {
        Error { code, call, detail: None }
    }

    /// An error whose cause the binding names.
    pub(crate) fn new(code: c_int, call: &'static str, detail: impl Into<String>) -> Self {
        Error { code, call, detail: Some(detail.into()) }
    }

    /// The C result code (negative).
    pub fn code(&self) -> i32 {
        self.code
    }

    /// The kind of the code.
    pub fn kind(&self) -> ErrorKind {
        match self.code {
            sys::CC_ERR_INVALID => ErrorKind::Invalid,
            sys::CC_ERR_NOT_FOUND => ErrorKind::NotFound,
            sys::CC_ERR_FULL => ErrorKind::Full,
            sys::CC_ERR_MEMORY => ErrorKind::Memory,
            sys::CC_ERR_VERSION => ErrorKind::Version,
            sys::CC_ERR_RANGE => ErrorKind::Range,
            sys::CC_ERR_BUSY => ErrorKind::Busy,
            _ => ErrorKind::Other,
        }
    }

    /// The function that failed (`"sweep"`, `"World::add_circle"`, ...).
    pub fn call(&self) -> &'static str {
        self.call
    }

    /// What was wrong, with the argument and its value, when the binding could tell
    /// (`"a.radius must be finite and > 0, got NaN"`); `None` when only the code is known.
    pub fn cause(&self) -> Option<&str> {
        self.detail.as_deref()
    }

    /// The library's own text for the code (cc_result_string).
    pub fn message(&self) -> &'static str {
        result_string(self.code)
    }

    fn code_name(&self) -> &'static str {
        let m = self.message();
        m.split(':').next().unwrap_or(m)
    }
}

impl fmt::Debug for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "Error({}: {self})", self.code)
    }
}

impl fmt::Display for Error {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.detail {
            Some(d) => write!(f, "{}: {d} ({})", self.call, self.code_name()),
            None => write!(f, "{}: {}", self.call, self.message()),
        }
    }
}

impl std::error::Error for Error {}

/// A batch call refused (`World::add_circles`; nothing changed): the library's error and the
/// index of the first element refused, `None` when no one element is at fault (a call from a
/// callback, a batch longer than a C int counts).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BatchError {
    /// The library's error (`Invalid` or `Full`).
    pub error: Error,
    /// The index of the element refused.
    pub index: Option<usize>,
}

impl fmt::Display for BatchError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.index {
            Some(i) => write!(f, "element {i}: {}", self.error),
            None => write!(f, "{}", self.error),
        }
    }
}

impl std::error::Error for BatchError {}

/// The result of every fallible call.
pub type Result<T> = core::result::Result<T, Error>;

pub(crate) fn check(code: c_int, call: &'static str) -> Result<c_int> {
    if code < 0 {
        Err(Error::from_code(code, call))
    } else {
        Ok(code)
    }
}

/// The library's static name and explanation of a result code. 0 is both `CC_OK` (an action
/// succeeded) and `CC_MISS` (a test found no contact): its text says both; the safe API never
/// shows it (successes are `Ok`, misses `None`).
pub fn result_string(code: i32) -> &'static str {
    // SAFETY: cc_result_string returns a static NUL-terminated string for every code.
    let p = unsafe { sys::cc_result_string(code) };
    if p.is_null() {
        return "unknown result code";
    }
    unsafe { CStr::from_ptr(p) }.to_str().unwrap_or("unknown result code")
}

/// (major, minor, patch) of the library linked.
pub fn version() -> (u32, u32, u32) {
    let v = unsafe { sys::cc_version() };
    (v >> 16, (v >> 8) & 0xff, v & 0xff)
}

/// True when the library linked has the major version of the declarations (always, when
/// statically linked by this crate's build; the check matters for dynamic loading).
pub fn version_matches() -> bool {
    version().0 == sys::CC_VERSION_MAJOR
}

// ---- value types -------------------------------------------------------------------------

/// A point or vector. `#[repr(C)]`: the same layout as `cc_vec2` (f64) and `cc_vec2f` (f32).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Vec2<T = f64> {
    /// The x coordinate.
    pub x: T,
    /// The y coordinate.
    pub y: T,
}

impl<T> Vec2<T> {
    /// The vector (x, y).
    pub const fn new(x: T, y: T) -> Self {
        Vec2 { x, y }
    }
}

impl<T: Real> Vec2<T> {
    /// The dot product.
    pub fn dot(self, o: Self) -> T {
        self.x * o.x + self.y * o.y
    }

    /// The z component of the cross product, `x * o.y - y * o.x`.
    pub fn cross(self, o: Self) -> T {
        self.x * o.y - self.y * o.x
    }

    /// The Euclidean length, without overflow for large components.
    pub fn length(self) -> T {
        T::hypot(self.x, self.y)
    }

    /// `x * x + y * y`.
    pub fn length_squared(self) -> T {
        self.dot(self)
    }

    /// The unit vector along this one; `None` for the zero vector (and for NaN).
    pub fn normalized(self) -> Option<Self> {
        let n = self.length();
        (n > T::ZERO && n < T::INFINITY).then(|| self / n)
    }
}

impl<T> From<(T, T)> for Vec2<T> {
    fn from((x, y): (T, T)) -> Self {
        Vec2 { x, y }
    }
}

impl<T> From<[T; 2]> for Vec2<T> {
    fn from([x, y]: [T; 2]) -> Self {
        Vec2 { x, y }
    }
}

impl<T> From<Vec2<T>> for (T, T) {
    fn from(v: Vec2<T>) -> Self {
        (v.x, v.y)
    }
}

impl<T: Real> ops::Add for Vec2<T> {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Vec2::new(self.x + o.x, self.y + o.y)
    }
}

impl<T: Real> ops::Sub for Vec2<T> {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        Vec2::new(self.x - o.x, self.y - o.y)
    }
}

impl<T: Real> ops::Neg for Vec2<T> {
    type Output = Self;
    fn neg(self) -> Self {
        Vec2::new(-self.x, -self.y)
    }
}

impl<T: Real> ops::Mul<T> for Vec2<T> {
    type Output = Self;
    fn mul(self, k: T) -> Self {
        Vec2::new(self.x * k, self.y * k)
    }
}

impl<T: Real> ops::Div<T> for Vec2<T> {
    type Output = Self;
    fn div(self, k: T) -> Self {
        Vec2::new(self.x / k, self.y / k)
    }
}

impl<T: Real> ops::AddAssign for Vec2<T> {
    fn add_assign(&mut self, o: Self) {
        *self = *self + o;
    }
}

impl<T: Real> ops::SubAssign for Vec2<T> {
    fn sub_assign(&mut self, o: Self) {
        *self = *self - o;
    }
}

impl<T: Real> ops::MulAssign<T> for Vec2<T> {
    fn mul_assign(&mut self, k: T) {
        *self = *self * k;
    }
}

impl<T: Real> ops::DivAssign<T> for Vec2<T> {
    fn div_assign(&mut self, k: T) {
        *self = *self / k;
    }
}

macro_rules! scalar_times_vec2 {
    ($($t:ty),*) => {$(
        impl ops::Mul<Vec2<$t>> for $t {
            type Output = Vec2<$t>;
            fn mul(self, v: Vec2<$t>) -> Vec2<$t> {
                v * self
            }
        }
    )*};
}
scalar_times_vec2!(f64, f32);

/// A circle moving at constant velocity from `pos` at t = 0. `mass = INFINITY` is immovable.
/// `#[repr(C)]`: the same layout as `cc_circle` / `cc_circlef`. `Circle::default()` is a valid
/// circle: at the origin, at rest, radius 1, mass 1.
#[repr(C)]
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Circle<T = f64> {
    /// Centre at t = 0.
    pub pos: Vec2<T>,
    /// Constant velocity: displacement per unit time.
    pub vel: Vec2<T>,
    /// Finite, > 0.
    pub radius: T,
    /// Finite and > 0, or infinite for an immovable circle.
    pub mass: T,
}

impl<T: Real> Default for Circle<T> {
    fn default() -> Self {
        Circle { pos: Vec2::default(), vel: Vec2::default(), radius: T::ONE, mass: T::ONE }
    }
}

impl<T: Real> Circle<T> {
    /// A circle at rest of mass 1: `Circle::new((0.0, 0.0), 1.0)`; give it a velocity with
    /// [`Circle::with_vel`] and a mass with [`Circle::with_mass`].
    pub fn new(pos: impl Into<Vec2<T>>, radius: T) -> Self {
        Circle { pos: pos.into(), vel: Vec2::default(), radius, mass: T::ONE }
    }

    /// A copy with this velocity.
    pub fn with_vel(self, vel: impl Into<Vec2<T>>) -> Self {
        Circle { vel: vel.into(), ..self }
    }

    /// A copy with this mass.
    pub fn with_mass(self, mass: T) -> Self {
        Circle { mass, ..self }
    }

    /// An immovable obstacle (mass = +infinity).
    pub fn immovable(self) -> Self {
        self.with_mass(T::INFINITY)
    }

    /// A copy moved along its velocity to time t.
    pub fn at(&self, t: T) -> Self {
        Circle { pos: self.pos + self.vel * t, ..*self }
    }

    /// True when the mass is infinite.
    pub fn is_immovable(&self) -> bool {
        self.mass == T::INFINITY
    }
}

/// A static wall from `a` to `b` (a == b: a point obstacle).
#[repr(C)]
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Segment<T = f64> {
    /// One end.
    pub a: Vec2<T>,
    /// The other end.
    pub b: Vec2<T>,
}

impl<T> Segment<T> {
    /// The wall from a to b.
    pub fn new(a: impl Into<Vec2<T>>, b: impl Into<Vec2<T>>) -> Self {
        Segment { a: a.into(), b: b.into() }
    }
}

/// Whether a contact is a touch ahead or an overlap now.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ContactKind {
    /// First touch at `t`, the bodies approaching.
    Hit,
    /// Already overlapping at t = 0 (`depth` > 0).
    Overlap,
}

/// A contact: time, point, unit normal (from a towards b or the wall) and penetration depth.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Contact<T = f64> {
    /// A hit ahead or an overlap at t = 0.
    pub kind: ContactKind,
    /// Time of first contact (0 for an overlap).
    pub t: T,
    /// Contact point at time t.
    pub point: Vec2<T>,
    /// Unit normal at time t from a towards b (or the wall).
    pub normal: Vec2<T>,
    /// Penetration depth: 0 for a hit, > 0 for an overlap.
    pub depth: T,
}

/// The C contact's layout (`cc_contact` / `cc_contactf`).
#[doc(hidden)]
#[repr(C)]
#[derive(Debug, Clone, Copy, Default)]
pub struct RawContact<T> {
    t: T,
    point: Vec2<T>,
    normal: Vec2<T>,
    depth: T,
}

impl<T: Real> RawContact<T> {
    fn of(c: &Contact<T>) -> Self {
        RawContact { t: c.t, point: c.point, normal: c.normal, depth: c.depth }
    }
    fn into_contact(self, code: c_int) -> Option<Contact<T>> {
        let kind = match code {
            sys::CC_HIT => ContactKind::Hit,
            sys::CC_OVERLAP => ContactKind::Overlap,
            _ => return None,
        };
        Some(Contact { kind, t: self.t, point: self.point, normal: self.normal, depth: self.depth })
    }
}

// The generic types are passed to C by pointer cast: prove at compile time that they have the
// C structs' layout field for field.
macro_rules! same_layout {
    ($ours:ty, $c:ty, $($f:ident),*) => {
        const _: () = {
            assert!(size_of::<$ours>() == size_of::<$c>());
            $(assert!(offset_of!($ours, $f) == offset_of!($c, $f));)*
        };
    };
}
same_layout!(Vec2<f64>, sys::cc_vec2, x, y);
same_layout!(Vec2<f32>, sys::cc_vec2f, x, y);
same_layout!(Circle<f64>, sys::cc_circle, pos, vel, radius, mass);
same_layout!(Circle<f32>, sys::cc_circlef, pos, vel, radius, mass);
same_layout!(Segment<f64>, sys::cc_segment, a, b);
same_layout!(Segment<f32>, sys::cc_segmentf, a, b);
same_layout!(RawContact<f64>, sys::cc_contact, t, point, normal, depth);
same_layout!(RawContact<f32>, sys::cc_contactf, t, point, normal, depth);

// ---- precision ---------------------------------------------------------------------------

mod sealed {
    pub trait Sealed {}
    impl Sealed for f64 {}
    impl Sealed for f32 {}
}

/// `f64` or `f32`: selects the C function family (`cc_sweep` or `cc_sweepf`, ...).
pub trait Real:
    Copy
    + PartialOrd
    + fmt::Debug
    + fmt::Display
    + Default
    + ops::Add<Output = Self>
    + ops::Sub<Output = Self>
    + ops::Mul<Output = Self>
    + ops::Div<Output = Self>
    + ops::Neg<Output = Self>
    + sealed::Sealed
    + 'static
{
    /// 0 in this precision.
    const ZERO: Self;
    /// 1 in this precision.
    const ONE: Self;
    /// +infinity in this precision (an immovable circle's mass).
    const INFINITY: Self;
    /// The accepted error of a contact normal's length (the header: 1e-6 in double, 1e-4 in
    /// float).
    const NORMAL_TOLERANCE: Self;
    /// sqrt(x^2 + y^2) without overflow.
    fn hypot(x: Self, y: Self) -> Self;
    /// Finite (not NaN, not infinite).
    fn is_finite(self) -> bool;
    #[doc(hidden)]
    unsafe fn c_detect_static(a: *const Circle<Self>, b: *const Circle<Self>, out: *mut RawContact<Self>) -> c_int;
    #[doc(hidden)]
    unsafe fn c_separate(a: *mut Circle<Self>, b: *mut Circle<Self>) -> c_int;
    #[doc(hidden)]
    unsafe fn c_sweep(a: *const Circle<Self>, b: *const Circle<Self>, t_max: Self, out: *mut RawContact<Self>)
        -> c_int;
    #[doc(hidden)]
    unsafe fn c_sweep_segment(
        c: *const Circle<Self>,
        s: *const Segment<Self>,
        t_max: Self,
        out: *mut RawContact<Self>,
    ) -> c_int;
    #[doc(hidden)]
    unsafe fn c_respond(a: *mut Circle<Self>, b: *mut Circle<Self>, c: *const RawContact<Self>, e: Self) -> c_int;
    #[doc(hidden)]
    unsafe fn c_respond_segment(c: *mut Circle<Self>, k: *const RawContact<Self>, e: Self) -> c_int;
    #[doc(hidden)]
    unsafe fn c_closest_point(p: Vec2<Self>, s: *const Segment<Self>) -> Vec2<Self>;
    #[doc(hidden)]
    unsafe fn c_sweep_rolling(
        a: *const Circle<Self>,
        da: Self,
        b: *const Circle<Self>,
        db: Self,
        t_max: Self,
        out: *mut RawContact<Self>,
    ) -> c_int;
    #[doc(hidden)]
    unsafe fn c_sweep_segment_rolling(
        c: *const Circle<Self>,
        d: Self,
        s: *const Segment<Self>,
        t_max: Self,
        out: *mut RawContact<Self>,
    ) -> c_int;
    #[doc(hidden)]
    unsafe fn c_rolling_advance(c: *mut Circle<Self>, d: Self, t: Self) -> c_int;
}

macro_rules! impl_real {
    ($t:ty, $tol:expr, $vec:ident, $detect:ident, $separate:ident, $sweep:ident, $sweep_seg:ident, $respond:ident, $respond_seg:ident, $closest:ident,
     $sweep_roll:ident, $sweep_seg_roll:ident, $advance:ident) => {
        impl Real for $t {
            const ZERO: Self = 0.0;
            const ONE: Self = 1.0;
            const INFINITY: Self = <$t>::INFINITY;
            const NORMAL_TOLERANCE: Self = $tol;
            fn hypot(x: Self, y: Self) -> Self {
                x.hypot(y)
            }
            fn is_finite(self) -> bool {
                <$t>::is_finite(self)
            }
            unsafe fn c_detect_static(
                a: *const Circle<Self>,
                b: *const Circle<Self>,
                out: *mut RawContact<Self>,
            ) -> c_int {
                sys::$detect(a.cast(), b.cast(), out.cast())
            }
            unsafe fn c_separate(a: *mut Circle<Self>, b: *mut Circle<Self>) -> c_int {
                sys::$separate(a.cast(), b.cast())
            }
            unsafe fn c_sweep(
                a: *const Circle<Self>,
                b: *const Circle<Self>,
                t_max: Self,
                out: *mut RawContact<Self>,
            ) -> c_int {
                sys::$sweep(a.cast(), b.cast(), t_max, out.cast())
            }
            unsafe fn c_sweep_segment(
                c: *const Circle<Self>,
                s: *const Segment<Self>,
                t_max: Self,
                out: *mut RawContact<Self>,
            ) -> c_int {
                sys::$sweep_seg(c.cast(), s.cast(), t_max, out.cast())
            }
            unsafe fn c_respond(
                a: *mut Circle<Self>,
                b: *mut Circle<Self>,
                c: *const RawContact<Self>,
                e: Self,
            ) -> c_int {
                sys::$respond(a.cast(), b.cast(), c.cast(), e)
            }
            unsafe fn c_respond_segment(c: *mut Circle<Self>, k: *const RawContact<Self>, e: Self) -> c_int {
                sys::$respond_seg(c.cast(), k.cast(), e)
            }
            unsafe fn c_closest_point(p: Vec2<Self>, s: *const Segment<Self>) -> Vec2<Self> {
                let r = sys::$closest(sys::$vec { x: p.x, y: p.y }, s.cast());
                Vec2::new(r.x, r.y)
            }
            unsafe fn c_sweep_rolling(
                a: *const Circle<Self>,
                da: Self,
                b: *const Circle<Self>,
                db: Self,
                t_max: Self,
                out: *mut RawContact<Self>,
            ) -> c_int {
                sys::$sweep_roll(a.cast(), da, b.cast(), db, t_max, out.cast())
            }
            unsafe fn c_sweep_segment_rolling(
                c: *const Circle<Self>,
                d: Self,
                s: *const Segment<Self>,
                t_max: Self,
                out: *mut RawContact<Self>,
            ) -> c_int {
                sys::$sweep_seg_roll(c.cast(), d, s.cast(), t_max, out.cast())
            }
            unsafe fn c_rolling_advance(c: *mut Circle<Self>, d: Self, t: Self) -> c_int {
                sys::$advance(c.cast(), d, t)
            }
        }
    };
}
impl_real!(
    f64,
    1e-6,
    cc_vec2,
    cc_detect_static,
    cc_separate,
    cc_sweep,
    cc_sweep_segment,
    cc_respond,
    cc_respond_segment,
    cc_closest_point_on_segment,
    cc_sweep_rolling,
    cc_sweep_segment_rolling,
    cc_rolling_advance
);
impl_real!(
    f32,
    1e-4,
    cc_vec2f,
    cc_detect_staticf,
    cc_separatef,
    cc_sweepf,
    cc_sweep_segmentf,
    cc_respondf,
    cc_respond_segmentf,
    cc_closest_point_on_segmentf,
    cc_sweep_rollingf,
    cc_sweep_segment_rollingf,
    cc_rolling_advancef
);

// ---- pair functions ----------------------------------------------------------------------
// Each calls the library first; only when it refuses are the arguments looked at, to name the
// cause (src/cause.rs).

/// First contact of two circles in t in [0, t_max] (`T::INFINITY` for no limit): `Some` hit or
/// overlap, `None` when they do not touch (moving apart, passing by, or later than t_max).
pub fn sweep<T: Real>(a: &Circle<T>, b: &Circle<T>, t_max: T) -> Result<Option<Contact<T>>> {
    let mut out = RawContact::default();
    // SAFETY: pointers to live values of the C layout (checked above); out is written only on a hit.
    let code = unsafe { T::c_sweep(a, b, t_max, &mut out) };
    if code < 0 {
        return Err(cause::refused(code, "sweep", [cause::circle("a", a), cause::circle("b", b), cause::t_max(t_max)]));
    }
    Ok(out.into_contact(code))
}

/// First contact of a moving circle with a static segment.
pub fn sweep_segment<T: Real>(c: &Circle<T>, s: &Segment<T>, t_max: T) -> Result<Option<Contact<T>>> {
    let mut out = RawContact::default();
    // SAFETY: as in sweep.
    let code = unsafe { T::c_sweep_segment(c, s, t_max, &mut out) };
    if code < 0 {
        return Err(cause::refused(
            code,
            "sweep_segment",
            [cause::circle("c", c), cause::segment(s), cause::t_max(t_max)],
        ));
    }
    Ok(out.into_contact(code))
}

/// First contact of two circles that slow down along their motion at constant decelerations
/// `decel_a`, `decel_b` (>= 0): a circle moving at v (speed s) is at pos + v (t - decel t^2 / (2s))
/// until it stops at s / decel. Zero decelerations give `sweep`'s answer bit for bit; two circles
/// that come to rest exactly touching do not hit.
pub fn sweep_rolling<T: Real>(
    a: &Circle<T>,
    decel_a: T,
    b: &Circle<T>,
    decel_b: T,
    t_max: T,
) -> Result<Option<Contact<T>>> {
    let mut out = RawContact::default();
    // SAFETY: pointers to live values of the C layout; out is written only on a hit.
    let code = unsafe { T::c_sweep_rolling(a, decel_a, b, decel_b, t_max, &mut out) };
    if code < 0 {
        let causes = [
            cause::circle("a", a),
            cause::nonneg_finite("decel_a", decel_a),
            cause::circle("b", b),
            cause::nonneg_finite("decel_b", decel_b),
            cause::t_max(t_max),
        ];
        return Err(cause::refused(code, "sweep_rolling", causes));
    }
    Ok(out.into_contact(code))
}

/// First contact of a decelerating circle with a static segment.
pub fn sweep_segment_rolling<T: Real>(c: &Circle<T>, decel: T, s: &Segment<T>, t_max: T) -> Result<Option<Contact<T>>> {
    let mut out = RawContact::default();
    // SAFETY: as in sweep_rolling.
    let code = unsafe { T::c_sweep_segment_rolling(c, decel, s, t_max, &mut out) };
    if code < 0 {
        let causes =
            [cause::circle("c", c), cause::nonneg_finite("decel", decel), cause::segment(s), cause::t_max(t_max)];
        return Err(cause::refused(code, "sweep_segment_rolling", causes));
    }
    Ok(out.into_contact(code))
}

/// Moves `c` to time `t >= 0` along its decelerating motion (at rest after its stop).
pub fn rolling_advance<T: Real>(c: &mut Circle<T>, decel: T, t: T) -> Result<()> {
    // SAFETY: a live circle of the C layout, changed only on success.
    let code = unsafe { T::c_rolling_advance(c, decel, t) };
    if code < 0 {
        let causes = [cause::circle("c", c), cause::nonneg_finite("decel", decel), cause::nonneg_finite("t", t)];
        return Err(cause::refused(code, "rolling_advance", causes));
    }
    Ok(())
}

/// The overlap of a and b at t = 0 (touching is not overlapping), or `None`.
pub fn detect_static<T: Real>(a: &Circle<T>, b: &Circle<T>) -> Result<Option<Contact<T>>> {
    let mut out = RawContact::default();
    // SAFETY: as in sweep.
    let code = unsafe { T::c_detect_static(a, b, &mut out) };
    if code < 0 {
        return Err(cause::refused(code, "detect_static", [cause::circle("a", a), cause::circle("b", b)]));
    }
    Ok(out.into_contact(code))
}

/// Pushes overlapping circles apart until they touch, by shares inversely proportional to their
/// masses. `Ok(true)` when they overlapped and moved; `Ok(false)` (unchanged) otherwise.
pub fn separate<T: Real>(a: &mut Circle<T>, b: &mut Circle<T>) -> Result<bool> {
    // SAFETY: live circles of the C layout, changed only on success.
    let code = unsafe { T::c_separate(a, b) };
    if code < 0 {
        let causes = [cause::circle("a", a), cause::circle("b", b), cause::not_both_immovable(a, b)];
        return Err(cause::refused(code, "separate", causes));
    }
    Ok(code == sys::CC_OVERLAP)
}

/// Applies the collision impulse along `contact.normal` with restitution e in [0, 1] to the
/// velocities. `Ok(false)` (unchanged) when they are not approaching. Positions are not moved.
pub fn respond<T: Real>(a: &mut Circle<T>, b: &mut Circle<T>, contact: &Contact<T>, restitution: T) -> Result<bool> {
    let raw = RawContact::of(contact);
    // SAFETY: live values of the C layout, the circles changed only on success.
    let code = unsafe { T::c_respond(a, b, &raw, restitution) };
    if code < 0 {
        let causes = [
            cause::circle("a", a),
            cause::circle("b", b),
            cause::restitution(restitution),
            cause::not_both_immovable(a, b),
            cause::unit_normal(contact.normal),
        ];
        return Err(cause::refused(code, "respond", causes));
    }
    Ok(code == sys::CC_HIT)
}

/// Bounces c off an immovable wall whose normal (circle towards wall) is `contact.normal`.
pub fn respond_segment<T: Real>(c: &mut Circle<T>, contact: &Contact<T>, restitution: T) -> Result<bool> {
    let raw = RawContact::of(contact);
    // SAFETY: as in respond.
    let code = unsafe { T::c_respond_segment(c, &raw, restitution) };
    if code < 0 {
        let immovable = c.is_immovable().then(|| {
            "c is immovable (mass INFINITY): an immovable circle cannot respond to an immovable wall".to_string()
        });
        let causes =
            [cause::circle("c", c), cause::restitution(restitution), immovable, cause::unit_normal(contact.normal)];
        return Err(cause::refused(code, "respond_segment", causes));
    }
    Ok(code == sys::CC_HIT)
}

/// The point of s closest to p.
pub fn closest_point_on_segment<T: Real>(p: Vec2<T>, s: &Segment<T>) -> Vec2<T> {
    unsafe { T::c_closest_point(p, s) }
}

// The README's Rust example (extracted by build.rs) is compiled and run as a doc test.
#[cfg(doctest)]
#[doc = include_str!(concat!(env!("OUT_DIR"), "/readme_rust.md"))]
pub struct ReadmeDoctests;
