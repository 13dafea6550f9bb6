//! `GET /api/lattices`: how the page draws each lattice's cells, made by
//! `dissect_render::tiling` from the lattice itself (the page keeps no
//! geometry of its own), with a title and the downloads the lattice has.

use dissect_core::LatticeKind;
use dissect_render::tiling::Tiling;
use serde_json::{json, Value};

use crate::export;

/// The name shown in the page's lattice menu.
fn title(lattice: LatticeKind) -> &'static str {
    match lattice {
        LatticeKind::Square => "square",
        LatticeKind::Tri4 => "tri4 (right triangles)",
        LatticeKind::Cubic => "cubic (layers)",
        LatticeKind::Tri3 => "tri3 (equilateral triangles)",
        LatticeKind::Hex => "hex (hexagons)",
    }
}

/// One lattice's description: the tiling (`dissect_render::tiling::Tiling`
/// as JSON), its title, its export formats, and whether the checkerboard
/// constraint is offered on it (the puzzle crate's test: block parity
/// colours every two neighbouring cells differently).
pub fn describe(lattice: LatticeKind) -> Value {
    let mut v = Tiling::of(lattice).to_json();
    v["title"] = json!(title(lattice));
    v["exports"] = json!(export::formats_for(lattice));
    v["checkerboard"] = json!(dissect_puzzle::constraints::has_checkerboard(lattice));
    v
}

/// Every lattice, in the order of `LatticeKind::ALL`.
pub fn list() -> Value {
    json!({ "lattices": LatticeKind::ALL.iter().map(|k| describe(*k)).collect::<Vec<_>>() })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_lattice_is_described_with_its_downloads() {
        let v = list();
        let ls = v["lattices"].as_array().unwrap();
        assert_eq!(ls.len(), 5);
        let by = |n: &str| ls.iter().find(|l| l["lattice"] == n).unwrap().clone();
        let has = |l: &Value, f: &str| l["exports"].as_array().unwrap().iter().any(|x| x == f);
        assert!(has(&by("square"), "ldraw") && has(&by("square"), "cut-sheet"));
        assert!(!has(&by("cubic"), "cut-sheet") && has(&by("cubic"), "ldraw"));
        for l in ["tri4", "tri3", "hex"] {
            assert!(
                !has(&by(l), "ldraw") && has(&by(l), "cut-sheet") && has(&by(l), "stl"),
                "{l}"
            );
        }
        assert_eq!(by("tri3")["period"], json!([2, 2]));
        for (l, checkerboard) in [
            ("square", true),
            ("cubic", true),
            ("tri4", false),
            ("tri3", true),
            ("hex", false),
        ] {
            assert_eq!(by(l)["checkerboard"], checkerboard, "{l}");
        }
        assert_eq!(
            by("hex")["tiles"][0]["polygon"].as_array().unwrap().len(),
            6
        );
    }
}
