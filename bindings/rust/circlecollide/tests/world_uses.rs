//! WorldDef::uses (1.2): a world reserves only what it uses, and refuses what it left out.
#![cfg(cc_has_world)]

use circlecollide::*;

fn gas(uses: u32) -> World<'static> {
    let mut w = World::new(&WorldDef { max_circles: 32, uses, ..WorldDef::default() }).unwrap();
    for i in 0..12 {
        let c = Circle {
            vel: Vec2::new(1.0 - 0.125 * i as f64, 0.5),
            ..Circle::new(Vec2::new(3.0 * (i % 4) as f64, 3.0 * (i / 4) as f64), 0.5)
        };
        w.add_circle(&c).unwrap();
    }
    w.step(2.0).unwrap();
    w
}

#[test]
fn the_default_uses_everything_and_a_world_of_no_uses_refuses_properties() {
    assert_eq!(WorldDef::default().uses, USES_ALL);
    assert_eq!((USES_PROPS, USES_SENSORS, USES_ROLLING, USES_CLOTH, USES_ALL), (1, 2, 4, 8, 0xffff));
    let mut w = gas(0);
    let id = CircleId(0);
    let (h, p) = (w.hash(), w.circle_props(id).unwrap());
    assert_eq!(p, CircleProps::default());
    for q in [
        CircleProps { restitution: 0.5, ..p },
        CircleProps { category: 2, ..p },
        CircleProps { rolling_decel: 0.25, ..p },
        CircleProps { sensor: true, ..p },
    ] {
        assert_eq!(w.set_circle_props(id, &q).unwrap_err().code(), sys::CC_ERR_INVALID);
        assert_eq!(w.hash(), h, "a refused call changes nothing");
    }
    w.set_circle_props(id, &p).unwrap(); // the defaults it has: accepted
    assert!(World::new(&WorldDef { rolling_decel: 0.5, uses: USES_PROPS, ..WorldDef::default() }).is_err());
    // a sensor world takes a sensor, and a plain scene runs alike with and without the reserves
    let mut s = gas(USES_SENSORS);
    s.set_circle_props(CircleId(1), &CircleProps { sensor: true, ..p }).unwrap();
    assert_eq!(gas(0).hash(), gas(USES_ALL).hash());
}
