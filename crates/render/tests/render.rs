//! End-to-end tests of dissect-render on small dissections written as ASCII
//! figures. Every solution is checked by `dissect_core::verify` (through
//! `Scene::from_solution`). Golden files live in `tests/golden/`; run with
//! `DISSECT_UPDATE_GOLDEN=1` to write them again after a deliberate change.

use std::collections::{HashMap, HashSet};
use std::path::PathBuf;

use dissect_core::io::parse_figure;
use dissect_core::{Cell, LatticeKind};
use dissect_render::ldraw::{self, PartKind};
use dissect_render::mesh::Mesh;
use dissect_render::rasterize::{rasterize, RasterOptions};
use dissect_render::stl::{self, PhysicalOptions};
use dissect_render::voxelize::{voxelize, VoxelOptions};
use dissect_render::{cut_sheet, png, svg, RenderError, Scene};

/// A small dissection: lattice, figure texts and the solution JSON.
struct Case {
    name: &'static str,
    lattice: LatticeKind,
    figures: [&'static str; 2],
    solution: &'static str,
}

const SQUARE: Case = Case {
    name: "square",
    lattice: LatticeKind::Square,
    // A 4x4 square with a hole-free L cut, into a 2x8 bar.
    figures: ["####\n####\n####\n####\n", "########\n########\n"],
    solution: r#"{"format":"dissection-solution/1","lattice":"square","mirror":true,"figures":[
      {"name":"square.txt","pieces":[[[0,0],[1,0],[2,0],[3,0],[0,1],[1,1],[2,1],[3,1]],
                                     [[0,2],[1,2],[2,2],[3,2],[0,3],[1,3],[2,3],[3,3]]]},
      {"name":"bar.txt","pieces":[[[0,0],[1,0],[2,0],[3,0],[0,1],[1,1],[2,1],[3,1]],
                                  [[4,0],[5,0],[6,0],[7,0],[4,1],[5,1],[6,1],[7,1]]]}]}"#,
};

const RING: Case = Case {
    name: "ring",
    lattice: LatticeKind::Square,
    // A ring (a figure with a hole) cut into two pieces.
    figures: ["####\n#..#\n####\n", "####\n#..#\n####\n"],
    solution: r#"{"format":"dissection-solution/1","lattice":"square","figures":[
      {"name":"a.txt","pieces":[[[0,0],[1,0],[2,0],[3,0],[0,1],[0,2],[1,2]],[[3,1],[3,2],[2,2]]]},
      {"name":"b.txt","pieces":[[[0,0],[1,0],[2,0],[3,0],[0,1],[0,2],[1,2]],[[3,1],[3,2],[2,2]]]}]}"#,
};

const PINCH: Case = Case {
    name: "pinch",
    lattice: LatticeKind::Square,
    // One piece whose hole touches the outside at a corner.
    figures: [".##\n#.#\n###\n", ".##\n#.#\n###\n"],
    solution: r#"{"format":"dissection-solution/1","lattice":"square","figures":[
      {"name":"a.txt","pieces":[[[1,0],[2,0],[0,1],[2,1],[0,2],[1,2],[2,2]]]},
      {"name":"b.txt","pieces":[[[1,0],[2,0],[0,1],[2,1],[0,2],[1,2],[2,2]]]}]}"#,
};

const TRI4: Case = Case {
    name: "tri4",
    lattice: LatticeKind::Tri4,
    // A 2x1 rectangle into a right triangle with legs 2.
    figures: ["##\n", ".6\n6#\n"],
    solution: r#"{"format":"dissection-solution/1","lattice":"tri4","figures":[
      {"name":"rect.txt","pieces":[[[0,0,0],[0,0,1],[0,0,2],[0,0,3]],[[1,0,1],[1,0,2]],[[1,0,3],[1,0,0]]]},
      {"name":"triangle.txt","pieces":[[[1,1,0],[1,1,1],[1,1,2],[1,1,3]],[[1,0,1],[1,0,2]],[[0,1,1],[0,1,2]]]}]}"#,
};

