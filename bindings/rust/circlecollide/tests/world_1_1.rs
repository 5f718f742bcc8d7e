//! The 1.1 additions through the safe API: properties (restitution and its mix, filters, rolling
//! deceleration), sensors and their callback, casts, queries, the state hash, periodic boxes and
//! the new statistics. Every expected value is derived by hand in the comments.
#![cfg(cc_has_world)]

use std::cell::RefCell;

use circlecollide::*;

fn v(x: f64, y: f64) -> Vec2 {
    Vec2::new(x, y)
}

fn def(max_circles: usize, max_segments: usize) -> WorldDef {
    WorldDef { max_circles, max_segments, ..WorldDef::default() }
}

fn close(a: f64, b: f64) -> bool {
    (a - b).abs() <= 1e-12 * (1.0 + b.abs())
}

#[test]
fn new_bodies_get_the_defs_properties_and_keep_what_is_set() {
    let d = WorldDef { restitution: 0.9, rolling_decel: 0.25, ..def(2, 1) };
    assert_eq!((d.restitution_mix, d.period), (RestitutionMix::Min, v(0.0, 0.0)), "the library's defaults");
    let mut w = World::new(&d).unwrap();
    let a = w.add_circle(&Circle::new(v(0.0, 0.0), 1.0)).unwrap();
    let s = w.add_segment(&Segment::new(v(5.0, -1.0), v(5.0, 1.0))).unwrap();
    let p = w.circle_props(a).unwrap();
    assert_eq!(p, CircleProps { restitution: 0.9, rolling_decel: 0.25, category: 1, mask: u32::MAX, sensor: false });
    assert_eq!(w.segment_props(s).unwrap(), SegmentProps { restitution: 0.9, category: 1, mask: u32::MAX });
    // Default is what a default world gives
    let mut plain = World::new(&def(1, 1)).unwrap();
    let c = plain.add_circle(&Circle::new(v(0.0, 0.0), 1.0)).unwrap();
    let t = plain.add_segment(&Segment::new(v(5.0, -1.0), v(5.0, 1.0))).unwrap();
    assert_eq!(
        (plain.circle_props(c).unwrap(), plain.segment_props(t).unwrap()),
        (CircleProps::default(), SegmentProps::default())
    );

    let q = CircleProps { restitution: 0.5, rolling_decel: 2.0, category: 6, mask: 0x0F0F, sensor: true };
    w.set_circle_props(a, &q).unwrap();
    assert_eq!(w.circle_props(a).unwrap(), q);
    let r = SegmentProps { restitution: 0.25, category: 8, mask: 3 };
    w.set_segment_props(s, &r).unwrap();
    assert_eq!(w.segment_props(s).unwrap(), r);

    // out of range: Invalid, nothing changed; unknown ids: NotFound
    for bad in [
        CircleProps { restitution: 1.5, ..q },
        CircleProps { restitution: f64::NAN, ..q },
        CircleProps { rolling_decel: -1.0, ..q },
        CircleProps { rolling_decel: f64::INFINITY, ..q },
    ] {
        assert_eq!(w.set_circle_props(a, &bad).unwrap_err().kind(), ErrorKind::Invalid, "{bad:?}");
    }
    assert_eq!(w.circle_props(a).unwrap(), q);
    assert_eq!(
        w.set_segment_props(s, &SegmentProps { restitution: -0.1, ..r }).unwrap_err().kind(),
        ErrorKind::Invalid
    );
    assert_eq!(w.segment_props(s).unwrap(), r);
    assert_eq!(w.circle_props(CircleId(1)).unwrap_err().kind(), ErrorKind::NotFound);
    assert_eq!(w.set_circle_props(CircleId(7), &q).unwrap_err().kind(), ErrorKind::NotFound);
    assert_eq!(w.segment_props(SegmentId(1)).unwrap_err().kind(), ErrorKind::NotFound);
    assert!(World::new(&WorldDef { rolling_decel: -1.0, ..def(1, 0) }).is_err());
}

#[test]
fn a_contacts_restitution_mixes_its_sides_and_the_wall_impulse_adds_up() {
    // radius 1 from x = 0 at speed 1 (mass 1) into a wall at x = 5: contact at t = 4. Circle
    // 0.8, wall 0.5: min 0.5, max 0.8, product 0.4, mean 0.65; it leaves at -e and, by t = 10,
    // is back at 4 - 6 e. The wall took the impulse m (1 + e) * 1.
    for (mix, e) in [
        (RestitutionMix::Min, 0.5),
        (RestitutionMix::Max, 0.8),
        (RestitutionMix::Product, 0.4),
        (RestitutionMix::Mean, 0.65),
    ] {
        let mut w = World::new(&WorldDef { restitution_mix: mix, ..def(1, 1) }).unwrap();
        let id = w.add_circle(&Circle::new(v(0.0, 0.0), 1.0).with_vel(v(1.0, 0.0))).unwrap();
        let wall = w.add_segment(&Segment::new(v(5.0, -10.0), v(5.0, 10.0))).unwrap();
        w.set_circle_props(id, &CircleProps { restitution: 0.8, ..w.circle_props(id).unwrap() }).unwrap();
        w.set_segment_props(wall, &SegmentProps { restitution: 0.5, ..w.segment_props(wall).unwrap() }).unwrap();
        w.step(10.0).unwrap();
        let c = w.circle(id).unwrap();
        assert!(close(c.vel.x, -e) && close(c.pos.x, 4.0 - 6.0 * e), "{mix:?}: {c:?}");
        let s = w.stats();
        assert_eq!(s.collisions, 1);
        assert!(close(s.wall_impulse, 1.0 + e) && s.virial == 0.0, "{mix:?}: {s:?}");
    }
}

