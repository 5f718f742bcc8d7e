//! The rolling pair functions, expected values derived by hand.
use circlecollide::{rolling_advance, sweep, sweep_rolling, sweep_segment_rolling, Circle, Segment, Vec2};

#[test]
fn a_rolling_ball_into_one_at_rest() {
    // radii 0.1, a from 0 at 2 with decel 0.4: 2t - 0.2t^2 = 0.8 at t = (2 - sqrt(3.36)) / 0.4
    let a = Circle::new(Vec2::new(0.0, 0.0), 0.1).with_vel(Vec2::new(2.0, 0.0));
    let b = Circle::new(Vec2::new(1.0, 0.0), 0.1);
    let c = sweep_rolling(&a, 0.4, &b, 0.0, 10.0).unwrap().expect("a hit");
    let expect: f64 = (2.0 - 3.36f64.sqrt()) / 0.4;
    assert!((c.t - expect).abs() < 1e-13);
    let af = Circle::new(Vec2::new(0.0f32, 0.0), 0.1).with_vel(Vec2::new(2.0, 0.0));
    let bf = Circle::new(Vec2::new(1.0f32, 0.0), 0.1);
    let cf = sweep_rolling(&af, 0.4f32, &bf, 0.0, 10.0).unwrap().expect("a hit in float");
    assert!((f64::from(cf.t) - c.t).abs() < 1e-5);
}

#[test]
fn stopping_short_misses_and_zero_deceleration_is_sweep() {
    // speed 2, decel 0.5: stops after 4; b's surface 1e-9 beyond
    let a: Circle<f64> = Circle::new(Vec2::new(0.0, 0.0), 0.25).with_vel(Vec2::new(2.0, 0.0));
    let far = Circle::new(Vec2::new(4.5 + 1e-9, 0.0), 0.25);
    assert!(sweep_rolling(&a, 0.5, &far, 0.0, 10.0).unwrap().is_none());
    assert_eq!(sweep_rolling(&a, 0.0, &far, 0.0, 10.0).unwrap(), sweep(&a, &far, 10.0).unwrap());
}

#[test]
fn a_wall_and_the_rest_position() {
    // radius 0.25, speed 2, decel 0.5, wall at x = 3.25: 2t - 0.25t^2 = 3 at t = 2
    let mut a: Circle<f64> = Circle::new(Vec2::new(0.0, 0.0), 0.25).with_vel(Vec2::new(2.0, 0.0));
    let wall = Segment::new(Vec2::new(3.25, -5.0), Vec2::new(3.25, 5.0));
    let c = sweep_segment_rolling(&a, 0.5, &wall, 10.0).unwrap().expect("a hit");
    assert!((c.t - 2.0).abs() < 1e-14);
    rolling_advance(&mut a, 0.5, 100.0).unwrap(); // stops after 2^2 / (2 * 0.5) = 4
    assert_eq!((a.pos.x, a.vel.x), (4.0, 0.0));
    assert!(rolling_advance(&mut a, -1.0, 1.0).is_err());
}
