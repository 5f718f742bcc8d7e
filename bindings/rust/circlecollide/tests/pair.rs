//! The pair functions through the safe API; expected values derived beside each check.

use circlecollide::*;

fn head_on() -> (Circle, Circle) {
    // centres 10 apart, radii 1 + 1: gap 8 closing at speed 2 -> t = 4
    (
        Circle::new(Vec2::new(0.0, 0.0), 1.0).with_vel(Vec2::new(1.0, 0.0)),
        Circle::new(Vec2::new(10.0, 0.0), 1.0).with_vel(Vec2::new(-1.0, 0.0)),
    )
}

#[test]
fn head_on_hit_then_elastic_swap() {
    let (a, b) = head_on();
    let c = sweep(&a, &b, 10.0).unwrap().unwrap();
    assert_eq!(
        c,
        Contact { kind: ContactKind::Hit, t: 4.0, point: Vec2::new(5.0, 0.0), normal: Vec2::new(1.0, 0.0), depth: 0.0 }
    );
    let (mut a, mut b) = (a.at(c.t), b.at(c.t));
    assert!(respond(&mut a, &mut b, &c, 1.0).unwrap());
    assert_eq!((a.vel, b.vel), (Vec2::new(-1.0, 0.0), Vec2::new(1.0, 0.0)));
    assert!(!respond(&mut a, &mut b, &c, 1.0).unwrap(), "separating: nothing to do");
}

#[test]
fn misses() {
    let (a, b) = head_on();
    assert_eq!(sweep(&a, &b, 3.9).unwrap(), None);
    assert_eq!(sweep(&b, &a.at(-100.0).with_mass(2.0), f64::INFINITY).unwrap().map(|c| c.kind), Some(ContactKind::Hit));
    let apart = Circle { vel: Vec2::new(-1.0, 0.0), ..a };
    assert_eq!(sweep(&apart, &Circle { vel: Vec2::new(1.0, 0.0), ..b }, f64::INFINITY).unwrap(), None);
}

#[test]
fn overlap_separate_and_immovable() {
    // centres 1.5 apart, radii 1 + 1: depth 0.5; equal masses move 0.25 each
    let mut a: Circle = Circle::new(Vec2::new(0.0, 0.0), 1.0);
    let mut b: Circle = Circle::new(Vec2::new(1.5, 0.0), 1.0);
    let c = detect_static(&a, &b).unwrap().unwrap();
    assert_eq!((c.kind, c.depth, c.normal), (ContactKind::Overlap, 0.5, Vec2::new(1.0, 0.0)));
    assert!(separate(&mut a, &mut b).unwrap());
    assert!((a.pos.x + 0.25).abs() < 1e-15 && (b.pos.x - 1.75).abs() < 1e-15);
    assert!(!separate(&mut a, &mut b).unwrap());
    let mut wall: Circle = Circle::new(Vec2::new(0.0, 0.0), 1.0).immovable();
    let mut c2: Circle = Circle::new(Vec2::new(1.0, 0.0), 1.0);
    assert!(separate(&mut wall, &mut c2).unwrap());
    assert_eq!(wall.pos, Vec2::new(0.0, 0.0));
    assert!((c2.pos.x - 2.0).abs() < 1e-15);
}

#[test]
fn segments() {
    // radius 1 moving +x at speed 1 towards the wall x = 5: touches at t = 4
    let c = Circle::new(Vec2::new(0.0, 0.0), 1.0).with_vel(Vec2::new(1.0, 1.0));
    let wall = Segment::new(Vec2::new(5.0, -100.0), Vec2::new(5.0, 100.0));
    let k = sweep_segment(&c, &wall, 10.0).unwrap().unwrap();
    assert_eq!((k.t, k.normal), (4.0, Vec2::new(1.0, 0.0)));
    let mut c = c.at(k.t);
    assert!(respond_segment(&mut c, &k, 1.0).unwrap());
    assert_eq!(c.vel, Vec2::new(-1.0, 1.0)); // normal part reversed, tangential kept
    assert_eq!(
        closest_point_on_segment(Vec2::new(7.0, 1.0), &Segment::new(Vec2::new(-1.0, 0.0), Vec2::new(1.0, 0.0))),
        Vec2::new(1.0, 0.0)
    );
}

