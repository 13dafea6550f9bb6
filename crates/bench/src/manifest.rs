//! The instance manifest (`instances/manifest.json`): which figure sets
//! exist, on which lattice, and the piece counts known for them.

use std::path::{Path, PathBuf};

use dissect_core::io::parse_figure;
use dissect_core::{Figure, LatticeKind};
use serde::Deserialize;

use crate::BenchError;

/// One figure set of the manifest.
///
/// # Validity
/// `files` is non-empty and `lattice` is a known lattice: [`Manifest::parse`]
/// rejects entries that are not.
#[derive(Clone, Debug, PartialEq, Eq, Deserialize)]
pub struct Instance {
    /// The instance's directory name under the manifest's directory.
    pub name: String,
    /// The lattice name as written in the manifest.
    lattice: String,
    /// The best known piece count for this layout (`null`: none known).
    #[serde(default)]
    pub reference: Option<usize>,
    /// The piece count the paper reports when it differs from `reference`
    /// (e.g. for a layout the paper does not describe).
    #[serde(default)]
    pub paper_pieces: Option<usize>,
    /// A proven lower bound on the piece count.
    #[serde(default)]
    pub lower_bound: Option<usize>,
    /// Where the figures come from.
    #[serde(default)]
    pub source: String,
    /// The figure files, in the order they are given to the solver.
    pub files: Vec<String>,
    /// The figures' common cell count.
    #[serde(default)]
    pub area: Option<usize>,
}

impl Instance {
    /// The lattice of the instance (checked by [`Manifest::parse`]).
    pub fn lattice(&self) -> LatticeKind {
        self.lattice
            .parse()
            .expect("Manifest::parse checked the lattice name")
    }

    /// Reads and parses the instance's figures from `root/name/file`.
    pub fn load_figures(&self, root: &Path) -> Result<Vec<Figure>, BenchError> {
        let dir = root.join(&self.name);
        let figures = self
            .files
            .iter()
            .map(|f| {
                let path = dir.join(f);
                let text = read(&path)?;
                parse_figure(&text, self.lattice())
                    .map_err(|source| BenchError::Figure { path, source })
            })
            .collect::<Result<Vec<Figure>, BenchError>>()?;
        if let Some(area) = self.area {
            if let Some((file, fig)) = self
                .files
                .iter()
                .zip(&figures)
                .find(|(_, f)| f.len() != area)
            {
                return Err(BenchError::Area {
                    path: dir.join(file),
                    cells: fig.len(),
                    expected: area,
                });
            }
        }
        Ok(figures)
    }
}

/// A parsed manifest.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Manifest {
    path: PathBuf,
    instances: Vec<Instance>,
}

impl Manifest {
    /// Reads `dir/manifest.json`.
    pub fn load(dir: &Path) -> Result<Manifest, BenchError> {
        let path = dir.join("manifest.json");
        let text = read(&path)?;
        Manifest::parse(&text, &path)
    }

    /// Parses a manifest's text; `path` names it in errors.
    pub fn parse(text: &str, path: &Path) -> Result<Manifest, BenchError> {
        let instances: Vec<Instance> =
            serde_json::from_str(text).map_err(|e| BenchError::ManifestJson {
                path: path.to_path_buf(),
                line: e.line(),
                column: e.column(),
                message: e.to_string(),
            })?;
        for inst in &instances {
            let bad = |what: String| BenchError::ManifestEntry {
                path: path.to_path_buf(),
                name: inst.name.clone(),
                what,
            };
            if inst.lattice.parse::<LatticeKind>().is_err() {
                return Err(bad(format!(
                    "unknown lattice {:?} (expected square, tri4, cubic, tri3 or hex)",
                    inst.lattice
                )));
            }
            if inst.files.is_empty() {
                return Err(bad("lists no figure files".to_string()));
            }
        }
        Ok(Manifest {
            path: path.to_path_buf(),
            instances,
        })
    }

    /// The manifest file.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The directory that holds the instance directories.
    pub fn root(&self) -> &Path {
        self.path.parent().unwrap_or(Path::new("."))
    }

    /// Every instance, in manifest order.
    pub fn instances(&self) -> &[Instance] {
        &self.instances
    }

    /// The instance called `name`.
    pub fn get(&self, name: &str) -> Result<&Instance, BenchError> {
        self.instances
            .iter()
            .find(|i| i.name == name)
            .ok_or_else(|| BenchError::UnknownInstance {
                path: self.path.clone(),
                name: name.to_string(),
                known: self.instances.iter().map(|i| i.name.clone()).collect(),
            })
    }
}

fn read(path: &Path) -> Result<String, BenchError> {
    std::fs::read_to_string(path).map_err(|source| BenchError::Read {
        path: path.to_path_buf(),
        source,
    })
}