#[test]
fn the_virial_of_a_head_on_impact() {
    // equal masses 1 at speeds +-1, radii 1: contact at t = 4 with the centres 2 apart; the
    // elastic impulse is 2 (each velocity changes by 2): virial = 2 * 2 = 4
    let mut w = World::new(&def(2, 0)).unwrap();
    w.add_circle(&Circle::new(v(0.0, 0.0), 1.0).with_vel(v(1.0, 0.0))).unwrap();
    w.add_circle(&Circle::new(v(10.0, 0.0), 1.0).with_vel(v(-1.0, 0.0))).unwrap();
    w.step(6.0).unwrap();
    let s = w.stats();
    assert!(close(s.virial, 4.0) && s.wall_impulse == 0.0, "{s:?}");
}

#[test]
fn filters_let_pairs_pass_through() {
    // the head-on pair of radius 1 from x = 0 and x = 10 at speeds +-1: after 10 they have
    // swapped places untouched when b's category is not in a's mask; they bounce otherwise
    for (a_mask, collides) in [(!2u32, false), (2, true)] {
        let mut w = World::new(&def(2, 1)).unwrap();
        let a = w.add_circle(&Circle::new(v(0.0, 0.0), 1.0).with_vel(v(1.0, 0.0))).unwrap();
        let b = w.add_circle(&Circle::new(v(10.0, 0.0), 1.0).with_vel(v(-1.0, 0.0))).unwrap();
        w.set_circle_props(b, &CircleProps { category: 2, ..Default::default() }).unwrap();
        w.set_circle_props(a, &CircleProps { mask: a_mask, ..Default::default() }).unwrap();
        w.step(10.0).unwrap();
        let (pa, pb) = (w.circle(a).unwrap().pos.x, w.circle(b).unwrap().pos.x);
        if collides {
            // contact at t = 4 (a at 4, b at 6), they swap velocities: a back to 4 - 6 = -2,
            // b on to 6 + 6 = 12
            assert!(close(pa, -2.0) && close(pb, 12.0), "{pa} {pb}");
        } else {
            assert!(close(pa, 10.0) && close(pb, 0.0) && w.stats().collisions == 0, "{pa} {pb}");
        }
    }
    // a wall of category 2 that the circle's mask (1) leaves out: the circle crosses x = 5
    let mut w = World::new(&def(1, 1)).unwrap();
    let a = w.add_circle(&Circle::new(v(0.0, 0.0), 1.0).with_vel(v(1.0, 0.0))).unwrap();
    let s = w.add_segment(&Segment::new(v(5.0, -10.0), v(5.0, 10.0))).unwrap();
    w.set_segment_props(s, &SegmentProps { category: 2, ..Default::default() }).unwrap();
    w.set_circle_props(a, &CircleProps { mask: 1, ..Default::default() }).unwrap();
    w.step(10.0).unwrap();
    assert!(close(w.circle(a).unwrap().pos.x, 10.0) && w.stats().collisions == 0);
}

#[test]
fn rolling_circles_slow_to_rest() {
    // speed s = 2 along x, decel k: p(t) = v (t - k t^2 / (2 s)) until t_stop = s / k, then at
    // rest at v t_stop / 2 = s^2 / (2 k) along x; the velocity is v (1 - t / t_stop).
    // def.rolling_decel = 1: t_stop = 2; at t = 1: x = 2 (1 - 1/4) = 1.5, speed 1; at rest at 2.
    // Circle b with its own decel 4: t_stop = 0.5, at rest at x = 4 / 8 = 0.5 (from y = 10).
    let mut w = World::new(&WorldDef { rolling_decel: 1.0, ..def(2, 0) }).unwrap();
    let a = w.add_circle(&Circle::new(v(0.0, 0.0), 1.0).with_vel(v(2.0, 0.0))).unwrap();
    let b = w.add_circle(&Circle::new(v(0.0, 10.0), 1.0).with_vel(v(2.0, 0.0))).unwrap();
    assert_eq!(w.circle_props(a).unwrap().rolling_decel, 1.0);
    w.step(0.0).unwrap(); // see set_rolling_decel_before_the_first_step below
    w.set_circle_props(b, &CircleProps { rolling_decel: 4.0, ..w.circle_props(b).unwrap() }).unwrap();
    w.step(1.0).unwrap();
    let (ca, cb) = (w.circle(a).unwrap(), w.circle(b).unwrap());
    assert!(close(ca.pos.x, 1.5) && close(ca.vel.x, 1.0), "{ca:?}");
    assert!(close(cb.pos.x, 0.5) && cb.vel == v(0.0, 0.0), "{cb:?}");
    w.step(5.0).unwrap();
    let ca = w.circle(a).unwrap();
    assert!(close(ca.pos.x, 2.0) && ca.vel == v(0.0, 0.0) && ca.pos.y == 0.0, "{ca:?}");
}