const CUBIC: Case = Case {
    name: "cubic",
    lattice: LatticeKind::Cubic,
    // A 2x2x2 cube into a 4x2x1 slab, with an L-shaped piece.
    figures: ["##\n##\n\n##\n##\n", "####\n####\n"],
    solution: r#"{"format":"dissection-solution/1","lattice":"cubic","mirror":false,"figures":[
      {"name":"cube.txt","pieces":[[[0,0,0],[1,0,0],[0,1,0],[1,1,0]],[[0,0,1],[1,0,1],[0,1,1],[1,1,1]]]},
      {"name":"slab.txt","pieces":[[[0,0,0],[1,0,0],[0,1,0],[1,1,0]],[[2,0,0],[3,0,0],[2,1,0],[3,1,0]]]}]}"#,
};

const CUBIC_STEP: Case = Case {
    name: "cubic-step",
    lattice: LatticeKind::Cubic,
    // Pieces with steps (faces meeting at T-junctions) and an L.
    figures: ["###\n#..\n\n#..\n...\n", "##\n.#\n\n##\n..\n"],
    solution: r#"{"format":"dissection-solution/1","lattice":"cubic","figures":[
      {"name":"a.txt","pieces":[[[0,0,0],[0,1,0],[0,0,1]],[[1,0,0],[2,0,0]]]},
      {"name":"b.txt","pieces":[[[0,0,0],[1,0,0],[1,1,0]],[[0,0,1],[1,0,1]]]}]}"#,
};

const TRI3: Case = Case {
    name: "tri3",
    lattice: LatticeKind::Tri3,
    // A hexagon of six triangles into a parallelogram: two trapezoids, one
    // turned upside down (up triangles become down ones).
    figures: ["###\n###\n", "######\n"],
    solution: r#"{"format":"dissection-solution/1","lattice":"tri3","mirror":true,"figures":[
      {"name":"hexagon.txt","pieces":[[[0,1],[1,1],[2,1]],[[0,0],[1,0],[2,0]]]},
      {"name":"parallelogram.txt","pieces":[[[3,0],[4,0],[5,0]],[[0,0],[1,0],[2,0]]]}]}"#,
};

const HEX: Case = Case {
    name: "hex",
    lattice: LatticeKind::Hex,
    // A hexagon of seven hexagons (odd rows shifted right) into a trapezoid.
    figures: [".##\n###\n.##\n", "####\n###\n"],
    solution: r#"{"format":"dissection-solution/1","lattice":"hex","mirror":true,"figures":[
      {"name":"hexagon.txt","pieces":[[[1,0],[1,1],[2,0],[2,1],[2,2]],[[0,1],[1,2]]]},
      {"name":"trapezoid.txt","pieces":[[[1,0],[1,1],[2,0],[2,1],[3,0]],[[0,0],[0,1]]]}]}"#,
};

fn scene(c: &Case) -> Scene {
    Scene::from_solution(c.solution, &c.figures).unwrap_or_else(|e| panic!("{}: {e}", c.name))
}

fn golden_path(name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("tests/golden")
        .join(name)
}

fn updating() -> bool {
    std::env::var_os("DISSECT_UPDATE_GOLDEN").is_some()
}

/// Compares text with its golden file (or writes it when updating).
fn check_golden_text(name: &str, text: &str) {
    let path = golden_path(name);
    if updating() {
        std::fs::write(&path, text).unwrap();
        return;
    }
    let want = std::fs::read_to_string(&path).unwrap_or_else(|_| {
        panic!(
            "missing {} (run with DISSECT_UPDATE_GOLDEN=1)",
            path.display()
        )
    });
    assert!(
        want == text,
        "{name} differs from its golden file; run with DISSECT_UPDATE_GOLDEN=1 if the change is meant"
    );
}

#[test]
fn the_fixtures_are_valid_dissections() {
    for c in [
        &SQUARE,
        &RING,
        &PINCH,
        &TRI4,
        &CUBIC,
        &CUBIC_STEP,
        &TRI3,
        &HEX,
    ] {
        let s = scene(c);
        assert_eq!(s.lattice(), c.lattice);
        assert_eq!(s.figure_count(), 2);
    }
}

#[test]
fn svg_views_match_their_snapshots() {
    for c in [&SQUARE, &RING, &TRI4, &CUBIC, &TRI3, &HEX] {
        let s = scene(c);
        check_golden_text(&format!("{}.svg", c.name), &svg::render(&s));
    }
}

