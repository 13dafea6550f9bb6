//! The page to share: one self-contained HTML file (scripts, styles and data
//! inline; nothing fetched) with the figures and pieces, the motion of the
//! pieces from one figure to another, and for `cubic` a 3D view to turn. It
//! opens from a double-click in any current browser.

use crate::{RenderError, Scene};

/// The motion player (an ES module without imports), shared with the studio.
pub const PLAYER_JS: &str = include_str!("../assets/player.js");

/// The HTML page of a scene.
pub fn page(scene: &Scene) -> Result<String, RenderError> {
    let data = crate::animation::data(scene)?;
    // '<' only occurs inside JSON strings, where \u003c means the same.
    let json = serde_json::to_string(&data)
        .map_err(|e| RenderError::Draw(e.to_string()))?
        .replace('<', "\\u003c");
    let title = (0..scene.figure_count())
        .map(|f| scene.name(f).to_string())
        .collect::<Vec<_>>()
        .join(" ↔ ");
    let picture = crate::svg::render(scene);
    let picture = picture
        .find("<svg")
        .map_or(picture.as_str(), |i| &picture[i..]);
    let summary = format!(
        "{} pieces · {} figures · lattice {}",
        scene.piece_count(),
        scene.figure_count(),
        scene.lattice()
    );
    let player = PLAYER_JS.replace("</script", "<\\/script");
    Ok(format!(
        r#"<!doctype html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<meta name="generator" content="dissect {version}">
<title>{title_e} — a dissection puzzle</title>
<style>
body {{ font: 15px system-ui, sans-serif; color: #1d1d1f; max-width: 1100px; margin: 24px auto; padding: 0 16px; }}
h1 {{ font-size: 22px; margin: 0 0 4px; }}
.sub {{ color: #6b6b70; margin: 0 0 12px; }}
.picture svg {{ max-width: 100%; height: auto; }}
</style>
</head>
<body>
<h1>{title_e}</h1>
<p class="sub">{summary}. Press ▶ Play or drag the slider to see every piece move from one figure to the other; tick “one at a time” to lay them down in order.</p>
<div id="player" data-testid="player"></div>
<h2>The figures</h2>
<div class="picture">{picture}</div>
<p class="sub">Made with dissect.</p>
<script type="application/json" id="dissection">{json}</script>
<script type="module">
{player}
const data = JSON.parse(document.getElementById('dissection').textContent);
window.dissectPlayer = createPlayer(document.getElementById('player'), data);
document.body.dataset.ready = 'true';
</script>
</body>
</html>
"#,
        version = env!("CARGO_PKG_VERSION"),
        title_e = escape(&title),
    ))
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}
