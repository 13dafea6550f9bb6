//! Colours of pieces.

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

/// Twenty well separated colours (light enough for black labels), then
/// golden-angle hues.
const PALETTE: [Rgb; 20] = [
    Rgb(230, 97, 92),
    Rgb(93, 165, 218),
    Rgb(250, 200, 80),
    Rgb(122, 196, 120),
    Rgb(196, 140, 216),
    Rgb(255, 153, 90),
    Rgb(110, 208, 200),
    Rgb(240, 140, 190),
    Rgb(180, 200, 90),
    Rgb(160, 160, 240),
    Rgb(210, 170, 120),
    Rgb(140, 220, 160),
    Rgb(255, 120, 140),
    Rgb(120, 190, 255),
    Rgb(220, 220, 110),
    Rgb(200, 120, 170),
    Rgb(150, 200, 200),
    Rgb(250, 180, 150),
    Rgb(170, 230, 110),
    Rgb(190, 170, 250),
];

/// The colour of piece `i`.
pub fn piece_colour(i: usize) -> Rgb {
    if let Some(c) = PALETTE.get(i) {
        return *c;
    }
    let h = (i as f64 * 137.508) % 360.0;
    hsl(h, 0.6, 0.65)
}

fn hsl(h: f64, s: f64, l: f64) -> Rgb {
    let c = (1.0 - (2.0 * l - 1.0).abs()) * s;
    let x = c * (1.0 - ((h / 60.0) % 2.0 - 1.0).abs());
    let m = l - c / 2.0;
    let (r, g, b) = match (h / 60.0) as u32 {
        0 => (c, x, 0.0),
        1 => (x, c, 0.0),
        2 => (0.0, c, x),
        3 => (0.0, x, c),
        4 => (x, 0.0, c),
        _ => (c, 0.0, x),
    };
    let f = |v: f64| ((v + m) * 255.0).round() as u8;
    Rgb(f(r), f(g), f(b))
}
