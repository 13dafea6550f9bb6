//! The two texts: DIMACS CNF (`p cnf VARS CLAUSES`, clauses ended by `0`,
//! `c` comment lines) and text DRAT (one lemma or `d` deletion per clause,
//! each ended by `0`).

use crate::{ProofError, Source};

/// A formula in conjunctive normal form.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Cnf {
    vars: usize,
    clauses: Vec<Vec<i32>>,
}

/// One step of a DRAT proof.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Step {
    /// Add a lemma (RUP, or RAT on its first literal).
    Add(Vec<i32>),
    /// Delete a clause.
    Delete(Vec<i32>),
}

/// A DRAT proof: its steps, each with the line it starts on.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Proof {
    steps: Vec<(usize, Step)>,
    last_line: usize,
}

/// One literal of a clause (a nonzero or zero `i32`), or an error naming
/// `line` of `source`.
pub(crate) fn literal(token: &str, line: usize, source: Source) -> Result<i32, ProofError> {
    token.parse().map_err(|_| ProofError::Parse {
        text: source,
        line,
        message: format!(
            "`{}` is not a literal",
            token.chars().take(20).collect::<String>()
        ),
    })
}

/// Splits clause text into clauses a line at a time: the whole-text
/// parsers and [`ProofStream`] share it.
struct Splitter {
    source: Source,
    deletions: bool,
    /// The clause being read: its first line, whether it is a deletion,
    /// its literals so far.
    open: Option<(usize, bool, Vec<i32>)>,
    /// Lines fed so far.
    line: usize,
}

impl Splitter {
    fn new(source: Source, deletions: bool) -> Splitter {
        Splitter {
            source,
            deletions,
            open: None,
            line: 0,
        }
    }

    /// Feeds the next line (`c` comments and the lines `skip` accepts are
    /// skipped); every clause it ends goes to `out` as `(line, is_deletion,
    /// literals)`.
    fn feed(
        &mut self,
        raw: &str,
        skip: &mut dyn FnMut(usize, &str) -> Result<bool, ProofError>,
        out: &mut dyn FnMut(usize, bool, Vec<i32>) -> Result<(), ProofError>,
    ) -> Result<(), ProofError> {
        self.line += 1;
        let line = self.line;
        let trimmed = raw.trim();
        if trimmed.is_empty() || trimmed.starts_with('c') || skip(line, trimmed)? {
            return Ok(());
        }
        for token in trimmed.split_whitespace() {
            if token == "d" && self.deletions {
                match &self.open {
                    Some((_, _, lits)) if !lits.is_empty() => {
                        return Err(ProofError::Parse {
                            text: self.source,
                            line,
                            message: "`d` inside a clause".into(),
                        })
                    }
                    _ => self.open = Some((line, true, Vec::new())),
                }
                continue;
            }
            let lit = literal(token, line, self.source)?;
            let entry = self.open.get_or_insert_with(|| (line, false, Vec::new()));
            if lit == 0 {
                let (at, del, lits) = self.open.take().expect("open");
                out(at, del, lits)?;
            } else {
                entry.2.push(lit);
            }
        }
        Ok(())
    }

    /// The end of the text: an error when a clause is left open; else the
    /// number of the last line (at least 1).
    fn end(self) -> Result<usize, ProofError> {
        if let Some((line, _, _)) = self.open {
            return Err(ProofError::Parse {
                text: self.source,
                line,
                message: "clause not ended by 0".into(),
            });
        }
        Ok(self.line.max(1))
    }
}

/// Splits `text` into clauses: `(line, is_deletion, literals)` for every
/// clause ended by `0`, skipping `c` comment lines and the lines `skip`
/// accepts.
fn clauses(
    text: &str,
    source: Source,
    deletions: bool,
    skip: &mut dyn FnMut(usize, &str) -> Result<bool, ProofError>,
) -> Result<Vec<(usize, bool, Vec<i32>)>, ProofError> {
    let mut out = Vec::new();
    let mut splitter = Splitter::new(source, deletions);
    for raw in text.lines() {
        splitter.feed(raw, skip, &mut |line, del, lits| {
            out.push((line, del, lits));
            Ok(())
        })?;
    }
    splitter.end()?;
    Ok(out)
}

