//! Instructions to print: for every figure one SVG sheet showing its
//! assembly step by step, one piece added per step, in an order a person
//! could lay the pieces down: for a 3D figure that comes apart, the reverse
//! of its disassembly plan (`animation::figure_plan`), so no step puts a
//! piece where a hand cannot; otherwise `dissect_core::motion::assembly_order`.
//! Every step is the usual view (flat, or isometric assembled and exploded
//! for `cubic`) of the pieces placed so far, in their own colours.

use std::fmt::Write;

use crate::drawing::{num, TextMode};
use crate::view::{view, ViewOptions};
use crate::Scene;

const GAP: f64 = 16.0;
const CAPTION: f64 = 28.0;

/// The sheet of figure `f`: one panel per step, `columns` panels a row.
pub fn sheet(scene: &Scene, f: usize, columns: usize) -> String {
    let n = scene.piece_count();
    let cells: Vec<Vec<dissect_core::Cell>> = (0..n).map(|i| scene.cells(f, i).to_vec()).collect();
    let order = crate::animation::figure_plan(scene.lattice(), &cells).order;
    // The same scale in every panel: the one of the whole figure.
    let whole = scene.subset(f, &order);
    let base = ViewOptions::default();
    let cell_px = crate::view::chosen_cell_px(&whole, &base);
    let opts = ViewOptions {
        cell_px: Some(cell_px),
        ..base
    };
    let panels: Vec<(String, f64, f64)> = (1..=n)
        .map(|k| {
            let d = view(&scene.subset(f, &order[..k]), &opts);
            (d.to_svg(TextMode::Text), d.width(), d.height())
        })
        .collect();
    let pw = panels.iter().map(|p| p.1).fold(0.0, f64::max);
    let ph = panels.iter().map(|p| p.2).fold(0.0, f64::max) + CAPTION;
    let cols = columns.clamp(1, n);
    let rows = n.div_ceil(cols);
    let width = cols as f64 * (pw + GAP) + GAP;
    let height = rows as f64 * (ph + GAP) + GAP + 40.0;
    let mut s = String::new();
    let _ = writeln!(
        s,
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{w}\" height=\"{h}\" viewBox=\"0 0 {w} {h}\">",
        w = num(width),
        h = num(height)
    );
    let _ = writeln!(
        s,
        "<rect x=\"0\" y=\"0\" width=\"{}\" height=\"{}\" fill=\"#ffffff\"/>",
        num(width),
        num(height)
    );
    let _ = writeln!(
        s,
        "<text x=\"{GAP}\" y=\"30\" font-family=\"sans-serif\" font-size=\"20\" fill=\"#222222\">{}: {n} pieces, one step each</text>",
        escape(scene.name(f))
    );
    for (k, (svg, _, _)) in panels.iter().enumerate() {
        let x = GAP + (k % cols) as f64 * (pw + GAP);
        let y = 40.0 + GAP + (k / cols) as f64 * (ph + GAP);
        let _ = writeln!(
            s,
            "<rect x=\"{}\" y=\"{}\" width=\"{}\" height=\"{}\" fill=\"none\" stroke=\"#cccccc\"/>",
            num(x),
            num(y),
            num(pw),
            num(ph)
        );
        let _ = writeln!(
            s,
            "<text x=\"{}\" y=\"{}\" font-family=\"sans-serif\" font-size=\"16\" fill=\"#222222\">Step {} of {n}: add piece {}</text>",
            num(x + 10.0),
            num(y + 20.0),
            k + 1,
            scene.label(order[k])
        );
        // Each step's view, nested at its place.
        let inner = svg.replacen(
            "<svg ",
            &format!("<svg x=\"{}\" y=\"{}\" ", num(x), num(y + CAPTION)),
            1,
        );
        s.push_str(&inner);
    }
    s.push_str("</svg>\n");
    s
}

