//! A fuzz loop on stable Rust (cargo-fuzz needs nightly): every parser of
//! `dissect` gets mutated inputs grown from small valid seeds, and every
//! call must return (an answer or an error) without panicking. Aborts and
//! stack overflows cannot be caught: they end the process, which the
//! caller (CI, the long run) reports as a failure.
//!
//! Targets: `figure` (figure text on every lattice, then the figure's
//! statistics), `solution` (solution JSON, then the independent verifier and
//! the drawing of a checked scene), `puzzle` (the puzzle fields and the
//! inputs of `solve`'s constraints, `assemblies`, `disassemble` and
//! `enumerate`: see the module), `picture` (PNG, JPEG and SVG
//! rasterized to a few cells), `mesh` (STL voxelized), `http` (requests to
//! the studio's router: method, path, headers and body).
//!
//! Everything is reproducible from the seed: the generator is SplitMix64.

mod puzzle;

use std::panic::{catch_unwind, AssertUnwindSafe};
use std::time::{Duration, Instant};

/// The targets, in the order a run visits them.
pub const TARGETS: &[&str] = &["figure", "solution", "puzzle", "picture", "mesh", "http"];

/// SplitMix64: small, fast and reproducible.
#[derive(Clone, Debug)]
pub struct Rng(u64);

impl Rng {
    /// A generator started from `seed`.
    pub fn new(seed: u64) -> Rng {
        Rng(seed ^ 0x9E37_79B9_7F4A_7C15)
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A number in `0..n` (`n > 0`).
    pub fn below(&mut self, n: usize) -> usize {
        (self.next_u64() % n.max(1) as u64) as usize
    }

    /// One of `items` (not empty).
    pub fn pick<'a, T>(&mut self, items: &'a [T]) -> &'a T {
        &items[self.below(items.len())]
    }
}

/// Tokens worth inserting: format keywords and numbers at the edges.
const DICTIONARY: &[&str] = &[
    "#",
    ".",
    "\n",
    "\r\n",
    "\n\n",
    "F",
    "0",
    "9",
    "{",
    "}",
    "[",
    "]",
    ",",
    ":",
    "\"",
    "-1",
    "0",
    "1e9",
    "1e308",
    "-1e308",
    "4294967295",
    "18446744073709551616",
    "2147483648",
    "NaN",
    "null",
    "true",
    "\"format\"",
    "\"dissection-solution/1\"",
    "\"lattice\"",
    "\"square\"",
    "\"tri4\"",
    "\"cubic\"",
    "\"hex\"",
    "\"figures\"",
    "\"pieces\"",
    "\"mirror\"",
    "\n--\n",
    "rank=",
    "rank=level",
    "pieces=",
    "min=",
    "max=",
    "keep=",
    "solutions=",
    "checkerboard=1",
    "sym=",
    "aa",
    "\"constraints\"",
    "\"keep\"",
    "\"min_piece\"",
    "\"max_piece\"",
    "\"solutions\"",
    "\"rank\"",
    "\"ranking\"",
    "\"regions\"",
    "\"text\"",
    "\"level\"",
    "\"checkerboard\"",
    "\"symmetry_weight\"",
    "<g>",
    "</g>",
    "<svg",
    "width=\"1e9\"",
    "height=\"0\"",
    "<!DOCTYPE svg [<!ENTITY a \"aaaa\">]>",
    "&a;",
    "<use href=\"#a\"/>",
    "id=\"a\"",
    "viewBox=\"0 0 1e-9 1e-9\"",
    "transform=\"scale(1e9)\"",
    "solid",
    "facet normal 0 0 1",
    "outer loop",
    "vertex 0 0 0",
    "vertex 1e30 0 0",
    "endloop",
    "endfacet",
    "endsolid",
    "\u{feff}",
    "\u{0}",
    "\u{ffff}",
    "ÿ",
];