/// Library bug (reported, not fixed here): a rolling deceleration given through the properties
/// is ignored in EXACT until the world's first step (and after a wall was added), and always in
/// SWEPT and DISCRETE; the circle keeps the deceleration it had when it was added or last struck.
/// `cargo test -- --ignored` runs it.
#[test]
fn set_rolling_decel_before_the_first_step() {
    // speed 2, decel 4: t_stop = 0.5, at rest at x = 0.5
    for mode in [Mode::Exact, Mode::Swept, Mode::Discrete] {
        let mut w = World::new(&WorldDef { mode, ..def(1, 0) }).unwrap();
        let a = w.add_circle(&Circle::new(v(0.0, 0.0), 1.0).with_vel(v(2.0, 0.0))).unwrap();
        w.set_circle_props(a, &CircleProps { rolling_decel: 4.0, ..Default::default() }).unwrap();
        for _ in 0..10 {
            w.step(0.1).unwrap();
        }
        let c = w.circle(a).unwrap();
        assert!(close(c.pos.x, 0.5) && c.vel == v(0.0, 0.0), "{mode:?}: {c:?}");
    }
}

/// A rolling ball (radius 0.1, from x = 0 at speed 2, decel 0.4: x(t) = 2 t - 0.2 t^2) into a
/// resting one at x = 1: contact at x = 0.8, at the speed sqrt(4 - 2 * 0.4 * 0.8) = sqrt(3.36);
/// equal masses, elastic: the first stops there, the second rolls 3.36 / (2 * 0.4) = 4.2 and
/// rests at x = 5.2 (the contact at t = (2 - sqrt(3.36)) / 0.4).
fn rolling_impact(mode: Mode, steps: usize) -> (Circle, Circle, u64) {
    let mut w = World::new(&WorldDef { mode, rolling_decel: 0.4, ..def(2, 0) }).unwrap();
    let a = w.add_circle(&Circle::new(v(0.0, 0.0), 0.1).with_vel(v(2.0, 0.0))).unwrap();
    let b = w.add_circle(&Circle::new(v(1.0, 0.0), 0.1)).unwrap();
    for _ in 0..steps {
        w.step(10.0 / steps as f64).unwrap();
    }
    (w.circle(a).unwrap(), w.circle(b).unwrap(), w.stats().collisions)
}

#[test]
fn a_rolling_ball_strikes_a_resting_one_in_swept_mode() {
    let (a, b, n) = rolling_impact(Mode::Swept, 1000);
    assert_eq!(n, 1);
    assert!((a.pos.x - 0.8).abs() < 1e-9 && (b.pos.x - 5.2).abs() < 1e-9, "{a:?} {b:?}");
    assert!(a.vel == v(0.0, 0.0) && b.vel == v(0.0, 0.0));
}

/// Library bug (reported, not fixed here): in EXACT a rolling circle passes through a circle at
/// rest (movable or immovable); SWEPT and DISCRETE find the impact.
#[test]
fn a_rolling_ball_strikes_a_resting_one_in_exact_mode() {
    let (a, b, n) = rolling_impact(Mode::Exact, 1);
    assert_eq!(n, 1, "{a:?} {b:?}");
    assert!(close(a.pos.x, 0.8) && close(b.pos.x, 5.2), "{a:?} {b:?}");
}

#[test]
fn sensors_report_begin_and_end_at_their_times_in_order_with_contacts() {
    // a sensor of radius 2 at rest at x = 10; a ball of radius 1 from x = 0 at speed 1 through it
    // (radii sum 3): begin at x = 7 (t = 7), end at x = 13 (t = 13); no impulse, so it goes on
    // to a wall at x = 25, touched at x = 24 (t = 24), and back through the sensor: begin at
    // x = 13 (t = 24 + 11 = 35), end at x = 7 (t = 41).
    let log = RefCell::new(Vec::new());
    {
        let mut w = World::with_callbacks(
            &def(2, 1),
            |e: &ContactEvent| log.borrow_mut().push(format!("contact {:?} t={}", e.other, e.t)),
            |e: &SensorEvent| {
                log.borrow_mut().push(format!("sensor {} {} begin={} t={}", e.sensor.0, e.visitor.0, e.begin, e.t))
            },
        )
        .unwrap();
        let s = w.add_circle(&Circle::new(v(10.0, 0.0), 2.0).immovable()).unwrap();
        w.set_circle_props(s, &CircleProps { sensor: true, ..Default::default() }).unwrap();
        let ball = w.add_circle(&Circle::new(v(0.0, 0.0), 1.0).with_vel(v(1.0, 0.0))).unwrap();
        w.add_segment(&Segment::new(v(25.0, -10.0), v(25.0, 10.0))).unwrap();
        w.step(50.0).unwrap();
        let c = w.circle(ball).unwrap();
        assert!(close(c.pos.x, -2.0) && c.vel == v(-1.0, 0.0), "{c:?}"); // 24 - 26
        assert_eq!(w.stats().collisions, 1, "the sensor took no impulse");
    }
    assert_eq!(
        log.into_inner(),
        [
            "sensor 0 1 begin=true t=7",
            "sensor 0 1 begin=false t=13",
            "contact Wall(SegmentId(0)) t=24",
            "sensor 0 1 begin=true t=35",
            "sensor 0 1 begin=false t=41",
        ]
    );
}

