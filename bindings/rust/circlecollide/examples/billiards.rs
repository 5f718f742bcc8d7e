//! A break shot: a triangle of 15 balls, a cue ball fired into it, a table of four cushions and
//! six pockets. Simulated in exact mode for 10 s with the 1.1 properties: balls of restitution
//! 0.95, cushions of 0.75 (each contact takes the smaller), and pockets that are sensors (a ball
//! whose centre enters one is taken off the table). Prints every 10th contact and every pocketed
//! ball, then the table and the energy balance.
//!
//!     cargo run --example billiards

use std::cell::RefCell;

use circlecollide::*;

fn main() -> Result<()> {
    let (w, h, r) = (2.54, 1.27, 0.028_575); // table (m) and ball radius of a pool table
    let pocket_r = 0.06; // a ball is pocketed when its centre comes within this of a pocket's
    let mut contacts = 0usize;
    let pocketed = RefCell::new(Vec::new()); // (ball, time), filled by the sensor callback
    let mut world = World::with_callbacks(
        &WorldDef {
            max_circles: 22,
            max_segments: 4,
            restitution: 0.95, // what new balls and cushions get; cushions are set to 0.75 below
            rest_speed: 1e-3,
            rolling_decel: 0.15, // cloth: every ball slows along its motion and stops exactly
            ..WorldDef::default()
        },
        |e: &ContactEvent| {
            if contacts % 10 == 0 {
                let with = match e.other {
                    Other::Circle(b) => format!("ball {}", b.0),
                    Other::Wall(s) => format!("cushion {}", s.0),
                };
                println!("t = {:8.5} s  ball {:2} hits {:10}  impulse {:.3e} N s", e.t, e.a.0, with, e.impulse);
            }
            contacts += 1;
        },
        |e: &SensorEvent| {
            if e.begin {
                pocketed.borrow_mut().push((e.visitor, e.t));
            }
        },
    )?;
    for (a, b) in [((0.0, 0.0), (w, 0.0)), ((w, 0.0), (w, h)), ((w, h), (0.0, h)), ((0.0, h), (0.0, 0.0))] {
        let cushion = world.add_segment(&Segment::new(Vec2::new(a.0, a.1), Vec2::new(b.0, b.1)))?;
        world.set_segment_props(cushion, &SegmentProps { restitution: 0.75, ..world.segment_props(cushion)? })?;
    }
    // the pockets: immovable sensors of radius (pocket - ball), so that they sense a ball whose
    // centre comes within pocket_r of theirs
    let mut pockets = Vec::new();
    for (x, y) in [(0.0, 0.0), (w / 2.0, 0.0), (w, 0.0), (0.0, h), (w / 2.0, h), (w, h)] {
        let p = world.add_circle(&Circle::new(Vec2::new(x, y), pocket_r - r).immovable())?;
        world.set_circle_props(p, &CircleProps { sensor: true, ..world.circle_props(p)? })?;
        pockets.push(p);
    }
    // the rack: rows of 1..5 balls, touching plus a hair, apex at three quarters of the table
    let gap = 2.0 * r * 1.0001;
    for row in 0..5 {
        for k in 0..=row {
            let x = 0.75 * w + row as f64 * gap * 0.866_025_403_784_438_6;
            let y = h / 2.0 + (k as f64 - row as f64 / 2.0) * gap;
            world.add_circle(&Circle::new(Vec2::new(x, y), r).with_mass(0.17))?;
        }
    }
    let cue = world.add_circle(
        &Circle::new(Vec2::new(0.25 * w, h / 2.0 + 0.002), r).with_vel(Vec2::new(8.0, 0.0)).with_mass(0.17),
    )?;
    let balls = |w: &World| w.circles().into_iter().filter(|(id, _)| !pockets.contains(id)).collect::<Vec<_>>();
    let energy =
        |w: &World| balls(w).iter().map(|(_, c)| 0.5 * c.mass * (c.vel.x * c.vel.x + c.vel.y * c.vel.y)).sum::<f64>();
    let e0 = energy(&world);
    // steps of 10 ms until every ball rests (at most 60 s); pocketed balls leave after each
    println!("(every tenth contact is shown; all are counted)");
    let mut taken = 0;
    for _ in 0..6000 {
        if balls(&world).iter().all(|(_, c)| c.vel.x == 0.0 && c.vel.y == 0.0) {
            break;
        }
        world.step(0.01)?;
        let list = pocketed.borrow();
        for &(ball, t) in &list[taken..] {
            if world.circle(ball).is_ok() {
                // (a ball may enter a pocket twice within one step: it leaves once)
                println!("t = {t:8.5} s  ball {:2} pocketed", ball.0);
                world.remove_circle(ball)?;
            }
        }
        taken = list.len();
    }
    let stats = world.stats();
    println!(
        "\nafter {:.2} s: {} collisions, {} events, impulse on the cushions {:.4} N s",
        world.time(),
        stats.collisions,
        stats.events,
        stats.wall_impulse
    );
    for (id, c) in balls(&world) {
        let tag = if id == cue { " (cue)" } else { "" };
        if c.vel.x == 0.0 && c.vel.y == 0.0 {
            println!("ball {:2}{tag:6} at ({:.4}, {:.4}), at rest", id.0, c.pos.x, c.pos.y);
        } else {
            println!(
                "ball {:2}{tag:6} at ({:.4}, {:.4}) moving ({:+.3e}, {:+.3e})",
                id.0, c.pos.x, c.pos.y, c.vel.x, c.vel.y
            );
        }
    }
    println!("kinetic energy {e0:.6} J -> {:.6} J; state hash {:016x}", energy(&world), world.hash());
    println!("library {}.{}.{}", version().0, version().1, version().2);
    drop(world); // ends the closures' borrows of `contacts` and `pocketed`
    println!("{contacts} contacts reported to the callback");
    Ok(())
}