#[test]
fn cut_sheets_match_their_snapshots() {
    for c in [&SQUARE, &TRI4, &TRI3, &HEX] {
        let s = scene(c);
        let sheet = cut_sheet::render(&s, &PhysicalOptions::default()).unwrap();
        assert!(sheet.contains("width=\""), "{sheet}");
        assert!(sheet.contains("mm\""));
        check_golden_text(&format!("{}-cut-sheet.svg", c.name), &sheet);
    }
    let e = cut_sheet::render(&scene(&CUBIC), &PhysicalOptions::default()).unwrap_err();
    assert!(e.to_string().contains("2D lattices"), "{e}");
}

#[test]
fn piece_outlines_are_merged_polygons() {
    let svg = svg::render(&scene(&SQUARE));
    // Each 2x4 piece is one path with one closed curve of 4 corners.
    let piece_paths: Vec<&str> = svg
        .lines()
        .filter(|l| l.starts_with("<path d=\"M") && l.contains("fill=\"#e6615c\""))
        .collect();
    assert_eq!(
        piece_paths.len(),
        2 + 1,
        "two figures and the legend swatch"
    );
    for p in &piece_paths[..2] {
        assert_eq!(p.matches('Z').count(), 1, "{p}");
        assert_eq!(p.matches('L').count(), 3, "{p}");
    }
    // The ring piece: one outer curve and one hole.
    let ring = svg::render(&scene(&RING));
    let first = ring
        .lines()
        .find(|l| l.starts_with("<path d=\"M") && l.contains("fill=\"#e6615c\""))
        .unwrap();
    assert_eq!(
        first.matches('Z').count(),
        1,
        "the hole touches the outside: one curve"
    );
    // Triangles are drawn as triangles.
    let tri = svg::render(&scene(&TRI4));
    let half = tri
        .lines()
        .find(|l| l.starts_with("<path d=\"M") && l.contains("fill=\"#5da5da\""))
        .unwrap();
    assert_eq!(half.matches('L').count(), 2, "{half}");
}

/// The corners of the first path drawn in a colour, in pixels.
fn first_path_corners(svg: &str, fill: &str) -> Vec<[f64; 2]> {
    let line = svg
        .lines()
        .find(|l| l.starts_with("<path d=\"M") && l.contains(fill))
        .unwrap_or_else(|| panic!("no {fill} path"));
    let d = line.split('"').nth(1).unwrap();
    d.split(['M', 'L', 'Z'])
        .filter(|t| !t.trim().is_empty())
        .map(|t| {
            let v: Vec<f64> = t
                .split([' ', ','])
                .filter(|x| !x.is_empty())
                .map(|x| x.parse().unwrap())
                .collect();
            [v[0], v[1]]
        })
        .collect()
}

#[test]
fn tri3_and_hex_pieces_are_true_triangles_and_hexagons() {
    let side = |p: &[[f64; 2]], k: usize| {
        let (a, b) = (p[k], p[(k + 1) % p.len()]);
        ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)).sqrt()
    };
    // The hexagon's top trapezoid: 4 corners, sides 1, 1, 2, 1 (equilateral
    // triangles, so the slanted sides are as long as the short base).
    let svg = svg::render(&scene(&TRI3));
    let p = first_path_corners(&svg, "fill=\"#e6615c\"");
    assert_eq!(p.len(), 4, "{p:?}");
    let mut sides: Vec<f64> = (0..4).map(|k| side(&p, k)).collect();
    sides.sort_by(f64::total_cmp);
    for k in 0..3 {
        assert!((sides[k] - sides[0]).abs() < 0.02 * sides[0], "{sides:?}");
    }
    assert!(
        (sides[3] - 2.0 * sides[0]).abs() < 0.02 * sides[0],
        "{sides:?}"
    );
    // The outline of five hexagons: every side of the same length, 60° or
    // 120° turns only.
    let svg = svg::render(&scene(&HEX));
    let p = first_path_corners(&svg, "fill=\"#e6615c\"");
    let unit = (0..p.len()).map(|k| side(&p, k)).fold(f64::MAX, f64::min);
    for k in 0..p.len() {
        let l = side(&p, k);
        let ratio = l / unit;
        assert!(
            (ratio - ratio.round()).abs() < 0.02,
            "side {l} of {unit}: {p:?}"
        );
    }
    // 5 hexagons in a compact clump: the outline has 14 or more corners.
    assert!(p.len() >= 14, "{p:?}");
}