/// Applies 1 to 8 random mutations to `data`, keeping it under `max` bytes.
pub fn mutate(rng: &mut Rng, data: &mut Vec<u8>, others: &[Vec<u8>], max: usize) {
    let n = 1 + rng.below(8);
    for _ in 0..n {
        let len = data.len();
        match rng.below(9) {
            0 if len > 0 => {
                let i = rng.below(len);
                data[i] ^= 1 << rng.below(8);
            }
            1 if len > 0 => {
                let i = rng.below(len);
                data[i] = rng.next_u64() as u8;
            }
            2 => {
                let i = rng.below(len + 1);
                data.insert(i, rng.next_u64() as u8);
            }
            3 if len > 0 => {
                let i = rng.below(len);
                let k = 1 + rng.below((len - i).min(64));
                data.drain(i..i + k);
            }
            4 if len > 0 => {
                // Repeat a range (nesting, long rows).
                let i = rng.below(len);
                let k = 1 + rng.below((len - i).min(32));
                let piece = data[i..i + k].to_vec();
                let most = if rng.below(8) == 0 { 2000 } else { 4 };
                let times = 1 + rng.below(most);
                let at = rng.below(len + 1);
                for _ in 0..times {
                    if data.len() + piece.len() > max {
                        break;
                    }
                    data.splice(at..at, piece.iter().copied());
                }
            }
            5 | 6 => {
                let t = rng.pick(DICTIONARY).as_bytes();
                let i = rng.below(len + 1);
                data.splice(i..i, t.iter().copied());
            }
            7 if !others.is_empty() => {
                // Splice: our head, another seed's tail.
                let o = rng.pick(others);
                let i = rng.below(len + 1);
                let j = rng.below(o.len() + 1);
                data.truncate(i);
                data.extend_from_slice(&o[j..]);
            }
            _ if len > 0 => {
                // Replace a run of digits with an edge number.
                let i = rng.below(len);
                if let Some(start) = (i..len).find(|&k| data[k].is_ascii_digit()) {
                    let end = (start..len)
                        .find(|&k| !data[k].is_ascii_digit())
                        .unwrap_or(len);
                    let t = rng.pick(&["0", "-1", "99999999", "1e9", "4294967296", "65535"]);
                    data.splice(start..end, t.bytes());
                }
            }
            _ => {}
        }
    }
    data.truncate(max);
}

/// What a run did on one target.
#[derive(Clone, Debug, Default)]
pub struct Tally {
    /// The target's name.
    pub target: String,
    /// Inputs fed.
    pub inputs: u64,
    /// Calls that returned an answer (the rest returned an error).
    pub accepted: u64,
    /// Inputs that panicked, with the panic message.
    pub failures: Vec<(Vec<u8>, String)>,
    /// How long it took.
    pub elapsed: Duration,
}

/// Feeds one input to a parser: `true` when it was accepted.
type Runner = Box<dyn FnMut(&[u8]) -> bool>;

/// One target: its seeds and how to feed it one input (`Ok(true)` when the
/// input was accepted, `Ok(false)` for a clean error).
pub struct Target {
    /// Its name (one of [`TARGETS`]).
    pub name: &'static str,
    /// Small valid inputs the mutations start from.
    pub seeds: Vec<Vec<u8>>,
    /// The longest input fed.
    pub max_len: usize,
    run: Runner,
}

impl Target {
    /// The target called `name`.
    pub fn new(name: &str) -> Option<Target> {
        Some(match name {
            "figure" => targets::figure(),
            "solution" => targets::solution(),
            "puzzle" => puzzle::target(),
            "picture" => targets::picture(),
            "mesh" => targets::mesh(),
            "http" => targets::http(),
            _ => return None,
        })
    }

