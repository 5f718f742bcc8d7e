//! sweep_many: many pairs in one call, over borrowed columns (structure of arrays).

use crate::{check, sys, Error, Result};

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
/// or overlap. Any length mismatch or invalid input is `ErrorKind::Invalid`, nothing written.
pub fn sweep_many(a: &Columns<'_>, b: &Columns<'_>, t_max: f64, t_out: &mut [f64], codes: Option<&mut [i32]>) -> Result<usize> {
    let invalid = Error { code: sys::CC_ERR_INVALID };
    let n = a.len().ok_or(invalid)?;
    if b.len() != Some(n) || t_out.len() != n || codes.as_ref().is_some_and(|c| c.len() != n) {
        return Err(invalid);
    }
    let (sa, sb) = (a.soa(), b.soa());
    let codes_ptr = codes.map_or(core::ptr::null_mut(), |c| c.as_mut_ptr());
    // SAFETY: every column and output holds n elements (checked above).
    let r = unsafe { sys::cc_sweep_many(n, &sa, &sb, t_max, t_out.as_mut_ptr(), codes_ptr) };
    let r = i32::try_from(r).map_or(Ok(r as usize), |c| check(c).map(|c| c as usize))?;
    Ok(r)
}
