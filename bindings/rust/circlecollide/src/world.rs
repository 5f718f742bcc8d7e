//! World: many circles and walls simulated by the C library in a buffer this object owns, with
//! an optional contact callback (a closure that may borrow from its caller).

use core::ffi::{c_int, c_void};
use core::marker::PhantomData;
use core::ptr::NonNull;
use std::any::Any;
use std::panic::{catch_unwind, resume_unwind, AssertUnwindSafe};

use crate::{check, sys, Circle, Error, Result, Segment, Vec2};

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

/// The world's settings; `WorldDef::default()` holds the library's defaults.
#[derive(Debug, Clone, PartialEq)]
pub struct WorldDef {
    pub max_circles: usize,
    pub max_segments: usize,
    pub mode: Mode,
    /// Coefficient of restitution of every contact, in [0, 1].
    pub restitution: f64,
    /// Approach speeds below this collide with restitution 0.
    pub rest_speed: f64,
    /// Grid cell size; 0 = derived from the radii.
    pub cell_size: f64,
    /// Cap on events per step.
    pub max_events: u64,
}

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
        }
    }
}

fn c_default() -> sys::cc_world_def {
    let mut d = core::mem::MaybeUninit::<sys::cc_world_def>::zeroed();
    // SAFETY: cc_world_def_init fills every field of the struct it is given.
    unsafe {
        sys::cc_world_def_init(d.as_mut_ptr());
        d.assume_init()
    }
}

/// A circle's id in a world: stable for its lifetime (removed ids may be reused).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct CircleId(pub i32);

/// A wall's id in a world.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct SegmentId(pub i32);

/// What circle `a` hit.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Other {
    Circle(CircleId),
    Wall(SegmentId),
}

/// One impulse the world applied.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactEvent {
    pub a: CircleId,
    pub other: Other,
    /// World time of the contact.
    pub t: f64,
    pub point: Vec2,
    /// Unit normal from a towards the other body.
    pub normal: Vec2,
    /// Magnitude of the normal impulse (mass times velocity).
    pub impulse: f64,
}

/// Counters since the world was made.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Stats {
    pub collisions: u64,
    pub events: u64,
    pub stale_events: u64,
    pub pairs_tested: u64,
    pub cell_crossings: u64,
    pub max_overlap: f64,
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

struct Slot<'cb> {
    f: Callback<'cb>,
    panic: Option<Box<dyn Any + Send>>,
}

/// A simulation in memory it owns. `'cb` is the lifetime of what the contact callback borrows.
pub struct World<'cb> {
    w: NonNull<sys::cc_world>,
    slot: *mut Slot<'cb>, // owned (Box::into_raw); the C world holds it as `user`
    capacity: usize,
    _memory: Vec<Align16>, // the world lives here; a Vec's heap block never moves with World
    _cb: PhantomData<Callback<'cb>>,
}

