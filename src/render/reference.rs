//! The reference renderer: one pixel at a time, [`Camera::ray`] and each
//! kind's scalar `reference::intersect`.
//!
//! [`Camera::ray`]: crate::camera::Camera::ray

#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
use super::plan::Object;
use super::plan::Plan;
use super::{Frame, counters, normal};
use crate::Ray;
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
use crate::hit::Intersection;

/// Renders rows `rows` of `plan` into `frame`, calling `on_row` after each.
pub(super) fn render_rows(
    plan: &Plan,
    frame: &mut Frame,
    rows: core::ops::Range<u32>,
    on_row: &mut dyn FnMut(),
) {
    let w = plan.res[0];
    let ch = plan.channels;
    let track = ch.tracks_objects();
    for y in rows {
        for x in 0..w {
            let ray = plan.camera.ray(x, y);
            let (t, who) = nearest(plan, &ray);
            let at = y as usize * w as usize + x as usize;
            frame.depth[at] = t;
            if track && ch.id {
                frame.id[at] = if who == 0 {
                    0
                } else {
                    plan.ids[who as usize - 1]
                };
            }
            if ch.normal {
                frame.normal[at] = if who == 0 {
                    [0.0; 3]
                } else {
                    normal_at(plan, who - 1, &ray, t)
                };
            }
        }
        on_row();
    }
}

/// The nearest hit in `[0, ∞)`: its `t` (`+∞` for none) and object number
/// plus one (0 for none). A later object replaces an earlier one only when
/// strictly nearer.
fn nearest(plan: &Plan, ray: &Ray) -> (f32, u32) {
    #[allow(unused_mut)] // Nothing to update with no kind compiled in.
    let mut n = Nearest {
        t: f32::INFINITY,
        who: 0,
    };
    // With no kind compiled in there is nothing to dispatch on.
    #[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
    if let Some(objects) = &plan.generic {
        for (i, o) in objects.iter().enumerate() {
            let t = match *o {
                #[cfg(feature = "plane")]
                Object::Plane(p, _) => {
                    counters::bump(counters::PLANE);
                    crate::plane::reference::intersect(ray, &p).nearest(0.0, n.t)
                }
                #[cfg(feature = "sphere")]
                Object::Sphere(s, _) => {
                    counters::bump(counters::SPHERE);
                    crate::sphere::reference::intersect(ray, &s).nearest(0.0, n.t)
                }
                #[cfg(feature = "quadric")]
                Object::Quadric(q, _) => {
                    counters::bump(counters::QUADRIC);
                    crate::quadric::reference::intersect(ray, &q).nearest(0.0, n.t)
                }
            };
            n.consider(t, i);
        }
        return (n.t, n.who);
    }
    #[allow(unused_variables)]
    let [pb, sb, qb] = plan.bases().map(|b| b as usize);
    #[cfg(feature = "plane")]
    for (i, p) in plan.planes.iter().enumerate() {
        counters::bump(counters::PLANE);
        n.consider(
            crate::plane::reference::intersect(ray, p).nearest(0.0, n.t),
            pb + i,
        );
    }
    #[cfg(feature = "sphere")]
    for (i, s) in plan.spheres.iter().enumerate() {
        counters::bump(counters::SPHERE);
        n.consider(
            crate::sphere::reference::intersect(ray, s).nearest(0.0, n.t),
            sb + i,
        );
    }
    #[cfg(feature = "quadric")]
    for (i, q) in plan.quadrics.iter().enumerate() {
        counters::bump(counters::QUADRIC);
        n.consider(
            crate::quadric::reference::intersect(ray, q).nearest(0.0, n.t),
            qb + i,
        );
    }
    (n.t, n.who)
}

/// The running nearest hit of one ray.
struct Nearest {
    t: f32,
    /// Object number plus one, 0 for none.
    who: u32,
}

impl Nearest {
    /// Takes `t` if there is one and it is strictly nearer.
    #[inline(always)]
    fn consider(&mut self, t: Option<f32>, i: usize) {
        if let Some(t) = t
            && t < self.t
        {
            self.t = t;
            self.who = i as u32 + 1;
        }
    }
}

/// The unit normal, facing the ray, of object `i` at `t`.
#[allow(unused_variables)] // With kinds compiled out.
fn normal_at(plan: &Plan, i: u32, ray: &Ray, t: f32) -> [f32; 3] {
    counters::bump(counters::NORMAL);
    let [_, sb, qb] = plan.bases();
    let (o, d) = (ray.origin.to_array(), ray.dir.to_array());
    let p = normal::hit_point(o, d, t);
    #[allow(unused_mut, unused_assignments)]
    let mut v = [0.0f32; 3];
    #[cfg(feature = "plane")]
    if i < sb {
        v = plan.planes[i as usize].normal.to_array();
    }
    #[cfg(feature = "sphere")]
    if (sb..qb).contains(&i) {
        v = normal::sphere(p, plan.spheres[(i - sb) as usize].center.to_array());
    }
    #[cfg(feature = "quadric")]
    if i >= qb {
        v = normal::quadric(&plan.quadrics[(i - qb) as usize].coeffs, p);
    }
    normal::facing_unit(v, d)
}