/// Counts pixels whose colour differs by more than 8 in any channel.
fn differing_pixels(a: &image::RgbaImage, b: &image::RgbaImage) -> usize {
    if a.dimensions() != b.dimensions() {
        return usize::MAX;
    }
    a.pixels()
        .zip(b.pixels())
        .filter(|(p, q)| p.0.iter().zip(q.0.iter()).any(|(x, y)| x.abs_diff(*y) > 8))
        .count()
}

#[test]
fn png_views_match_their_reference_pictures() {
    for c in [&SQUARE, &TRI4, &CUBIC, &TRI3, &HEX] {
        let bytes = png::render(&scene(c)).unwrap();
        let name = format!("{}.png", c.name);
        let path = golden_path(&name);
        if updating() {
            std::fs::write(&path, &bytes).unwrap();
            continue;
        }
        let got = image::load_from_memory(&bytes).unwrap().to_rgba8();
        let want = image::open(&path)
            .unwrap_or_else(|_| {
                panic!(
                    "missing {} (run with DISSECT_UPDATE_GOLDEN=1)",
                    path.display()
                )
            })
            .to_rgba8();
        let diff = differing_pixels(&got, &want);
        assert!(
            diff <= 20,
            "{name}: {diff} pixels differ from the reference"
        );
        // And the picture is not blank: the pieces' colours are there.
        let red = got.pixels().filter(|p| p.0[..3] == [230, 97, 92]).count();
        assert!(red > 100, "{name}: piece A is not drawn");
    }
}

fn check_meshes(c: &Case, opts: &PhysicalOptions) {
    let s = scene(c);
    let files = stl::render(&s, opts).unwrap();
    assert_eq!(files.len(), s.piece_count());
    let (area, h) = match c.lattice {
        LatticeKind::Cubic => (opts.cell_mm.powi(3), 1.0),
        LatticeKind::Square => (opts.cell_mm.powi(2), opts.thickness_mm),
        LatticeKind::Tri4 => (opts.cell_mm.powi(2) / 4.0, opts.thickness_mm),
        // A triangle of side cell_mm; a hexagon whose centres are cell_mm apart.
        LatticeKind::Tri3 => (3f64.sqrt() / 4.0 * opts.cell_mm.powi(2), opts.thickness_mm),
        LatticeKind::Hex => (3f64.sqrt() / 2.0 * opts.cell_mm.powi(2), opts.thickness_mm),
    };
    for (i, (name, bytes)) in files.iter().enumerate() {
        assert_eq!(name, &format!("piece-{:02}-{}.stl", i + 1, s.label(i)));
        let m = Mesh::from_stl(bytes).unwrap();
        assert_eq!(
            m.bad_edges(),
            0,
            "{} {name}: not closed and manifold",
            c.name
        );
        let full = s.area(i) as f64 * area * h;
        let v = m.volume();
        if opts.clearance_mm == 0.0 {
            assert!(
                (v - full).abs() < 1e-3 * full,
                "{} {name}: volume {v}, want {full}",
                c.name
            );
        } else {
            assert!(
                v > 0.5 * full && v < full,
                "{} {name}: volume {v} not below {full}",
                c.name
            );
        }
        // Coplanar faces are merged: far fewer triangles than cell faces.
        let cells = s.area(i);
        let per_cell = match c.lattice {
            LatticeKind::Cubic => 12,
            // Six walls and two faces of four triangles per hexagon.
            LatticeKind::Hex => 20,
            _ => 8,
        };
        assert!(m.triangles().len() <= per_cell * cells, "{} {name}", c.name);
    }
}

#[test]
fn every_stl_is_closed_and_manifold_with_the_right_volume() {
    for clearance in [0.0, 0.1, 0.4] {
        let opts = PhysicalOptions {
            cell_mm: 10.0,
            thickness_mm: 3.0,
            clearance_mm: clearance,
        };
        for c in [&SQUARE, &RING, &TRI4, &CUBIC, &CUBIC_STEP, &TRI3, &HEX] {
            check_meshes(c, &opts);
        }
        // A piece touching itself at a corner: only with a clearance do its
        // walls come apart there (without, four walls share one edge).
        if clearance > 0.0 {
            check_meshes(&PINCH, &opts);
        } else {
            let e = stl::render(&scene(&PINCH), &opts).unwrap_err();
            assert!(e.to_string().contains("--clearance > 0"), "{e}");
        }
    }
}