unsafe extern "C" fn trampoline(event: *const sys::cc_contact_event, user: *mut c_void) {
    // SAFETY: user is the Slot this World registered; the C library calls back only inside
    // cc_world_step, which World::step calls with &mut self, so nothing else touches the slot.
    let slot = unsafe { &mut *(user as *mut Slot<'_>) };
    if slot.panic.is_some() {
        return; // a panic is pending: report no more contacts in this step
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
    if let Err(p) = catch_unwind(AssertUnwindSafe(|| (slot.f)(&event))) {
        slot.panic = Some(p);
    }
}

fn c_int_of(v: usize) -> Result<c_int> {
    c_int::try_from(v).map_err(|_| Error { code: sys::CC_ERR_INVALID })
}

impl World<'static> {
    /// A world without a contact callback.
    pub fn new(def: &WorldDef) -> Result<World<'static>> {
        World::build(def, None)
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
    /// w.add_circle(&Circle::new(Vec2::new(0.0, 0.0), Vec2::new(1.0, 0.0), 1.0)).unwrap();
    /// w.add_circle(&Circle::new(Vec2::new(10.0, 0.0), Vec2::new(-1.0, 0.0), 1.0)).unwrap();
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
        World::build(def, Some(Box::new(on_contact)))
    }

    fn build(def: &WorldDef, cb: Option<Callback<'cb>>) -> Result<World<'cb>> {
        let mut d = c_default();
        d.struct_size = core::mem::size_of::<sys::cc_world_def>();
        d.max_circles = c_int_of(def.max_circles)?;
        d.max_segments = c_int_of(def.max_segments)?;
        d.mode = match def.mode {
            Mode::Exact => sys::CC_MODE_EXACT,
            Mode::Swept => sys::CC_MODE_SWEPT,
            Mode::Discrete => sys::CC_MODE_DISCRETE,
        };
        d.restitution = def.restitution;
        d.rest_speed = def.rest_speed;
        d.cell_size = def.cell_size;
        d.max_events = def.max_events;
        let slot = cb.map_or(core::ptr::null_mut(), |f| Box::into_raw(Box::new(Slot { f, panic: None })));
        // From here on, `slot` must be freed on every path: make the World first.
        let mut world = World { w: NonNull::dangling(), slot, capacity: def.max_circles, _memory: Vec::new(), _cb: PhantomData };
        if !slot.is_null() {
            d.on_contact = Some(trampoline);
            d.user = slot.cast();
        }
        let bytes = unsafe { sys::cc_world_size(&d) };
        if bytes == 0 {
            return Err(Error { code: sys::CC_ERR_INVALID });
        }
        world._memory = vec![Align16([0; 16]); bytes.div_ceil(16)];
        let mut status: c_int = 0;
        // SAFETY: the buffer is 16-byte aligned, at least `bytes` long, and outlives the world.
        let w = unsafe { sys::cc_world_init(world._memory.as_mut_ptr().cast(), bytes, &d, &mut status) };
        world.w = NonNull::new(w).ok_or(Error { code: if status < 0 { status } else { sys::CC_ERR_INVALID } })?;
        Ok(world)
    }

    /// Adds a circle (its state at the current world time).
    pub fn add_circle(&mut self, c: &Circle) -> Result<CircleId> {
        let c: *const Circle = c;
        check(unsafe { sys::cc_world_add_circle(self.w.as_ptr(), c.cast()) }).map(CircleId)
    }

    /// Adds a static wall.
    pub fn add_segment(&mut self, s: &Segment) -> Result<SegmentId> {
        let s: *const Segment = s;
        check(unsafe { sys::cc_world_add_segment(self.w.as_ptr(), s.cast()) }).map(SegmentId)
    }

    pub fn remove_circle(&mut self, id: CircleId) -> Result<()> {
        check(unsafe { sys::cc_world_remove_circle(self.w.as_ptr(), id.0) }).map(drop)
    }

    /// The circle's state now.
    pub fn circle(&self, id: CircleId) -> Result<Circle> {
        let mut out = Circle::default();
        let p: *mut Circle = &mut out;
        check(unsafe { sys::cc_world_get_circle(self.w.as_ptr(), id.0, p.cast()) })?;
        Ok(out)
    }

    /// Replaces the circle's state now.
    pub fn set_circle(&mut self, id: CircleId, c: &Circle) -> Result<()> {
        let c: *const Circle = c;
        check(unsafe { sys::cc_world_set_circle(self.w.as_ptr(), id.0, c.cast()) }).map(drop)
    }

    /// The wall's end points.
    pub fn segment(&self, id: SegmentId) -> Result<Segment> {
        let mut out = Segment::default();
        let p: *mut Segment = &mut out;
        check(unsafe { sys::cc_world_get_segment(self.w.as_ptr(), id.0, p.cast()) })?;
        Ok(out)
    }

    /// Every live circle with its id, in increasing id order.
    pub fn circles(&self) -> Vec<(CircleId, Circle)> {
        let cap = self.capacity.max(1);
        let mut ids = vec![0 as c_int; cap];
        let mut out = vec![Circle::default(); cap];
        let n = unsafe { sys::cc_world_get_circles(self.w.as_ptr(), ids.as_mut_ptr(), out.as_mut_ptr().cast(), cap as c_int) };
        let n = (n.max(0) as usize).min(cap);
        ids.into_iter().zip(out).take(n).map(|(i, c)| (CircleId(i), c)).collect()
    }

    /// Number of live circles.
    pub fn len(&self) -> usize {
        let n = unsafe { sys::cc_world_get_circles(self.w.as_ptr(), core::ptr::null_mut(), core::ptr::null_mut(), 0) };
        n.max(0) as usize
    }

    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Advances world time by dt >= 0. A panic in the contact callback is resumed here, after
    /// the C step has returned (the world stays consistent).
    pub fn step(&mut self, dt: f64) -> Result<StepOutcome> {
        let code = unsafe { sys::cc_world_step(self.w.as_ptr(), dt) };
        if !self.slot.is_null() {
            // SAFETY: the C step has returned; we hold &mut self.
            if let Some(p) = unsafe { (*self.slot).panic.take() } {
                resume_unwind(p);
            }
        }
        Ok(if check(code)? == sys::CC_EVENT_LIMIT { StepOutcome::EventLimit } else { StepOutcome::Done })
    }

    /// Current world time.
    pub fn time(&self) -> f64 {
        unsafe { sys::cc_world_time(self.w.as_ptr()) }
    }

    pub fn stats(&self) -> Stats {
        let mut s = sys::cc_world_stats { struct_size: core::mem::size_of::<sys::cc_world_stats>(), ..Default::default() };
        // cannot fail: the world and the struct are valid
        let _ = unsafe { sys::cc_world_get_stats(self.w.as_ptr(), &mut s) };
        Stats {
            collisions: s.collisions,
            events: s.events,
            stale_events: s.stale_events,
            pairs_tested: s.pairs_tested,
            cell_crossings: s.cell_crossings,
            max_overlap: s.max_overlap,
        }
    }
}

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
