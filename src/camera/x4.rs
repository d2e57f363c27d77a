//! Four camera rays at once, bit-identical to [`super::Camera::ray`]: the
//! same [`super::filter`] filter at [`F64x4`], undecided lanes from the
//! oracle (correct rounding is unique, so the two agree by construction).

use super::{Camera, filter};
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
        // Baseline lanes: the filter is so short that an AVX2 function
        // entered through run-time dispatch costs more than it saves
        // (kernels bench, camera/x4/packed: 129 Mrays/s on SSE2 against
        // 104 through AVX2 dispatch).
        self.ray4_in::<F64x4>(pixels)
    }

    /// [`Camera::ray4`] over any four-lane [`Real4`]: the same bits on
    /// every one, since each lane is correctly rounded.
    #[inline(always)]
    fn ray4_in<L: Real4>(&self, pixels: [[u32; 2]; 4]) -> Ray4 {
        let [w, h] = self.params.res;
        let nx = L::from_array(pixels.map(|p| filter::numerator(p[0], w)));
        let ny = L::from_array(pixels.map(|p| filter::numerator(p[1], h)));
        let d = self.params.dir.to_array();
        let tiny = L::splat(f32::MIN_POSITIVE as f64);
        let mut normal = L::splat(1.0).gt(tiny);
        let mut dir = [f32x4::ZERO; 3];
        let mut ok = [normal; 3];
        for i in 0..3 {
            let (r, k) = filter::component(
                L::splat(d[i] as f64),
                L::splat(self.unit[0][i]),
                L::splat(self.unit[1][i]),
                nx,
                ny,
                1.0,
            );
            (dir[i], ok[i]) = (r.narrow(), k);
            normal = normal & r.abs().gt(tiny);
        }
        // Per packet, as [`filter::flushed`] per pixel: with subnormals
        // flushed, every lane goes to the oracle if any component is below
        // the least normal f32 or `dir` has a subnormal component (rare).
        let flushed = (!L::all(normal) || needs_probe(&d, &[])) && flushing();
        if flushed || !L::all(ok[0] & ok[1] & ok[2]) {
            let ok = ok.map(|m| L::mask_i32(m).to_array().map(|b| b != 0));
            self.settle4(pixels, &mut dir, ok, flushed);
        }
        Ray4 {
            origin: self.params.position.to_array().map(f32x4::splat),
            dir,
        }
    }

    /// The lanes [`Camera::ray4`] leaves undecided (all of them where
    /// `all`), from the oracle.
    #[cold]
    #[inline(never)]
    fn settle4(&self, pixels: [[u32; 2]; 4], dir: &mut [f32x4; 3], ok: [[bool; 4]; 3], all: bool) {
        let mut out = dir.map(|v| v.to_array());
        for (lane, [px, py]) in pixels.into_iter().enumerate() {
            let undecided = [0, 1, 2].map(|i| all || !ok[i][lane]);
            if undecided.contains(&true) {
                let mut v = [0, 1, 2].map(|i| out[i][lane]);
                self.escalate(&mut v, undecided, px, py);
                (0..3).for_each(|i| out[i][lane] = v[i]);
            }
        }
        *dir = out.map(f32x4::from);
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
