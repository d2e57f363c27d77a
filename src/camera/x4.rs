//! Four camera rays at once, bit-identical to [`super::Camera::ray`]: the
//! same [`super::filter`] filter at [`F64x4`], undecided lanes from the
//! oracle (correct rounding is unique, so the two agree by construction).

use super::{Camera, filter};
use crate::num::Real;
use crate::num::certify::{needs_probe, subnormals_work};
use crate::num::real::{F64x4, Real4};
use crate::ray4::Ray4;
use wide::f32x4;

/// Whether subnormals are flushed, out of line: the kernels ask only on the
/// rare packets where it matters.
#[cold]
#[inline(never)]
fn flushing() -> bool {
    !subnormals_work()
}

impl Camera {
    /// The rays of four arbitrary pixels `[[X, Y]; 4]`.
    ///
    /// ```
    /// use rayoracle::camera::CameraParams;
    /// use glam::Vec3;
    /// let cam = CameraParams::new(Vec3::ZERO, -Vec3::Z, Vec3::Y, 1.0, [8, 6]).build().unwrap();
    /// let px = [[0, 0], [7, 5], [3, 2], [4, 1]];
    /// assert_eq!(cam.ray4(px).to_rays(), px.map(|[x, y]| cam.ray(x, y)));
    /// ```
    #[inline]
    pub fn ray4(&self, pixels: [[u32; 2]; 4]) -> Ray4 {
        let [w, h] = self.params.res;
        let nx = F64x4::from(pixels.map(|p| filter::numerator(p[0], w)));
        let ny = F64x4::from(pixels.map(|p| filter::numerator(p[1], h)));
        let d = self.params.dir.to_array();
        let mut out = [[0.0f32; 4]; 3];
        let mut undecided = [[false; 3]; 4];
        let tiny = <F64x4 as Real>::splat(f32::MIN_POSITIVE as f64);
        let mut normal = <F64x4 as Real>::splat(1.0).gt(tiny);
        for i in 0..3 {
            let s = |x: f64| <F64x4 as crate::num::Real>::splat(x);
            let (r, ok) = filter::component(
                s(d[i] as f64),
                s(self.unit[0][i]),
                s(self.unit[1][i]),
                nx,
                ny,
                1.0,
            );
            out[i] = r.to_f32();
            normal = normal & r.abs().gt(tiny);
            for (lane, ok) in ok.lanes().into_iter().enumerate() {
                undecided[lane][i] = !ok;
            }
        }
        // Per packet, as [`filter::flushed`] per pixel: with subnormals
        // flushed, every lane goes to the oracle if any component is below
        // the least normal f32 or `dir` has a subnormal component (rare).
        if (!F64x4::all(normal) || needs_probe(&d, &[])) && flushing() {
            undecided = [[true; 3]; 4];
        }
        for (lane, [px, py]) in pixels.into_iter().enumerate() {
            if undecided[lane].contains(&true) {
                let mut dir = [0, 1, 2].map(|i| out[i][lane]);
                self.escalate(&mut dir, undecided[lane], px, py);
                (0..3).for_each(|i| out[i][lane] = dir[i]);
            }
        }
        let splat = |v: glam::Vec3| v.to_array().map(f32x4::splat);
        let dir = out.map(f32x4::from);
        Ray4 {
            origin: splat(self.params.position),
            dir,
        }
    }

    /// Four consecutive pixels of row `py`: `(px, py) … (px + 3, py)`.
    ///
    /// ```
    /// use rayoracle::camera::CameraParams;
    /// use glam::Vec3;
    /// let cam = CameraParams::new(Vec3::ZERO, -Vec3::Z, Vec3::Y, 1.0, [8, 6]).build().unwrap();
    /// assert_eq!(cam.ray4_row(4, 2).to_rays(), [4, 5, 6, 7].map(|x| cam.ray(x, 2)));
    /// ```
    #[inline]
    pub fn ray4_row(&self, px: u32, py: u32) -> Ray4 {
        self.ray4([[px, py], [px + 1, py], [px + 2, py], [px + 3, py]])
    }

    /// A 2×2 tile: `(px, py), (px + 1, py), (px, py + 1), (px + 1, py + 1)`.
    ///
    /// ```
    /// use rayoracle::camera::CameraParams;
    /// use glam::Vec3;
    /// let cam = CameraParams::new(Vec3::ZERO, -Vec3::Z, Vec3::Y, 1.0, [8, 6]).build().unwrap();
    /// let want = [[2, 3], [3, 3], [2, 4], [3, 4]].map(|[x, y]| cam.ray(x, y));
    /// assert_eq!(cam.ray4_tile(2, 3).to_rays(), want);
    /// ```
    #[inline]
    pub fn ray4_tile(&self, px: u32, py: u32) -> Ray4 {
        self.ray4([[px, py], [px + 1, py], [px, py + 1], [px + 1, py + 1]])
    }
}
