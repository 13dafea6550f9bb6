//! The example puzzles shipped in the binary: the repository's example and a
//! few of the benchmark instances (copied into `crates/web/puzzles/`).

use serde_json::{json, Value};

/// One shipped example: id, title, lattice and its figure files.
pub struct Example {
    pub id: &'static str,
    pub title: &'static str,
    pub lattice: &'static str,
    pub figures: &'static [(&'static str, &'static str)],
}

macro_rules! fig {
    ($dir:literal, $file:literal) => {
        (
            $file,
            include_str!(concat!("../puzzles/", $dir, "/", $file)),
        )
    };
}

/// All shipped examples.
pub const EXAMPLES: &[Example] = &[
    Example {
        id: "squares-3-4-to-5",
        title: "3×3 and 4×4 squares to a 5×5 square",
        lattice: "square",
        figures: &[
            fig!("squares-3-4-to-5", "a.txt"),
            fig!("squares-3-4-to-5", "b.txt"),
        ],
    },
    Example {
        id: "rect10x7-hole-to-square8",
        title: "10×7 rectangle with a hole to an 8×8 square (paper Fig. 2)",
        lattice: "square",
        figures: &[
            fig!("rect10x7-hole-to-square8", "a.txt"),
            fig!("rect10x7-hole-to-square8", "b.txt"),
        ],
    },
    Example {
        id: "tri-triangle8-to-rect4x8",
        title: "Right triangle to a 4×8 rectangle (tri4)",
        lattice: "tri4",
        figures: &[
            fig!("tri-triangle8-to-rect4x8", "a.txt"),
            fig!("tri-triangle8-to-rect4x8", "b.txt"),
        ],
    },
    Example {
        id: "cube4-cavity-to-7x4x2",
        title: "4×4×4 cube with a cavity to a 7×4×2 box (cubic)",
        lattice: "cubic",
        figures: &[
            fig!("cube4-cavity-to-7x4x2", "a.txt"),
            fig!("cube4-cavity-to-7x4x2", "b.txt"),
        ],
    },
    Example {
        id: "tri3-hexagon2-to-parallelogram4x3",
        title: "Hexagon of side 2 to a 4×3 parallelogram (tri3, optimum 3 pieces)",
        lattice: "tri3",
        figures: &[
            fig!("tri3-hexagon2-to-parallelogram4x3", "a.txt"),
            fig!("tri3-hexagon2-to-parallelogram4x3", "b.txt"),
        ],
    },
    Example {
        id: "hex-three-hexagons2-to-rhombus7x3",
        title: "Three hexagons of side 2 to a 7×3 rhombus (hex, optimum 5 pieces)",
        lattice: "hex",
        figures: &[
            fig!("hex-three-hexagons2-to-rhombus7x3", "a.txt"),
            fig!("hex-three-hexagons2-to-rhombus7x3", "b.txt"),
        ],
    },
    Example {
        id: "hex-hexagon6-to-rhombus13x7",
        title: "Hexagon of side 6 to a 13×7 rhombus (hex)",
        lattice: "hex",
        figures: &[
            fig!("hex-hexagon6-to-rhombus13x7", "a.txt"),
            fig!("hex-hexagon6-to-rhombus13x7", "b.txt"),
        ],
    },
];

/// The examples as the API lists them.
pub fn list() -> Value {
    Value::Array(
        EXAMPLES
            .iter()
            .map(|e| {
                json!({
                    "id": e.id,
                    "title": e.title,
                    "lattice": e.lattice,
                    "figures": e.figures.iter().map(|(n, t)| json!({"name": n, "text": t})).collect::<Vec<_>>(),
                })
            })
            .collect(),
    )
}
