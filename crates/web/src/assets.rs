//! The page's files, compiled into the binary.

/// `(path, content type, bytes)` of every asset served under `/`.
pub const ASSETS: &[(&str, &str, &[u8])] = &[
    (
        "index.html",
        "text/html; charset=utf-8",
        include_bytes!("../assets/index.html"),
    ),
    (
        "studio.css",
        "text/css; charset=utf-8",
        include_bytes!("../assets/studio.css"),
    ),
    (
        "studio.js",
        "text/javascript; charset=utf-8",
        include_bytes!("../assets/studio.js"),
    ),
];

/// `palette.js`: the piece colours of `dissect_core::palette` for the page
/// (the page holds no copy of its own).
pub fn palette_js() -> String {
    let colours: Vec<String> = (0..PALETTE_LEN)
        .map(|i| format!("'{}'", dissect_core::palette::piece_hex(i)))
        .collect();
    format!(
        "// Made by dissect-web from dissect_core::palette: piece i has this colour\n\
         // in the studio, in SVG/PNG pictures and in the terminal.\n\
         export const PALETTE = [{}];\n\
         export const pieceColour = (i) => PALETTE[i % PALETTE.length];\n",
        colours.join(", ")
    )
}

/// How many colours `palette.js` lists (pieces beyond wrap round).
pub const PALETTE_LEN: usize = 256;

static PALETTE_JS: std::sync::LazyLock<String> = std::sync::LazyLock::new(palette_js);

/// The asset at `path` (without the leading `/`), if any.
pub fn find(path: &str) -> Option<(&'static str, &'static [u8])> {
    let path = if path.is_empty() { "index.html" } else { path };
    const JS: &str = "text/javascript; charset=utf-8";
    match path {
        "palette.js" => return Some((JS, PALETTE_JS.as_bytes())),
        // The motion player, shared with the HTML page of `dissect render`.
        "player.js" => return Some((JS, dissect_render::html::PLAYER_JS.as_bytes())),
        _ => {}
    }
    ASSETS
        .iter()
        .find(|(p, _, _)| *p == path)
        .map(|(_, t, b)| (*t, *b))
}
