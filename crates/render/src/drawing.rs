//! Drawings: flat lists of filled/stroked paths and labels in one unit
//! (pixels or millimetres), written out as SVG. Every 2D exporter builds a
//! [`Drawing`] and every picture format is written from one.

use std::fmt::Write;

use crate::colour::Rgb;

/// The unit of a drawing's coordinates.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unit {
    /// Screen pixels.
    Px,
    /// Millimetres (the SVG's width and height say `mm`).
    Mm,
}

/// Where a label's `x` is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Anchor {
    /// `x` is the left end.
    Start,
    /// `x` is the middle.
    Middle,
}

/// How labels are written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum TextMode {
    /// As SVG `<text>` (selectable, engraved as text by laser software).
    Text,
    /// As filled paths of the built-in pixel font (same on every machine).
    Paths,
}

/// One thing drawn.
#[derive(Clone, Debug, PartialEq)]
pub enum Item {
    /// A path (SVG path data) with a fill and/or a stroke.
    Path {
        /// SVG path data.
        d: String,
        /// Fill colour, or none.
        fill: Option<Rgb>,
        /// Stroke colour and width, or none.
        stroke: Option<(Rgb, f64)>,
    },
    /// A one-line label.
    Text {
        /// Anchor position.
        x: f64,
        /// Baseline.
        y: f64,
        /// Font size (em).
        size: f64,
        /// How `x` is read.
        anchor: Anchor,
        /// The text.
        text: String,
        /// Colour.
        fill: Rgb,
    },
}

/// A picture: a size, a unit and the items in painting order.
#[derive(Clone, Debug, PartialEq)]
pub struct Drawing {
    width: f64,
    height: f64,
    unit: Unit,
    background: Option<Rgb>,
    items: Vec<Item>,
}

impl Drawing {
    /// An empty drawing of the given size.
    pub fn new(width: f64, height: f64, unit: Unit, background: Option<Rgb>) -> Drawing {
        Drawing {
            width: width.max(1.0),
            height: height.max(1.0),
            unit,
            background,
            items: Vec::new(),
        }
    }

    /// Adds an item on top.
    pub fn push(&mut self, item: Item) {
        self.items.push(item);
    }

    /// The items in painting order.
    pub fn items(&self) -> &[Item] {
        &self.items
    }

    /// Width in the drawing's unit.
    pub fn width(&self) -> f64 {
        self.width
    }

    /// Height in the drawing's unit.
    pub fn height(&self) -> f64 {
        self.height
    }

    /// The SVG document.
    pub fn to_svg(&self, text: TextMode) -> String {
        let u = match self.unit {
            Unit::Px => "",
            Unit::Mm => "mm",
        };
        let mut s = String::new();
        let _ = writeln!(
            s,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}{u}\" height=\"{h}{u}\" viewBox=\"0 0 {w} {h}\">",
            w = num(self.width),
            h = num(self.height),
        );
        if let Some(bg) = self.background {
            let _ = writeln!(
                s,
                "<rect x=\"0\" y=\"0\" width=\"{}\" height=\"{}\" fill=\"{bg}\"/>",
                num(self.width),
                num(self.height)
            );
        }
        for item in &self.items {
            match item {
                Item::Path { d, fill, stroke } => {
                    let fill = fill.map_or("none".to_string(), |c| c.to_string());
                    let stroke = stroke.map_or(String::new(), |(c, w)| {
                        format!(
                            " stroke=\"{c}\" stroke-width=\"{}\" stroke-linejoin=\"round\"",
                            num(w)
                        )
                    });
                    let _ = writeln!(s, "<path d=\"{d}\" fill=\"{fill}\"{stroke}/>");
                }
                Item::Text {
                    x,
                    y,
                    size,
                    anchor,
                    text: t,
                    fill,
                } => match text {
                    TextMode::Text => {
                        let a = match anchor {
                            Anchor::Start => "",
                            Anchor::Middle => " text-anchor=\"middle\"",
                        };
                        let _ = writeln!(
                            s,
                            "<text x=\"{}\" y=\"{}\" font-family=\"sans-serif\" font-size=\"{}\"{a} fill=\"{fill}\">{}</text>",
                            num(*x),
                            num(*y),
                            num(*size),
                            escape(t)
                        );
                    }
                    TextMode::Paths => {
                        let h = size * 0.7;
                        let w = crate::font::text_width(t, h);
                        let left = match anchor {
                            Anchor::Start => *x,
                            Anchor::Middle => x - w / 2.0,
                        };
                        let d = crate::font::text_path(t, left, y - h, h);
                        if !d.is_empty() {
                            let _ = writeln!(s, "<path d=\"{d}\" fill=\"{fill}\"/>");
                        }
                    }
                },
            }
        }
        s.push_str("</svg>\n");
        s
    }
}

/// Formats a coordinate with at most 3 decimals and no trailing zeros.
pub fn num(v: f64) -> String {
    let v = (v * 1000.0).round() / 1000.0;
    let v = if v == 0.0 { 0.0 } else { v };
    let s = format!("{v:.3}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    s.to_string()
}

/// SVG path data of closed polygons.
pub fn polygon_path(loops: &[Vec<[f64; 2]>]) -> String {
    let mut d = String::new();
    for l in loops {
        for (i, p) in l.iter().enumerate() {
            d.push(if i == 0 { 'M' } else { 'L' });
            d += &num(p[0]);
            d.push(' ');
            d += &num(p[1]);
        }
        d.push('Z');
    }
    d
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_short() {
        assert_eq!(num(1.0), "1");
        assert_eq!(num(1.25), "1.25");
        assert_eq!(num(-0.0001), "0");
        assert_eq!(num(2.0 / 3.0), "0.667");
    }

    #[test]
    fn labels_are_escaped() {
        let mut d = Drawing::new(10.0, 10.0, Unit::Mm, None);
        d.push(Item::Text {
            x: 1.0,
            y: 2.0,
            size: 3.0,
            anchor: Anchor::Start,
            text: "a<b".into(),
            fill: Rgb::BLACK,
        });
        let svg = d.to_svg(TextMode::Text);
        assert!(svg.contains("width=\"10mm\""));
        assert!(svg.contains("a&lt;b"));
    }
}
