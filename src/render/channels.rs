//! Which output channels a render produces.

/// A set of output channels. A plan computes only what is in it: no normal
/// arithmetic without `normal`, no object tracking without `normal` or `id`.
///
/// ```
/// use rayoracle::render::Channels;
/// assert_eq!(Channels::parse("depth,id").unwrap(), Channels { depth: true, normal: false, id: true });
/// assert_eq!(Channels::parse("all").unwrap(), Channels::ALL);
/// assert!(Channels::parse("colour").unwrap_err().contains("colour"));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Channels {
    /// The nearest hit's `t`, as 16-bit grey.
    pub depth: bool,
    /// The nearest hit's unit normal, facing the ray, as RGB.
    pub normal: bool,
    /// The nearest hit's object id, in a fixed palette.
    pub id: bool,
}

impl Channels {
    /// Every channel.
    pub const ALL: Channels = Channels {
        depth: true,
        normal: true,
        id: true,
    };
    /// Depth only.
    pub const DEPTH: Channels = Channels {
        depth: true,
        normal: false,
        id: false,
    };

    /// Parses `depth`, `normal`, `id`, `all`, or a comma-separated list.
    ///
    /// ```
    /// use rayoracle::render::Channels;
    /// assert_eq!(Channels::parse("normal").unwrap().names(), vec!["normal"]);
    /// assert!(Channels::parse("").is_err());
    /// ```
    pub fn parse(text: &str) -> Result<Channels, String> {
        let mut c = Channels {
            depth: false,
            normal: false,
            id: false,
        };
        for name in text.split(',').map(str::trim) {
            match name {
                "depth" => c.depth = true,
                "normal" => c.normal = true,
                "id" => c.id = true,
                "all" => c = Channels::ALL,
                other => {
                    return Err(format!(
                        "unknown channel \"{other}\"; expected depth, normal, id or all"
                    ));
                }
            }
        }
        Ok(c)
    }

    /// Whether the render must remember which object each pixel hit.
    ///
    /// ```
    /// use rayoracle::render::Channels;
    /// assert!(!Channels::DEPTH.tracks_objects() && Channels::ALL.tracks_objects());
    /// assert!(Channels::parse("normal").unwrap().tracks_objects());
    /// assert!(Channels::parse("id").unwrap().tracks_objects());
    /// ```
    pub fn tracks_objects(&self) -> bool {
        self.normal || self.id
    }

    /// The names of the channels in the set, in a fixed order.
    ///
    /// ```
    /// use rayoracle::render::Channels;
    /// assert_eq!(Channels::ALL.names(), vec!["depth", "normal", "id"]);
    /// ```
    pub fn names(&self) -> Vec<&'static str> {
        [
            (self.depth, "depth"),
            (self.normal, "normal"),
            (self.id, "id"),
        ]
        .into_iter()
        .filter_map(|(on, n)| on.then_some(n))
        .collect()
    }
}