#[test]
fn a_rectangle_piece_is_twelve_triangles() {
    let s = scene(&SQUARE);
    let m = stl::piece_mesh(&s, 0, &PhysicalOptions::default()).unwrap();
    assert_eq!(m.triangles().len(), 12);
}

#[test]
fn bad_physical_options_are_refused() {
    let s = scene(&SQUARE);
    let opts = PhysicalOptions {
        clearance_mm: 5.0,
        ..PhysicalOptions::default()
    };
    let e = stl::render(&s, &opts).unwrap_err();
    assert!(e.to_string().contains("--clearance"), "{e}");
}

/// Part lines of a model: the cells each covers.
fn parts(text: &str, kind: PartKind) -> Vec<(u32, Vec<Cell>)> {
    text.lines()
        .filter(|l| l.starts_with("1 "))
        .map(|l| ldraw::part_cells(l, kind).unwrap_or_else(|| panic!("unknown part line {l:?}")))
        .collect()
}

#[test]
fn ldraw_models_have_one_part_per_merged_brick_inside_one_piece() {
    for (c, kind, want_parts) in [
        (&SQUARE, PartKind::Plate, [2, 2]),
        (&CUBIC, PartKind::Brick, [2, 2]),
        (&CUBIC_STEP, PartKind::Brick, [3, 3]),
    ] {
        let s = scene(c);
        let models = ldraw::render(&s, kind).unwrap();
        assert_eq!(models.len(), 2);
        for (f, (name, text)) in models.iter().enumerate() {
            assert!(name.ends_with(".ldr"));
            assert!(text.starts_with("0 "));
            for l in text.lines() {
                let kind_ok = l.starts_with("0 ") || l.starts_with("1 ");
                assert!(kind_ok, "{l}");
            }
            let ps = parts(text, kind);
            let merged: usize = (0..s.piece_count())
                .map(|i| ldraw::merge_cells(i, s.cells(f, i), kind).len())
                .sum();
            assert_eq!(ps.len(), merged, "{} {name}", c.name);
            assert_eq!(ps.len(), want_parts[f], "{} {name}", c.name);
            // Every part lies inside exactly one piece, and parts cover the figure once.
            let owner: HashMap<Cell, usize> = (0..s.piece_count())
                .flat_map(|i| s.cells(f, i).iter().map(move |c| (*c, i)))
                .collect();
            let mut seen = HashSet::new();
            for (_, cells) in &ps {
                let pieces: HashSet<usize> = cells.iter().map(|c| owner[c]).collect();
                assert_eq!(pieces.len(), 1, "{} {name}: a part spans pieces", c.name);
                for c in cells {
                    assert!(seen.insert(*c));
                }
            }
            assert_eq!(seen.len(), owner.len());
        }
    }
    for c in [&TRI3, &HEX] {
        let e = ldraw::render(&scene(c), PartKind::Plate).unwrap_err();
        assert!(e.to_string().contains("square and cubic"), "{e}");
        assert!(e.to_string().contains("--format stl"), "{e}");
    }
    let e = ldraw::render(&scene(&TRI4), PartKind::Plate).unwrap_err();
    assert!(e.to_string().contains("square and cubic"), "{e}");
}

#[test]
fn ldraw_merges_cells_into_big_parts() {
    let f = parse_figure("####\n####\n###.\n#...\n", LatticeKind::Square).unwrap();
    let bricks = ldraw::merge_cells(0, f.cells(), PartKind::Plate);
    let parts: Vec<&str> = bricks.iter().map(|b| b.part).collect();
    assert_eq!(parts, ["3020", "3623", "3024"]);
}

