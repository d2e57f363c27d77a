//! The x4 renderer: four pixels of a row at a time, [`Camera::ray4`] and
//! each kind's `x4::intersect` against the object splatted to four lanes.
//! The nearest-hit rule, the object numbering and the normal arithmetic are
//! the reference renderer's, lane by lane, so the frames are the same bits.
//!
//! [`Camera::ray4`]: crate::camera::Camera::ray4

#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
use super::plan::Object;
use super::plan::Plan;
use super::{Frame, counters, normal};
use crate::ray4::Ray4;
use wide::{f32x4, i32x4};

/// The running nearest hit of four rays.
struct Nearest {
    t: f32x4,
    /// Object number plus one, 0 for none (kept only when tracking).
    who: i32x4,
    track: bool,
}

impl Nearest {
    /// Takes `t` where `ok` and strictly nearer, as the reference does.
    #[inline(always)]
    fn consider(&mut self, (ok, t): (f32x4, f32x4), i: usize) {
        let closer = ok & t.simd_lt(self.t);
        self.t = closer.select(t, self.t);
        if self.track {
            self.who = closer.select(i32x4::splat(i as i32 + 1), self.who);
        }
    }
}

/// Renders rows `rows` of `plan` into `frame`, calling `on_row` after each.
pub(super) fn render_rows(
    plan: &Plan,
    frame: &mut Frame,
    rows: core::ops::Range<u32>,
    on_row: &mut dyn FnMut(),
) {
    let w = plan.res[0];
    let ch = plan.channels;
    for y in rows {
        for x in (0..w).step_by(4) {
            // The last packet of a row repeats its last pixel in the lanes
            // past the edge; those lanes are computed and dropped.
            let px = [0, 1, 2, 3].map(|l| [(x + l).min(w - 1), y]);
            let rays = plan.camera.ray4(px);
            let hit = nearest(plan, &rays);
            let lanes = (w - x).min(4) as usize;
            let at = y as usize * w as usize + x as usize;
            let t = hit.t.to_array();
            frame.depth[at..at + lanes].copy_from_slice(&t[..lanes]);
            let who = hit.who.to_array().map(|i| i as u32);
            if ch.id {
                for (id, &w) in frame.id[at..at + lanes].iter_mut().zip(&who) {
                    *id = if w == 0 { 0 } else { plan.ids[w as usize - 1] };
                }
            }
            if ch.normal {
                let n = normals(plan, &rays, hit.t, who);
                frame.normal[at..at + lanes].copy_from_slice(&n[..lanes]);
            }
        }
        on_row();
    }
}

/// The nearest hit in `[0, ∞)` of four rays, as
/// [`super::reference`](mod@super::reference) finds it.
#[inline(always)]
fn nearest(plan: &Plan, rays: &Ray4) -> Nearest {
    let zero = f32x4::ZERO;
    #[allow(unused_mut)] // Nothing to update with no kind compiled in.
    let mut n = Nearest {
        t: f32x4::splat(f32::INFINITY),
        who: i32x4::ZERO,
        track: plan.channels.tracks_objects(),
    };
    // With no kind compiled in there is nothing to dispatch on.
    #[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
    if let Some(objects) = &plan.generic {
        for (i, o) in objects.iter().enumerate() {
            let hit = match *o {
                #[cfg(feature = "plane")]
                Object::Plane(_, p) => {
                    counters::bump(counters::PLANE);
                    crate::plane::x4::intersect(rays, &p).nearest(zero, n.t)
                }
                #[cfg(feature = "sphere")]
                Object::Sphere(_, s) => {
                    counters::bump(counters::SPHERE);
                    crate::sphere::x4::intersect(rays, &s).nearest(zero, n.t)
                }
                #[cfg(feature = "quadric")]
                Object::Quadric(_, q) => {
                    counters::bump(counters::QUADRIC);
                    crate::quadric::x4::intersect(rays, &q).nearest(zero, n.t)
                }
            };
            n.consider(hit, i);
        }
        return n;
    }
    #[allow(unused_variables)]
    let [pb, sb, qb] = plan.bases().map(|b| b as usize);
    #[cfg(feature = "plane")]
    for (i, p) in plan.planes4.iter().enumerate() {
        counters::bump(counters::PLANE);
        n.consider(
            crate::plane::x4::intersect(rays, p).nearest(zero, n.t),
            pb + i,
        );
    }
    #[cfg(feature = "sphere")]
    for (i, s) in plan.spheres4.iter().enumerate() {
        counters::bump(counters::SPHERE);
        n.consider(
            crate::sphere::x4::intersect(rays, s).nearest(zero, n.t),
            sb + i,
        );
    }
    #[cfg(feature = "quadric")]
    for (i, q) in plan.quadrics4.iter().enumerate() {
        counters::bump(counters::QUADRIC);
        n.consider(
            crate::quadric::x4::intersect(rays, q).nearest(zero, n.t),
            qb + i,
        );
    }
    n
}

/// The unit normals, facing the rays, of each lane's object at its `t`:
/// for each kind some lane hit, that kind's parameters gathered lane by
/// lane and its normal computed four-wide.
#[allow(unused_variables, unused_mut)] // With kinds compiled out.
fn normals(plan: &Plan, rays: &Ray4, t: f32x4, who: [u32; 4]) -> [[f32; 3]; 4] {
    counters::bump(counters::NORMAL);
    let [_, sb, qb] = plan.bases();
    let p = normal::hit_point(rays.origin, rays.dir, t);
    let mut out = [[0.0f32; 3]; 4];
    // Object number per lane, or None for no hit.
    let obj = who.map(|w| w.checked_sub(1));
    let mut emit = |v: [f32x4; 3], mine: [bool; 4]| {
        let n = normal::facing_unit(v, rays.dir).map(f32x4::to_array);
        for l in 0..4 {
            if mine[l] {
                out[l] = [n[0][l], n[1][l], n[2][l]];
            }
        }
    };
    let gather = |f: &dyn Fn(u32) -> f32, range: core::ops::Range<u32>| {
        f32x4::from(obj.map(|o| match o {
            Some(i) if range.contains(&i) => f(i - range.start),
            _ => f(0),
        }))
    };
    #[cfg(feature = "plane")]
    {
        let mine = obj.map(|o| o.is_some_and(|i| i < sb));
        if mine.contains(&true) {
            let v = [0, 1, 2].map(|c| gather(&|i| plan.planes[i as usize].normal[c], 0..sb));
            emit(v, mine);
        }
    }
    #[cfg(feature = "sphere")]
    {
        let mine = obj.map(|o| o.is_some_and(|i| (sb..qb).contains(&i)));
        if mine.contains(&true) {
            let c = [0, 1, 2].map(|c| gather(&|i| plan.spheres[i as usize].center[c], sb..qb));
            emit(normal::sphere(p, c), mine);
        }
    }
    #[cfg(feature = "quadric")]
    {
        let mine = obj.map(|o| o.is_some_and(|i| i >= qb));
        if mine.contains(&true) {
            let k: [f32x4; 10] = core::array::from_fn(|j| {
                gather(&|i| plan.quadrics[i as usize].coeffs[j], qb..u32::MAX)
            });
            emit(normal::quadric(&k, p), mine);
        }
    }
    out
}
