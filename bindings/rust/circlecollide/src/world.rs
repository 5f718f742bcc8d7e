//! World: many circles and walls simulated by the C library in a buffer this object owns, with
//! optional contact and sensor callbacks (closures that may borrow from their caller), per-body
//! properties (restitution, filters, sensors, rolling deceleration), periodic boxes, and queries
//! of the world as it stands (casts, overlap queries, the state hash).

use core::ffi::{c_int, c_void};
use core::marker::PhantomData;
use core::ptr::NonNull;
use std::any::Any;
use std::panic::{catch_unwind, resume_unwind, AssertUnwindSafe};

use crate::{cause, check, sys, BatchError, Circle, ContactKind, Error, Result, Segment, Vec2};

/// The most circles (and walls) a world holds: 2^26 (the header's `cc_world_def`).
pub const MAX_CAPACITY: usize = 1 << 26;

/// How the world advances.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Mode {
    /// Event-driven: every collision in time order, no tunnelling.
    #[default]
    Exact,
    /// Once per step, each pair's first impact in the step.
    Swept,
    /// Move, then find overlaps, push apart and respond.
    Discrete,
}

/// How the restitution of a contact is made from its two sides' (a circle's and the other
/// circle's or the wall's, see [`CircleProps::restitution`] and [`SegmentProps::restitution`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum RestitutionMix {
    /// The smaller of the two (`CC_MIX_MIN`, the library's default).
    #[default]
    Min,
    /// The larger of the two (`CC_MIX_MAX`).
    Max,
    /// Their product (`CC_MIX_PRODUCT`).
    Product,
    /// Their mean (`CC_MIX_MEAN`).
    Mean,
}

impl RestitutionMix {
    fn to_c(self) -> c_int {
        match self {
            RestitutionMix::Min => sys::CC_MIX_MIN,
            RestitutionMix::Max => sys::CC_MIX_MAX,
            RestitutionMix::Product => sys::CC_MIX_PRODUCT,
            RestitutionMix::Mean => sys::CC_MIX_MEAN,
        }
    }
}

/// The world's settings; `WorldDef::default()` holds the library's defaults.
#[derive(Debug, Clone, PartialEq)]
pub struct WorldDef {
    /// Capacity for circles (default 64).
    pub max_circles: usize,
    /// Capacity for walls (default 0: a scene without walls pays nothing).
    pub max_segments: usize,
    /// How the world advances (default [`Mode::Exact`]).
    pub mode: Mode,
    /// The restitution, in [0, 1], that every new circle and wall gets (its properties may then
    /// change it); a contact's is [`WorldDef::restitution_mix`] of its two sides': between two
    /// sides that keep it, this value for `Min`, `Max` and `Mean`, its square for `Product`.
    pub restitution: f64,
    /// Approach speeds below this collide with restitution 0.
    pub rest_speed: f64,
    /// Grid cell size; 0 = derived from the radii.
    pub cell_size: f64,
    /// Cap on events per [`Mode::Exact`] step, or 0 (the default, the C default): the automatic
    /// cap of 32 events per circle of `max_circles` and at least 10,000 (the C header's
    /// "Collapse"), so that a step that jams returns within about 0.2 s for 1,000 circles. A
    /// step at the cap returns [`StepOutcome::EventLimit`]; a long offline step (a whole run in
    /// one call) sets a larger cap or steps again to the same end time.
    pub max_events: u64,
    /// Deceleration (length / time^2, >= 0) of every movable circle rolling on the ground: a
    /// circle of speed s comes to rest after s / rolling_decel along a straight line. The value
    /// a new circle gets ([`CircleProps::rolling_decel`]); 0 (the default) is no friction.
    pub rolling_decel: f64,
    /// How a contact's restitution is made from its two sides' (default [`RestitutionMix::Min`]).
    pub restitution_mix: RestitutionMix,
    /// A component > 0 makes the world wrap along that axis with that period, positions kept in
    /// [0, period); 0 leaves the axis open (default (0, 0)). Each period must be at least twice
    /// the largest circle diameter plus a cell. See [`World::unwrapped`].
    pub period: Vec2,
    /// What the world may use (default [`USES_ALL`]): `USES_*` bits. Its memory holds no more
    /// (0, 1.0's world, is the smallest and fastest), and a call that needs what it left out
    /// (properties other than the defaults, a sensor, `rolling_decel` without
    /// [`USES_ROLLING`]) is refused with `CC_ERR_INVALID`, the world unchanged.
    pub uses: u32,
}

/// [`WorldDef::uses`]: per-body properties (restitution, filters, per-circle deceleration).
pub const USES_PROPS: u32 = sys::CC_USES_PROPS;
/// [`WorldDef::uses`]: sensor circles.
pub const USES_SENSORS: u32 = sys::CC_USES_SENSORS;
/// [`WorldDef::uses`]: `rolling_decel` or per-circle deceleration.
pub const USES_ROLLING: u32 = sys::CC_USES_ROLLING;
/// [`WorldDef::uses`]: spin (cloth).
pub const USES_CLOTH: u32 = sys::CC_USES_CLOTH;
/// [`WorldDef::uses`]: everything (the default).
pub const USES_ALL: u32 = sys::CC_USES_ALL;

impl Default for WorldDef {
    fn default() -> Self {
        let d = c_default();
        WorldDef {
            max_circles: d.max_circles.max(0) as usize,
            max_segments: d.max_segments.max(0) as usize,
            mode: match d.mode {
                sys::CC_MODE_SWEPT => Mode::Swept,
                sys::CC_MODE_DISCRETE => Mode::Discrete,
                _ => Mode::Exact,
            },
            restitution: d.restitution,
            rest_speed: d.rest_speed,
            cell_size: d.cell_size,
            max_events: d.max_events,
            rolling_decel: d.rolling_decel,
            restitution_mix: match d.restitution_mix {
                sys::CC_MIX_MAX => RestitutionMix::Max,
                sys::CC_MIX_PRODUCT => RestitutionMix::Product,
                sys::CC_MIX_MEAN => RestitutionMix::Mean,
                _ => RestitutionMix::Min,
            },
            period: Vec2::new(d.period.x, d.period.y),
            uses: d.uses,
        }
    }
}