#[test]
fn sensor_events_from_props_filters_and_the_limit() {
    let mut events = Vec::new();
    {
        let mut w = World::with_sensor_callback(&def(MAX_SENSORS + 2, 0), |e: &SensorEvent| events.push(*e)).unwrap();
        let ball = w.add_circle(&Circle::new(v(0.0, 0.0), 1.0)).unwrap();
        // a sensor (made one far away) set onto the ball: begin at once, at t = 0; the ball's
        // mask then leaving the sensor's category out: end at once; back in: begin again
        let s = w.add_circle(&Circle::new(v(1.0, 50.0), 1.0).immovable()).unwrap();
        w.set_circle_props(s, &CircleProps { sensor: true, category: 4, ..Default::default() }).unwrap();
        w.step(0.0).unwrap(); // (after a step: the same holds before one, in every mode)
        w.set_circle(s, &Circle::new(v(1.0, 0.0), 1.0).immovable()).unwrap();
        w.set_circle_props(ball, &CircleProps { mask: !4, ..Default::default() }).unwrap();
        w.set_circle_props(ball, &CircleProps::default()).unwrap();
        // sensors do not sense sensors; the 65th sensor is one too many
        for i in 1..MAX_SENSORS {
            let id = w.add_circle(&Circle::new(v(100.0 + 3.0 * i as f64, 0.0), 1.0).immovable()).unwrap();
            w.set_circle_props(id, &CircleProps { sensor: true, ..Default::default() }).unwrap();
        }
        let extra = w.add_circle(&Circle::new(v(-100.0, 0.0), 1.0).immovable()).unwrap();
        assert_eq!(
            w.set_circle_props(extra, &CircleProps { sensor: true, ..Default::default() }).unwrap_err().kind(),
            ErrorKind::Full
        );
        assert!(!w.circle_props(extra).unwrap().sensor);
    }
    let got: Vec<_> = events.iter().map(|e| (e.sensor.0, e.visitor.0, e.begin, e.t)).collect();
    assert_eq!(got, [(1, 0, true, 0.0), (1, 0, false, 0.0), (1, 0, true, 0.0)]);
}

#[test]
fn a_panic_in_the_sensor_callback_reaches_the_caller_after_the_call() {
    let mut w = World::with_sensor_callback(&def(3, 0), |_: &SensorEvent| panic!("from the sensor callback")).unwrap();
    let s = w.add_circle(&Circle::new(v(10.0, 0.0), 2.0).immovable()).unwrap();
    w.set_circle_props(s, &CircleProps { sensor: true, ..Default::default() }).unwrap();
    w.add_circle(&Circle::new(v(0.0, 0.0), 1.0).with_vel(v(1.0, 0.0))).unwrap();
    let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| w.step(20.0)));
    assert!(r.is_err());
    assert!(close(w.time(), 20.0), "the C step completed");
    w.step(1.0).unwrap(); // nothing pending any more
                          // and from set_circle_props: a ball put into the sensor by a filter change
    let b = w.add_circle(&Circle::new(v(10.0, 5.0), 1.0)).unwrap();
    w.set_circle_props(b, &CircleProps { mask: 0, ..Default::default() }).unwrap();
    w.set_circle(b, &Circle::new(v(10.0, 0.0), 1.0)).unwrap(); // filtered: no event
    let r = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| w.set_circle_props(b, &CircleProps::default())));
    assert!(r.is_err());
    assert!(w.circle_props(b).unwrap().mask == u32::MAX, "the change was made");
}

fn cast_scene() -> World<'static> {
    // circles 0 at (10, 0) and 1 at (20, 0), radius 1; a sensor 2 at (5, 0) radius 1 (skipped by
    // casts); a wall 0 at x = 30
    let mut w = World::new(&def(3, 1)).unwrap();
    w.add_circle(&Circle::new(v(10.0, 0.0), 1.0)).unwrap();
    w.add_circle(&Circle::new(v(20.0, 0.0), 1.0)).unwrap();
    let s = w.add_circle(&Circle::new(v(5.0, 0.0), 1.0).immovable()).unwrap();
    w.set_circle_props(s, &CircleProps { sensor: true, ..Default::default() }).unwrap();
    w.add_segment(&Segment::new(v(30.0, -10.0), v(30.0, 10.0))).unwrap();
    w.step(0.0).unwrap();
    w
}

