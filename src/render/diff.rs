//! Difference images for snapshot review: `old | new | heat map`, so a
//! reviewer sees what moved instead of reading numbers.

/// A decoded image: RGB for display, and the raw samples (8 or 16 bits,
/// 1 or 3 channels, widened to `u16`) for measuring differences.
struct Decoded {
    width: u32,
    height: u32,
    rgb: Vec<[u8; 3]>,
    samples: Vec<Vec<u16>>,
    max: u16,
}

fn decode(bytes: &[u8]) -> Result<Decoded, String> {
    let mut reader = png::Decoder::new(std::io::Cursor::new(bytes))
        .read_info()
        .map_err(|e| format!("not a PNG: {e}"))?;
    let size = reader
        .output_buffer_size()
        .ok_or_else(|| "PNG too large".to_string())?;
    let mut buf = vec![0; size];
    let info = reader
        .next_frame(&mut buf)
        .map_err(|e| format!("bad PNG data: {e}"))?;
    let (w, h) = (info.width, info.height);
    let channels = match info.color_type {
        png::ColorType::Grayscale => 1,
        png::ColorType::Rgb => 3,
        other => return Err(format!("unsupported PNG colour type {other:?}")),
    };
    let wide = match info.bit_depth {
        png::BitDepth::Eight => false,
        png::BitDepth::Sixteen => true,
        other => return Err(format!("unsupported PNG bit depth {other:?}")),
    };
    let max: u16 = if wide { 65535 } else { 255 };
    let sample = |b: &[u8], i: usize| {
        if wide {
            u16::from_be_bytes([b[2 * i], b[2 * i + 1]])
        } else {
            u16::from(b[i])
        }
    };
    let n = w as usize * h as usize;
    let samples: Vec<Vec<u16>> = (0..n)
        .map(|p| {
            (0..channels)
                .map(|c| sample(&buf, p * channels + c))
                .collect()
        })
        .collect();
    let to8 = |s: u16| if max == 255 { s as u8 } else { (s >> 8) as u8 };
    let rgb = samples
        .iter()
        .map(|s| {
            if channels == 1 {
                [to8(s[0]); 3]
            } else {
                [to8(s[0]), to8(s[1]), to8(s[2])]
            }
        })
        .collect();
    Ok(Decoded {
        width: w,
        height: h,
        rgb,
        samples,
        max,
    })
}

/// The heat colour of a relative difference `d ∈ [0, 1]`: black for none,
/// then from dark red through orange and yellow to white. Any difference at
/// all is at least a clearly visible red (a one-level change in a 16-bit
/// depth must not vanish), and the brightness grows with `√d`.
///
/// ```
/// use rayoracle::render::diff::heat;
/// assert_eq!(heat(0.0), [0, 0, 0]);
/// assert!(heat(1e-9)[0] >= 96);
/// // √0.25 = 0.5, so v = 0.25 + 0.75·0.5 = 0.625: red full, green 0.875.
/// assert_eq!(heat(0.25), [255, 223, 0]);
/// // √(1/144) = 1/12, v = 0.3125: red 0.375 + 0.625·0.9375, no green.
/// assert_eq!(heat(1.0 / 144.0), [245, 0, 0]);
/// assert_eq!(heat(1.0), [255, 255, 255]);
/// ```
pub fn heat(d: f64) -> [u8; 3] {
    if d <= 0.0 {
        return [0, 0, 0];
    }
    let v = 0.25 + 0.75 * d.clamp(0.0, 1.0).sqrt();
    let ramp = |lo: f64| ((v - lo) / (1.0 / 3.0)).clamp(0.0, 1.0);
    let r = 0.375 + 0.625 * ramp(0.0);
    let g = ramp(1.0 / 3.0);
    let b = ramp(2.0 / 3.0);
    [r, g, b].map(|c| (c * 255.0).round() as u8)
}

/// Summary of a comparison.
///
/// ```
/// use rayoracle::render::diff::Comparison;
/// let c = Comparison { pixels: 4, differing: 1, max_difference: 0.5 };
/// assert!(c.to_string().contains("1 of 4"));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Comparison {
    /// Pixels compared (0 if the sizes differ).
    pub pixels: usize,
    /// Pixels with any sample different.
    pub differing: usize,
    /// The largest sample difference, as a fraction of full scale.
    pub max_difference: f64,
}

