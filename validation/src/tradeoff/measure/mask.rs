//! The surface pixels, over which every measure is taken.

/// The surface pixels: `true` where the pixel's centre sees an object.
#[derive(Clone, Debug, PartialEq)]
pub struct Mask(pub(super) Vec<bool>);

impl Mask {
    /// From the first hits of the pixel centres (`None`: background).
    pub fn from_hits(hits: &[Option<u32>]) -> Self {
        Mask(hits.iter().map(Option::is_some).collect())
    }

    /// Every pixel of a `count`-pixel image.
    pub fn all(count: usize) -> Self {
        Mask(vec![true; count])
    }

    /// How many pixels it keeps.
    pub fn count(&self) -> usize {
        self.0.iter().filter(|&&keep| keep).count()
    }

    /// The kept pixels' indices.
    pub(crate) fn kept(&self) -> impl Iterator<Item = usize> + '_ {
        self.0
            .iter()
            .enumerate()
            .filter_map(|(i, &keep)| keep.then_some(i))
    }
}