#[test]
fn casts_hit_what_the_geometry_says() {
    let mut w = cast_scene();
    // radius 0.5 from the origin along (34, 0): touches circle 0 (radius sum 1.5) with its
    // centre at x = 8.5, t = 8.5 / 34 = 0.25; contact point (9, 0), normal +x
    let h = w.cast_circle(v(0.0, 0.0), v(34.0, 0.0), 0.5, u32::MAX).unwrap().unwrap();
    assert_eq!((h.kind, h.what), (ContactKind::Hit, Other::Circle(CircleId(0))));
    assert!(close(h.t, 0.25) && close(h.point.x, 9.0) && h.point.y.abs() < 1e-12, "{h:?}");
    assert!(close(h.normal.x, 1.0) && h.normal.y.abs() < 1e-12, "{h:?}");
    // a ray at y = 0.6 along (46, 0): enters circle 0 at x = 10 - sqrt(1 - 0.36) = 9.2, t = 0.2,
    // the normal from the hit point towards the centre (0.8, -0.6)
    let h = w.cast_circle(v(0.0, 0.6), v(46.0, 0.0), 0.0, u32::MAX).unwrap().unwrap();
    assert_eq!(h.what, Other::Circle(CircleId(0)));
    assert!(close(h.t, 0.2) && close(h.point.x, 9.2) && close(h.point.y, 0.6), "{h:?}");
    assert!(close(h.normal.x, 0.8) && close(h.normal.y, -0.6), "{h:?}");
    // circle 0 moved to category 2, cast with mask 1: it passes to circle 1, centre at 18.5
    w.set_circle_props(CircleId(0), &CircleProps { category: 2, ..Default::default() }).unwrap();
    let h = w.cast_circle(v(0.0, 0.0), v(37.0, 0.0), 0.5, 1).unwrap().unwrap();
    assert!(h.what == Other::Circle(CircleId(1)) && close(h.t, 0.5), "{h:?}");
    // radius 1 from (25, 0) along (10, 0): the wall at x = 30 with the centre at 29, t = 0.4
    let h = w.cast_circle(v(25.0, 0.0), v(10.0, 0.0), 1.0, u32::MAX).unwrap().unwrap();
    assert!(
        h.what == Other::Wall(SegmentId(0)) && close(h.t, 0.4) && close(h.point.x, 30.0) && close(h.normal.x, 1.0),
        "{h:?}"
    );
    // along -x from (25, 0) a length 3 reaches x = 22 only: circle 1's edge at 21 + 0.5 is out
    // of reach; a path through the sensor alone (from (5, 3) down to (5, -3)) touches nothing
    assert_eq!(w.cast_circle(v(25.0, 0.0), v(-3.0, 0.0), 0.5, u32::MAX).unwrap(), None);
    assert_eq!(w.cast_circle(v(5.0, 3.0), v(0.0, -6.0), 0.1, u32::MAX).unwrap(), None);
    // starting inside circle 1: an overlap at t = 0, normal from p towards its centre
    let h = w.cast_circle(v(19.5, 0.0), v(1.0, 0.0), 0.25, u32::MAX).unwrap().unwrap();
    assert!(
        h.kind == ContactKind::Overlap && h.what == Other::Circle(CircleId(1)) && h.t == 0.0 && close(h.normal.x, 1.0),
        "{h:?}"
    );
    assert_eq!(w.cast_circle(v(0.0, 0.0), v(1.0, 0.0), -1.0, u32::MAX).unwrap_err().kind(), ErrorKind::Invalid);
    assert_eq!(w.cast_circle(v(f64::NAN, 0.0), v(1.0, 0.0), 1.0, u32::MAX).unwrap_err().kind(), ErrorKind::Invalid);
}