impl core::fmt::Display for Comparison {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "{} of {} pixels differ, by up to {:.3}% of full scale",
            self.differing,
            self.pixels,
            100.0 * self.max_difference
        )
    }
}

/// A PNG showing `old | new | heat map of |old − new|`, side by side with
/// 4-pixel grey gutters, and the numbers behind it. Images of different
/// sizes are shown side by side with an all-white heat map.
///
/// ```
/// # #[cfg(feature = "sphere")] {
/// use rayoracle::render::{Channels, Path, Plan, render, diff::diff_png};
/// use rayoracle::scene::Scene;
/// let s = Scene::parse(r#"{"camera": {"position": [0, 0, 0], "dir": [0, 0, -1],
///     "up": [0, 1, 0], "angle": 1, "res": [8, 6]},
///     "spheres": [{"id": 1, "center": [0, 0, -3], "radius": 1}]}"#).unwrap();
/// let a = render(&Plan::compile(&s, Channels::DEPTH).unwrap(), Path::X4).depth_png();
/// let s2 = Scene { spheres: vec![], ..s };
/// let b = render(&Plan::compile(&s2, Channels::DEPTH).unwrap(), Path::X4).depth_png();
/// let (png, c) = diff_png(&a, &b).unwrap();
/// assert!(c.differing > 0 && c.differing < 48);
/// assert_eq!(&png[1..4], b"PNG");
/// assert_eq!(diff_png(&a, &a).unwrap().1.differing, 0);
/// # }
/// ```
pub fn diff_png(old: &[u8], new: &[u8]) -> Result<(Vec<u8>, Comparison), String> {
    let a = decode(old).map_err(|e| format!("old image: {e}"))?;
    let b = decode(new).map_err(|e| format!("new image: {e}"))?;
    let same_size = (a.width, a.height) == (b.width, b.height)
        && a.samples.first().map(Vec::len) == b.samples.first().map(Vec::len);
    let (hw, hh) = (a.width.max(b.width), a.height.max(b.height));
    let mut heat_px = vec![[255u8; 3]; hw as usize * hh as usize];
    let mut cmp = Comparison {
        pixels: 0,
        differing: 0,
        max_difference: 0.0,
    };
    if same_size {
        cmp.pixels = a.samples.len();
        let full = f64::from(a.max.max(b.max));
        for (i, (sa, sb)) in a.samples.iter().zip(&b.samples).enumerate() {
            let d = sa
                .iter()
                .zip(sb)
                .map(|(&x, &y)| f64::from(x.abs_diff(y)) / full)
                .fold(0.0, f64::max);
            if d > 0.0 {
                cmp.differing += 1;
                cmp.max_difference = cmp.max_difference.max(d);
            }
            heat_px[i] = heat(d);
        }
    }
    const GUTTER: u32 = 4;
    let width = a.width + b.width + hw + 2 * GUTTER;
    let height = a.height.max(b.height).max(hh);
    let mut out = vec![[96u8; 3]; width as usize * height as usize];
    let mut blit = |x0: u32, w: u32, h: u32, px: &[[u8; 3]]| {
        for y in 0..h {
            for x in 0..w {
                out[(y * width + x0 + x) as usize] = px[(y * w + x) as usize];
            }
        }
    };
    blit(0, a.width, a.height, &a.rgb);
    blit(a.width + GUTTER, b.width, b.height, &b.rgb);
    blit(a.width + b.width + 2 * GUTTER, hw, hh, &heat_px);
    let data: Vec<u8> = out.into_iter().flatten().collect();
    let mut bytes = Vec::new();
    {
        let mut enc = png::Encoder::new(&mut bytes, width, height);
        enc.set_color(png::ColorType::Rgb);
        enc.set_depth(png::BitDepth::Eight);
        let mut w = enc
            .write_header()
            .map_err(|e| format!("encoding the diff: {e}"))?;
        w.write_image_data(&data)
            .map_err(|e| format!("encoding the diff: {e}"))?;
    }
    Ok((bytes, cmp))
}

#[cfg(test)]
mod tests {
    use super::{decode, diff_png, heat};

    fn png(w: u32, h: u32, color: png::ColorType, depth: png::BitDepth, data: &[u8]) -> Vec<u8> {
        let mut bytes = Vec::new();
        let mut enc = png::Encoder::new(&mut bytes, w, h);
        enc.set_color(color);
        enc.set_depth(depth);
        enc.write_header().unwrap().write_image_data(data).unwrap();
        bytes
    }