/// A PNG of a black disc of radius `r` on white, `size` pixels square.
fn disc_png(size: u32, r: f64) -> Vec<u8> {
    let c = size as f64 / 2.0;
    let img = image::GrayImage::from_fn(size, size, |x, y| {
        let d = ((x as f64 + 0.5 - c).powi(2) + (y as f64 + 0.5 - c).powi(2)).sqrt();
        image::Luma([if d <= r { 0 } else { 255 }])
    });
    let mut out = Vec::new();
    img.write_to(&mut std::io::Cursor::new(&mut out), image::ImageFormat::Png)
        .unwrap();
    out
}

#[test]
fn rasterize_a_disc_hits_the_exact_cell_count() {
    let pic = disc_png(300, 120.0);
    for (lattice, n) in [
        (LatticeKind::Square, 144),
        (LatticeKind::Square, 145),
        (LatticeKind::Tri4, 128),
        (LatticeKind::Tri4, 129),
        (LatticeKind::Tri3, 150),
        (LatticeKind::Tri3, 151),
        (LatticeKind::Hex, 61),
        (LatticeKind::Hex, 62),
    ] {
        let opts = RasterOptions {
            lattice,
            cells: Some(n),
            ..RasterOptions::default()
        };
        let r = rasterize(&[&pic], &opts).unwrap();
        assert_eq!(r.figure.len(), n, "{lattice} {n}");
        assert_eq!(parse_figure(&r.text, lattice).unwrap().len(), n);
        assert_eq!(r.figure.stats().components, 1, "{lattice} {n}\n{}", r.text);
        assert!(r.changed <= n / 10, "{lattice} {n}: {} changed", r.changed);
    }
}

#[test]
fn rasterize_reads_jpeg_and_transparent_png() {
    let png = disc_png(200, 70.0);
    let img = image::load_from_memory(&png).unwrap().to_rgb8();
    let mut jpeg = Vec::new();
    img.write_to(
        &mut std::io::Cursor::new(&mut jpeg),
        image::ImageFormat::Jpeg,
    )
    .unwrap();
    let opts = RasterOptions {
        cells: Some(144),
        ..RasterOptions::default()
    };
    assert_eq!(rasterize(&[&jpeg], &opts).unwrap().figure.len(), 144);
    // Opaque = inside, whatever the colour: a white disc on transparency.
    let rgba = image::RgbaImage::from_fn(100, 100, |x, y| {
        let d = ((x as f64 - 49.5).powi(2) + (y as f64 - 49.5).powi(2)).sqrt();
        image::Rgba([255, 255, 255, if d <= 40.0 { 255 } else { 0 }])
    });
    let mut bytes = Vec::new();
    rgba.write_to(
        &mut std::io::Cursor::new(&mut bytes),
        image::ImageFormat::Png,
    )
    .unwrap();
    let r = rasterize(&[&bytes], &opts).unwrap();
    assert_eq!(r.figure.len(), 144);
    assert_eq!(r.figure.stats().holes, 0);
}

#[test]
fn tri4_discs_use_half_squares_on_their_diagonals() {
    let pic = disc_png(300, 120.0);
    let opts = RasterOptions {
        lattice: LatticeKind::Tri4,
        cells: Some(128),
        ..RasterOptions::default()
    };
    let r = rasterize(&[&pic], &opts).unwrap();
    let halves = r.text.chars().filter(|c| "369C".contains(*c)).count();
    let ragged = r.text.chars().filter(|c| "1248BDE7".contains(*c)).count();
    assert!(halves >= 4, "{}", r.text);
    assert_eq!(ragged, 0, "{}", r.text);
}

#[test]
fn rasterize_an_svg_outline_and_a_stack_of_slices() {
    let svg = br#"<svg xmlns="http://www.w3.org/2000/svg" width="100" height="60">
      <path d="M10 10 H90 V50 H10 Z" fill="black"/></svg>"#;
    let opts = RasterOptions {
        lattice: LatticeKind::Tri4,
        cells: Some(128),
        ..RasterOptions::default()
    };
    let r = rasterize(&[svg], &opts).unwrap();
    assert_eq!(r.figure.len(), 128);
    let slices = [disc_png(80, 30.0), disc_png(80, 30.0), disc_png(80, 20.0)];
    let refs: Vec<&[u8]> = slices.iter().map(|s| s.as_slice()).collect();
    let opts = RasterOptions {
        lattice: LatticeKind::Cubic,
        cells: Some(56),
        ..RasterOptions::default()
    };
    let r = rasterize(&refs, &opts).unwrap();
    assert_eq!(r.figure.len(), 56);
    assert_eq!(r.figure.stats().max[2], 2, "three layers");
}

