//! Bounds on what a picture, a mesh or a drawing may cost, checked before
//! anything is allocated, so that hostile input (a 100-byte SVG claiming to
//! be 10⁹ pixels wide, a PNG "bomb", 50,000 nested SVG groups, a scale of
//! 10⁻⁹) ends with an error instead of an abort, a stack overflow or a hang.
//! The command line and the web server share these checks.

use crate::RenderError;

/// The most pixels a PNG or JPEG picture may have (decoded: 4 bytes each).
pub const MAX_PICTURE_PIXELS: u64 = 1 << 24;
/// The longest side of a PNG or JPEG picture, in pixels.
pub const MAX_PICTURE_SIDE: u32 = 1 << 15;
/// The most bytes a picture decoder may allocate.
pub const MAX_DECODE_BYTES: u64 = 256 << 20;
/// The most pixels of a picture drawn from an SVG document (a rasterized
/// SVG or a PNG export): 4 bytes each.
pub const MAX_DRAWN_PIXELS: u64 = 1 << 25;
/// The deepest element nesting of an SVG document.
pub const MAX_SVG_DEPTH: usize = 128;
/// The most XML nodes of an SVG document.
pub const MAX_SVG_NODES: u32 = 500_000;
/// The most cells (or cubes) of the grid a picture or a mesh is sampled on,
/// and so of a figure made from one.
pub const MAX_GRID_CELLS: u64 = 1 << 20;
/// The most triangles of a mesh.
pub const MAX_TRIANGLES: usize = 2_000_000;
/// The most pixels per cell edge of a view (`--cell-px`).
pub const MAX_CELL_PX: f64 = 1000.0;

/// Fails unless a decoded picture of `w`×`h` pixels is within the bounds.
pub fn check_picture_size(w: u64, h: u64) -> Result<(), RenderError> {
    if w > MAX_PICTURE_SIDE as u64
        || h > MAX_PICTURE_SIDE as u64
        || w.saturating_mul(h) > MAX_PICTURE_PIXELS
    {
        return Err(RenderError::TooLarge(format!(
            "the picture is {w}x{h} pixels; at most {MAX_PICTURE_PIXELS} pixels \
             ({MAX_PICTURE_SIDE} on a side) are read: make it smaller"
        )));
    }
    Ok(())
}

/// Fails unless a sampling grid of `dims` cells is within the bounds;
/// `what` says how to make it smaller.
pub(crate) fn check_grid(dims: [f64; 3], what: &str) -> Result<(), RenderError> {
    let cells = dims.iter().product::<f64>();
    if !cells.is_finite() || cells > MAX_GRID_CELLS as f64 {
        let shown: Vec<String> = dims
            .iter()
            .filter(|d| **d != 1.0)
            .map(|d| {
                if d.is_finite() && *d < 1e15 {
                    format!("{d:.0}")
                } else {
                    format!("{d:.1e}")
                }
            })
            .collect();
        return Err(RenderError::TooLarge(format!(
            "that would be a grid of {} cells, more than {MAX_GRID_CELLS}: {what}",
            if shown.is_empty() {
                "1".to_string()
            } else {
                shown.join("x")
            }
        )));
    }
    Ok(())
}

/// Fails unless `--cell-px` is a positive size up to [`MAX_CELL_PX`].
pub fn check_cell_px(px: Option<f64>) -> Result<(), RenderError> {
    match px {
        Some(v) if !(v.is_finite() && v > 0.0 && v <= MAX_CELL_PX) => Err(RenderError::BadOption(
            format!("--cell-px must be more than 0 and at most {MAX_CELL_PX}, got {v}"),
        )),
        _ => Ok(()),
    }
}

/// Parses an SVG document after checking its nesting depth and node count
/// (resvg recurses once per nesting level).
pub(crate) fn parse_svg(text: &str) -> Result<resvg::usvg::Tree, RenderError> {
    let bad = |m: String| RenderError::NotAPicture(format!("SVG: {m}"));
    check_svg_markup(text)?;
    let xml = resvg::usvg::roxmltree::Document::parse_with_options(
        text,
        resvg::usvg::roxmltree::ParsingOptions {
            allow_dtd: true,
            nodes_limit: MAX_SVG_NODES,
        },
    )
    .map_err(|e| bad(e.to_string()))?;
    // Depth after entities are expanded: iteratively, in document order.
    let mut depth: Vec<(resvg::usvg::roxmltree::NodeId, usize)> = Vec::new();
    for node in xml.root().descendants() {
        let parent = node.parent().map(|p| p.id());
        while depth.last().is_some_and(|(id, _)| Some(*id) != parent) {
            depth.pop();
        }
        let d = depth.last().map_or(0, |(_, d)| d + 1);
        if d > MAX_SVG_DEPTH {
            return Err(too_deep());
        }
        depth.push((node.id(), d));
    }
    resvg::usvg::Tree::from_xmltree(&xml, &resvg::usvg::Options::default())
        .map_err(|e| bad(e.to_string()))
}

fn too_deep() -> RenderError {
    RenderError::TooLarge(format!(
        "the SVG nests elements more than {MAX_SVG_DEPTH} deep"
    ))
}