#[test]
fn queries_return_the_ids_the_geometry_says() {
    // 0 at (0, 0) r 1, 1 at (5, 0) r 1, 2 at (10, 0) r 1, 3 at (0, 5) r 0.5 (category 2)
    let mut w = World::new(&def(4, 0)).unwrap();
    for (x, y, r) in [(0.0, 0.0, 1.0), (5.0, 0.0, 1.0), (10.0, 0.0, 1.0), (0.0, 5.0, 0.5)] {
        w.add_circle(&Circle::new(v(x, y), r)).unwrap();
    }
    w.set_circle_props(CircleId(3), &CircleProps { category: 2, ..Default::default() }).unwrap();
    w.step(0.0).unwrap();
    let ids = |v: &[i32]| v.iter().map(|&i| CircleId(i)).collect::<Vec<_>>();
    // disc (2.5, 0) r 1.6: 0 and 1 are 2.5 away (< 2.6), 2 is 7.5, 3 is sqrt(31.25) = 5.59 (> 2.1)
    assert_eq!(w.query_circle_vec(v(2.5, 0.0), 1.6, u32::MAX).unwrap(), ids(&[0, 1]));
    // r 1.5: 0 and 1 exactly touch (2.5 = 2.5): not overlapping
    assert_eq!(w.query_circle_vec(v(2.5, 0.0), 1.5, u32::MAX).unwrap(), ids(&[]));
    // radius 0: the circles whose interior holds the point
    assert_eq!(w.query_circle_vec(v(0.2, 4.7), 0.0, u32::MAX).unwrap(), ids(&[3]));
    // box [-1, 0.5] x [-1, 6]: 0 and 3 have their centres inside; 1 is 4.5 away (> 1)
    assert_eq!(w.query_box_vec(v(-1.0, -1.0), v(0.5, 6.0), u32::MAX).unwrap(), ids(&[0, 3]));
    assert_eq!(w.query_box_vec(v(-1.0, -1.0), v(0.5, 6.0), 1).unwrap(), ids(&[0]), "3 is category 2");
    // box [6, 9] x [-1, 1]: 1 and 2 are exactly 1 (their radius) away: a closed box counts them
    assert_eq!(w.query_box_vec(v(6.0, -1.0), v(9.0, 1.0), u32::MAX).unwrap(), ids(&[1, 2]));
    // into a caller slice: the count is of them all, the slice gets the first in id order
    let mut one = [CircleId(-7)];
    assert_eq!(w.query_box(v(6.0, -1.0), v(9.0, 1.0), u32::MAX, &mut one).unwrap(), 2);
    assert_eq!(one, [CircleId(1)]);
    assert_eq!(w.query_circle(v(2.5, 0.0), 1.6, u32::MAX, &mut []).unwrap(), 2);
    let mut many = [CircleId(-7); 4];
    assert_eq!(w.query_circle(v(2.5, 0.0), 1.6, u32::MAX, &mut many).unwrap(), 2);
    assert_eq!(many, [CircleId(0), CircleId(1), CircleId(-7), CircleId(-7)], "nothing written past the count");
    assert_eq!(w.query_box_vec(v(1.0, 0.0), v(0.0, 1.0), u32::MAX).unwrap_err().kind(), ErrorKind::Invalid);
    assert_eq!(w.query_circle_vec(v(0.0, 0.0), -1.0, u32::MAX).unwrap_err().kind(), ErrorKind::Invalid);
}

#[test]
fn query_vecs_grow_past_their_first_buffer() {
    // 50 circles of radius 0.5 at x = 0, 2, ..., 98, ids 0..50; a box over x in [10, 58] meets
    // those at x = 10..58 (ids 5..=29); ids 4 and 30 are 2 away (> 0.5): not them
    let mut w = World::new(&def(50, 0)).unwrap();
    for i in 0..50 {
        w.add_circle(&Circle::new(v(2.0 * i as f64, 0.0), 0.5)).unwrap();
    }
    w.step(0.0).unwrap();
    assert_eq!(
        w.query_box_vec(v(10.0, -1.0), v(58.0, 1.0), u32::MAX).unwrap(),
        (5..=29).map(CircleId).collect::<Vec<_>>()
    );
    assert_eq!(
        w.query_box_vec(v(-10.0, -1.0), v(200.0, 1.0), u32::MAX).unwrap(),
        (0..50).map(CircleId).collect::<Vec<_>>()
    );
}

fn gas(vx0: f64) -> World<'static> {
    // 12 circles in a box, as in tests/world.rs, circle 0's x velocity given
    let mut w = World::new(&def(12, 4)).unwrap();
    let (x0, x1, y0, y1) = (-3.0, 16.0, -3.0, 12.0);
    for (p, q) in [((x0, y0), (x1, y0)), ((x1, y0), (x1, y1)), ((x1, y1), (x0, y1)), ((x0, y1), (x0, y0))] {
        w.add_segment(&Segment::new(v(p.0, p.1), v(q.0, q.1))).unwrap();
    }
    for i in 0..12 {
        let vel = if i == 0 { v(vx0, 1.0) } else { v(((i * 7) % 5) as f64 - 2.0, ((i * 3) % 7) as f64 - 3.0) };
        w.add_circle(&Circle::new(v(4.0 * (i % 4) as f64, 4.0 * (i / 4) as f64), 1.0).with_vel(vel)).unwrap();
    }
    w
}

#[test]
fn hash_equal_after_identical_runs_and_different_one_bit_apart() {
    let (mut a, mut b) = (gas(1.5), gas(1.5));
    assert_eq!(a.hash(), b.hash());
    let h0 = a.hash();
    a.step(20.0).unwrap();
    b.step(20.0).unwrap();
    assert!(a.stats().collisions > 10);
    assert_eq!(a.hash(), b.hash(), "the same calls, the same state");
    assert_ne!(a.hash(), h0, "time and positions moved on");
    // one bit apart in circle 0's x velocity (the next double after 1.5), before any step
    let mut c = gas(f64::from_bits(1.5f64.to_bits() + 1));
    assert_ne!(c.hash(), h0);
    c.step(20.0).unwrap();
    assert_ne!(c.hash(), a.hash());
    // one bit of one property
    let d = gas(1.5);
    let mut e = gas(1.5);
    e.set_circle_props(CircleId(11), &CircleProps { mask: u32::MAX - 1, ..Default::default() }).unwrap();
    assert_ne!(d.hash(), e.hash());
}

