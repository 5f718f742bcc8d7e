//! Issue 35, "Feels native, second pass": Vec2 arithmetic and conversions, `Circle::new`
//! without a velocity and a valid `Circle::default()`, errors that carry their cause, and
//! `cast_circle` taking Python's `(p, d, radius)` with a filter that can leave a circle out.

use circlecollide::*;

#[test]
fn vec2_is_a_vector() {
    let (a, b) = (Vec2::new(1.0, 2.0), Vec2::new(3.0, 4.0));
    assert_eq!(a + b, Vec2::new(4.0, 6.0));
    assert_eq!(b - a, Vec2::new(2.0, 2.0));
    assert_eq!(-a, Vec2::new(-1.0, -2.0));
    assert_eq!(a * 2.0, Vec2::new(2.0, 4.0));
    assert_eq!(2.0 * a, Vec2::new(2.0, 4.0));
    assert_eq!(b / 2.0, Vec2::new(1.5, 2.0));
    assert_eq!(b.dot(Vec2::new(1.0, 0.0)), 3.0); // 3 * 1 + 4 * 0
    assert_eq!(Vec2::new(1.0, 0.0).cross(Vec2::new(0.0, 1.0)), 1.0);
    assert_eq!(b.length(), 5.0); // the 3-4-5 triangle
    assert_eq!(b.length_squared(), 25.0);
    assert_eq!(b.normalized(), Some(Vec2::new(0.6, 0.8)));
    assert_eq!(Vec2::<f64>::default().normalized(), None);
    let mut c = a;
    c += b;
    c -= a;
    c *= 2.0;
    c /= 4.0;
    assert_eq!(c, Vec2::new(1.5, 2.0));
    assert_eq!(2.0f32 * Vec2::new(1.0f32, 1.0), Vec2::new(2.0f32, 2.0));
}

#[test]
fn vec2_converts_from_and_to_pairs() {
    let v: Vec2 = (1.0, 2.0).into();
    assert_eq!(v, Vec2::new(1.0, 2.0));
    assert_eq!(Vec2::from([3.0, 4.0]), Vec2::new(3.0, 4.0));
    let (x, y): (f64, f64) = v.into();
    assert_eq!((x, y), (1.0, 2.0));
    // and everything that takes a point takes a pair
    let s = Segment::new((0.0, 0.0), (1.0, 0.0));
    assert_eq!(s.b, Vec2::new(1.0, 0.0));
}

#[test]
fn circle_new_needs_no_velocity_and_default_is_valid() {
    let c = Circle::new((10.0, 0.0), 2.0);
    assert_eq!((c.pos, c.vel, c.radius, c.mass), (Vec2::new(10.0, 0.0), Vec2::new(0.0, 0.0), 2.0, 1.0));
    let a = Circle::new((0.0, 0.0), 1.0).with_vel((2.0, 0.0));
    // the gap 10 - 1 - 2 = 7 closes at speed 2: t = 3.5
    assert_eq!(sweep(&a, &c, 10.0).unwrap().unwrap().t, 3.5);
    let d: Circle = Circle::default();
    assert_eq!((d.radius, d.mass), (1.0, 1.0)); // 1.1's default had radius 0 and mass 0: invalid
                                                // a default circle is one the library accepts: two at the same place overlap
    assert_eq!(detect_static(&d, &d).unwrap().unwrap().kind, ContactKind::Overlap);
    let mut w = World::new(&WorldDef::default()).unwrap();
    assert!(w.add_circle(&Circle::default()).is_ok());
}

#[test]
fn pair_errors_name_the_argument() {
    let a = Circle::new((0.0, 0.0), 1.0).with_vel((1.0, 0.0));
    let b = Circle::new((10.0, 0.0), 1.0);
    let e = sweep(&a, &Circle { radius: f64::NAN, ..b }, 1.0).unwrap_err();
    assert_eq!(e.to_string(), "sweep: b.radius must be finite and > 0, got NaN (CC_ERR_INVALID)");
    assert_eq!((e.call(), e.cause()), ("sweep", Some("b.radius must be finite and > 0, got NaN")));
    assert_eq!(sweep(&a, &b, -1.0).unwrap_err().cause(), Some("t_max must be >= 0, got -1"));
    let c = sweep(&a, &b, 20.0).unwrap().unwrap();
    let (mut ia, mut ib) = (a.immovable(), b.immovable());
    let e = respond(&mut ia, &mut ib, &c, 1.0).unwrap_err();
    assert!(e.to_string().starts_with("respond: a and b are both immovable"), "{e}");
    let (mut a2, mut b2) = (a, b);
    assert_eq!(respond(&mut a2, &mut b2, &c, 2.0).unwrap_err().cause(), Some("restitution must be in [0, 1], got 2"));
}

