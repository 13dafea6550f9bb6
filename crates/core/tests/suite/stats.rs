//! Figure statistics (what `dissect info` prints): cells, connected
//! components, holes (cavities in 3D) and the bounding box of blocks.

use dissect_core::figure::{components_of, FigureError, FigureStats};
use dissect_core::{Figure, LatticeKind};

use super::util::{fig, Cubic, Square, Tri4};

fn check(
    lattice: LatticeKind,
    compact: &str,
    cells: usize,
    components: usize,
    holes: usize,
    min: [i32; 3],
    max: [i32; 3],
) {
    let f = fig(lattice, compact);
    let want = FigureStats {
        cells,
        components,
        holes,
        min,
        max,
    };
    assert_eq!(f.stats(), want, "stats of {compact:?} on {lattice}");
    assert_eq!(f.len(), cells);
    assert_eq!(f.components().len(), components);
}

#[test]
fn square_stats() {
    check(Square, "#", 1, 1, 0, [0, 0, 0], [0, 0, 0]);
    check(Square, "###|#.#|###", 8, 1, 1, [0, 0, 0], [2, 2, 0]);
    check(Square, "#.#", 2, 2, 0, [0, 0, 0], [2, 0, 0]);
    // Diagonal contact joins neither cells nor holes.
    check(Square, "#.|.#", 2, 2, 0, [0, 0, 0], [1, 1, 0]);
    check(Square, ".#.|#.#|.#.", 4, 4, 1, [0, 0, 0], [2, 2, 0]);
    check(Square, "#####|#.#.#|#####", 13, 1, 2, [0, 0, 0], [4, 2, 0]);
    check(Square, "####|#..#|####", 10, 1, 1, [0, 0, 0], [3, 2, 0]);
    // A notch open to the outside is not a hole.
    check(Square, "###|#.#|#.#", 7, 1, 0, [0, 0, 0], [2, 2, 0]);
    check(Square, "..|.##|.#", 3, 1, 0, [1, 1, 0], [2, 2, 0]);
    // An island in a ring: two components, one hole around the island.
    check(
        Square,
        "#####|#...#|#.#.#|#...#|#####",
        17,
        2,
        1,
        [0, 0, 0],
        [4, 4, 0],
    );
    // A ring inside a ring: two components, two holes.
    check(
        Square,
        "#######|#.....#|#.###.#|#.#.#.#|#.###.#|#.....#|#######",
        32,
        2,
        2,
        [0, 0, 0],
        [6, 6, 0],
    );
}

#[test]
fn tri4_stats() {
    check(Tri4, "#", 4, 1, 0, [0, 0, 0], [0, 0, 0]);
    check(Tri4, "6#9", 8, 1, 0, [0, 0, 0], [2, 0, 0]);
    // Top and bottom triangles of one square do not touch.
    check(Tri4, "5", 2, 2, 0, [0, 0, 0], [0, 0, 0]);
    check(Tri4, "3", 2, 1, 0, [0, 0, 0], [0, 0, 0]);
    // A missing top triangle in the middle of a 3x3 block is a hole.
    check(Tri4, "###|#E#|###", 35, 1, 1, [0, 0, 0], [2, 2, 0]);
    check(Tri4, "###|#.#|###", 32, 1, 1, [0, 0, 0], [2, 2, 0]);
    // A diamond of four half squares ...
    check(Tri4, "6C|39", 8, 1, 0, [0, 0, 0], [1, 1, 0]);
    // ... and its complement in the 2x2 block: four corners that touch only
    // at vertices, around a diamond-shaped hole.
    check(Tri4, "93|C6", 8, 4, 1, [0, 0, 0], [1, 1, 0]);
    check(Tri4, ".1|.4", 2, 2, 0, [1, 0, 0], [1, 1, 0]);
}

#[test]
fn cubic_stats() {
    check(Cubic, "#", 1, 1, 0, [0, 0, 0], [0, 0, 0]);
    check(
        Cubic,
        "###|###|###/###|#.#|###/###|###|###",
        26,
        1,
        1,
        [0, 0, 0],
        [2, 2, 2],
    );
    // A ring is no cavity in 3D: its middle is open above and below.
    check(Cubic, "###|#.#|###", 8, 1, 0, [0, 0, 0], [2, 2, 0]);
    check(Cubic, "#/./#", 2, 2, 0, [0, 0, 0], [0, 0, 2]);
    check(Cubic, "#./.#", 2, 2, 0, [0, 0, 0], [1, 0, 1]);
    check(Cubic, "##/##", 4, 1, 0, [0, 0, 0], [1, 0, 1]);
    check(Cubic, "./.#.|#.#", 3, 3, 0, [0, 0, 1], [2, 1, 1]);
}

#[test]
fn figures_are_sorted_sets() {
    let f = Figure::new(Square, [[1, 0, 0], [0, 0, 0], [1, 0, 0]]).unwrap();
    assert_eq!(f.cells(), &[[0, 0, 0], [1, 0, 0]]);
    assert!(f.contains([1, 0, 0]));
    assert!(!f.contains([2, 0, 0]));
    assert!(!f.is_empty());
    assert_eq!(Figure::new(Cubic, []), Err(FigureError::Empty));
    assert_eq!(
        Figure::new(Tri4, [[0, 0, 4]]),
        Err(FigureError::BadCell {
            cell: [0, 0, 4],
            lattice: Tri4
        })
    );
    assert_eq!(
        Figure::new(Square, [[0, 0, 0], [0, 0, 1]]),
        Err(FigureError::BadCell {
            cell: [0, 0, 1],
            lattice: Square
        })
    );
    let comps = components_of(
        LatticeKind::Square,
        &[[0, 0, 0], [2, 0, 0], [1, 0, 0], [5, 5, 0]],
    );
    assert_eq!(
        comps,
        vec![vec![[0, 0, 0], [1, 0, 0], [2, 0, 0]], vec![[5, 5, 0]]]
    );
}

#[test]
fn debug_prints_the_figure() {
    let f = fig(Square, "##|#.");
    assert_eq!(format!("{f:?}"), "Figure(square, 3 cells)\n##\n#\n");
}

/// `components_of` finds neighbours by a galloping search in a sorted list
/// and by a hash table otherwise: both give the same components, on random
/// cells of every lattice.
#[test]
fn components_are_the_same_sorted_or_not() {
    use rand::{RngExt, SeedableRng};

    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(17);
    for lattice in LatticeKind::ALL {
        for _ in 0..20 {
            let hi = [rng.random_range(0..12), rng.random_range(0..12), 2];
            let cells: Vec<_> = lattice
                .lattice()
                .cells_in_box([0, 0, 0], hi)
                .into_iter()
                .filter(|_| rng.random_bool(0.55))
                .collect();
            let Ok(f) = Figure::new(lattice, cells) else {
                continue;
            };
            let mut sorted = components_of(lattice, f.cells());
            let reversed: Vec<_> = f.cells().iter().rev().copied().collect();
            let mut unsorted = components_of(lattice, &reversed);
            sorted.sort();
            unsorted.sort();
            assert_eq!(sorted, unsorted, "{lattice}");
            assert_eq!(sorted.iter().map(Vec::len).sum::<usize>(), f.len());
        }
    }
}