#[test]
fn periodic_boxes_wrap_positions_and_unwrapped_does_not() {
    // period 10 along x, open along y. A circle from x = 9 at speed 2: after 1.5 at 12, kept at
    // 2, its unwrapped x 12. Another at (1.5, 5) at speed -1 meets one at (8.5, 5) at speed +1
    // across the edge: through the image at 8.5 - 10 = -1.5 the gap is 3 - 2 * 0.5 = 2, closed
    // at 2: contact at t = 1 (at 0.5 and 9.5), the velocities swap; at t = 1.5 they are at 1
    // and 9.
    let d = WorldDef { period: v(10.0, 0.0), ..def(3, 0) };
    assert_eq!(d.period, v(10.0, 0.0));
    let mut w = World::new(&d).unwrap();
    let a = w.add_circle(&Circle::new(v(9.0, 0.0), 0.5).with_vel(v(2.0, 0.0))).unwrap();
    let b = w.add_circle(&Circle::new(v(1.5, 5.0), 0.5).with_vel(v(-1.0, 0.0))).unwrap();
    let c = w.add_circle(&Circle::new(v(8.5, 5.0), 0.5).with_vel(v(1.0, 0.0))).unwrap();
    w.step(1.5).unwrap();
    let ca = w.circle(a).unwrap();
    assert!(close(ca.pos.x, 2.0) && ca.pos.y == 0.0, "{ca:?}");
    assert_eq!(w.unwrapped(a).unwrap(), v(12.0, 0.0));
    let (cb, cc) = (w.circle(b).unwrap(), w.circle(c).unwrap());
    assert!(close(cb.pos.x, 1.0) && cb.vel.x == 1.0 && close(cc.pos.x, 9.0) && cc.vel.x == -1.0, "{cb:?} {cc:?}");
    assert_eq!(w.stats().collisions, 1);
    // the impulse 2 at centres 1 apart: virial 2
    assert!(close(w.stats().virial, 2.0), "{:?}", w.stats());
    assert_eq!(w.unwrapped(CircleId(3)).unwrap_err().kind(), ErrorKind::NotFound);
    // a period too small for the circles (< 2 diameters + a cell) refuses them
    let mut small = World::new(&WorldDef { period: v(3.0, 3.0), ..def(1, 0) }).unwrap();
    assert_eq!(small.add_circle(&Circle::new(v(1.0, 1.0), 1.0)).unwrap_err().kind(), ErrorKind::Range);
    // open axes: unwrapped is the position
    let mut open = World::new(&def(1, 0)).unwrap();
    let o = open.add_circle(&Circle::new(v(-3.0, 4.0), 1.0).with_vel(v(1.0, 0.0))).unwrap();
    open.step(2.0).unwrap();
    assert_eq!(open.unwrapped(o).unwrap(), open.circle(o).unwrap().pos);
}

#[test]
fn sensors_in_swept_and_discrete_report_at_the_end_of_the_step() {
    // the ball of the EXACT scene above (begin at t = 7, end at t = 13), stepped by 4: the
    // overlap is seen at the ends of the steps, t = 8 (x = 8) and t = 16 (x = 16, out again)
    for mode in [Mode::Swept, Mode::Discrete] {
        let mut events = Vec::new();
        {
            let mut w = World::with_sensor_callback(&WorldDef { mode, ..def(2, 0) }, |e: &SensorEvent| {
                events.push((e.begin, e.t))
            })
            .unwrap();
            let s = w.add_circle(&Circle::new(v(10.0, 0.0), 2.0).immovable()).unwrap();
            w.set_circle_props(s, &CircleProps { sensor: true, ..Default::default() }).unwrap();
            w.add_circle(&Circle::new(v(0.0, 0.0), 1.0).with_vel(v(1.0, 0.0))).unwrap();
            for _ in 0..5 {
                w.step(4.0).unwrap();
            }
        }
        assert_eq!(events, [(true, 8.0), (false, 16.0)], "{mode:?}");
    }
}

#[test]
fn queries_and_casts_see_across_the_period() {
    // period 10 in x and y; circle 0 of radius 0.5 at (0.5, 5). A disc at (9.8, 5) of radius 0.5
    // is 0.7 from its image at (10.5, 5) (< 1): found; a box [9, 9.9] x [4, 6] is 0.6 from it
    // (> 0.5): not. A circle of radius 0.5 cast from (7, 5) along (4, 0) touches the image with
    // its centre at 9.5: t = 2.5 / 4 = 0.625.
    let mut w = World::new(&WorldDef { period: v(10.0, 10.0), ..def(1, 0) }).unwrap();
    let a = w.add_circle(&Circle::new(v(0.5, 5.0), 0.5)).unwrap();
    w.step(0.0).unwrap();
    assert_eq!(w.query_circle_vec(v(9.8, 5.0), 0.5, u32::MAX).unwrap(), [a]);
    assert_eq!(w.query_box_vec(v(9.0, 4.0), v(9.9, 6.0), u32::MAX).unwrap(), []);
    let h = w.cast_circle(v(7.0, 5.0), v(4.0, 0.0), 0.5, u32::MAX).unwrap().unwrap();
    assert!(h.what == Other::Circle(a) && close(h.t, 0.625) && close(h.normal.x, 1.0), "{h:?}");
}

