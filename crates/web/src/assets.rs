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
    (
        "view3d.js",
        "text/javascript; charset=utf-8",
        include_bytes!("../assets/view3d.js"),
    ),
    (
        "vendor/three/three.module.js",
        "text/javascript; charset=utf-8",
        include_bytes!("../assets/vendor/three/three.module.js"),
    ),
    (
        "vendor/three/three.core.js",
        "text/javascript; charset=utf-8",
        include_bytes!("../assets/vendor/three/three.core.js"),
    ),
    (
        "vendor/three/OrbitControls.js",
        "text/javascript; charset=utf-8",
        include_bytes!("../assets/vendor/three/OrbitControls.js"),
    ),
];

/// The asset at `path` (without the leading `/`), if any.
pub fn find(path: &str) -> Option<(&'static str, &'static [u8])> {
    let path = if path.is_empty() { "index.html" } else { path };
    ASSETS
        .iter()
        .find(|(p, _, _)| *p == path)
        .map(|(_, t, b)| (*t, *b))
}