#[test]
fn rasterize_bad_input_gets_clear_errors() {
    let opts = RasterOptions {
        cells: Some(10),
        ..RasterOptions::default()
    };
    let e = rasterize(&[b"hello"], &opts).unwrap_err();
    assert!(matches!(e, RenderError::NotAPicture(_)), "{e}");
    let blank = disc_png(50, 0.0);
    let e = rasterize(&[&blank], &opts).unwrap_err();
    assert_eq!(e, RenderError::EmptyPicture);
    let dot = disc_png(50, 4.0);
    let opts = RasterOptions {
        cells: Some(100_000),
        ..RasterOptions::default()
    };
    let e = rasterize(&[&dot], &opts).unwrap_err();
    assert!(
        matches!(e, RenderError::Unreachable { asked: 100_000, .. }),
        "{e}"
    );
    assert!(
        e.to_string().contains("cannot make exactly 100000 cells"),
        "{e}"
    );
}

/// A closed box mesh from `lo` to `hi`, triangles facing outward.
fn box_stl(lo: [f64; 3], hi: [f64; 3]) -> Vec<u8> {
    Mesh::new(dissect_testkit::box_triangles(lo, hi)).to_binary_stl("box")
}

#[test]
fn voxelize_hits_counts_that_no_threshold_gives() {
    // A cube's face cells are covered alike, so between 27 and 64 cells no
    // threshold gives the count: ties are broken by the neighbours' ink.
    let stl = box_stl([0.0, 0.0, 0.0], [3.0, 3.0, 3.0]);
    for n in [30, 40, 50] {
        let r = voxelize(
            &stl,
            &VoxelOptions {
                cells: Some(n),
                scale: None,
            },
        )
        .unwrap();
        assert_eq!(r.figure.len(), n);
        assert_eq!(r.text.matches('#').count(), n);
    }
}

#[test]
fn voxelize_a_cube_mesh_gives_the_cube() {
    let stl = box_stl([-1.5, 2.0, 0.0], [1.5, 5.0, 3.0]);
    let r = voxelize(
        &stl,
        &VoxelOptions {
            cells: Some(27),
            scale: None,
        },
    )
    .unwrap();
    assert_eq!(r.text, "###\n###\n###\n\n###\n###\n###\n\n###\n###\n###\n");
    assert_eq!(r.changed, 0);
    // A box 4 x 2 x 1 at one unit per cube.
    let stl = box_stl([0.0, 0.0, 0.0], [4.0, 2.0, 1.0]);
    let r = voxelize(
        &stl,
        &VoxelOptions {
            cells: None,
            scale: Some(1.0),
        },
    )
    .unwrap();
    assert_eq!(r.text, "####\n####\n");
    // What we write, we read back: the STL of a piece voxelizes to the piece.
    let s = scene(&CUBIC_STEP);
    let opts = PhysicalOptions {
        clearance_mm: 0.0,
        ..PhysicalOptions::default()
    };
    let m = stl::piece_mesh(&s, 0, &opts).unwrap();
    let r = voxelize(
        &m.to_binary_stl("a"),
        &VoxelOptions {
            cells: Some(3),
            scale: None,
        },
    )
    .unwrap();
    assert_eq!(r.text, "#\n#\n\n#\n.\n");
}

#[test]
fn voxelize_refuses_open_meshes_and_garbage() {
    let stl = box_stl([0.0; 3], [1.0; 3]);
    let mut m = Mesh::from_stl(&stl).unwrap().triangles().to_vec();
    m.pop();
    let e = voxelize(
        &Mesh::new(m).to_binary_stl("open"),
        &VoxelOptions::default(),
    )
    .unwrap_err();
    assert_eq!(e, RenderError::OpenMesh(3));
    assert!(e.to_string().contains("not closed"));
    let e = voxelize(b"not a mesh at all", &VoxelOptions::default()).unwrap_err();
    assert!(matches!(e, RenderError::BadMesh(_)), "{e}");
}