fn c_default() -> sys::cc_world_def {
    let mut d = core::mem::MaybeUninit::<sys::cc_world_def>::zeroed();
    // SAFETY: cc_world_def_init_sized fills every field of a def of the size given, ours.
    unsafe {
        sys::cc_world_def_init_sized(d.as_mut_ptr(), core::mem::size_of::<sys::cc_world_def>());
        d.assume_init()
    }
}

/// A circle's id in a world: stable for its lifetime (removed ids may be reused).
/// `#[repr(transparent)]`: a slice of ids is a C `int` array (the queries write into one).
#[repr(transparent)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct CircleId(pub i32);

/// A wall's id in a world.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct SegmentId(pub i32);

/// What circle `a` hit.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Other {
    /// Another circle.
    Circle(CircleId),
    /// A wall.
    Wall(SegmentId),
}

/// One impulse the world applied.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactEvent {
    /// The circle that took the impulse.
    pub a: CircleId,
    /// What it hit.
    pub other: Other,
    /// World time of the contact.
    pub t: f64,
    /// The contact point.
    pub point: Vec2,
    /// Unit normal from a towards the other body.
    pub normal: Vec2,
    /// Magnitude of the normal impulse (mass times velocity).
    pub impulse: f64,
}

/// Counters since the world was made.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Stats {
    /// Impulses applied: circle-circle and circle-wall.
    pub collisions: u64,
    /// Events processed: impacts, cell crossings, stale events.
    pub events: u64,
    /// Predicted events found invalid when their time came.
    pub stale_events: u64,
    /// Pair tests made (sweeps and static tests).
    pub pairs_tested: u64,
    /// Grid cell changes processed (EXACT).
    pub cell_crossings: u64,
    /// The deepest overlap seen.
    pub max_overlap: f64,
    /// Sum over circle-circle impulses of the impulse times the distance between the centres at
    /// contact: in a periodic box of area A, the pressure of a hard-disk fluid of N circles is
    /// P A = N kT + virial / (2 t).
    pub virial: f64,
    /// Sum of the impulses on walls (the force on them, times the time).
    pub wall_impulse: f64,
}

/// A circle begins or stops overlapping a sensor circle (see [`CircleProps::sensor`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SensorEvent {
    /// The sensor circle.
    pub sensor: CircleId,
    /// The other circle (never a sensor).
    pub visitor: CircleId,
    /// `true`: their distance became less than the sum of the radii at `t`; `false`: it is no
    /// longer less.
    pub begin: bool,
    /// World time of the event.
    pub t: f64,
}

/// The properties of a circle in a world. A new circle gets the def's restitution and
/// rolling_decel, category 1, mask `u32::MAX` and is not a sensor; `Default` gives those of a
/// default [`WorldDef`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CircleProps {
    /// Its side of a contact's restitution, in [0, 1] (mixed by [`WorldDef::restitution_mix`]).
    pub restitution: f64,
    /// Its rolling deceleration (>= 0, finite); ignored for an immovable circle.
    pub rolling_decel: f64,
    /// The bits this circle is.
    pub category: u32,
    /// The bits it interacts with: two bodies interact when each one's category meets the
    /// other's mask.
    pub mask: u32,
    /// A sensor takes and gives no impulses, touches no wall, and reports the circles that begin
    /// and stop overlapping it ([`World::with_callbacks`]). At most [`MAX_SENSORS`] at once.
    pub sensor: bool,
}

impl Default for CircleProps {
    fn default() -> Self {
        CircleProps { restitution: 1.0, rolling_decel: 0.0, category: 1, mask: u32::MAX, sensor: false }
    }
}

/// The properties of a wall in a world. A new wall gets the def's restitution, category 1 and
/// mask `u32::MAX`; `Default` gives those of a default [`WorldDef`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SegmentProps {
    /// Its side of a contact's restitution, in [0, 1].
    pub restitution: f64,
    /// The bits this wall is.
    pub category: u32,
    /// The bits it interacts with.
    pub mask: u32,
}

impl Default for SegmentProps {
    fn default() -> Self {
        SegmentProps { restitution: 1.0, category: 1, mask: u32::MAX }
    }
}

/// How many sensors a world holds at once (`CC_MAX_SENSORS`).
pub const MAX_SENSORS: usize = sys::CC_MAX_SENSORS as usize;

/// What a cast ([`World::cast_circle`]) touched first.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CastHit {
    /// [`ContactKind::Hit`]: touched at `t` while approaching; [`ContactKind::Overlap`]: the cast
    /// circle already overlaps `what` at the start (`t` = 0).
    pub kind: ContactKind,
    /// The circle or wall touched.
    pub what: Other,
    /// In [0, 1]: the cast circle's centre is at p + d t at contact.
    pub t: f64,
    /// The contact point.
    pub point: Vec2,
    /// Unit normal from the cast circle towards what it touched.
    pub normal: Vec2,
}

/// Which circles a cast or a query looks at (`cc_query_filter`): those whose category meets
/// `mask`, all but `ignore`. `QueryFilter::default()` is every category, nothing left out; a
/// `u32` is the filter of that mask, so `w.cast_circle(p, d, 0.0, u32::MAX)` reads as before.
///
/// ```
/// use circlecollide::*;
/// let mut w = World::new(&WorldDef::default()).unwrap();
/// let cue = w.add_circle(&Circle::new((0.0, 0.0), 1.0)).unwrap();
/// let ball = w.add_circle(&Circle::new((10.0, 0.0), 1.0)).unwrap();
/// // the cue ball's aiming line starts inside the cue ball: leave it out
/// let hit = w.cast_circle((0.0, 0.0), (20.0, 0.0), 1.0, QueryFilter::default().ignoring(cue)).unwrap().unwrap();
/// assert_eq!((hit.what, hit.t), (Other::Circle(ball), 0.4)); // its centre at x = 8: t = 8 / 20
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub struct QueryFilter {
    /// Only circles (and walls) whose category meets it.
    pub mask: u32,
    /// A circle left out (a cast from a circle of the world leaves that circle out).
    pub ignore: Option<CircleId>,
}

