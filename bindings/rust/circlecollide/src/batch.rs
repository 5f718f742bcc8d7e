//! sweep_many: many pairs in one call, over borrowed columns (structure of arrays).

use crate::{sys, Error, Result};

/// Columns of n circles (positions, velocities, radii), borrowed for one call.
#[derive(Debug, Clone, Copy)]
pub struct Columns<'a> {
    /// Centres' x.
    pub px: &'a [f64],
    /// Centres' y.
    pub py: &'a [f64],
    /// Velocities' x.
    pub vx: &'a [f64],
    /// Velocities' y.
    pub vy: &'a [f64],
    /// Radii.
    pub radius: &'a [f64],
}

impl<'a> Columns<'a> {
    /// The common length, or `None` when the columns differ in length.
    pub fn len(&self) -> Option<usize> {
        let n = self.px.len();
        [self.py.len(), self.vx.len(), self.vy.len(), self.radius.len()].iter().all(|&m| m == n).then_some(n)
    }

    /// True when the columns are all empty.
    pub fn is_empty(&self) -> bool {
        self.len() == Some(0)
    }

    fn soa(&self) -> sys::cc_circle_soa {
        sys::cc_circle_soa {
            px: self.px.as_ptr(),
            py: self.py.as_ptr(),
            vx: self.vx.as_ptr(),
            vy: self.vy.as_ptr(),
            radius: self.radius.as_ptr(),
        }
    }
}

/// Sweeps pairs (a[i], b[i]): `t_out[i]` = time of first contact, 0 for an overlap, +inf for a
/// miss; `codes[i]` (if given) = `CC_MISS`, `CC_HIT` or `CC_OVERLAP`. Returns how many pairs hit
/// or overlap. A length mismatch or an invalid input is `ErrorKind::Invalid`, nothing written;
/// the error names the first row holding a bad value (`row 3: a.radius[3] must be finite and > 0,
/// got NaN`).
pub fn sweep_many(
    a: &Columns<'_>,
    b: &Columns<'_>,
    t_max: f64,
    t_out: &mut [f64],
    codes: Option<&mut [i32]>,
) -> Result<usize> {
    const CALL: &str = "sweep_many";
    let n = a.len().ok_or_else(|| Error::new(sys::CC_ERR_INVALID, CALL, "a's columns differ in length"))?;
    if b.len() != Some(n) || t_out.len() != n || codes.as_ref().is_some_and(|c| c.len() != n) {
        return Err(Error::new(
            sys::CC_ERR_INVALID,
            CALL,
            format!("b's columns, t_out and codes must hold {n} values (a's)"),
        ));
    }
    let (sa, sb) = (a.soa(), b.soa());
    let codes_ptr = codes.map_or(core::ptr::null_mut(), |c| c.as_mut_ptr());
    // SAFETY: every column and output holds n elements (checked above).
    let r = unsafe { sys::cc_sweep_many(n, &sa, &sb, t_max, t_out.as_mut_ptr(), codes_ptr) };
    if r < 0 {
        let code = i32::try_from(r).unwrap_or(sys::CC_ERR_INVALID);
        return Err(match first_bad_row(a, b) {
            Some(detail) => Error::new(code, CALL, detail),
            None => Error::new(code, CALL, format!("t_max must be >= 0, got {t_max}")),
        });
    }
    Ok(r as usize)
}

/// The first row whose position or velocity is not finite, or whose radius is not finite and
/// > 0, in either batch (the library says only that one is).
fn first_bad_row(a: &Columns<'_>, b: &Columns<'_>) -> Option<String> {
    let bad = |c: &Columns<'_>, i: usize| -> Option<&'static str> {
        if !(c.px[i].is_finite() && c.py[i].is_finite()) {
            Some("pos")
        } else if !(c.vx[i].is_finite() && c.vy[i].is_finite()) {
            Some("vel")
        } else if !(c.radius[i].is_finite() && c.radius[i] > 0.0) {
            Some("radius")
        } else {
            None
        }
    };
    (0..a.px.len()).find_map(|i| {
        [("a", a), ("b", b)].into_iter().find_map(|(name, c)| {
            bad(c, i).map(|field| {
                let value = match field {
                    "pos" => format!("({}, {})", c.px[i], c.py[i]),
                    "vel" => format!("({}, {})", c.vx[i], c.vy[i]),
                    _ => c.radius[i].to_string(),
                };
                let rule = if field == "radius" { "finite and > 0" } else { "finite" };
                format!("row {i}: {name}.{field}[{i}] must be {rule}, got {value}")
            })
        })
    })
}
