//! What was wrong with a call's arguments, found only after the library refused them (the
//! library says `CC_ERR_INVALID`, not which argument): each check is the header's rule for one
//! argument, spelled as a message naming it and its value. A call that succeeds pays nothing.

use core::cmp::Ordering;

use crate::{Circle, Error, Real, Segment, Vec2};

/// a > b, false for NaN (the header's rules are written so that NaN fails them).
fn above<T: Real>(a: T, b: T) -> bool {
    a.partial_cmp(&b) == Some(Ordering::Greater)
}

/// a >= b, false for NaN.
fn at_least<T: Real>(a: T, b: T) -> bool {
    matches!(a.partial_cmp(&b), Some(Ordering::Greater | Ordering::Equal))
}

fn vec<T: Real>(v: Vec2<T>) -> String {
    format!("({}, {})", v.x, v.y)
}

/// The header's "Valid input" for a circle named `name`.
pub(crate) fn circle<T: Real>(name: &str, c: &Circle<T>) -> Option<String> {
    if !(c.pos.x.is_finite() && c.pos.y.is_finite()) {
        return Some(format!("{name}.pos must be finite, got {}", vec(c.pos)));
    }
    if !(c.vel.x.is_finite() && c.vel.y.is_finite()) {
        return Some(format!("{name}.vel must be finite, got {}", vec(c.vel)));
    }
    if !(c.radius.is_finite() && above(c.radius, T::ZERO)) {
        return Some(format!("{name}.radius must be finite and > 0, got {}", c.radius));
    }
    if !above(c.mass, T::ZERO) {
        return Some(format!("{name}.mass must be > 0 (INFINITY: immovable), got {}", c.mass));
    }
    None
}

/// A wall's end points: finite.
pub(crate) fn segment<T: Real>(s: &Segment<T>) -> Option<String> {
    let ok = |v: Vec2<T>| v.x.is_finite() && v.y.is_finite();
    (!(ok(s.a) && ok(s.b))).then(|| format!("the segment's ends must be finite, got {} and {}", vec(s.a), vec(s.b)))
}

/// A sweep's horizon: >= 0 (INFINITY allowed), not NaN.
pub(crate) fn t_max<T: Real>(t: T) -> Option<String> {
    (!at_least(t, T::ZERO)).then(|| format!("t_max must be >= 0, got {t}"))
}

/// A time, a time step or a deceleration: finite and >= 0.
pub(crate) fn nonneg_finite<T: Real>(name: &str, x: T) -> Option<String> {
    (!(x.is_finite() && at_least(x, T::ZERO))).then(|| format!("{name} must be finite and >= 0, got {x}"))
}

/// A restitution in [0, 1].
pub(crate) fn restitution<T: Real>(e: T) -> Option<String> {
    (!(at_least(e, T::ZERO) && at_least(T::ONE, e))).then(|| format!("restitution must be in [0, 1], got {e}"))
}

/// Two immovable circles cannot respond to each other.
pub(crate) fn not_both_immovable<T: Real>(a: &Circle<T>, b: &Circle<T>) -> Option<String> {
    (a.is_immovable() && b.is_immovable())
        .then(|| "a and b are both immovable (mass INFINITY): two immovable circles cannot respond".to_string())
}

/// A contact normal: a unit vector up to the precision's tolerance.
pub(crate) fn unit_normal<T: Real>(n: Vec2<T>) -> Option<String> {
    let len = n.length();
    let d = if len > T::ONE { len - T::ONE } else { T::ONE - len };
    (!at_least(T::NORMAL_TOLERANCE, d)).then(|| {
        format!("contact.normal must be a unit vector (length within {} of 1), got length {len}", T::NORMAL_TOLERANCE)
    })
}

/// The error for `code` from `call`, with the first cause found among `causes`.
pub(crate) fn refused(code: i32, call: &'static str, causes: impl IntoIterator<Item = Option<String>>) -> Error {
    match causes.into_iter().flatten().next() {
        Some(detail) => Error::new(code, call, detail),
        None => Error::from_code(code, call),
    }
}
