//! Four camera rays at once, bit-identical to [`super::Camera::ray`]: the
//! same [`super::filter`] filter at [`F64x4`], undecided lanes from the
//! oracle (correct rounding is unique, so the two agree by construction).

use super::{Camera, filter};
use crate::num::real::{F64x4, Real};
use crate::ray4::Ray4;
use wide::{f32x4, i32x4};

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
        let n = [
            filter::numerators(pixels.map(|p| p[0]), w),
            filter::numerators(pixels.map(|p| p[1]), h),
        ];
        let inside = pixels.iter().all(|&[x, y]| x < w && y < h);
        self.ray4_of(n, inside)
    }

    /// The rays of four pixels from their numerators `[nx, ny]`
    /// ([`filter::numerator`]), `inside` where every pixel is in the image.
    #[inline(always)]
    fn ray4_of(&self, n: [F64x4; 2], inside: bool) -> Ray4 {
        let s = <F64x4 as Real>::splat;
        let mut dir = [f32x4::ZERO; 3];
        let mut ok = [i32x4::ZERO; 3];
        let mut good = i32x4::splat(-1);
        for i in 0..3 {
            let e = if inside {
                s(self.e_image[i])
            } else {
                filter::bound(n, [0, 1, 2].map(|j| s(self.err[j][i])))
            };
            let b = [s(self.unit[0][i]), s(self.unit[1][i])];
            (dir[i], ok[i]) = filter::component(s(self.d64[i]), b, n, e);
            good = good & ok[i] & !filter::tiny(dir[i]);
        }
        // As [`Camera::ray`] per pixel: a lane with a component undecided,
        // 0 or subnormal, or every lane of a `slow` camera.
        if !good.all() || self.slow {
            self.settle4(&mut dir, ok, good, n);
        }
        Ray4 {
            origin: self.params.position.to_array().map(f32x4::splat),
            dir,
        }
    }

    /// [`Camera::settle`] for the lanes of a packet that need it.
    #[cold]
    #[inline(never)]
    fn settle4(&self, dir: &mut [f32x4; 3], ok: [i32x4; 3], good: i32x4, n: [F64x4; 2]) {
        let mut lanes = dir.map(|v| v.to_array());
        let (ok, good) = (ok.map(i32x4::to_bitmask), good.to_bitmask());
        let [nx, ny] = n.map(F64x4::to_array);
        for lane in 0..4 {
            if good & 1 << lane == 0 || self.slow {
                let mut out = [0, 1, 2].map(|i| lanes[i][lane]);
                let ok = [0, 1, 2].map(|i| ok[i] & 1 << lane != 0);
                self.settle(&mut out, ok, [nx[lane], ny[lane]]);
                (0..3).for_each(|i| lanes[i][lane] = out[i]);
            }
        }
        *dir = lanes.map(f32x4::from);
    }

    /// Four consecutive pixels of row `py`: `(px, py) … (px + 3, py)`,
    /// counted as integers past `u32::MAX`.
    ///
    /// ```
    /// use rayoracle::camera::CameraParams;
    /// use glam::Vec3;
    /// let cam = CameraParams::new(Vec3::ZERO, -Vec3::Z, Vec3::Y, 1.0, [8, 6]).build().unwrap();
    /// assert_eq!(cam.ray4_row(4, 2).to_rays(), [4, 5, 6, 7].map(|x| cam.ray(x, 2)));
    /// ```
    #[inline]
    pub fn ray4_row(&self, px: u32, py: u32) -> Ray4 {
        // The numerators straight from `px` and `py` in vector registers:
        // built in an array of pixels, four scalar stores read back as one
        // vector load stall store forwarding (`rayoracle report`'s x4
        // camera, with this call out of line, took twice its time).
        let [w, h] = self.params.res;
        let nx = F64x4::splat(filter::numerator(px, w)) + F64x4::from([0.0, 2.0, 4.0, 6.0]);
        let ny = F64x4::splat(filter::numerator(py, h));
        let inside = u64::from(px) + 3 < u64::from(w) && py < h;
        self.ray4_of([nx, ny], inside)
    }

    /// A 2×2 tile: `(px, py), (px + 1, py), (px, py + 1), (px + 1, py + 1)`,
    /// counted as integers past `u32::MAX`.
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
        let [w, h] = self.params.res;
        let nx = F64x4::splat(filter::numerator(px, w)) + F64x4::from([0.0, 2.0, 0.0, 2.0]);
        let ny = F64x4::splat(filter::numerator(py, h)) + F64x4::from([0.0, 0.0, 2.0, 2.0]);
        let inside = u64::from(px) + 1 < u64::from(w) && u64::from(py) + 1 < u64::from(h);
        self.ray4_of([nx, ny], inside)
    }
}