impl Default for QueryFilter {
    fn default() -> Self {
        QueryFilter { mask: u32::MAX, ignore: None }
    }
}

impl From<u32> for QueryFilter {
    fn from(mask: u32) -> Self {
        QueryFilter { mask, ignore: None }
    }
}

impl QueryFilter {
    /// This filter with this mask.
    pub fn with_mask(self, mask: u32) -> Self {
        QueryFilter { mask, ..self }
    }

    /// This filter, leaving circle `id` out.
    pub fn ignoring(self, id: CircleId) -> Self {
        QueryFilter { ignore: Some(id), ..self }
    }

    fn to_c(self) -> sys::cc_query_filter {
        sys::cc_query_filter {
            struct_size: core::mem::size_of::<sys::cc_query_filter>(),
            mask: self.mask,
            ignore: self.ignore.map_or(-1, |id| id.0),
        }
    }
}

/// How a step ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum StepOutcome {
    /// World time advanced by the whole dt.
    Done,
    /// The step stopped at `max_events`; the world is consistent; step again to go on.
    EventLimit,
}

#[repr(C, align(16))]
#[derive(Clone, Copy)]
struct Align16([u8; 16]);

type Callback<'cb> = Box<dyn FnMut(&ContactEvent) + 'cb>;
type SensorCallback<'cb> = Box<dyn FnMut(&SensorEvent) + 'cb>;

struct Slot<'cb> {
    f: Option<Callback<'cb>>,
    sensor: Option<SensorCallback<'cb>>,
    panic: Option<Box<dyn Any + Send>>,
}

/// A simulation in memory it owns. `'cb` is the lifetime of what the callbacks borrow.
pub struct World<'cb> {
    w: NonNull<sys::cc_world>,
    slot: *mut Slot<'cb>, // owned (Box::into_raw); the C world holds it as `user`
    capacity: usize,
    limits: Limits,
    _memory: Vec<Align16>, // the world lives here; a Vec's heap block never moves with World
    _cb: PhantomData<(Callback<'cb>, SensorCallback<'cb>)>,
}

