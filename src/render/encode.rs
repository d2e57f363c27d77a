//! Frames to PNG bytes: the channel mappings of [`super`] and, with the
//! `png` feature, the `png` crate with fixed settings.

#[cfg(feature = "png")]
use super::Frame;
use crate::scene::DepthRange;

/// The id channel's colours: object id `k` gets `PALETTE[(k − 1) % 12]`
/// (Paul Tol's "muted" and "bright" schemes, chosen to be told apart, also
/// with common colour-vision deficiencies); 0 (no hit) is black.
pub const PALETTE: [[u8; 3]; 12] = [
    [0x44, 0x77, 0xaa],
    [0xee, 0x66, 0x77],
    [0x22, 0x88, 0x33],
    [0xcc, 0xbb, 0x44],
    [0x66, 0xcc, 0xee],
    [0xaa, 0x33, 0x77],
    [0xbb, 0xbb, 0xbb],
    [0x88, 0x22, 0x55],
    [0x11, 0x77, 0x33],
    [0xdd, 0xcc, 0x77],
    [0x88, 0xcc, 0xee],
    [0xcc, 0x66, 0x77],
];

/// The depth channel's grey for `t` (see [`super`]): 0 for no hit (`t` not
/// finite), else `65535 − round(65534 · clamp((L(t) − L(near)) / (L(far) −
/// L(near)), 0, 1))` with `L` the f32 bit pattern as an integer, in exact
/// integer arithmetic.
///
/// ```
/// use rayoracle::render::depth_grey;
/// use rayoracle::scene::DepthRange;
/// let r = DepthRange { near: 1.0, far: 4.0 };
/// assert_eq!(depth_grey(f32::INFINITY, r), 0);
/// assert_eq!(depth_grey(0.5, r), 65535);
/// assert_eq!(depth_grey(1.0, r), 65535);
/// assert_eq!(depth_grey(2.0, r), 32768); // one octave of two: half way
/// assert_eq!(depth_grey(4.0, r), 1);
/// assert_eq!(depth_grey(1e30, r), 1);
/// ```
pub fn depth_grey(t: f32, range: DepthRange) -> u16 {
    if !t.is_finite() {
        return 0;
    }
    let l = |x: f32| i64::from(x.abs().to_bits());
    let (lo, hi) = (l(range.near), l(range.far));
    let span = (hi - lo).max(1);
    let x = (l(t) - lo).clamp(0, span);
    // round(65534 · x / span), halves up, in integers.
    let scaled = (2 * 65534 * x + span) / (2 * span);
    (65535 - scaled) as u16
}

/// A normal component to 8 bits: `round(127.5 · (n + 1))`, clamped.
#[cfg(feature = "png")]
fn normal_byte(n: f32) -> u8 {
    ((n + 1.0) * 127.5).round().clamp(0.0, 255.0) as u8
}

/// Encodes 8- or 16-bit samples as PNG with fixed settings.
#[cfg(feature = "png")]
fn png(
    width: u32,
    height: u32,
    color: png::ColorType,
    depth: png::BitDepth,
    data: &[u8],
) -> Vec<u8> {
    let mut out = Vec::new();
    {
        let mut enc = png::Encoder::new(&mut out, width, height);
        enc.set_color(color);
        enc.set_depth(depth);
        enc.set_compression(png::Compression::Balanced);
        enc.set_filter(png::Filter::Adaptive);
        // Writing to a Vec cannot fail, and the sizes match by construction.
        let mut w = enc.write_header().expect("PNG header to memory");
        w.write_image_data(data).expect("PNG data to memory");
    }
    out
}

#[cfg(feature = "png")]
impl Frame {
    /// RGB 8-bit samples of this frame's size as PNG.
    fn rgb_png(&self, data: &[u8]) -> Vec<u8> {
        png(
            self.width,
            self.height,
            png::ColorType::Rgb,
            png::BitDepth::Eight,
            data,
        )
    }

    /// The depth channel as a 16-bit greyscale PNG.
    ///
    /// ```
    /// use rayoracle::render::Frame;
    /// use rayoracle::scene::DepthRange;
    /// let f = Frame { width: 2, height: 1, range: DepthRange::DEFAULT, depth: vec![1.0, f32::INFINITY], id: vec![], normal: vec![] };
    /// assert_eq!(&f.depth_png()[1..4], b"PNG");
    /// ```
    pub fn depth_png(&self) -> Vec<u8> {
        let data: Vec<u8> = self
            .depth
            .iter()
            .flat_map(|&t| depth_grey(t, self.range).to_be_bytes())
            .collect();
        png(
            self.width,
            self.height,
            png::ColorType::Grayscale,
            png::BitDepth::Sixteen,
            &data,
        )
    }