    /// Feeds `inputs` mutated inputs (or until `deadline`), seeds first.
    pub fn fuzz(&mut self, seed: u64, inputs: u64, deadline: Option<Instant>) -> Tally {
        let start = Instant::now();
        let mut rng = Rng::new(seed);
        let mut tally = Tally {
            target: self.name.to_string(),
            ..Tally::default()
        };
        let mut pool: Vec<Vec<u8>> = self.seeds.clone();
        for k in 0..inputs {
            if deadline.is_some_and(|d| Instant::now() >= d) {
                break;
            }
            let input = if (k as usize) < self.seeds.len() {
                self.seeds[k as usize].clone()
            } else {
                let mut d = rng.pick(&pool).clone();
                mutate(&mut rng, &mut d, &self.seeds, self.max_len);
                d
            };
            let run = &mut self.run;
            match catch_unwind(AssertUnwindSafe(|| run(&input))) {
                Ok(accepted) => {
                    if accepted {
                        tally.accepted += 1;
                        // Accepted inputs breed: they reach deeper code.
                        if pool.len() < 256 {
                            pool.push(input);
                        } else {
                            let i = rng.below(pool.len());
                            pool[i] = input;
                        }
                    }
                }
                Err(p) => {
                    let msg = p
                        .downcast_ref::<String>()
                        .cloned()
                        .or_else(|| p.downcast_ref::<&str>().map(|s| s.to_string()))
                        .unwrap_or_else(|| "panic".into());
                    tally.failures.push((input, msg));
                }
            }
            tally.inputs += 1;
        }
        tally.elapsed = start.elapsed();
        tally
    }
}

mod targets {
    use super::Target;
    use dissect_core::io::{parse_figure, parse_solution};
    use dissect_core::LatticeKind;

    /// Every lattice this build knows (names it cannot parse are skipped).
    fn lattices() -> Vec<LatticeKind> {
        ["square", "tri4", "cubic", "tri3", "hex"]
            .iter()
            .filter_map(|n| n.parse().ok())
            .collect()
    }

    pub fn figure() -> Target {
        let lattices = lattices();
        let seeds = [
            "###\n#.#\n",
            "##\n##\n\n#.\n##\n",
            "F3\n9C\n",
            "..\n.#\r\n",
            "#\n",
            "",
        ];
        Target {
            name: "figure",
            seeds: seeds.iter().map(|s| s.as_bytes().to_vec()).collect(),
            max_len: 1 << 16,
            run: Box::new(move |input| {
                let Ok(text) = std::str::from_utf8(input) else {
                    return false;
                };
                let mut any = false;
                for &l in &lattices {
                    if let Ok(f) = parse_figure(text, l) {
                        let _ = f.stats();
                        let _ = dissect_core::io::format_figure(&f);
                        any = true;
                    }
                }
                any
            }),
        }
    }

    pub fn solution() -> Target {
        let seeds = [
            r#"{"format": "dissection-solution/1", "lattice": "square", "mirror": true, "figures": [{"name": "a", "pieces": [[[0,0],[1,0]], [[0,1],[1,1]]]}, {"name": "b", "pieces": [[[0,0],[1,0]], [[2,0],[3,0]]]}]}"#,
            r#"{"format": "dissection-solution/1", "lattice": "tri4", "figures": [{"pieces": [[[0,0,0],[0,0,1]], [[0,0,2],[0,0,3]]]}, {"pieces": [[[0,0,0],[0,0,1]], [[1,0,2],[1,0,3]]]}]}"#,
            r#"{"format": "dissection-solution/1", "lattice": "cubic", "figures": [{"pieces": [[[0,0,0],[1,0,0]]]}, {"pieces": [[[0,0,0],[0,0,1]]]}], "score": 3}"#,
            r#"{"lattice": "square", "figures": []}"#,
        ];
        Target {
            name: "solution",
            seeds: seeds.iter().map(|s| s.as_bytes().to_vec()).collect(),
            max_len: 1 << 15,
            run: Box::new(|input| {
                let Ok(text) = std::str::from_utf8(input) else {
                    return false;
                };
                let Ok((_, d)) = parse_solution(text) else {
                    return false;
                };
                // Drawn only when small: the drawing's size follows the coordinates.
                let small = d
                    .pieces()
                    .iter()
                    .flatten()
                    .flatten()
                    .all(|c| c.iter().all(|v| v.abs() < 64))
                    && d.pieces()
                        .iter()
                        .map(|f| f.iter().map(Vec::len).sum::<usize>())
                        .sum::<usize>()
                        < 2000;
                if !small {
                    return true;
                }
                if let Ok(scene) = dissect_render::Scene::verified(&d) {
                    let _ = dissect_render::svg::render(&scene);
                    let _ = dissect_render::stl::render(&scene, &Default::default());
                }
                true
            }),
        }
    }