unsafe extern "C" fn trampoline(event: *const sys::cc_contact_event, user: *mut c_void) {
    // SAFETY: user is the Slot this World registered; the C library calls back only inside the
    // calls that World makes with &mut self (step, add, set, set props), so nothing else touches
    // the slot.
    let slot = unsafe { &mut *(user as *mut Slot<'_>) };
    let Some(f) = slot.f.as_mut() else { return };
    if slot.panic.is_some() {
        return; // a panic is pending: report nothing more in this call
    }
    let e = unsafe { *event };
    let event = ContactEvent {
        a: CircleId(e.a),
        other: if e.b >= 0 { Other::Circle(CircleId(e.b)) } else { Other::Wall(SegmentId(e.segment)) },
        t: e.t,
        point: Vec2::new(e.point.x, e.point.y),
        normal: Vec2::new(e.normal.x, e.normal.y),
        impulse: e.impulse,
    };
    // A panic must not unwind through C: keep it and resume it when the step returns.
    if let Err(p) = catch_unwind(AssertUnwindSafe(|| f(&event))) {
        slot.panic = Some(p);
    }
}

unsafe extern "C" fn sensor_trampoline(event: *const sys::cc_sensor_event, user: *mut c_void) {
    // SAFETY: as for `trampoline`: the same slot, reached only from calls made with &mut self.
    let slot = unsafe { &mut *(user as *mut Slot<'_>) };
    let Some(f) = slot.sensor.as_mut() else { return };
    if slot.panic.is_some() {
        return;
    }
    let e = unsafe { *event };
    let event = SensorEvent { sensor: CircleId(e.sensor), visitor: CircleId(e.visitor), begin: e.begin != 0, t: e.t };
    // Same scheme as contacts: the panic is kept and resumed when the C call has returned.
    if let Err(p) = catch_unwind(AssertUnwindSafe(|| f(&event))) {
        slot.panic = Some(p);
    }
}

/// What a world's refusals are judged by: its period, cell size and mode (src/cause.rs's rules
/// for the world: the library names only the code).
#[derive(Debug, Clone, Copy)]
struct Limits {
    period: Vec2,
    cell_size: f64,
    swept: bool,
}

impl Limits {
    /// A refusal of add or set: a valid circle (the causes checked first) refused in a periodic
    /// world is too wide for its period (CC_ERR_RANGE; CC_ERR_INVALID from a 1.1 library).
    fn placing(&self, code: c_int, call: &'static str, c: &Circle) -> Error {
        if let Some(detail) = cause::circle("c", c) {
            return Error::new(code, call, detail);
        }
        if (code == sys::CC_ERR_RANGE || code == sys::CC_ERR_INVALID) && (self.period.x > 0.0 || self.period.y > 0.0) {
            let d = 2.0 * c.radius;
            let need = 2.0 * d + (1.0625 * d).max(self.cell_size);
            return Error::new(
                sys::CC_ERR_RANGE,
                call,
                format!(
                    "a circle of radius {} is too wide for the period ({}, {}): a periodic axis needs at least 2 d + max(1.0625 d, cell_size) = {need}",
                    c.radius, self.period.x, self.period.y
                ),
            );
        }
        Error::from_code(code, call)
    }

    /// A refusal of a step: a dt that is not finite and >= 0, else one of the header's limits.
    fn stepping(&self, code: c_int, dt: f64, now: f64) -> Error {
        const CALL: &str = "World::step";
        if let Some(detail) = cause::nonneg_finite("dt", dt) {
            return Error::new(code, CALL, detail);
        }
        if code != sys::CC_ERR_RANGE && code != sys::CC_ERR_INVALID {
            return Error::from_code(code, CALL);
        }
        let detail = if !(now + dt).is_finite() {
            format!("dt = {dt} at world time {now}: the world time would overflow")
        } else if self.swept && (self.period.x > 0.0 || self.period.y > 0.0) {
            format!(
                "dt = {dt} would carry a circle half a period or more (period ({}, {})), which a periodic SWEPT world cannot sweep: take shorter steps",
                self.period.x, self.period.y
            )
        } else {
            format!("dt = {dt} would carry a circle past 2^1017 (about 1.4e306) in a coordinate")
        };
        Error::new(sys::CC_ERR_RANGE, CALL, detail)
    }
}

/// A capacity: at most [`MAX_CAPACITY`].
fn capacity(v: usize, name: &str) -> Result<c_int> {
    if v > MAX_CAPACITY {
        return Err(Error::new(
            sys::CC_ERR_RANGE,
            "World::new",
            format!("{name} must be at most 2^26 = {MAX_CAPACITY}, got {v}"),
        ));
    }
    Ok(v as c_int)
}

impl World<'static> {
    /// A world without a contact callback.
    pub fn new(def: &WorldDef) -> Result<World<'static>> {
        World::build(def, None, None)
    }
}

impl<'cb> World<'cb> {
    /// A world that calls `on_contact` for every impulse during `step`. The closure may borrow
    /// from the caller for as long as the world lives:
    ///
    /// ```
    /// use circlecollide::*;
    /// let mut hits = Vec::new();
    /// let mut w = World::with_callback(&WorldDef::default(), |e: &ContactEvent| hits.push(e.t)).unwrap();
    /// w.add_circle(&Circle::new(Vec2::new(0.0, 0.0), 1.0).with_vel(Vec2::new(1.0, 0.0))).unwrap();
    /// w.add_circle(&Circle::new(Vec2::new(10.0, 0.0), 1.0).with_vel(Vec2::new(-1.0, 0.0))).unwrap();
    /// w.step(10.0).unwrap();
    /// drop(w); // the borrow of `hits` ends with the world
    /// assert_eq!(hits, [4.0]);
    /// ```
    ///
    /// and the borrow checker refuses to let anything else touch what it borrowed meanwhile:
    ///
    /// ```compile_fail
    /// use circlecollide::*;
    /// let mut hits = Vec::new();
    /// let mut w = World::with_callback(&WorldDef::default(), |e: &ContactEvent| hits.push(e.t)).unwrap();
    /// println!("{}", hits.len()); // error: `hits` is mutably borrowed by the world
    /// w.step(1.0).unwrap();
    /// ```
    pub fn with_callback(def: &WorldDef, on_contact: impl FnMut(&ContactEvent) + 'cb) -> Result<World<'cb>> {
        World::build(def, Some(Box::new(on_contact)), None)
    }

    /// A world that calls `on_contact` for every impulse and `on_sensor` for every sensor event
    /// (a circle beginning or ending an overlap with a sensor circle), in time order, from inside
    /// the calls that cause them (`step`; in EXACT also `add_circle`, `set_circle` and
    /// `set_circle_props`). A panic in either closure is resumed when that call returns (the
    /// world stays consistent; no more events are reported in that call). Two closures may not
    /// both borrow the same thing mutably: share a `RefCell` or a channel when they must.
    ///
    /// ```
    /// use circlecollide::*;
    /// let (mut hits, mut sensed) = (Vec::new(), Vec::new());
    /// let mut w = World::with_callbacks(
    ///     &WorldDef::default(),
    ///     |e: &ContactEvent| hits.push(e.t),
    ///     |e: &SensorEvent| sensed.push((e.begin, e.t)),
    /// )
    /// .unwrap();
    /// let goal = w.add_circle(&Circle::new(Vec2::new(10.0, 0.0), 2.0).immovable()).unwrap();
    /// w.set_circle_props(goal, &CircleProps { sensor: true, ..w.circle_props(goal).unwrap() }).unwrap();
    /// w.add_circle(&Circle::new(Vec2::new(0.0, 0.0), 1.0).with_vel(Vec2::new(1.0, 0.0))).unwrap();
    /// w.step(20.0).unwrap();
    /// drop(w);
    /// // the ball's edge reaches the goal's at x = 7 and leaves it at x = 13, passing through
    /// assert_eq!(sensed, [(true, 7.0), (false, 13.0)]);
    /// assert!(hits.is_empty());
    /// ```
    pub fn with_callbacks(
        def: &WorldDef,
        on_contact: impl FnMut(&ContactEvent) + 'cb,
        on_sensor: impl FnMut(&SensorEvent) + 'cb,
    ) -> Result<World<'cb>> {
        World::build(def, Some(Box::new(on_contact)), Some(Box::new(on_sensor)))
    }

    /// A world with a sensor callback only (see [`World::with_callbacks`]).
    pub fn with_sensor_callback(def: &WorldDef, on_sensor: impl FnMut(&SensorEvent) + 'cb) -> Result<World<'cb>> {
        World::build(def, None, Some(Box::new(on_sensor)))
    }

    fn build(def: &WorldDef, cb: Option<Callback<'cb>>, sensor_cb: Option<SensorCallback<'cb>>) -> Result<World<'cb>> {
        let mut d = c_default();
        d.struct_size = core::mem::size_of::<sys::cc_world_def>();
        d.max_circles = capacity(def.max_circles, "max_circles")?;
        d.max_segments = capacity(def.max_segments, "max_segments")?;
        d.mode = match def.mode {
            Mode::Exact => sys::CC_MODE_EXACT,
            Mode::Swept => sys::CC_MODE_SWEPT,
            Mode::Discrete => sys::CC_MODE_DISCRETE,
        };
        d.restitution = def.restitution;
        d.rest_speed = def.rest_speed;
        d.cell_size = def.cell_size;
        d.max_events = def.max_events;
        d.rolling_decel = def.rolling_decel;
        d.restitution_mix = def.restitution_mix.to_c();
        d.period = sys::cc_vec2 { x: def.period.x, y: def.period.y };
        d.uses = def.uses;
        let (has_contact, has_sensor) = (cb.is_some(), sensor_cb.is_some());
        let slot = if has_contact || has_sensor {
            Box::into_raw(Box::new(Slot { f: cb, sensor: sensor_cb, panic: None }))
        } else {
            core::ptr::null_mut()
        };
        // From here on, `slot` must be freed on every path: make the World first.
        let limits = Limits { period: def.period, cell_size: def.cell_size, swept: def.mode == Mode::Swept };
        let mut world = World {
            w: NonNull::dangling(),
            slot,
            capacity: def.max_circles,
            limits,
            _memory: Vec::new(),
            _cb: PhantomData,
        };
        if has_contact {
            d.on_contact = Some(trampoline);
        }
        if has_sensor {
            d.on_sensor = Some(sensor_trampoline);
        }
        if !slot.is_null() {
            d.user = slot.cast();
        }
        let bytes = unsafe { sys::cc_world_size(&d) };
        if bytes == 0 {
            // the library's code for the def, which its size cannot say
            let mut status: c_int = 0;
            let _ = unsafe { sys::cc_world_init(core::ptr::null_mut(), 0, &d, &mut status) };
            return Err(def_refusal(status, def));
        }
        world._memory = vec![Align16([0; 16]); bytes.div_ceil(16)];
        let mut status: c_int = 0;
        // SAFETY: the buffer is 16-byte aligned, at least `bytes` long, and outlives the world.
        let w = unsafe { sys::cc_world_init(world._memory.as_mut_ptr().cast(), bytes, &d, &mut status) };
        world.w = NonNull::new(w).ok_or_else(|| def_refusal(status, def))?;
        Ok(world)
    }

    /// Adds a circle (its state at the current world time). In EXACT, a circle added on top of
    /// others is pushed apart at once (the contact callback may run); in every mode and state a
    /// circle that lands in a sensor begins at once (the sensor callback runs); a panic there is
    /// resumed before this returns.
    pub fn add_circle(&mut self, c: &Circle) -> Result<CircleId> {
        let p: *const Circle = c;
        let code = unsafe { sys::cc_world_add_circle(self.w.as_ptr(), p.cast()) };
        self.resume_panic();
        if code < 0 {
            return Err(self.limits.placing(code, "World::add_circle", c));
        }
        Ok(CircleId(code))
    }

    /// Adds the circles in order, in one C call (`cc_world_add_circles`): the ids and the world's
    /// state are those of an `add_circle` per circle. Every circle is checked before any is
    /// added: when one is refused (invalid, too wide for the period, or the world full when it
    /// comes) nothing is added, and the error names its index. Not from a callback (a refusal
    /// with no index). In EXACT an added circle that overlaps another may fire the contact
    /// callback, as `add_circle`'s does.
    pub fn add_circles(&mut self, circles: &[Circle]) -> core::result::Result<Vec<CircleId>, BatchError> {
        let n = c_int::try_from(circles.len()).map_err(|_| BatchError {
            error: Error::new(sys::CC_ERR_INVALID, "World::add_circles", "more circles than a C int counts"),
            index: None,
        })?;
        let mut ids = vec![0 as c_int; circles.len()];
        let mut failed: c_int = -1;
        let code = unsafe {
            sys::cc_world_add_circles(self.w.as_ptr(), circles.as_ptr().cast(), n, ids.as_mut_ptr(), &mut failed)
        };
        self.resume_panic();
        match check(code, "World::add_circles") {
            Ok(_) => Ok(ids.into_iter().map(CircleId).collect()),
            Err(error) => Err(BatchError { error, index: usize::try_from(failed).ok() }),
        }
    }

    /// Adds a static wall.
    pub fn add_segment(&mut self, s: &Segment) -> Result<SegmentId> {
        let p: *const Segment = s;
        let code = unsafe { sys::cc_world_add_segment(self.w.as_ptr(), p.cast()) };
        if code < 0 {
            return Err(cause::refused(code, "World::add_segment", [cause::segment(s)]));
        }
        Ok(SegmentId(code))
    }

    /// Removes a circle (a pocketed ball); other ids are unchanged. Not from a callback.
    pub fn remove_circle(&mut self, id: CircleId) -> Result<()> {
        check(unsafe { sys::cc_world_remove_circle(self.w.as_ptr(), id.0) }, "World::remove_circle").map(drop)
    }

    /// The circle's state now.
    pub fn circle(&self, id: CircleId) -> Result<Circle> {
        let mut out = Circle::default();
        let p: *mut Circle = &mut out;
        check(unsafe { sys::cc_world_get_circle(self.w.as_ptr(), id.0, p.cast()) }, "World::circle")?;
        Ok(out)
    }

    /// Replaces the circle's state now (callbacks as for [`World::add_circle`]).
    pub fn set_circle(&mut self, id: CircleId, c: &Circle) -> Result<()> {
        let p: *const Circle = c;
        let code = unsafe { sys::cc_world_set_circle(self.w.as_ptr(), id.0, p.cast()) };
        self.resume_panic();
        if code < 0 {
            return Err(self.limits.placing(code, "World::set_circle", c));
        }
        Ok(())
    }

    /// The wall's end points.
    pub fn segment(&self, id: SegmentId) -> Result<Segment> {
        let mut out = Segment::default();
        let p: *mut Segment = &mut out;
        check(unsafe { sys::cc_world_get_segment(self.w.as_ptr(), id.0, p.cast()) }, "World::segment")?;
        Ok(out)
    }

    /// Every live circle with its id, in increasing id order.
    pub fn circles(&self) -> Vec<(CircleId, Circle)> {
        let cap = self.capacity.max(1);
        let mut ids = vec![0 as c_int; cap];
        let mut out = vec![Circle::default(); cap];
        let n = unsafe {
            sys::cc_world_get_circles(self.w.as_ptr(), ids.as_mut_ptr(), out.as_mut_ptr().cast(), cap as c_int)
        };
        let n = (n.max(0) as usize).min(cap);
        ids.into_iter().zip(out).take(n).map(|(i, c)| (CircleId(i), c)).collect()
    }

    /// Every live circle's position without the periods taken off (`unwrapped` for each), in
    /// increasing id order, in one C call (`cc_world_get_unwrapped_all`).
    pub fn unwrapped_all(&self) -> Vec<(CircleId, Vec2)> {
        let cap = self.capacity.max(1);
        let mut ids = vec![0 as c_int; cap];
        let mut out = vec![sys::cc_vec2::default(); cap];
        let n = unsafe {
            sys::cc_world_get_unwrapped_all(self.w.as_ptr(), ids.as_mut_ptr(), out.as_mut_ptr(), cap as c_int)
        };
        let n = (n.max(0) as usize).min(cap);
        ids.into_iter().zip(out).take(n).map(|(i, p)| (CircleId(i), Vec2::new(p.x, p.y))).collect()
    }

    /// Number of live circles.
    pub fn len(&self) -> usize {
        let n = unsafe { sys::cc_world_get_circles(self.w.as_ptr(), core::ptr::null_mut(), core::ptr::null_mut(), 0) };
        n.max(0) as usize
    }

    /// True when no circle lives in the world.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Advances world time by dt >= 0. A panic in the contact callback is resumed here, after
    /// the C step has returned (the world stays consistent).
    pub fn step(&mut self, dt: f64) -> Result<StepOutcome> {
        let code = unsafe { sys::cc_world_step(self.w.as_ptr(), dt) };
        self.resume_panic();
        if code < 0 {
            return Err(self.limits.stepping(code, dt, self.time()));
        }
        Ok(if code == sys::CC_EVENT_LIMIT { StepOutcome::EventLimit } else { StepOutcome::Done })
    }

    /// Resumes a panic that a callback raised during the C call that just returned.
    fn resume_panic(&mut self) {
        if !self.slot.is_null() {
            // SAFETY: the C call has returned; we hold &mut self.
            if let Some(p) = unsafe { (*self.slot).panic.take() } {
                resume_unwind(p);
            }
        }
    }

    /// Current world time.
    pub fn time(&self) -> f64 {
        unsafe { sys::cc_world_time(self.w.as_ptr()) }
    }

    /// The counters since the world was made.
    pub fn stats(&self) -> Stats {
        let mut s =
            sys::cc_world_stats { struct_size: core::mem::size_of::<sys::cc_world_stats>(), ..Default::default() };
        // cannot fail: the world and the struct are valid
        let _ = unsafe { sys::cc_world_get_stats(self.w.as_ptr(), &mut s) };
        Stats {
            collisions: s.collisions,
            events: s.events,
            stale_events: s.stale_events,
            pairs_tested: s.pairs_tested,
            cell_crossings: s.cell_crossings,
            max_overlap: s.max_overlap,
            virial: s.virial,
            wall_impulse: s.wall_impulse,
        }
    }

    /// The position of a circle without the periods taken off (see [`WorldDef::period`]): where
    /// it would be had the world not wrapped, for displacements over many periods. Along an
    /// open axis, its position.
    pub fn unwrapped(&self, id: CircleId) -> Result<Vec2> {
        let mut out = sys::cc_vec2::default();
        check(unsafe { sys::cc_world_get_unwrapped(self.w.as_ptr(), id.0, &mut out) }, "World::unwrapped")?;
        Ok(Vec2::new(out.x, out.y))
    }

    /// The circle's properties.
    pub fn circle_props(&self, id: CircleId) -> Result<CircleProps> {
        let mut p =
            sys::cc_circle_props { struct_size: core::mem::size_of::<sys::cc_circle_props>(), ..Default::default() };
        check(unsafe { sys::cc_world_get_circle_props(self.w.as_ptr(), id.0, &mut p) }, "World::circle_props")?;
        Ok(CircleProps {
            restitution: p.restitution,
            rolling_decel: p.rolling_decel,
            category: p.category,
            mask: p.mask,
            sensor: p.sensor != 0,
        })
    }

    /// Sets the circle's properties at the current world time. A value out of range is
    /// `Invalid` and changes nothing; making the [`MAX_SENSORS`] + 1st sensor is `Full`. In
    /// EXACT a change may fire the callbacks at once (a pair that now interacts while
    /// overlapping is pushed apart; a circle that now overlaps a sensor, or no longer does, gets
    /// its event); a panic there is resumed before this returns.
    pub fn set_circle_props(&mut self, id: CircleId, props: &CircleProps) -> Result<()> {
        let p = sys::cc_circle_props {
            struct_size: core::mem::size_of::<sys::cc_circle_props>(),
            restitution: props.restitution,
            rolling_decel: props.rolling_decel,
            category: props.category,
            mask: props.mask,
            sensor: props.sensor as c_int,
        };
        let code = unsafe { sys::cc_world_set_circle_props(self.w.as_ptr(), id.0, &p) };
        self.resume_panic();
        if code < 0 {
            let causes =
                [cause::restitution(props.restitution), cause::nonneg_finite("rolling_decel", props.rolling_decel)];
            return Err(cause::refused(code, "World::set_circle_props", causes));
        }
        Ok(())
    }

    /// The wall's properties.
    pub fn segment_props(&self, id: SegmentId) -> Result<SegmentProps> {
        let mut p =
            sys::cc_segment_props { struct_size: core::mem::size_of::<sys::cc_segment_props>(), ..Default::default() };
        check(unsafe { sys::cc_world_get_segment_props(self.w.as_ptr(), id.0, &mut p) }, "World::segment_props")?;
        Ok(SegmentProps { restitution: p.restitution, category: p.category, mask: p.mask })
    }

    /// Sets the wall's properties (a value out of range is `Invalid` and changes nothing).
    pub fn set_segment_props(&mut self, id: SegmentId, props: &SegmentProps) -> Result<()> {
        let p = sys::cc_segment_props {
            struct_size: core::mem::size_of::<sys::cc_segment_props>(),
            restitution: props.restitution,
            category: props.category,
            mask: props.mask,
        };
        let code = unsafe { sys::cc_world_set_segment_props(self.w.as_ptr(), id.0, &p) };
        self.resume_panic();
        if code < 0 {
            return Err(cause::refused(code, "World::set_segment_props", [cause::restitution(props.restitution)]));
        }
        Ok(())
    }

    /// The first circle or wall that a circle of `radius` (finite, >= 0; 0 casts a ray) moving
    /// from `p` to `p + d` touches, the world held still at its current time: the earliest t in
    /// [0, 1] at which it touches one while approaching. Only bodies the `filter` admits (a
    /// [`QueryFilter`], or a `u32` mask): whose category meets its mask, not the circle it
    /// ignores; sensors are skipped. `Ok(None)` when it touches nothing; an overlap at `p` is a
    /// hit of kind [`ContactKind::Overlap`] at t = 0. Equal times go to the lowest circle id,
    /// then the lowest wall id. A cue ball's aiming line (ignoring the cue ball): the object
    /// ball moves off along `normal`. The arguments come in Python's order, `(p, d, radius)`.
    pub fn cast_circle(
        &self,
        p: impl Into<Vec2>,
        d: impl Into<Vec2>,
        radius: f64,
        filter: impl Into<QueryFilter>,
    ) -> Result<Option<CastHit>> {
        let (p, d, f) = (p.into(), d.into(), filter.into().to_c());
        let mut out = sys::cc_cast_hit::default();
        // SAFETY: the world is live, the filter and out are ours.
        let code = unsafe {
            sys::cc_world_cast_circle_filtered(
                self.w.as_ptr(),
                sys::cc_vec2 { x: p.x, y: p.y },
                radius,
                sys::cc_vec2 { x: d.x, y: d.y },
                &f,
                &mut out,
            )
        };
        if code < 0 {
            let finite = |name: &str, v: Vec2| {
                (!(v.x.is_finite() && v.y.is_finite()))
                    .then(|| format!("{name} must be finite, got ({}, {})", v.x, v.y))
            };
            return Err(cause::refused(
                code,
                "World::cast_circle",
                [finite("p", p), finite("d", d), cause::nonneg_finite("radius", radius)],
            ));
        }
        let kind = match code {
            sys::CC_HIT => ContactKind::Hit,
            sys::CC_OVERLAP => ContactKind::Overlap,
            _ => return Ok(None),
        };
        Ok(Some(CastHit {
            kind,
            what: if out.circle >= 0 {
                Other::Circle(CircleId(out.circle))
            } else {
                Other::Wall(SegmentId(out.segment))
            },
            t: out.t,
            point: Vec2::new(out.point.x, out.point.y),
            normal: Vec2::new(out.normal.x, out.normal.y),
        }))
    }

    /// The circles that overlap the disc of centre `c` and `radius` (>= 0, finite): their
    /// distance less than the sum of the radii (radius 0: the circles whose interior holds c),
    /// that the `filter` admits (category meets its mask, not the circle it ignores), sensors
    /// included. Writes the first `ids.len()` of them in increasing id order into `ids` and
    /// returns how many there are (which may be more).
    pub fn query_circle(
        &self,
        c: impl Into<Vec2>,
        radius: f64,
        filter: impl Into<QueryFilter>,
        ids: &mut [CircleId],
    ) -> Result<usize> {
        let (c, f) = (c.into(), filter.into().to_c());
        let cap = c_int::try_from(ids.len()).unwrap_or(c_int::MAX);
        // SAFETY: CircleId is repr(transparent) over i32 = c_int; the C side writes at most cap.
        let n = unsafe {
            sys::cc_world_query_circle_filtered(
                self.w.as_ptr(),
                sys::cc_vec2 { x: c.x, y: c.y },
                radius,
                &f,
                ids.as_mut_ptr().cast(),
                cap,
            )
        };
        if n < 0 {
            let centre =
                (!(c.x.is_finite() && c.y.is_finite())).then(|| format!("c must be finite, got ({}, {})", c.x, c.y));
            return Err(cause::refused(n, "World::query_circle", [centre, cause::nonneg_finite("radius", radius)]));
        }
        Ok(n as usize)
    }

    /// [`World::query_circle`] into a new `Vec` holding them all.
    pub fn query_circle_vec(
        &self,
        c: impl Into<Vec2>,
        radius: f64,
        filter: impl Into<QueryFilter>,
    ) -> Result<Vec<CircleId>> {
        let (c, f) = (c.into(), filter.into());
        collect_ids(|ids| self.query_circle(c, radius, f, ids))
    }

    /// The circles that meet the closed box [lo, hi] (the closed disc against the box, exactly:
    /// a circle whose distance from the box equals its radius counts), that the `filter` admits,
    /// sensors included; lo <= hi in both coordinates, all finite. Written and counted as by
    /// [`World::query_circle`].
    pub fn query_box(
        &self,
        lo: impl Into<Vec2>,
        hi: impl Into<Vec2>,
        filter: impl Into<QueryFilter>,
        ids: &mut [CircleId],
    ) -> Result<usize> {
        let (lo, hi, f) = (lo.into(), hi.into(), filter.into().to_c());
        let cap = c_int::try_from(ids.len()).unwrap_or(c_int::MAX);
        // SAFETY: as in query_circle.
        let n = unsafe {
            sys::cc_world_query_box_filtered(
                self.w.as_ptr(),
                sys::cc_vec2 { x: lo.x, y: lo.y },
                sys::cc_vec2 { x: hi.x, y: hi.y },
                &f,
                ids.as_mut_ptr().cast(),
                cap,
            )
        };
        if n < 0 {
            let finite = (!(lo.x.is_finite() && lo.y.is_finite() && hi.x.is_finite() && hi.y.is_finite()))
                .then(|| format!("lo and hi must be finite, got ({}, {}) and ({}, {})", lo.x, lo.y, hi.x, hi.y));
            let order = (!(lo.x <= hi.x && lo.y <= hi.y)).then(|| {
                format!(
                    "lo must be <= hi in both coordinates, got lo = ({}, {}), hi = ({}, {})",
                    lo.x, lo.y, hi.x, hi.y
                )
            });
            return Err(cause::refused(n, "World::query_box", [finite, order]));
        }
        Ok(n as usize)
    }

    /// [`World::query_box`] into a new `Vec` holding them all.
    pub fn query_box_vec(
        &self,
        lo: impl Into<Vec2>,
        hi: impl Into<Vec2>,
        filter: impl Into<QueryFilter>,
    ) -> Result<Vec<CircleId>> {
        let (lo, hi, f) = (lo.into(), hi.into(), filter.into());
        collect_ids(|ids| self.query_box(lo, hi, f, ids))
    }

    /// A 64-bit hash of the simulation state: the time, every live circle (id, state as
    /// [`World::circle`] gives it, properties, sensor overlaps), every wall and its properties,
    /// and the def's settings (not the callbacks). Equal states give equal hashes (on another
    /// world fed the same calls, on another machine); a state one bit apart gives another. For
    /// replays and lock-step networking: compare hashes to find where two runs part.
    pub fn hash(&self) -> u64 {
        unsafe { sys::cc_world_hash(self.w.as_ptr()) }
    }
}

impl World<'_> {
    /// An independent world in the same state: a copy of the C world's memory (which stores no
    /// address into itself, so a copy of its bytes is a valid world). Stepping the copy gives,
    /// bit for bit, what stepping `self` gives.
    ///
    /// A world made with callbacks is refused (`ErrorKind::Invalid`): its memory holds the
    /// pointer to this world's closures (boxed `FnMut`s, which cannot be cloned), so a copy
    /// would call back into `self`'s. `Clone` is not implemented for that reason.
    ///
    /// ```
    /// use circlecollide::*;
    /// let mut w = World::new(&WorldDef::default()).unwrap();
    /// w.add_circle(&Circle::new(Vec2::new(0.0, 0.0), 1.0).with_vel(Vec2::new(1.0, 0.0))).unwrap();
    /// w.add_circle(&Circle::new(Vec2::new(10.0, 0.0), 1.0).with_vel(Vec2::new(-1.0, 0.0))).unwrap();
    /// let mut c = w.try_clone().unwrap();
    /// w.step(10.0).unwrap();
    /// assert_ne!(c.hash(), w.hash()); // the copy did not move
    /// c.step(10.0).unwrap();
    /// assert_eq!(c.hash(), w.hash());
    /// ```
    pub fn try_clone(&self) -> Result<World<'static>> {
        if !self.slot.is_null() {
            return Err(Error::new(
                sys::CC_ERR_INVALID,
                "World::try_clone",
                "a world made with callbacks cannot be cloned: its memory points at this world's closures",
            ));
        }
        let memory = self._memory.clone();
        // the world starts at the buffer's start (cc_world_init returns its memory argument)
        let offset = self.w.as_ptr() as usize - self._memory.as_ptr() as usize;
        let mut world = World {
            w: NonNull::dangling(),
            slot: core::ptr::null_mut(),
            capacity: self.capacity,
            limits: self.limits,
            _memory: memory,
            _cb: PhantomData,
        };
        // SAFETY: offset is within the buffer (the same as in self's, of the same length), and the
        // new buffer is 16-byte aligned like the old one.
        let p = unsafe { world._memory.as_mut_ptr().cast::<u8>().add(offset) };
        world.w = NonNull::new(p.cast()).ok_or_else(|| Error::from_code(sys::CC_ERR_MEMORY, "World::try_clone"))?;
        Ok(world)
    }
}