#[test]
fn scenes_refuse_solutions_that_do_not_fit_their_figures() {
    let e = Scene::from_solution(SQUARE.solution, &["###\n", "###\n"]).unwrap_err();
    assert!(e.to_string().contains("not a valid dissection"), "{e}");
    let e = Scene::from_solution(SQUARE.solution, &["#x\n", "##\n"]).unwrap_err();
    assert!(e.to_string().contains("figure 1: line 1, column 2"), "{e}");
    let e = Scene::from_solution("{", &[]).unwrap_err();
    assert!(matches!(e, RenderError::Solution(_)), "{e}");
}

/// FORMAT.md's cell centres, written here apart from the renderer: a tri3
/// triangle's centroid, a hex cell's centre (lattice units, y down).
fn format_centre(lattice: LatticeKind, [x, y, _]: Cell) -> [f64; 2] {
    let h = 3f64.sqrt() / 2.0;
    let (xf, yf) = (x as f64, y as f64);
    match lattice {
        LatticeKind::Tri3 if (x + y).rem_euclid(2) == 0 => [(xf + 1.0) / 2.0, (yf + 2.0 / 3.0) * h],
        LatticeKind::Tri3 => [(xf + 1.0) / 2.0, (yf + 1.0 / 3.0) * h],
        LatticeKind::Hex => [xf + y.rem_euclid(2) as f64 / 2.0, yf * h],
        _ => unreachable!("tri3 and hex only"),
    }
}

fn sorted_points(ps: impl Iterator<Item = [f64; 2]>) -> Vec<[i64; 2]> {
    let mut v: Vec<[i64; 2]> = ps
        .map(|p| [(p[0] * 1e6).round() as i64, (p[1] * 1e6).round() as i64])
        .collect();
    v.sort();
    v
}

#[test]
fn tri3_and_hex_motions_carry_every_cell_onto_its_place_in_the_other_figure() {
    for c in [&TRI3, &HEX] {
        let s = scene(c);
        let data = dissect_render::animation::data(&s).unwrap();
        assert_eq!(data["lattice"], c.lattice.name());
        for f in 0..2 {
            for i in 0..s.piece_count() {
                let p = &data["figures"][f]["pieces"][i];
                let m: Vec<Vec<f64>> = serde_json::from_value(p["matrix"].clone()).unwrap();
                let t: Vec<f64> = serde_json::from_value(p["shift"].clone()).unwrap();
                // Orthogonal: a turn or a flip, no stretch.
                for r in 0..2 {
                    for q in 0..2 {
                        let dot = m[r][0] * m[q][0] + m[r][1] * m[q][1];
                        assert!(
                            (dot - if r == q { 1.0 } else { 0.0 }).abs() < 1e-9,
                            "{}",
                            c.name
                        );
                    }
                }
                let moved = s.cells(0, i).iter().map(|cell| {
                    let x = format_centre(c.lattice, *cell);
                    [
                        m[0][0] * x[0] + m[0][1] * x[1] + t[0],
                        m[1][0] * x[0] + m[1][1] * x[1] + t[1],
                    ]
                });
                let want = s
                    .cells(f, i)
                    .iter()
                    .map(|cell| format_centre(c.lattice, *cell));
                assert_eq!(
                    sorted_points(moved),
                    sorted_points(want),
                    "{}: piece {i} into figure {f}",
                    c.name
                );
            }
        }
        // The shared page carries the data and fetches nothing.
        let page = dissect_render::html::page(&s).unwrap();
        assert!(
            page.contains(&format!("\"lattice\":\"{}\"", c.lattice.name())),
            "{}",
            c.name
        );
        for bad in ["src=\"http", "href=\"http", "src=\"/", "import("] {
            assert!(!page.contains(bad), "{}: {bad}", c.name);
        }
        // Step sheets: one panel per piece, each adding one piece's colour.
        for (f, (_, svg)) in dissect_render::steps::sheets(&s).iter().enumerate() {
            let panels: Vec<&str> = svg.split("<svg x=").skip(1).collect();
            assert_eq!(panels.len(), s.piece_count(), "{} figure {f}", c.name);
            for (k, p) in panels.iter().enumerate() {
                let shown = (0..s.piece_count())
                    .filter(|&i| p.contains(&s.colour(i).to_string()))
                    .count();
                assert_eq!(shown, k + 1, "{} figure {f} panel {k}", c.name);
            }
        }
    }
}