/// The sheets of every figure: `(file name, SVG)`, named
/// `steps-<figure>.svg` after the figure's name without its extension.
pub fn sheets(scene: &Scene) -> Vec<(String, String)> {
    (0..scene.figure_count())
        .map(|f| {
            let name = scene.name(f);
            let stem = name.rsplit_once('.').map_or(name, |(a, _)| a);
            let safe: String = stem
                .chars()
                .map(|c| {
                    if c.is_ascii_alphanumeric() || c == '-' || c == '_' {
                        c
                    } else {
                        '_'
                    }
                })
                .collect();
            (format!("steps-{}-{safe}.svg", f + 1), sheet(scene, f, 3))
        })
        .collect()
}

fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

#[cfg(test)]
mod tests {
    use super::*;
    use dissect_core::Dissection;
    use dissect_core::LatticeKind;

    #[test]
    fn one_panel_per_piece_each_with_one_more_piece() {
        let pieces = vec![
            vec![[0, 0, 0], [1, 0, 0], [2, 0, 0]],
            vec![[0, 1, 0], [1, 1, 0], [2, 1, 0]],
            vec![[0, 2, 0], [1, 2, 0], [2, 2, 0]],
        ];
        let d = Dissection::new(
            LatticeKind::Square,
            true,
            vec!["sq.txt".into(), "sq2.txt".into()],
            vec![pieces.clone(), pieces],
        )
        .unwrap();
        let scene = Scene::new(&d).unwrap();
        let files = sheets(&scene);
        assert_eq!(files.len(), 2);
        assert_eq!(files[0].0, "steps-1-sq.svg");
        let svg = &files[0].1;
        // Bottom row first (piece C), then B, then A.
        let steps: Vec<&str> = svg
            .match_indices("Step ")
            .map(|(i, _)| &svg[i..i + 26])
            .collect();
        assert_eq!(steps.len(), 3);
        assert!(
            steps[0].starts_with("Step 1 of 3: add piece C"),
            "{steps:?}"
        );
        assert!(
            steps[2].starts_with("Step 3 of 3: add piece A"),
            "{steps:?}"
        );
        // Step k shows k pieces, each in its own colour.
        let colour = |i: usize| crate::colour::piece_colour(i).to_string();
        let panels: Vec<&str> = svg.split("<svg x=").skip(1).collect();
        assert_eq!(panels.len(), 3);
        for (k, p) in panels.iter().enumerate() {
            let shown = (0..3).filter(|&i| p.contains(&colour(i))).count();
            assert_eq!(shown, k + 1, "panel {k}");
        }
        assert!(panels[0].contains(&colour(2)) && !panels[0].contains(&colour(0)));
        // It is a picture resvg can draw.
        crate::png::svg_to_png(&svg.replace("<text", "<g").replace("</text>", "</g>")).unwrap();
    }

    /// A 2x2x1 slab, an L lying on it and a cube in the L's corner, the
    /// cube given first: the plan takes the cube off first, then the L, so
    /// the sheet adds the slab, the L, the cube: the plan in reverse.
    #[test]
    fn a_3d_sheet_adds_the_pieces_in_the_plan_reversed() {
        let solution = r#"{"format": "dissection-solution/1", "lattice": "cubic", "mirror": true,
          "figures": [{"name": "a", "pieces": [[[1,1,1]], [[0,0,1],[1,0,1],[0,1,1]],
            [[0,0,0],[1,0,0],[0,1,0],[1,1,0]]]}]}"#;
        let scene = Scene::from_solution(solution, &[]).expect("a scene");
        let cells: Vec<Vec<dissect_core::Cell>> =
            (0..3).map(|i| scene.cells(0, i).to_vec()).collect();
        let plan = crate::animation::figure_plan(scene.lattice(), &cells);
        assert_eq!(plan.order, vec![2, 1, 0]);
        let svg = sheet(&scene, 0, 3);
        let steps: Vec<&str> = svg
            .match_indices("add piece ")
            .map(|(i, _)| &svg[i + 10..i + 11])
            .collect();
        assert_eq!(steps, ["C", "B", "A"]);
    }
}