    /// 16-bit samples are big-endian pairs, one per pixel, shown by their
    /// high byte; every pixel of a 3×2 image lands in its own place.
    #[test]
    fn sixteen_bit_grey_decodes_each_pixel_in_place() {
        let values: [u16; 6] = [0x0102, 0x0304, 0xfe05, 0x0006, 0x8007, 0xffff];
        let data: Vec<u8> = values.iter().flat_map(|v| v.to_be_bytes()).collect();
        let d = decode(&png(
            3,
            2,
            png::ColorType::Grayscale,
            png::BitDepth::Sixteen,
            &data,
        ))
        .unwrap();
        assert_eq!((d.width, d.height, d.max), (3, 2, 65535));
        assert_eq!(d.samples, values.map(|v| vec![v]).to_vec());
        let high = values.map(|v| (v >> 8) as u8);
        assert_eq!(d.rgb, high.map(|g| [g; 3]).to_vec());
    }

    /// 8-bit RGB keeps its three channels per pixel, in order.
    #[test]
    fn eight_bit_rgb_decodes_each_channel_in_place() {
        let data: Vec<u8> = (1..=12).collect();
        let d = decode(&png(2, 2, png::ColorType::Rgb, png::BitDepth::Eight, &data)).unwrap();
        assert_eq!((d.width, d.height, d.max), (2, 2, 255));
        let px: Vec<[u8; 3]> = data.chunks(3).map(|c| [c[0], c[1], c[2]]).collect();
        assert_eq!(d.rgb, px);
        assert_eq!(d.samples[3], vec![10, 11, 12]);
    }

    /// Colour types and depths the snapshots never use are refused by name.
    #[test]
    fn other_formats_are_refused_with_their_name() {
        let rgba = png(
            1,
            1,
            png::ColorType::Rgba,
            png::BitDepth::Eight,
            &[1, 2, 3, 4],
        );
        assert_eq!(
            decode(&rgba).err().unwrap(),
            "unsupported PNG colour type Rgba"
        );
        assert!(decode(b"GIF89a").err().unwrap().starts_with("not a PNG: "));
    }

    fn grey(w: u32, h: u32, data: &[u8]) -> Vec<u8> {
        png(w, h, png::ColorType::Grayscale, png::BitDepth::Eight, data)
    }

    /// Two 2×2 greys: the diff is `old | 4 grey | new | 4 grey | heat`,
    /// 14×2, each pixel in place, and the numbers count the one pixel that
    /// changed, by 100 of 255.
    #[test]
    fn the_diff_lays_out_old_new_and_heat() {
        let (old, new) = ([0, 100, 50, 255], [0, 200, 50, 255]);
        let (png, c) = diff_png(&grey(2, 2, &old), &grey(2, 2, &new)).unwrap();
        assert_eq!(
            (c.pixels, c.differing, c.max_difference),
            (4, 1, 100.0 / 255.0)
        );
        let d = decode(&png).unwrap();
        assert_eq!((d.width, d.height), (14, 2));
        let g = |v: u8| [v; 3];
        let h = heat(100.0 / 255.0);
        let rows: Vec<&[[u8; 3]]> = d.rgb.chunks(14).collect();
        let gutter = [g(96); 4];
        let row0 = [
            &[g(0), g(100)][..],
            &gutter,
            &[g(0), g(200)],
            &gutter,
            &[g(0), h],
        ]
        .concat();
        let row1 = [
            &[g(50), g(255)][..],
            &gutter,
            &[g(50), g(255)],
            &gutter,
            &[g(0), g(0)],
        ]
        .concat();
        assert_eq!(rows, [&row0[..], &row1[..]]);
    }

    /// Images of different sizes are shown side by side, with a white
    /// heat map and no pixel compared, even when their pixel counts match.
    #[test]
    fn images_of_different_sizes_are_not_compared() {
        let (png, c) = diff_png(&grey(2, 1, &[10, 20]), &grey(1, 2, &[30, 40])).unwrap();
        assert_eq!((c.pixels, c.differing), (0, 0));
        let d = decode(&png).unwrap();
        assert_eq!((d.width, d.height), (2 + 4 + 1 + 4 + 2, 2));
        assert_eq!(&d.rgb[11..13], &[[255; 3]; 2]);
        assert_eq!(d.rgb[6], [30; 3]);
        assert_eq!(d.rgb[13 + 6], [40; 3]);
    }
}