    fn png(w: u32, h: u32) -> Vec<u8> {
        let img = image::RgbaImage::from_fn(w, h, |x, y| {
            if (x + y) % 3 == 0 {
                image::Rgba([0, 0, 0, 255])
            } else {
                image::Rgba([255, 255, 255, 0])
            }
        });
        let mut out = std::io::Cursor::new(Vec::new());
        img.write_to(&mut out, image::ImageFormat::Png)
            .expect("encode");
        out.into_inner()
    }

    fn jpeg(w: u32, h: u32) -> Vec<u8> {
        let img = image::RgbImage::from_fn(w, h, |x, _| {
            if x < w / 2 {
                image::Rgb([0, 0, 0])
            } else {
                image::Rgb([255, 255, 255])
            }
        });
        let mut out = std::io::Cursor::new(Vec::new());
        img.write_to(&mut out, image::ImageFormat::Jpeg)
            .expect("encode");
        out.into_inner()
    }

    pub fn picture() -> Target {
        let seeds = vec![
            png(12, 9),
            jpeg(16, 8),
            br#"<svg xmlns="http://www.w3.org/2000/svg" width="20" height="10"><rect width="10" height="10"/><circle cx="15" cy="5" r="4"/></svg>"#.to_vec(),
            br#"<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 4 4"><g transform="rotate(45 2 2)"><path d="M1 1h2v2z"/></g></svg>"#.to_vec(),
        ];
        let lattices = lattices();
        let mut k = 0usize;
        Target {
            name: "picture",
            seeds,
            max_len: 1 << 14,
            run: Box::new(move |input| {
                k += 1;
                let lattice = lattices[k % lattices.len()];
                let opts = dissect_render::rasterize::RasterOptions {
                    lattice,
                    cells: if k.is_multiple_of(3) {
                        None
                    } else {
                        Some(1 + k % 12)
                    },
                    scale: [10.0, 1.0, 0.5, 1e-9][k % 4],
                    ..Default::default()
                };
                dissect_render::rasterize::rasterize(&[input], &opts).is_ok()
            }),
        }
    }

    pub fn mesh() -> Target {
        let tris = dissect_testkit::box_triangles([0.0; 3], [1.0; 3]);
        let ascii = dissect_testkit::ascii_stl("c", &tris);
        let binary = dissect_testkit::binary_stl(&tris);
        let mut k = 0usize;
        Target {
            name: "mesh",
            seeds: vec![ascii.into_bytes(), binary],
            max_len: 1 << 14,
            run: Box::new(move |input| {
                k += 1;
                let opts = dissect_render::voxelize::VoxelOptions {
                    cells: if k.is_multiple_of(2) {
                        Some(1 + k % 9)
                    } else {
                        None
                    },
                    scale: if k % 4 == 1 {
                        Some([0.5, 1e-6, 3.0][k % 3])
                    } else {
                        None
                    },
                };
                dissect_render::voxelize::voxelize(input, &opts).is_ok()
            }),
        }
    }