#[test]
fn errors_carry_the_cause_and_change_nothing() {
    let (mut a, mut b) = head_on();
    let bad = Circle { radius: 0.0, ..a };
    let e = sweep(&bad, &b, 1.0).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Invalid);
    assert_eq!(e.code(), -1);
    assert_eq!(e.to_string(), "sweep: a.radius must be finite and > 0, got 0 (CC_ERR_INVALID)");
    assert!(e.message().starts_with("CC_ERR_INVALID"), "{}", e.message());
    assert_eq!(sweep(&a, &b, -1.0).unwrap_err().kind(), ErrorKind::Invalid);
    assert_eq!(sweep(&Circle { pos: Vec2::new(f64::NAN, 0.0), ..a }, &b, 1.0).unwrap_err().kind(), ErrorKind::Invalid);
    let c = sweep(&a, &b, 10.0).unwrap().unwrap();
    let before = (a, b);
    assert!(respond(&mut a, &mut b, &c, 1.5).is_err());
    let (mut ia, mut ib) = (a.immovable(), b.immovable());
    assert!(respond(&mut ia, &mut ib, &c, 1.0).is_err());
    assert_eq!((a, b), before);
}

#[test]
fn single_precision_uses_the_float_functions() {
    // gap 1 closing at speed 3: t = 1/3, which f32 holds to 24 bits
    let a = Circle::<f32>::new(Vec2::new(0.0, 0.0), 1.0).with_vel(Vec2::new(3.0, 0.0));
    let b = Circle::<f32>::new(Vec2::new(3.0, 0.0), 1.0);
    let t = sweep(&a, &b, 1.0f32).unwrap().unwrap().t;
    assert!((t - 1.0 / 3.0).abs() <= 2.0 * f32::EPSILON / 3.0, "{t}");
    let big = Circle::<f32>::new(Vec2::new(f32::INFINITY, 0.0), 1.0);
    assert!(sweep(&big, &b, 1.0).is_err());
}

#[test]
fn sweep_many_agrees_with_sweep_bit_for_bit() {
    // a small deterministic set: pairs i = 0..64 with varied offsets and speeds
    let n = 64;
    let f = |i: usize, k: f64| ((i as f64 * 0.618_033_988_749 * k).fract() - 0.5) * 20.0;
    let (apx, apy, avx, avy): (Vec<f64>, Vec<f64>, Vec<f64>, Vec<f64>) = (
        (0..n).map(|i| f(i, 1.0)).collect(),
        (0..n).map(|i| f(i, 2.0)).collect(),
        (0..n).map(|i| f(i, 3.0) / 5.0).collect(),
        (0..n).map(|i| f(i, 5.0) / 5.0).collect(),
    );
    let (bpx, bpy, bvx, bvy): (Vec<f64>, Vec<f64>, Vec<f64>, Vec<f64>) = (
        (0..n).map(|i| f(i, 7.0)).collect(),
        (0..n).map(|i| f(i, 11.0)).collect(),
        (0..n).map(|i| f(i, 13.0) / 5.0).collect(),
        (0..n).map(|i| f(i, 17.0) / 5.0).collect(),
    );
    let r: Vec<f64> = (0..n).map(|i| 0.5 + (i % 5) as f64 * 0.4).collect();
    let a = Columns { px: &apx, py: &apy, vx: &avx, vy: &avy, radius: &r };
    let b = Columns { px: &bpx, py: &bpy, vx: &bvx, vy: &bvy, radius: &r };
    let mut t = vec![0.0; n];
    let mut codes = vec![0; n];
    let hits = sweep_many(&a, &b, 5.0, &mut t, Some(&mut codes)).unwrap();
    let mut count = 0;
    for i in 0..n {
        let ca = Circle::new(Vec2::new(apx[i], apy[i]), r[i]).with_vel(Vec2::new(avx[i], avy[i]));
        let cb = Circle::new(Vec2::new(bpx[i], bpy[i]), r[i]).with_vel(Vec2::new(bvx[i], bvy[i]));
        match sweep(&ca, &cb, 5.0).unwrap() {
            Some(c) => {
                count += 1;
                assert_eq!(t[i].to_bits(), c.t.to_bits());
                assert_eq!(codes[i], if c.kind == ContactKind::Hit { 1 } else { 2 });
            }
            None => assert!(t[i].is_infinite() && codes[i] == 0),
        }
    }
    assert_eq!(hits, count);
    assert!(count > 0 && count < n, "the sample has both outcomes: {count}");
    let short = Columns { px: &apx[..3], ..a };
    assert_eq!(sweep_many(&short, &b, 5.0, &mut t, None).unwrap_err().kind(), ErrorKind::Invalid);
}

#[test]
fn version_is_the_headers() {
    assert_eq!(version().0, sys::CC_VERSION_MAJOR);
    assert!(version_matches());
    assert!(result_string(sys::CC_HIT).starts_with("CC_HIT"));
}