#[test]
fn sweep_many_names_the_row() {
    let (zeros, ones, far) = ([0.0; 4], [1.0; 4], [10.0; 4]);
    let radius = [1.0, 1.0, f64::NAN, 1.0];
    let a = Columns { px: &zeros, py: &zeros, vx: &ones, vy: &zeros, radius: &radius };
    let b = Columns { px: &far, py: &zeros, vx: &zeros, vy: &zeros, radius: &ones };
    let mut t = [0.0; 4];
    let e = sweep_many(&a, &b, 20.0, &mut t, None).unwrap_err();
    assert_eq!(e.cause(), Some("row 2: a.radius[2] must be finite and > 0, got NaN"));
}

#[test]
fn world_refusals_name_their_cause() {
    let e = World::new(&WorldDef { max_circles: 100_000_000, ..Default::default() }).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Range);
    assert_eq!(e.to_string(), "World::new: max_circles must be at most 2^26 = 67108864, got 100000000 (CC_ERR_RANGE)");
    // period 10: radius 2 (d = 4) needs 2 d + 1.0625 d = 12.25
    let mut w = World::new(&WorldDef { period: Vec2::new(10.0, 0.0), ..Default::default() }).unwrap();
    let id = w.add_circle(&Circle::new((5.0, 5.0), 1.0)).unwrap();
    let e = w.add_circle(&Circle::new((5.0, 5.0), 2.0)).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Range);
    assert!(
        e.to_string().starts_with("World::add_circle: a circle of radius 2 is too wide for the period (10, 0)"),
        "{e}"
    );
    assert_eq!(w.set_circle(id, &Circle::new((5.0, 5.0), 2.0)).unwrap_err().kind(), ErrorKind::Range);
    // SWEPT, period 10: speed 10 for 0.5 s is half a period
    let def = WorldDef { mode: Mode::Swept, period: Vec2::new(10.0, 10.0), ..Default::default() };
    let mut w = World::new(&def).unwrap();
    w.add_circle(&Circle::new((5.0, 5.0), 0.5).with_vel((10.0, 0.0))).unwrap();
    let e = w.step(0.5).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Range);
    assert!(e.to_string().contains("would carry a circle half a period"), "{e}");
    assert_eq!(w.step(-1.0).unwrap_err().cause(), Some("dt must be finite and >= 0, got -1"));
    assert_eq!(w.step(0.4).unwrap(), StepOutcome::Done);
    let e = w.query_box_vec((1.0, 0.0), (0.0, 1.0), u32::MAX).unwrap_err();
    assert_eq!(e.cause(), Some("lo must be <= hi in both coordinates, got lo = (1, 0), hi = (0, 1)"));
    let e = World::new(&WorldDef { period: Vec2::new(1.0, 0.0), cell_size: 2.0, ..Default::default() }).unwrap_err();
    assert_eq!((e.kind(), e.cause()), (ErrorKind::Range, Some("period.x = 1 must be wider than cell_size = 2")));
}

#[test]
fn cast_circle_takes_pythons_order_and_a_filter() {
    let mut w = World::new(&WorldDef::default()).unwrap();
    let cue = w.add_circle(&Circle::new((0.0, 0.0), 1.0)).unwrap();
    let ball = w.add_circle(&Circle::new((10.0, 0.0), 1.0)).unwrap();
    // (p, d, radius, filter), as Python's cast_circle(p, d, radius=, mask=, ignore=)
    let own = w.cast_circle((0.0, 0.0), (20.0, 0.0), 1.0, u32::MAX).unwrap().unwrap();
    assert_eq!((own.kind, own.what), (ContactKind::Overlap, Other::Circle(cue)));
    let hit = w.cast_circle((0.0, 0.0), (20.0, 0.0), 1.0, QueryFilter::default().ignoring(cue)).unwrap().unwrap();
    // the centre touches the object ball at x = 8: t = 8 / 20
    assert_eq!(
        (hit.kind, hit.what, hit.t, hit.normal),
        (ContactKind::Hit, Other::Circle(ball), 0.4, Vec2::new(1.0, 0.0))
    );
    assert_eq!(w.query_circle_vec((0.0, 0.0), 0.5, QueryFilter::default()).unwrap(), [cue]);
    assert_eq!(w.query_circle_vec((0.0, 0.0), 0.5, QueryFilter::default().ignoring(cue)).unwrap(), []);
    assert_eq!(w.query_box_vec((-2.0, -2.0), (12.0, 2.0), QueryFilter::default().ignoring(ball)).unwrap(), [cue]);
    assert_eq!(w.query_box_vec((-2.0, -2.0), (12.0, 2.0), QueryFilter::default().with_mask(0)).unwrap(), []);
}
