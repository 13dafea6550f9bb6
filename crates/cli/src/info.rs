//! `dissect info`.

use std::fmt::Write;

use anyhow::Result;

use crate::args::InfoArgs;
use crate::{input, progress, Status};

pub fn run(args: InfoArgs) -> Result<Status> {
    let figures = input::figures(&args.figures, args.lattice)?;
    let three_d = args.lattice == dissect_core::LatticeKind::Cubic;
    let mut out = String::new();
    for (path, fig) in args.figures.iter().zip(&figures) {
        let s = fig.stats();
        let size = if three_d {
            format!(
                "{}x{}x{}",
                s.max[0] - s.min[0] + 1,
                s.max[1] - s.min[1] + 1,
                s.max[2] - s.min[2] + 1
            )
        } else {
            format!("{}x{}", s.max[0] - s.min[0] + 1, s.max[1] - s.min[1] + 1)
        };
        let plural = |n: usize, w: &str| format!("{n} {w}{}", if n == 1 { "" } else { "s" });
        _ = writeln!(
            out,
            "{}: {} ({}), {}, {}, bounding box {size} at ({}, {}{})",
            path.display(),
            plural(s.cells, "cell"),
            args.lattice,
            plural(s.components, "component"),
            plural(s.holes, if three_d { "cavity" } else { "hole" }).replace("cavitys", "cavities"),
            s.min[0],
            s.min[1],
            if three_d {
                format!(", {}", s.min[2])
            } else {
                String::new()
            },
        );
    }
    if figures.len() > 1 {
        let areas: Vec<usize> = figures.iter().map(|f| f.len()).collect();
        if areas.iter().all(|a| *a == areas[0]) {
            _ = writeln!(out, "areas are equal: {} cells each", areas[0]);
        } else {
            let lo = *areas.iter().min().expect("non-empty");
            let hi = *areas.iter().max().expect("non-empty");
            _ = writeln!(
 out,"AREAS DIFFER: the figures cannot be dissected into each other until they have the same cell count");
            for (path, a) in args.figures.iter().zip(&areas) {
                _ = writeln!(
                    out,
                    "  {}: {a} cells ({:+} against the smallest)",
                    path.display(),
                    *a as i64 - lo as i64
                );
            }
            _ = writeln!(
                out,
                "  largest difference: {} cell{}",
                hi - lo,
                if hi - lo == 1 { "" } else { "s" }
            );
        }
    }
    progress::stdout(&out);
    Ok(Status::Ok)
}
