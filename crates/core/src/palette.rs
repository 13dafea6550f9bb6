//! The piece colours: defined once here and used by every picture of a
//! dissection (ASCII art in a terminal, SVG, PNG, cut sheets, the studio and
//! the shared HTML page), so that piece `i` has one colour everywhere.
//!
//! Pure data: no I/O. The terminal colours are derived from the RGB colours
//! (the nearest colour of the xterm 256-colour cube), never listed apart.

/// Twenty well separated colours, light enough for black labels and dark
/// outlines; pieces past the twentieth get golden-angle hues.
pub const PIECE_COLOURS: [[u8; 3]; 20] = [
    [230, 97, 92],
    [93, 165, 218],
    [250, 200, 80],
    [122, 196, 120],
    [196, 140, 216],
    [255, 153, 90],
    [110, 208, 200],
    [240, 140, 190],
    [180, 200, 90],
    [160, 160, 240],
    [210, 170, 120],
    [140, 220, 160],
    [255, 120, 140],
    [120, 190, 255],
    [220, 220, 110],
    [200, 120, 170],
    [150, 200, 200],
    [250, 180, 150],
    [170, 230, 110],
    [190, 170, 250],
];

/// The sRGB colour of piece `i`.
pub fn piece_rgb(i: usize) -> [u8; 3] {
    if let Some(c) = PIECE_COLOURS.get(i) {
        return *c;
    }
    let h = (i as f64 * 137.508) % 360.0;
    hsl(h, 0.6, 0.65)
}

/// The colour of piece `i` as CSS/SVG `#rrggbb`.
pub fn piece_hex(i: usize) -> String {
    let [r, g, b] = piece_rgb(i);
    format!("#{r:02x}{g:02x}{b:02x}")
}

/// The xterm 256-colour index nearest to the colour of piece `i` (in the
/// 6×6×6 colour cube, indices 16..=231).
pub fn piece_ansi256(i: usize) -> u8 {
    const LEVELS: [u8; 6] = [0, 95, 135, 175, 215, 255];
    let nearest = |v: u8| -> u8 {
        (0..6u8)
            .min_by_key(|&k| (LEVELS[k as usize] as i32 - v as i32).abs())
            .expect("six levels")
    };
    let [r, g, b] = piece_rgb(i);
    16 + 36 * nearest(r) + 6 * nearest(g) + nearest(b)
}

fn hsl(h: f64, s: f64, l: f64) -> [u8; 3] {
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
    [f(r), f(g), f(b)]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn colours_are_distinct_and_stable() {
        let all: Vec<[u8; 3]> = (0..60).map(piece_rgb).collect();
        for (i, a) in all.iter().enumerate() {
            for b in &all[i + 1..] {
                assert_ne!(a, b);
            }
        }
        assert_eq!(piece_hex(0), "#e6615c");
        assert_eq!(piece_rgb(1), [93, 165, 218]);
    }

    #[test]
    fn terminal_colours_come_from_the_rgb_colours() {
        // [230, 97, 92] -> levels (4: 215, 1: 95, 1: 95) -> 16 + 144 + 6 + 1.
        assert_eq!(piece_ansi256(0), 167);
        // [93, 165, 218] -> (1, 3, 4).
        assert_eq!(piece_ansi256(1), 16 + 36 + 18 + 4);
        for i in 0..40 {
            assert!((16..=231).contains(&piece_ansi256(i)));
        }
    }
}
