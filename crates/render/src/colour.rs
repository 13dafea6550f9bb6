//! Colours of pieces (from the one palette, `dissect_core::palette`).

use std::fmt;

/// An sRGB colour.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Rgb(pub u8, pub u8, pub u8);

impl Rgb {
    /// Black.
    pub const BLACK: Rgb = Rgb(0, 0, 0);
    /// White.
    pub const WHITE: Rgb = Rgb(255, 255, 255);
    /// The dark grey of outlines.
    pub const INK: Rgb = Rgb(34, 34, 34);

    /// This colour with every channel multiplied by `f` (0..=1).
    pub fn shade(self, f: f64) -> Rgb {
        let m = |c: u8| (c as f64 * f).round().clamp(0.0, 255.0) as u8;
        Rgb(m(self.0), m(self.1), m(self.2))
    }
}

impl fmt::Display for Rgb {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "#{:02x}{:02x}{:02x}", self.0, self.1, self.2)
    }
}

/// The colour of piece `i`: the one palette of `dissect_core::palette`.
pub fn piece_colour(i: usize) -> Rgb {
    let [r, g, b] = dissect_core::palette::piece_rgb(i);
    Rgb(r, g, b)
}