    /// The normal channel as an RGB PNG, or `None` if the frame has none.
    ///
    /// ```
    /// use rayoracle::render::Frame;
    /// use rayoracle::scene::DepthRange;
    /// let f = Frame { width: 1, height: 1, range: DepthRange::DEFAULT, depth: vec![1.0], id: vec![1], normal: vec![] };
    /// assert!(f.normal_png().is_none());
    /// ```
    pub fn normal_png(&self) -> Option<Vec<u8>> {
        if self.normal.is_empty() {
            return None;
        }
        let data: Vec<u8> = self
            .normal
            .iter()
            .zip(&self.depth)
            .flat_map(|(n, t)| {
                if t.is_finite() {
                    n.map(normal_byte)
                } else {
                    [0; 3]
                }
            })
            .collect();
        Some(self.rgb_png(&data))
    }

    /// The id channel as an RGB PNG in [`PALETTE`], or `None` if the frame
    /// has none.
    ///
    /// ```
    /// use rayoracle::render::Frame;
    /// use rayoracle::scene::DepthRange;
    /// let f = Frame { width: 1, height: 1, range: DepthRange::DEFAULT, depth: vec![1.0], id: vec![1], normal: vec![] };
    /// assert!(f.id_png().is_some());
    /// ```
    pub fn id_png(&self) -> Option<Vec<u8>> {
        if self.id.is_empty() {
            return None;
        }
        let data: Vec<u8> = self
            .id
            .iter()
            .flat_map(|&k| {
                if k == 0 {
                    [0; 3]
                } else {
                    PALETTE[(k as usize - 1) % PALETTE.len()]
                }
            })
            .collect();
        Some(self.rgb_png(&data))
    }

    /// Every channel the frame has, as `(name, PNG bytes)`.
    ///
    /// ```
    /// use rayoracle::render::Frame;
    /// use rayoracle::scene::DepthRange;
    /// let f = Frame { width: 1, height: 1, range: DepthRange::DEFAULT, depth: vec![1.0], id: vec![1], normal: vec![] };
    /// let names: Vec<_> = f.pngs().into_iter().map(|(n, _)| n).collect();
    /// assert_eq!(names, vec!["depth", "id"]);
    /// ```
    pub fn pngs(&self) -> Vec<(&'static str, Vec<u8>)> {
        let mut out = vec![("depth", self.depth_png())];
        if let Some(p) = self.normal_png() {
            out.push(("normal", p));
        }
        if let Some(p) = self.id_png() {
            out.push(("id", p));
        }
        out
    }
}

/// Writes the asked-for channels of `frame` as `DIR/STEM.CHANNEL.png`,
/// creating `DIR`; returns the paths written.
///
/// ```
/// use rayoracle::render::{Channels, Path, Plan, render, write_pngs};
/// use rayoracle::scene::Scene;
/// let s = Scene::parse(r#"{"camera": {"position": [0, 0, 0], "dir": [0, 0, -1],
///     "up": [0, 1, 0], "angle": 1, "res": [4, 3]}}"#).unwrap();
/// let f = render(&Plan::compile(&s, Channels::ALL).unwrap(), Path::X4);
/// let dir = std::env::temp_dir().join("rayoracle-doc-write-pngs");
/// let files = write_pngs(&f, Channels::parse("id").unwrap(), &dir, "empty").unwrap();
/// assert_eq!(files, vec![dir.join("empty.id.png")]);
/// # std::fs::remove_dir_all(&dir).unwrap();
/// ```
#[cfg(feature = "png")]
pub fn write_pngs(
    frame: &Frame,
    channels: super::Channels,
    dir: &std::path::Path,
    stem: &str,
) -> Result<Vec<std::path::PathBuf>, String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("{}: cannot create: {e}", dir.display()))?;
    let wanted = channels.names();
    let mut written = Vec::new();
    for (name, bytes) in frame.pngs() {
        if !wanted.contains(&name) {
            continue;
        }
        let path = dir.join(format!("{stem}.{name}.png"));
        std::fs::write(&path, bytes)
            .map_err(|e| format!("{}: cannot write: {e}", path.display()))?;
        written.push(path);
    }
    Ok(written)
}