/// A def the library refused: named where the binding can tell why (its values against the
/// header's rules), else the library's code.
fn def_refusal(status: c_int, def: &WorldDef) -> Error {
    const CALL: &str = "World::new";
    let code = if status < 0 { status } else { sys::CC_ERR_INVALID };
    let causes = [
        cause::restitution(def.restitution),
        cause::nonneg_finite("rest_speed", def.rest_speed),
        cause::nonneg_finite("cell_size", def.cell_size),
        cause::nonneg_finite("rolling_decel", def.rolling_decel),
        cause::nonneg_finite("period.x", def.period.x),
        cause::nonneg_finite("period.y", def.period.y),
        (def.uses > USES_ALL).then(|| format!("uses = {:#x} has bits beyond USES_ALL", def.uses)),
        (def.rolling_decel > 0.0 && def.uses & USES_ROLLING == 0)
            .then(|| "rolling_decel > 0 needs uses to include USES_ROLLING".to_string()),
    ];
    if let Some(detail) = causes.into_iter().flatten().next() {
        return Error::new(code, CALL, detail);
    }
    for (p, axis) in [(def.period.x, "x"), (def.period.y, "y")] {
        if p > 0.0 && p <= def.cell_size {
            return Error::new(
                sys::CC_ERR_RANGE,
                CALL,
                format!("period.{axis} = {p} must be wider than cell_size = {}", def.cell_size),
            );
        }
    }
    Error::from_code(code, CALL)
}

/// Runs a query into a buffer, growing it to the count the query reports.
fn collect_ids(mut query: impl FnMut(&mut [CircleId]) -> Result<usize>) -> Result<Vec<CircleId>> {
    let mut ids = vec![CircleId(-1); 32];
    let n = query(&mut ids)?;
    if n > ids.len() {
        ids.resize(n, CircleId(-1));
        let again = query(&mut ids)?;
        debug_assert_eq!(again, n, "the world did not change between the two calls");
    }
    ids.truncate(n);
    Ok(ids)
}

const _: () = assert!(core::mem::size_of::<CircleId>() == core::mem::size_of::<c_int>());

impl Drop for World<'_> {
    fn drop(&mut self) {
        if !self.slot.is_null() {
            // SAFETY: made by Box::into_raw in build; the world (and its memory) dies with us.
            drop(unsafe { Box::from_raw(self.slot) });
        }
    }
}

impl core::fmt::Debug for World<'_> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("World").field("time", &self.time()).field("circles", &self.len()).finish()
    }
}