#[test]
fn a_clone_steps_bit_for_bit_like_the_original() {
    for mode in [Mode::Exact, Mode::Swept, Mode::Discrete] {
        let d = WorldDef { mode, restitution: 0.9, rolling_decel: 0.05, ..def(40, 4) };
        let mut w = World::new(&d).unwrap();
        for (p, q) in [
            ((0.0, 0.0), (20.0, 0.0)),
            ((20.0, 0.0), (20.0, 20.0)),
            ((20.0, 20.0), (0.0, 20.0)),
            ((0.0, 20.0), (0.0, 0.0)),
        ] {
            w.add_segment(&Segment::new(v(p.0, p.1), v(q.0, q.1))).unwrap();
        }
        for i in 0..36 {
            let (x, y) = (1.5 + (i % 6) as f64 * 3.0, 1.5 + (i / 6) as f64 * 3.0);
            let vel = v(((i * 7919) % 13) as f64 - 6.0, ((i * 104729) % 11) as f64 - 5.0);
            w.add_circle(&Circle::new(v(x, y), 0.6 + 0.02 * i as f64).with_vel(vel)).unwrap();
        }
        w.step(0.7).unwrap(); // mid-flight: events predicted and queued
        let mut c = w.try_clone().unwrap();
        assert_eq!(c.hash(), w.hash());
        for _ in 0..30 {
            w.step(0.13).unwrap();
            c.step(0.13).unwrap();
            assert_eq!(c.hash(), w.hash(), "{mode:?}");
            assert_eq!(format!("{:?}", c.circles()), format!("{:?}", w.circles()));
        }
        assert!(w.stats().collisions > 0);
        drop(w); // the clone owns its memory
        c.step(1.0).unwrap();
    }
}

#[test]
fn a_world_with_callbacks_refuses_to_clone() {
    let w = World::with_callback(&def(2, 0), |_: &ContactEvent| {}).unwrap();
    assert_eq!(w.try_clone().unwrap_err().kind(), ErrorKind::Invalid);
}

#[test]
fn add_circles_is_one_add_per_circle_or_nothing() {
    // three circles into a world of room 4 that holds one: ids 1, 2, 3, as three add_circle give
    let mut w = World::new(&def(4, 0)).unwrap();
    let mut singles = World::new(&def(4, 0)).unwrap();
    let first = Circle::new(v(0.0, 0.0), 1.0).with_vel(v(1.0, 0.0));
    w.add_circle(&first).unwrap();
    singles.add_circle(&first).unwrap();
    let batch: Vec<Circle> =
        (0..3).map(|i| Circle::new(v(5.0 * (i + 1) as f64, 0.0), 1.0).with_vel(v(-1.0, 0.5))).collect();
    let ids = w.add_circles(&batch).unwrap();
    assert_eq!(ids, vec![CircleId(1), CircleId(2), CircleId(3)]);
    for c in &batch {
        singles.add_circle(c).unwrap();
    }
    assert_eq!(w.hash(), singles.hash());
    // full: one more fits nowhere; the first circle refused is index 0, nothing changes
    let before = w.hash();
    let e = w.add_circles(&batch[..1]).unwrap_err();
    assert_eq!((e.error.kind(), e.index), (ErrorKind::Full, Some(0)));
    assert_eq!((w.hash(), w.len()), (before, 4));
    // an invalid circle (radius 0, made past Circle::new's checks) at index 1 of 2: nothing added
    let mut room = World::new(&def(8, 0)).unwrap();
    let mut bad = batch[..2].to_vec();
    bad[1].radius = 0.0;
    let e = room.add_circles(&bad).unwrap_err();
    assert_eq!((e.error.kind(), e.index, room.len()), (ErrorKind::Invalid, Some(1), 0));
    assert_eq!(room.add_circles(&[]).unwrap(), vec![]);
}

#[test]
fn unwrapped_all_is_unwrapped_for_each() {
    // a circle at x = 9 moving at speed 1 in a period of 10: at t = 2.5 it is at 1.5, unwrapped 11.5
    let mut w = World::new(&WorldDef { period: v(10.0, 10.0), ..def(4, 0) }).unwrap();
    let a = w.add_circle(&Circle::new(v(9.0, 5.0), 1.0).with_vel(v(1.0, 0.0))).unwrap();
    let b = w.add_circle(&Circle::new(v(2.0, 1.0), 1.0).with_vel(v(0.0, -1.0))).unwrap();
    w.step(2.5).unwrap();
    let all = w.unwrapped_all();
    assert_eq!(all.len(), 2);
    assert_eq!(all[0], (a, w.unwrapped(a).unwrap()));
    assert_eq!(all[1], (b, w.unwrapped(b).unwrap()));
    assert!(close(all[0].1.x, 11.5) && close(all[1].1.y, -1.5));
}