/// A text DRAT proof read a line at a time, for proofs too large to hold
/// (the caller reads the lines; each finished step goes to a callback,
/// e.g. [`Checker::step`](crate::Checker::step)). It accepts what
/// [`Proof::parse`] accepts, with the same errors.
pub struct ProofStream {
    splitter: Splitter,
}

impl Default for ProofStream {
    fn default() -> ProofStream {
        ProofStream::new()
    }
}

impl ProofStream {
    /// A stream at the proof's first line.
    pub fn new() -> ProofStream {
        ProofStream {
            splitter: Splitter::new(Source::Proof, true),
        }
    }

    /// Reads the next line (without its line break); every step it ends
    /// goes to `each` with the line it starts on.
    pub fn line(
        &mut self,
        text: &str,
        each: &mut dyn FnMut(usize, Step) -> Result<(), ProofError>,
    ) -> Result<(), ProofError> {
        self.splitter
            .feed(text, &mut |_, _| Ok(false), &mut |line, del, lits| {
                each(
                    line,
                    if del {
                        Step::Delete(lits)
                    } else {
                        Step::Add(lits)
                    },
                )
            })
    }

    /// The end of the proof: the number of its last line, or an error when
    /// a step is left open.
    pub fn end(self) -> Result<usize, ProofError> {
        self.splitter.end()
    }
}

impl Cnf {
    /// Parses DIMACS CNF; the header must come first and its counts must
    /// match the clauses.
    pub fn parse(text: &str) -> Result<Cnf, ProofError> {
        let err = |line: usize, message: String| ProofError::Parse {
            text: Source::Formula,
            line,
            message,
        };
        let mut header: Option<(usize, usize, usize)> = None;
        let mut skip = |line: usize, l: &str| {
            if !l.starts_with('p') {
                return match header {
                    None => Err(err(line, "a clause before the `p cnf` header".into())),
                    Some(_) => Ok(false),
                };
            }
            let f: Vec<&str> = l.split_whitespace().collect();
            let count = |s: &str| s.parse::<usize>().ok();
            match (header, f.as_slice()) {
                (None, ["p", "cnf", v, c]) => match (count(v), count(c)) {
                    (Some(v), Some(c)) if v <= i32::MAX as usize => {
                        header = Some((line, v, c));
                        Ok(true)
                    }
                    _ => Err(err(line, format!("bad header `{l}`"))),
                },
                (None, _) => Err(err(line, format!("bad header `{l}`"))),
                (Some(_), _) => Err(err(line, "a second header".into())),
            }
        };
        let found = clauses(text, Source::Formula, false, &mut skip)?;
        let Some((hline, vars, count)) = header else {
            return Err(err(1, "no `p cnf` header".into()));
        };
        if found.len() != count {
            return Err(err(
                hline,
                format!(
                    "the header says {count} clauses, the file has {}",
                    found.len()
                ),
            ));
        }
        let mut out = Vec::with_capacity(found.len());
        for (line, _, lits) in found {
            if let Some(l) = lits.iter().find(|l| l.unsigned_abs() as usize > vars) {
                return Err(err(
                    line,
                    format!("literal {l} beyond the {vars} variables"),
                ));
            }
            out.push(lits);
        }
        Ok(Cnf { vars, clauses: out })
    }

    /// A formula from its parts (for tests and tools).
    pub fn new(vars: usize, clauses: Vec<Vec<i32>>) -> Cnf {
        Cnf { vars, clauses }
    }

    /// The number of variables the header declares.
    pub fn vars(&self) -> usize {
        self.vars
    }

    /// The clauses, in order.
    pub fn clauses(&self) -> &[Vec<i32>] {
        &self.clauses
    }
}

impl Proof {
    /// Parses a text DRAT proof (binary DRAT is refused with an error).
    pub fn parse(text: &str) -> Result<Proof, ProofError> {
        let found = clauses(text, Source::Proof, true, &mut |_, _| Ok(false))?;
        let steps = found
            .into_iter()
            .map(|(line, del, lits)| {
                (
                    line,
                    if del {
                        Step::Delete(lits)
                    } else {
                        Step::Add(lits)
                    },
                )
            })
            .collect();
        Ok(Proof {
            steps,
            last_line: text.lines().count().max(1),
        })
    }

    /// The steps, each with the line (from 1) it starts on.
    pub fn steps(&self) -> &[(usize, Step)] {
        &self.steps
    }

    /// The number of the last line.
    pub fn last_line(&self) -> usize {
        self.last_line
    }
}