/// A scan of the markup before the XML parser sees it: element nesting
/// deeper than [`MAX_SVG_DEPTH`], and entities that hold markup (which could
/// nest elements without bound), are refused. Comments, CDATA, processing
/// instructions and quoted attribute values are skipped.
fn check_svg_markup(text: &str) -> Result<(), RenderError> {
    let b = text.as_bytes();
    let mut i = 0;
    let mut depth = 0usize;
    let skip_to = |from: usize, end: &[u8]| -> usize {
        b[from..]
            .windows(end.len())
            .position(|w| w == end)
            .map_or(b.len(), |p| from + p + end.len())
    };
    while i < b.len() {
        if b[i] != b'<' {
            i += 1;
            continue;
        }
        let rest = &b[i..];
        if rest.starts_with(b"<!--") {
            i = skip_to(i + 4, b"-->");
        } else if rest.starts_with(b"<![CDATA[") {
            i = skip_to(i + 9, b"]]>");
        } else if rest.starts_with(b"<?") {
            i = skip_to(i + 2, b"?>");
        } else if rest.starts_with(b"<!") {
            // DOCTYPE with its internal subset: entity values must be text.
            let mut j = i + 2;
            let mut bracket = 0usize;
            let mut quote: Option<u8> = None;
            while j < b.len() {
                let c = b[j];
                match quote {
                    Some(q) if c == q => quote = None,
                    Some(_) if c == b'<' => {
                        return Err(RenderError::NotAPicture(
                            "SVG: entities that hold markup are not read".into(),
                        ))
                    }
                    Some(_) => {}
                    None => match c {
                        b'"' | b'\'' => quote = Some(c),
                        b'[' => bracket += 1,
                        b']' => bracket = bracket.saturating_sub(1),
                        b'>' if bracket == 0 => break,
                        _ => {}
                    },
                }
                j += 1;
            }
            i = j + 1;
        } else if rest.starts_with(b"</") {
            depth = depth.saturating_sub(1);
            i = skip_to(i + 2, b">");
        } else {
            let mut j = i + 1;
            let mut quote: Option<u8> = None;
            while j < b.len() {
                let c = b[j];
                match quote {
                    Some(q) if c == q => quote = None,
                    Some(_) => {}
                    None if c == b'"' || c == b'\'' => quote = Some(c),
                    None if c == b'>' => break,
                    None => {}
                }
                j += 1;
            }
            if !(j > i + 1 && j < b.len() && b[j - 1] == b'/') {
                depth += 1;
                if depth > MAX_SVG_DEPTH {
                    return Err(too_deep());
                }
            }
            i = j + 1;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn nested(n: usize) -> String {
        format!(
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"10\" height=\"10\">{}<rect width=\"5\" height=\"5\"/>{}</svg>",
            "<g>".repeat(n),
            "</g>".repeat(n)
        )
    }

    #[test]
    fn nesting_is_bounded_before_parsing() {
        assert!(parse_svg(&nested(MAX_SVG_DEPTH - 2)).is_ok());
        for n in [MAX_SVG_DEPTH + 1, 50_000] {
            let e = parse_svg(&nested(n)).unwrap_err();
            assert!(e.to_string().contains("nests elements more than"), "{e}");
        }
    }

    #[test]
    fn the_deepest_allowed_svg_draws_on_a_small_stack() {
        // The server draws on tokio's blocking threads (2 MiB stacks).
        let text = nested(MAX_SVG_DEPTH - 2);
        let r = std::thread::Builder::new()
            .stack_size(2 << 20)
            .spawn(move || crate::png::svg_to_png(&text).map(|p| p.len()))
            .unwrap()
            .join()
            .unwrap();
        assert!(r.unwrap() > 0);
    }

    #[test]
    fn markup_in_entities_and_comments() {
        let e = check_svg_markup(
            "<!DOCTYPE svg [<!ENTITY g \"<g><g>\">]><svg xmlns=\"http://www.w3.org/2000/svg\">&g;</svg>",
        )
        .unwrap_err();
        assert!(e.to_string().contains("entities"), "{e}");
        let text_entity = "<!DOCTYPE svg [<!ENTITY ns \"http://www.w3.org/2000/svg\">]>\
            <svg xmlns=\"&ns;\" width=\"4\" height=\"4\"><!-- <g><g><g> --><rect width=\"2\" height=\"2\" title='a>b'/></svg>";
        assert!(parse_svg(text_entity).is_ok());
    }

    #[test]
    fn sizes() {
        assert!(check_picture_size(4096, 4096).is_ok());
        assert!(check_picture_size(20_000, 20_000).is_err());
        assert!(check_picture_size(1 << 16, 1).is_err());
        assert!(check_cell_px(Some(0.0)).is_err());
        assert!(check_cell_px(Some(f64::NAN)).is_err());
        assert!(check_cell_px(Some(100_000.0)).is_err());
        assert!(check_cell_px(Some(12.5)).is_ok());
        assert!(check_grid([1e9, 1e9, 1.0], "x").is_err());
        assert!(check_grid([f64::INFINITY, 1.0, 1.0], "x").is_err());
        assert!(check_grid([1000.0, 1000.0, 1.0], "x").is_ok());
    }
}
