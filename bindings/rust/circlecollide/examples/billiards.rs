//! A break shot: a triangle of 15 balls, a cue ball fired into it, a table of four cushions.
//! Simulated in exact mode; prints every 10th contact, then the table and the energy balance.
//!
//!     cargo run --example billiards

use circlecollide::*;

fn main() -> Result<()> {
    let (w, h, r) = (2.54, 1.27, 0.028_575); // table (m) and ball radius of a pool table
    let mut contacts = 0usize;
    let mut world = World::with_callback(
        &WorldDef { max_circles: 16, max_segments: 4, restitution: 1.0, ..WorldDef::default() },
        |e: &ContactEvent| {
            if contacts % 10 == 0 {
                let with = match e.other {
                    Other::Circle(b) => format!("ball {}", b.0),
                    Other::Wall(s) => format!("cushion {}", s.0),
                };
                println!("t = {:8.5} s  ball {:2} hits {:10}  impulse {:.4}", e.t, e.a.0, with, e.impulse);
            }
            contacts += 1;
        },
    )?;
    for (a, b) in [((0.0, 0.0), (w, 0.0)), ((w, 0.0), (w, h)), ((w, h), (0.0, h)), ((0.0, h), (0.0, 0.0))] {
        world.add_segment(&Segment::new(Vec2::new(a.0, a.1), Vec2::new(b.0, b.1)))?;
    }
    // the rack: rows of 1..5 balls, touching plus a hair, apex at three quarters of the table
    let gap = 2.0 * r * 1.0001;
    for row in 0..5 {
        for k in 0..=row {
            let x = 0.75 * w + row as f64 * gap * 0.866_025_403_784_438_6;
            let y = h / 2.0 + (k as f64 - row as f64 / 2.0) * gap;
            world.add_circle(&Circle::new(Vec2::new(x, y), Vec2::new(0.0, 0.0), r).with_mass(0.17))?;
        }
    }
    let cue = world.add_circle(&Circle::new(Vec2::new(0.25 * w, h / 2.0 + 0.002), Vec2::new(8.0, 0.0), r).with_mass(0.17))?;
    let energy = |w: &World| w.circles().iter().map(|(_, c)| 0.5 * c.mass * (c.vel.x * c.vel.x + c.vel.y * c.vel.y)).sum::<f64>();
    let e0 = energy(&world);
    let outcome = world.step(2.0)?;
    let stats = world.stats();
    let e1 = energy(&world);
    println!("\nafter 2 s ({outcome:?}): {} collisions, {} events", stats.collisions, stats.events);
    for (id, c) in world.circles() {
        let tag = if id == cue { " (cue)" } else { "" };
        println!("ball {:2}{tag:6} at ({:.4}, {:.4}) moving ({:+.4}, {:+.4})", id.0, c.pos.x, c.pos.y, c.vel.x, c.vel.y);
    }
    println!("kinetic energy {e0:.9} J -> {e1:.9} J (relative change {:.1e})", (e1 - e0) / e0);
    println!("library {}.{}.{}", version().0, version().1, version().2);
    drop(world); // ends the closure's borrow of `contacts`
    println!("{contacts} contacts reported to the callback");
    Ok(())
}
