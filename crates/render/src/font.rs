//! A tiny built-in 3×5 pixel font, so that pictures rendered to PNG show
//! their labels the same on every machine (no system fonts are read).

/// Glyph rows, top to bottom, `#` = ink. Lower-case letters use the
/// upper-case glyphs; unknown characters draw as a box.
fn glyph(c: char) -> [&'static str; 5] {
    match c.to_ascii_uppercase() {
        '0' => ["###", "#.#", "#.#", "#.#", "###"],
        '1' => [".#.", "##.", ".#.", ".#.", "###"],
        '2' => ["###", "..#", "###", "#..", "###"],
        '3' => ["###", "..#", ".##", "..#", "###"],
        '4' => ["#.#", "#.#", "###", "..#", "..#"],
        '5' => ["###", "#..", "###", "..#", "###"],
        '6' => ["###", "#..", "###", "#.#", "###"],
        '7' => ["###", "..#", ".#.", ".#.", ".#."],
        '8' => ["###", "#.#", "###", "#.#", "###"],
        '9' => ["###", "#.#", "###", "..#", "###"],
        'A' => [".#.", "#.#", "###", "#.#", "#.#"],
        'B' => ["##.", "#.#", "##.", "#.#", "##."],
        'C' => [".##", "#..", "#..", "#..", ".##"],
        'D' => ["##.", "#.#", "#.#", "#.#", "##."],
        'E' => ["###", "#..", "##.", "#..", "###"],
        'F' => ["###", "#..", "##.", "#..", "#.."],
        'G' => [".##", "#..", "#.#", "#.#", ".##"],
        'H' => ["#.#", "#.#", "###", "#.#", "#.#"],
        'I' => ["###", ".#.", ".#.", ".#.", "###"],
        'J' => ["..#", "..#", "..#", "#.#", ".#."],
        'K' => ["#.#", "#.#", "##.", "#.#", "#.#"],
        'L' => ["#..", "#..", "#..", "#..", "###"],
        'M' => ["#.#", "###", "###", "#.#", "#.#"],
        'N' => ["##.", "#.#", "#.#", "#.#", "#.#"],
        'O' => [".#.", "#.#", "#.#", "#.#", ".#."],
        'P' => ["##.", "#.#", "##.", "#..", "#.."],
        'Q' => [".#.", "#.#", "#.#", "##.", ".##"],
        'R' => ["##.", "#.#", "##.", "#.#", "#.#"],
        'S' => [".##", "#..", ".#.", "..#", "##."],
        'T' => ["###", ".#.", ".#.", ".#.", ".#."],
        'U' => ["#.#", "#.#", "#.#", "#.#", "###"],
        'V' => ["#.#", "#.#", "#.#", "#.#", ".#."],
        'W' => ["#.#", "#.#", "###", "###", "#.#"],
        'X' => ["#.#", "#.#", ".#.", "#.#", "#.#"],
        'Y' => ["#.#", "#.#", ".#.", ".#.", ".#."],
        'Z' => ["###", "..#", ".#.", "#..", "###"],
        ' ' => ["...", "...", "...", "...", "..."],
        ':' => ["...", ".#.", "...", ".#.", "..."],
        '.' => ["...", "...", "...", "...", ".#."],
        ',' => ["...", "...", "...", ".#.", "#.."],
        '-' => ["...", "...", "###", "...", "..."],
        '_' => ["...", "...", "...", "...", "###"],
        '=' => ["...", "###", "...", "###", "..."],
        '(' => [".#.", "#..", "#..", "#..", ".#."],
        ')' => [".#.", "..#", "..#", "..#", ".#."],
        '/' => ["..#", "..#", ".#.", "#..", "#.."],
        '+' => ["...", ".#.", "###", ".#.", "..."],
        '#' => ["#.#", "###", "#.#", "###", "#.#"],
        _ => ["###", "#.#", "#.#", "#.#", "###"],
    }
}

/// The width of `text` drawn `height` high.
pub fn text_width(text: &str, height: f64) -> f64 {
    let n = text.chars().count() as f64;
    if n == 0.0 {
        0.0
    } else {
        (n * 4.0 - 1.0) * height / 5.0
    }
}

/// SVG path data drawing `text` with its top-left corner at `(x, y)`,
/// `height` high: one rectangle per run of ink pixels in a row.
pub fn text_path(text: &str, x: f64, y: f64, height: f64) -> String {
    let px = height / 5.0;
    let mut d = String::new();
    for (i, c) in text.chars().enumerate() {
        let gx = x + i as f64 * 4.0 * px;
        for (row, bits) in glyph(c).iter().enumerate() {
            let bits = bits.as_bytes();
            let mut col = 0;
            while col < 3 {
                if bits[col] != b'#' {
                    col += 1;
                    continue;
                }
                let start = col;
                while col < 3 && bits[col] == b'#' {
                    col += 1;
                }
                d += &format!(
                    "M{} {}h{}v{}h{}Z",
                    crate::drawing::num(gx + start as f64 * px),
                    crate::drawing::num(y + row as f64 * px),
                    crate::drawing::num((col - start) as f64 * px),
                    crate::drawing::num(px),
                    crate::drawing::num(-((col - start) as f64) * px),
                );
            }
        }
    }
    d
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_glyph_is_three_by_five() {
        for c in "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ :.,-_=()/+#?".chars() {
            for row in glyph(c) {
                assert_eq!(row.len(), 3, "{c}");
                assert!(row.bytes().all(|b| b == b'#' || b == b'.'), "{c}");
            }
        }
    }

    #[test]
    fn one_is_drawn_with_five_rectangles() {
        assert_eq!(text_path("1", 0.0, 0.0, 5.0).matches('M').count(), 5);
        assert_eq!(text_width("12", 5.0), 7.0);
    }
}