    pub fn http() -> Target {
        use axum::body::Body;
        use axum::http::Request;
        use http_body_util::BodyExt;
        use tower::ServiceExt;

        // Solves stop within a tenth of a second and use one thread.
        let limits = dissect_web::Limits::new(64, 32, 4, 1, 0.1, 1);
        let app = dissect_web::router(limits);
        let runtime = tokio::runtime::Builder::new_current_thread()
            .enable_all()
            .build()
            .expect("runtime");
        let seeds = [
            "POST /api/figures application/json\n{\"lattice\": \"square\", \"figures\": [{\"text\": \"##\\n#.\"}, {\"cells\": [[0,0],[1,0]]}]}",
            "POST /api/solve application/json\n{\"lattice\": \"square\", \"time_limit\": 0.05, \"figures\": [{\"text\": \"##\"}, {\"text\": \"#\\n#\"}]}",
            "POST /api/export/svg application/json\n{\"solution\": {\"format\": \"dissection-solution/1\", \"lattice\": \"square\", \"figures\": [{\"pieces\": [[[0,0]],[[1,0]]]}, {\"pieces\": [[[0,0]],[[0,1]]]}]}}",
            "POST /api/export/stl application/json\n{\"solution\": {\"format\": \"dissection-solution/1\", \"lattice\": \"square\", \"figures\": [{\"pieces\": [[[0,0]],[[1,0]]]}, {\"pieces\": [[[0,0]],[[0,1]]]}]}, \"thickness_mm\": 2}",
            "POST /api/rasterize?lattice=square&cells=4 image/svg+xml\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"4\" height=\"4\"><rect width=\"2\" height=\"2\"/></svg>",
            "POST /api/solve application/json\n{\"lattice\": \"square\", \"time_limit\": 0.05, \"figures\": [{\"text\": \"##\\n##\"}, {\"text\": \"####\"}], \"solutions\": 2, \"rank\": \"level\", \"keep\": [{\"figure\": 1, \"regions\": {\"a\": [[0,0],[1,0]]}}], \"min_piece\": 1, \"max_piece\": 3, \"checkerboard\": true, \"symmetry_weight\": 0.5}",
            "POST /api/solve application/json\n{\"lattice\": \"square\", \"time_limit\": 0.05, \"figures\": [{\"text\": \"##\\n##\"}, {\"text\": \"####\"}], \"solutions\": 3, \"rank\": \"unique\", \"keep\": [{\"figure\": 2, \"text\": \"aa..\"}]}",
            "GET /api/solve/1 \n",
            "GET /api/info \n",
            "POST /api/solve/1/stop \n",
        ];
        Target {
            name: "http",
            seeds: seeds.iter().map(|s| s.as_bytes().to_vec()).collect(),
            max_len: 1 << 14,
            run: Box::new(move |input| {
                // "METHOD PATH CONTENT-TYPE\nBODY"
                let (head, body) = match input.iter().position(|b| *b == b'\n') {
                    Some(i) => (&input[..i], &input[i + 1..]),
                    None => (input, &[][..]),
                };
                let head = String::from_utf8_lossy(head);
                let mut parts = head.splitn(3, ' ');
                let method = parts.next().unwrap_or("GET");
                let path = parts.next().unwrap_or("/");
                let ty = parts.next().unwrap_or("");
                let mut req = Request::builder().method(method).uri(path);
                if !ty.is_empty() {
                    req = req.header("content-type", ty);
                }
                let Ok(req) = req.body(Body::from(body.to_vec())) else {
                    return false;
                };
                let app = app.clone();
                runtime.block_on(async move {
                    let res = app.oneshot(req).await.expect("the router answers");
                    let status = res.status();
                    let bytes = res.into_body().collect().await.expect("a body").to_bytes();
                    assert!(
                        status.as_u16() != 500,
                        "HTTP 500: {}",
                        String::from_utf8_lossy(&bytes)
                    );
                    status.is_success()
                })
            }),
        }
    }
}
