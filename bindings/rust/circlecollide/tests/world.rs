//! World through the safe API: hand-derived scenes, errors, the closure callback, panics.
#![cfg(cc_has_world)]

use circlecollide::*;

fn v(x: f64, y: f64) -> Vec2 {
    Vec2::new(x, y)
}

fn def(max_circles: usize, max_segments: usize) -> WorldDef {
    WorldDef { max_circles, max_segments, ..WorldDef::default() }
}

#[test]
fn bounce_off_a_wall_with_a_borrowing_callback() {
    // radius 1 at x = 0 moving +x at speed 1, wall at x = 5: contact at t = 4, back to x = -2 at t = 10
    let mut events = Vec::new();
    {
        let mut w = World::with_callback(&def(2, 1), |e: &ContactEvent| events.push(*e)).unwrap();
        let id = w.add_circle(&Circle::new(v(0.0, 0.0), 1.0).with_vel(v(1.0, 0.0))).unwrap();
        let wall = w.add_segment(&Segment::new(v(5.0, -10.0), v(5.0, 10.0))).unwrap();
        assert_eq!(w.step(10.0).unwrap(), StepOutcome::Done);
        let c = w.circle(id).unwrap();
        assert!((c.pos.x + 2.0).abs() < 1e-12 && c.vel == v(-1.0, 0.0), "{c:?}");
        assert!((w.time() - 10.0).abs() < 1e-12);
        assert_eq!(w.stats().collisions, 1);
        assert_eq!(w.segment(wall).unwrap(), Segment::new(v(5.0, -10.0), v(5.0, 10.0)));
    }
    assert_eq!(events.len(), 1);
    let e = events[0];
    // mass 1, speed 1 reversed: impulse 2, normal towards the wall
    assert_eq!((e.a, e.other), (CircleId(0), Other::Wall(SegmentId(0))));
    assert!((e.t - 4.0).abs() < 1e-12 && (e.impulse - 2.0).abs() < 1e-12 && e.normal == v(1.0, 0.0));
}

#[test]
fn head_on_pair_swaps() {
    let mut w = World::new(&def(2, 0)).unwrap();
    let a = w.add_circle(&Circle::new(v(0.0, 0.0), 1.0).with_vel(v(1.0, 0.0))).unwrap();
    let b = w.add_circle(&Circle::new(v(10.0, 0.0), 1.0).with_vel(v(-1.0, 0.0))).unwrap();
    let (m0, m1) = (w.circle(a).unwrap().mass, w.circle(b).unwrap().mass);
    w.step(6.0).unwrap(); // contact at t = 4, 2 more units apart: a at 2, b at 8
    let p = m0 * w.circle(a).unwrap().vel.x + m1 * w.circle(b).unwrap().vel.x;
    assert_eq!(p, 0.0, "momentum 1 - 1 = 0 stays 0");
    let all = w.circles();
    assert_eq!(all.iter().map(|p| p.0).collect::<Vec<_>>(), vec![a, b]);
    assert!((all[0].1.pos.x - 2.0).abs() < 1e-12 && (all[1].1.pos.x - 8.0).abs() < 1e-12);
    assert_eq!(w.len(), 2);
}

#[test]
fn errors() {
    let mut w = World::new(&def(1, 0)).unwrap();
    let a = w.add_circle(&Circle::new(v(0.0, 0.0), 1.0)).unwrap();
    assert_eq!(w.add_circle(&Circle::new(v(5.0, 0.0), 1.0)).unwrap_err().kind(), ErrorKind::Full);
    assert_eq!(w.add_segment(&Segment::default()).unwrap_err().kind(), ErrorKind::Full);
    assert_eq!(w.step(-1.0).unwrap_err().kind(), ErrorKind::Invalid);
    assert_eq!(w.step(f64::NAN).unwrap_err().kind(), ErrorKind::Invalid);
    w.remove_circle(a).unwrap();
    assert_eq!(w.circle(a).unwrap_err().kind(), ErrorKind::NotFound);
    assert!(w.circle(a).unwrap_err().to_string().starts_with("World::circle: CC_ERR_NOT_FOUND"));
    assert_eq!(w.add_circle(&Circle::new(v(0.0, 0.0), -1.0)).unwrap_err().kind(), ErrorKind::Invalid);
    assert!(World::new(&WorldDef { restitution: 2.0, ..def(1, 0) }).is_err());
}

#[test]
fn a_panic_in_the_callback_reaches_the_caller_after_the_step() {
    let mut w = World::with_callback(&def(1, 1), |_: &ContactEvent| panic!("from the callback")).unwrap();
    w.add_circle(&Circle::new(v(0.0, 0.0), 1.0).with_vel(v(1.0, 0.0))).unwrap();
    w.add_segment(&Segment::new(v(5.0, -10.0), v(5.0, 10.0))).unwrap();
    let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| w.step(10.0)));
    assert!(r.is_err());
    assert!((w.time() - 10.0).abs() < 1e-12, "the C step completed");
    w.step(1.0).unwrap();
}

#[test]
fn exact_mode_in_a_box_conserves_energy() {
    // 12 circles on a grid 4 apart (radius 1) inside walls around [-3, 16] x [-3, 12], varied
    // velocities and masses, e = 1: walls take momentum but no energy
    let mut w = World::new(&def(12, 4)).unwrap();
    let (x0, x1, y0, y1) = (-3.0, 16.0, -3.0, 12.0);
    for (p, q) in [((x0, y0), (x1, y0)), ((x1, y0), (x1, y1)), ((x1, y1), (x0, y1)), ((x0, y1), (x0, y0))] {
        w.add_segment(&Segment::new(v(p.0, p.1), v(q.0, q.1))).unwrap();
    }
    for i in 0..12 {
        let vel = v(((i * 7) % 5) as f64 - 2.0, ((i * 3) % 7) as f64 - 3.0);
        w.add_circle(
            &Circle::new(v(4.0 * (i % 4) as f64, 4.0 * (i / 4) as f64), 1.0)
                .with_vel(vel)
                .with_mass(1.0 + (i % 3) as f64),
        )
        .unwrap();
    }
    let energy = |w: &World| {
        w.circles().iter().map(|(_, c)| 0.5 * c.mass * (c.vel.x * c.vel.x + c.vel.y * c.vel.y)).sum::<f64>()
    };
    let before = energy(&w);
    w.step(20.0).unwrap();
    assert!(w.stats().collisions > 10, "{:?}", w.stats());
    assert!((energy(&w) - before).abs() < 1e-9 * before);
    for (_, c) in w.circles() {
        assert!(c.pos.x > x0 && c.pos.x < x1 && c.pos.y > y0 && c.pos.y < y1, "escaped: {c:?}");
    }
}

#[test]
fn a_panic_in_the_callback_during_add_circle_reaches_the_caller_from_add_circle() {
    // in EXACT (after the first step) a circle added overlapping another and approaching it is
    // pushed apart and given its impulse inside add_circle: the panic comes out of that call,
    // not out of the next step (which then reports its own contacts again)
    let mut n = 0;
    let mut w = World::with_callback(&def(3, 1), |_: &ContactEvent| {
        n += 1;
        if n == 1 {
            panic!("from the callback");
        }
    })
    .unwrap();
    w.add_circle(&Circle::new(v(0.0, 0.0), 1.0)).unwrap();
    w.step(0.0).unwrap();
    let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
        w.add_circle(&Circle::new(v(1.5, 0.0), 1.0).with_vel(v(-1.0, 0.0)))
    }));
    assert!(r.is_err(), "add_circle resumed the panic");
    assert_eq!(w.len(), 2, "the circle was added");
    // equal masses: the first now leaves at -1 towards a wall at x = -10, and the next step's
    // contacts come through
    w.add_segment(&Segment::new(v(-10.0, -10.0), v(-10.0, 10.0))).unwrap();
    w.step(20.0).unwrap();
    drop(w);
    assert!(n >= 2, "{n}");
}

/// A jam (a kinematic circle pushing rolling ones: every step ends at the cap): the step's
/// outcome and the events it processed.
fn jam(def: WorldDef) -> (StepOutcome, u64) {
    let mut w = World::new(&WorldDef { restitution: 0.5, rolling_decel: 0.5, ..def }).unwrap();
    for i in 0..5 {
        w.add_circle(&Circle::new(v(i as f64 * 2.2, 0.0), 1.0)).unwrap();
    }
    w.add_circle(&Circle::new(v(-3.0, 0.0), 1.0).with_vel(v(1.0, 0.0)).immovable()).unwrap();
    w.step(0.0).unwrap();
    let r = w.step(30.0).unwrap();
    (r, w.stats().events)
}

#[test]
fn the_default_event_cap_is_automatic_and_an_explicit_one_is_kept() {
    // the C default: 0, 32 events per circle of max_circles, at least 10,000
    assert_eq!(WorldDef::default().max_events, 0);
    assert_eq!(jam(def(6, 0)), (StepOutcome::EventLimit, 10_000));
    assert_eq!(jam(def(400, 0)), (StepOutcome::EventLimit, 12_800));
    assert_eq!(jam(WorldDef { max_events: 123, ..def(6, 0) }), (StepOutcome::EventLimit, 123));
}
