//! The anytime search ([`solve_anytime`]): the constructive dissection,
//! then rounds that look for fewer pieces. A [`Run`] holds the run's state;
//! its steps are the round-0 ladder, the descent, the coarse lift and climb
//! (large figures), the plateau, and the incumbent's keep-best
//! ([`Incumbent::improve`]).

use std::sync::atomic::AtomicBool;

use crate::figure::Figure;
use crate::lattice::{Point, Symmetry};
use crate::solver::candidate::{Candidate, Score};
use crate::solver::explore::Executor;
use crate::solver::incumbent::Incumbent;
use crate::solver::plateau::{plateau_descents, plateau_walk};
use crate::solver::search::{From, Level, Search};
use crate::solver::{coarse, greedy, guillotine, regroup, sectors};
use crate::solver::{Event, Observer, Options, Outcome, Repair, SolveError, Via};

/// Levels climbed at full resolution from a lifted coarse candidate.
const CLIMB: usize = 2;

/// Motions the pilot method tries at each step it looks ahead, the first
/// time; each later pilot doubles it ([`Run::pilot`]).
pub(crate) const PILOT_WIDTH: usize = 4;

/// The widest pilot.
pub(crate) const PILOT_MAX_WIDTH: usize = 256;

/// Pilots up to this width run before the level search whatever they
/// find; a wider one runs there only while the last one improved. On
/// voxel figures the pilot finds what the level search does not
/// (BENCHMARKS, "3D at scale"), and a width that finds nothing is often
/// followed by one that does.
pub(crate) const PILOT_EAGER_WIDTH: usize = 32;

/// Steps the pilot method looks ahead at (the first ones: they cut the
/// largest pieces).
const PILOT_DEPTH: usize = 8;

/// Steps the beam pilots of voxel meshes look ahead at: their answers
/// have 17 to 40 pieces, and past the eighth step the plain greedy cut a
/// tail of small pieces that a look ahead cuts in fewer (the pawn: 27
/// pieces at depth 8, 26 at 16 and at 32, on seeds 1-3; BENCHMARKS, "3D:
/// deeper pilots on the meshes").
const MESH_PILOT_DEPTH: usize = 16;

/// Tail rebuilds per batch ([`Run::rebuild`]).
const REBUILDS: usize = 64;

/// Batches of tail rebuilds per round of the anytime search on large
/// figures (where the level search seldom finds fewer pieces).
const REBUILD_BATCHES_PER_ROUND: usize = 8;

/// A rebuild's step draws its motion among this many of the best.
const REBUILD_TOP: usize = 4;

/// Constructive dissections tied with the best that regrouping also
/// tries ([`Run::regroup`]).
const TIES: usize = 4;
/// The rungs of the guillotine cuts ([`guillotine::RUNGS`]) climbed before
/// the rest of the run whether or not each improves: the plain beams and
/// the pilots up to width 64 (about 13 s on 7³+14³+17³ = 20³, two threads; a wider
/// pilot is not always better, and a narrower one often finds nothing
/// below the plain beams).
const BOXES_EAGER_RUNGS: usize = 6;

/// A constructive count out of the level search's reach: the ladder climbs
/// one piece per level from two, and on voxel figures of a few hundred
/// cells a level takes seconds (a 252-voxel pawn into a 6×6×7 box: 4
/// pieces at 25 s, against 19 from the greedy). Figures under
/// [`coarse::MIN_CELLS`] whose greedy has at least this many pieces get
/// the constructive steps of large figures too: tidy choices, pilots,
/// regrouping and tail rebuilds (BENCHMARKS, "3D: mid-size meshes get the
/// large figures' steps").
const LADDER_REACH: usize = 10;

/// How far (in lattice translations along one axis) a displaced start
/// moves the first piece off the largest common part ([`Run::displaced`]):
/// on a 2,000-voxel blob into a 20×10×10 box, 4 along the box's first axis
/// cut the first two pieces as 997 + 549 voxels instead of 1,413 + 150
/// and led to 40 pieces where every undisplaced seed ended at 42-44
/// (BENCHMARKS, "A lead: a first piece placed a few voxels off the
/// largest overlap").
const DISPLACEMENT: i32 = 4;

/// Displaced starts a large voxel run takes beside the undisplaced one,
/// along this many of the axes the figures reach farthest on
/// ([`displacements`]): the second one found the torus's 17 and the
/// blob's 41 on the seed where one lane alone stayed at 18 and 44
/// (BENCHMARKS, "3D: displaced starts on the meshes").
const DISPLACED_LANES: usize = 2;

/// States the pilots of voxel meshes keep from one step to the next
/// ([`greedy::Lookahead::beam`]; 1 elsewhere): the 1,000-voxel pawn into
/// a 10×10×10 box reaches 27 pieces where the pilot method stayed at 28,
/// and the 2,000-voxel blob 40 on every seed (BENCHMARKS, "3D: beam
/// pilots on the meshes"). Such a pilot does `MESH_PILOT_BEAM` times the
/// work of its width, and so do the rebuilds that follow it.
const MESH_PILOT_BEAM: usize = 4;

/// Attempts (fresh streams) at one descent step while it ends near misses.
const DESCENT_ATTEMPTS: usize = 4;

/// Settings of [`solve_anytime`] beyond [`Options`].
#[derive(Clone, Debug, PartialEq)]
pub struct Anytime {
    /// End after this many rounds in a row that found no fewer pieces
    /// (with [`Anytime::plateau`]: nor a dissection the judge calls
    /// fresh; `None`: only a stop, or having nothing left to try, ends
    /// the run).
    pub idle_rounds: Option<usize>,
    /// Near-miss candidates handed to the repairer per level.
    pub repair_tries: usize,
    /// End after this many rounds (`None`: no such cap).
    pub max_rounds: Option<usize>,
    /// Keep searching at the best piece count, not only below it: every
    /// round's ladder runs up to the best count's level, so more valid
    /// dissections with the fewest pieces reach [`Observer::judge`]
    /// (several solutions). `false`: each round looks for fewer pieces only.
    pub plateau: bool,
}

impl Default for Anytime {
    fn default() -> Anytime {
        Anytime {
            idle_rounds: Some(1),
            repair_tries: 2,
            max_rounds: None,
            plateau: false,
        }
    }
}

/// The anytime search: a valid dissection first (the constructive greedy
/// dissection, never fails), then rounds of the paper's level schedule with
/// fresh random streams, each looking for fewer pieces than the best so
/// far; near misses go to `repair`. Every improvement is reported as
/// [`Event::Improved`]; the answer never has more pieces than an earlier
/// one.
///
/// Without a stop the run ends after [`Anytime::idle_rounds`] rounds
/// without improvement, or when two pieces are reached (one is impossible:
/// the figures are not congruent), so it is the same for any thread count.
pub fn solve_anytime(
    figures: &[Figure],
    options: &Options,
    anytime: &Anytime,
    stop: &AtomicBool,
    observer: &dyn Observer,
    repair: Option<&dyn Repair>,
) -> Result<Outcome, SolveError> {
    solve_anytime_with(figures, options, anytime, stop, observer, repair, None)
}

/// [`solve_anytime`], with the explorations run by `executor` (`None`: the
/// solver's thread pool); the same answer when it returns what
/// [`Explorer::explore`](crate::solver::Explorer::explore) returns.
pub fn solve_anytime_with(
    figures: &[Figure],
    options: &Options,
    anytime: &Anytime,
    stop: &AtomicBool,
    observer: &dyn Observer,
    repair: Option<&dyn Repair>,
    executor: Option<&dyn Executor>,
) -> Result<Outcome, SolveError> {
    let search = Search::new(figures, options, stop, observer, executor)?;
    let (whole, s0) = search.level_zero();
    if s0.valid {
        return Ok(congruent(&search, &whole, &s0));
    }
    let mut run = Run::new(&search, anytime, repair, s0.mismatch);
    let cells = figures[0].len();
    run.constructive(cells >= coarse::MIN_CELLS);
    // Figures the level search cannot reach the constructive count on
    // take the large figures' constructive steps.
    let mid_size = cells < coarse::MIN_CELLS && run.beyond_the_ladder();
    let scaled = cells >= coarse::MIN_CELLS || mid_size;
    if mid_size && !search.stopped() {
        run.constructive(true);
    }
    // Large figures that coarsen (and those beyond the ladder) regroup the
    // tail and rebuild it every round; large figures on lattices that do
    // not coarsen keep the paper's rounds.
    let large = cells >= coarse::MIN_CELLS && coarse::downsample(figures, coarse::FACTOR).is_some();
    let tail = large || mid_size;
    // Mid-size voxel figures: a level of the ladder takes tens of seconds
    // there, and the paper's ladder alone finds nothing below the greedy's
    // count in minutes (BENCHMARKS, "3D: mid-size voxel figures only
    // descend"), so their rounds only descend, as large figures' do, and
    // the time goes to the pilots and rebuilds.
    let descend_only = large || (mid_size && figures[0].lattice().lattice().dim() >= 3);
    // Figures of a few boxes (sums of cubes): boxes and bent slabs.
    if !search.stopped() {
        run.boxes();
    }
    // Large voxel figures that are not a few boxes (meshes): deeper beam
    // pilots, and displaced starts below (asked again there: a pilot may
    // beat the boxes).
    let voxels = figures[0].lattice().lattice().dim() >= 3;
    let large_voxels = cells >= coarse::MIN_CELLS && voxels;
    if large_voxels && !run.boxes_hold_the_best() {
        run.pilot_beam = MESH_PILOT_BEAM;
        run.pilot_depth = MESH_PILOT_DEPTH;
    }
    // Large figures (and those beyond the ladder): the level search is
    // slow there, so the constructive step looks ahead (the pilot method).
    if scaled && !search.stopped() {
        run.pilot();
    }
    // Figures that are mostly alike get their sectors early (they take a
    // second); the wider pilots follow.
    if !search.stopped() {
        run.sectors();
    }
    // Large voxel figures that are not a few boxes (meshes): displaced
    // starts beside the undisplaced one, other basins for the rebuilds.
    if large_voxels && !run.boxes_hold_the_best() {
        run.displaced();
    }
    if scaled && !search.stopped() {
        run.pilots();
    }
    // Large figures (and those beyond the ladder): the constructive step
    // leaves small pieces that the level search rarely merges; regroup
    // them exactly.
    if tail && !search.stopped() {
        run.regroup();
    }
    // Large figures: the level search costs about the same per level at
    // any resolution, so it runs on the figures at half resolution (halved
    // again while they are large); the coarse dissection is lifted, refined
    // at full resolution and, when it is a near miss, repaired. The ladder
    // at full resolution is then not run: the coarse search is the ladder.
    if large && !search.stopped() {
        run.coarse()?;
    }

    let mut idle = 0;
    // On large figures the coarse step was round 0.
    let first_round = usize::from(large);
    if large {
        run.inc.outcome.rounds = 1;
    }
    for round in first_round.. {
        if !run.round_starts(round, idle) {
            break;
        }
        let fresh = search.fresh();
        let mut improved = run.round(round, descend_only)?;
        // Large figures (and those beyond the ladder): the level search
        // there rarely beats a wider pilot, so every round also widens it
        // (until its widest), and rebuilds the tail.
        if tail && !search.stopped() {
            improved |= run.pilot();
        }
        if tail && !search.stopped() {
            improved |= run.rebuild(REBUILD_BATCHES_PER_ROUND);
        }
        // Figures of a few boxes: the next, wider rung of the guillotine
        // cuts (until the last), while they hold the best count (where the
        // search does better, as on joined cubes, the wide rungs would
        // only take its time).
        if !search.stopped() && run.boxes_hold_the_best() {
            improved |= run.box_rung();
        }
        if improved && tail && !search.stopped() {
            let before = run.inc.pieces();
            run.regroup();
            improved |= run.inc.pieces() < before;
        }
        // With the plateau, new solutions the judge wanted are progress.
        if improved || (anytime.plateau && search.fresh() > fresh) {
            idle = 0;
        } else {
            idle += 1;
        }
    }
    Ok(run.finish())
}

/// Two figures of a few boxes on a grid lattice, as boxes.
fn boxes_of(figures: &[Figure], syms: &[Symmetry]) -> Option<guillotine::Boxes> {
    if figures.len() != 2 || !figures[0].lattice().lattice().is_grid() {
        return None;
    }
    guillotine::Boxes::new([figures[0].cells(), figures[1].cells()], syms)
}

/// The displacements of the displaced starts' first motions:
/// [`DISPLACEMENT`] lattice translations along each of the
/// [`DISPLACED_LANES`] axes on which the figures reach farthest (their
/// extent in blocks, the longest first, the first axis on ties: the length
/// of a box they go into first). The greedy's largest common part leaves a
/// remainder that the later steps cut into small pieces; a first piece a
/// few cells off it leaves a second large part beside it, another basin
/// for the rebuilds.
pub(crate) fn displacements(figures: &[Figure]) -> Vec<Point> {
    let Some(first) = figures.first() else {
        return Vec::new();
    };
    let lattice = first.lattice().lattice();
    let mut extent = [0; 3];
    for (lo, hi) in figures.iter().map(Figure::bounds) {
        for axis in 0..3 {
            extent[axis] = extent[axis].max(hi[axis].saturating_sub(lo[axis]));
        }
    }
    let mut axes: Vec<usize> = (0..lattice.dim()).collect();
    // Stable: the first axis first on ties.
    axes.sort_by_key(|&a| std::cmp::Reverse(extent[a]));
    axes.into_iter()
        .take(DISPLACED_LANES)
        .map(|axis| {
            let mut d = [0; 3];
            d[axis] = DISPLACEMENT * lattice.modulus();
            Point::from(d)
        })
        .collect()
}

/// The figures are congruent: one piece, found at level 0.
fn congruent(search: &Search<'_>, whole: &Candidate, s0: &Score) -> Outcome {
    let found = search.found(whole, s0, 0);
    search.observer.on_event(&Event::Improved {
        pieces: 1,
        smallest: search.figures[0].len(),
        level: 0,
        round: 0,
        via: Via::Search,
    });
    Outcome {
        found: Some(found),
        best_mismatch: Some(0),
        last_pieces: 1,
        stopped: false,
        explorations: 1,
        rounds: 0,
    }
}

/// One anytime run: its fixed settings and its incumbent. Each method is a
/// step of the run.
struct Run<'r, 'a> {
    search: &'r Search<'a>,
    anytime: &'r Anytime,
    repair: Option<&'r dyn Repair>,
    /// The cap on pieces ([`Options::max_pieces`], at most the area).
    max_pieces: usize,
    /// The largest matching cost that counts as a near miss.
    near_miss: u64,
    /// 1: rounds look below the best count; 0 (the plateau, several
    /// solutions): at the best count too.
    below: usize,
    /// The best dissection so far and the outcome.
    inc: Incumbent,
    /// The constructive steps' state: the undisplaced one while the
    /// others wait ([`Run::pilots`]).
    lane: Lane,
    /// States the pilots keep from step to step ([`MESH_PILOT_BEAM`] on
    /// meshes, else 1).
    pilot_beam: usize,
    /// Steps the pilots look ahead at ([`MESH_PILOT_DEPTH`] on meshes,
    /// else [`PILOT_DEPTH`]).
    pilot_depth: usize,
    /// The displaced starts' lanes, for [`Run::pilots`] (none but on
    /// large voxel figures).
    displaced: Vec<Lane>,
    /// Constructive dissections with as many pieces as the best (the
    /// last [`TIES`]: the widest pilots'), for [`Run::regroup`].
    ties: Vec<Candidate>,
    /// Batches of rebuilds so far (each draws its own streams).
    rebuild_batch: usize,
    /// The figures as boxes, when they are two figures of a few boxes on
    /// a grid lattice ([`Run::boxes`]).
    boxes: Option<guillotine::Boxes>,
    /// The next rung of [`guillotine::RUNGS`].
    box_rung: usize,
    /// The fewest pieces any rung found.
    boxes_best: usize,
}

/// The state of one start of the constructive steps: its pilots, the greedy
/// choices it ran, and its walk of tail rebuilds. A run has the
/// undisplaced lane and, on large voxel figures, displaced ones
/// ([`Run::pilots`]).
struct Lane {
    /// The width of the next pilot ([`Run::pilot`]).
    pilot_width: usize,
    /// The fewest pieces any pilot found ([`Run::pilot`]).
    pilot_best: usize,
    /// How the pilot's greedy chooses motions (set by
    /// [`Run::constructive`]).
    pilot_choice: greedy::Choice,
    /// The fewest pieces of each greedy choice the constructive step ran.
    fewest: Vec<(greedy::Choice, usize)>,
    /// Where the tail rebuilds' walk stands ([`Run::rebuild`]).
    walk: Option<Candidate>,
    /// Added to the first motion of every constructive step
    /// ([`greedy::GreedyStyle::start`]; [`Point::ORIGIN`]: the
    /// undisplaced lane).
    start: Point,
    /// A displaced lane's fewest-piece dissection: its rebuilds walk from
    /// there rather than from the run's best, which lies in another basin
    /// (`None` in the undisplaced lane).
    basin: Option<Candidate>,
}

/// The order in which [`Run::pilots`] runs its lanes' pilots: the open
/// lane whose next pilot is narrowest goes first, the lowest index on
/// ties (lane 0, the undisplaced one, then the displaced ones in order).
/// A lane closes once its next pilot is past [`PILOT_MAX_WIDTH`], or past
/// [`PILOT_EAGER_WIDTH`] when its last pilot found no fewer pieces than
/// its narrower ones did. Test: `lanes_take_turns_narrowest_first`.
#[derive(Debug)]
pub(crate) struct Schedule {
    /// Whether each lane goes on.
    open: Vec<bool>,
    /// Whether each lane's last pilot found fewer pieces than its
    /// narrower ones (`true` before the first).
    progress: Vec<bool>,
}

impl Schedule {
    /// `lanes` lanes, all open.
    pub(crate) fn new(lanes: usize) -> Schedule {
        Schedule {
            open: vec![true; lanes],
            progress: vec![true; lanes],
        }
    }

    /// The lane to run next, given each lane's next pilot width (one per
    /// lane); `None` once every lane is closed.
    pub(crate) fn next(&self, widths: &[usize]) -> Option<usize> {
        debug_assert_eq!(widths.len(), self.open.len(), "a width per lane");
        // `min_by_key` keeps the first of equal keys.
        (0..self.open.len())
            .filter(|&i| self.open[i])
            .min_by_key(|&i| widths[i])
    }

    /// Whether lane `i` runs its next pilot, `width` wide; closes it if
    /// not.
    pub(crate) fn runs(&mut self, i: usize, width: usize) -> bool {
        let runs = width <= PILOT_MAX_WIDTH && (width <= PILOT_EAGER_WIDTH || self.progress[i]);
        self.open[i] &= runs;
        runs
    }

    /// Whether lane `i`'s pilot just found fewer pieces than its narrower
    /// ones.
    pub(crate) fn record(&mut self, i: usize, progress: bool) {
        self.progress[i] = progress;
    }
}

impl Lane {
    /// A lane before its first step, its first motions displaced by
    /// `start`.
    fn new(start: Point) -> Lane {
        Lane {
            pilot_width: PILOT_WIDTH,
            pilot_best: usize::MAX,
            pilot_choice: greedy::Choice::Connected,
            fewest: Vec::new(),
            walk: None,
            start,
            basin: None,
        }
    }

    /// Whether this lane's first motions are displaced.
    fn is_displaced(&self) -> bool {
        self.start != Point::ORIGIN
    }
}

impl<'r, 'a> Run<'r, 'a> {
    /// A run after level 0, whose matching cost was `mismatch`.
    fn new(
        search: &'r Search<'a>,
        anytime: &'r Anytime,
        repair: Option<&'r dyn Repair>,
        mismatch: u64,
    ) -> Run<'r, 'a> {
        let (figures, options) = (search.figures, search.options);
        let cells = figures[0].len();
        let max_pieces = options.max_pieces.unwrap_or(cells).min(cells);
        let outcome = Outcome {
            found: None,
            best_mismatch: Some(mismatch),
            last_pieces: 1,
            stopped: false,
            explorations: 1,
            rounds: 0,
        };
        Run {
            search,
            anytime,
            repair,
            max_pieces,
            near_miss: options.near_miss(figures.len(), cells),
            // The plateau (several solutions) searches at the best count too.
            below: usize::from(!anytime.plateau),
            inc: Incumbent::new(outcome, max_pieces),
            lane: Lane::new(Point::ORIGIN),
            pilot_beam: 1,
            pilot_depth: PILOT_DEPTH,
            displaced: Vec::new(),
            ties: Vec::new(),
            rebuild_batch: 0,
            boxes: boxes_of(figures, &search.problem.geo.syms),
            box_rung: 0,
            boxes_best: usize::MAX,
        }
    }

    /// The constructive dissection: every figure as the pivot, two ways of
    /// choosing motions and two of keeping components (with `tidy`, also
    /// the tidy choices, [`greedy::TIDY_SLACKS`]; a second call runs only
    /// those); each one with fewer pieces is an improvement. The pilot's
    /// choice is then the tidy or connected choice whose greedy had the
    /// fewest pieces.
    fn constructive(&mut self, tidy: bool) {
        let search = self.search;
        let mut choices = Vec::new();
        if self.lane.fewest.is_empty() {
            choices = vec![
                (greedy::Choice::Overlap, 2),
                (greedy::Choice::Overlap, 1),
                (greedy::Choice::Connected, 2),
                (greedy::Choice::Connected, 1),
            ];
        }
        if tidy {
            for slack in greedy::TIDY_SLACKS {
                let choice = greedy::Choice::Tidy { slack };
                choices.extend([(choice, 2), (choice, 1)]);
            }
        }
        // The fewest pieces of each choice, for the pilot's.
        let mut fewest = std::mem::take(&mut self.lane.fewest);
        'styles: for (choice, divisor) in choices {
            for pivot in 0..search.figures.len() {
                if search.stopped() {
                    break 'styles;
                }
                let style = greedy::GreedyStyle {
                    pivot,
                    divisor,
                    choice,
                    start: self.lane.start,
                };
                // The first dissection is always finished; later ones stop
                // with the run.
                let never = AtomicBool::new(false);
                let stop = if self.inc.pieces().is_some() {
                    search.stop
                } else {
                    &never
                };
                let Some(cand) =
                    search.install(|| greedy::greedy_until(&search.problem, style, stop))
                else {
                    break 'styles;
                };
                match fewest.iter_mut().find(|(c, _)| *c == choice) {
                    Some(entry) => entry.1 = entry.1.min(cand.k),
                    None => fewest.push((choice, cand.k)),
                }
                self.offer_greedy(cand);
            }
        }
        // The fewest pieces; on ties tidy first (in the order of
        // TIDY_SLACKS, as they were run), then connected.
        self.lane.pilot_choice = fewest
            .iter()
            .filter(|(c, _)| *c != greedy::Choice::Overlap)
            .min_by_key(|&&(c, k)| (k, c == greedy::Choice::Connected))
            .map_or(greedy::Choice::Connected, |&(c, _)| c);
        self.lane.fewest = fewest;
    }

    /// Whether the best count so far is out of the level search's reach
    /// on a figure of this size ([`LADDER_REACH`]).
    fn beyond_the_ladder(&self) -> bool {
        self.inc.pieces().is_some_and(|k| k >= LADDER_REACH)
    }

    /// A constructive dissection (greedy or pilot, always valid) scored,
    /// judged and offered to the incumbent; whether it improved.
    fn offer_greedy(&mut self, cand: Candidate) -> bool {
        self.offer(cand, Via::Greedy)
    }

    /// [`Run::offer_greedy`] for a dissection made by `via`.
    fn offer(&mut self, mut cand: Candidate, via: Via) -> bool {
        let search = self.search;
        let mut score = cand.evaluate(&search.problem, 0.0, search.options.split_penalty);
        debug_assert!(score.valid, "a constructive dissection is valid");
        search.judge(&cand, &mut score);
        if !score.valid {
            return false;
        }
        self.keep_in_basin(&cand);
        let level = cand.k - 1;
        let best = self.inc.pieces();
        if best == Some(cand.k) {
            if self.ties.len() == TIES {
                self.ties.remove(0);
            }
            self.ties.push(cand);
            return false;
        }
        let improved = self.inc.improve(search, cand, score, level, 0, via);
        if improved {
            self.ties.clear();
        }
        improved
    }

    /// While a displaced start runs, `cand` as its basin's best when it
    /// has fewer pieces than that.
    fn keep_in_basin(&mut self, cand: &Candidate) {
        if self.lane.is_displaced() && self.lane.basin.as_ref().is_none_or(|b| cand.k < b.k) {
            self.lane.basin = Some(cand.clone());
        }
    }

    /// The pilot method on the greedy ([`greedy::pilot_until`]) at the
    /// current width, which then doubles: the constructive step's pilot
    /// choice, then (past the first width) the connected choice when that
    /// was a tidy one; every
    /// figure as the pivot, both ways of keeping components; each one with fewer
    /// pieces is an improvement. Whether one was; `false` once the width
    /// is past [`PILOT_MAX_WIDTH`] or a pilot took every motion a step
    /// ranks (a wider one would repeat it). Stops with the run.
    fn pilot(&mut self) -> bool {
        let search = self.search;
        let width = self.lane.pilot_width;
        if width > PILOT_MAX_WIDTH {
            return false;
        }
        let mut improved = false;
        let mut truncated = false;
        // The first pilot (before the sectors) runs one choice only.
        let mut choices = vec![self.lane.pilot_choice];
        if self.lane.pilot_choice != greedy::Choice::Connected && width > PILOT_WIDTH {
            choices.push(greedy::Choice::Connected);
        }
        let styles = choices
            .into_iter()
            .flat_map(|choice| [1, 2].map(|divisor| (choice, divisor)));
        'styles: for (choice, divisor) in styles {
            for pivot in 0..search.figures.len() {
                if search.stopped() {
                    break 'styles;
                }
                let style = greedy::GreedyStyle {
                    pivot,
                    divisor,
                    choice,
                    start: self.lane.start,
                };
                let found = search.install(|| {
                    let look = greedy::Lookahead {
                        width,
                        depth: self.pilot_depth,
                        beam: self.pilot_beam,
                    };
                    greedy::pilot_until(&search.problem, style, look, search.stop)
                });
                let Some((cand, more)) = found else {
                    break 'styles;
                };
                truncated |= more;
                self.lane.pilot_best = self.lane.pilot_best.min(cand.k);
                improved |= self.offer_greedy(cand);
            }
        }
        self.lane.pilot_width = if truncated { width * 2 } else { usize::MAX };
        improved
    }

    /// Pilots of growing width before the level search: up to
    /// [`PILOT_EAGER_WIDTH`] whatever they find, then while each finds
    /// fewer pieces than the narrower ones did. That test looks at the
    /// pilots alone, which draw nothing at random, so how wide they get
    /// here does not hang on what the rebuilds between them found (on
    /// 7-14-17 a lucky rebuild used to end them before the width that
    /// found the fewest pieces).
    ///
    /// With displaced lanes ([`Run::displaced`]) the lanes share the
    /// time: the lane whose next pilot is narrowest goes first (the
    /// undisplaced one, then the displaced ones in order, on ties), each
    /// with its own rule; a displaced one first runs its constructive
    /// steps. The undisplaced lane is the run's again afterwards.
    fn pilots(&mut self) {
        let mut schedule = Schedule::new(1 + self.displaced.len());
        while !self.search.stopped() {
            // Lane 0 is the undisplaced one, lane i the displaced i - 1.
            let widths: Vec<usize> = std::iter::once(&self.lane)
                .chain(&self.displaced)
                .map(|lane| lane.pilot_width)
                .collect();
            let Some(i) = schedule.next(&widths) else {
                break;
            };
            self.switch_lanes(i);
            if i > 0 && self.lane.fewest.is_empty() {
                self.constructive(true);
            }
            let width = self.lane.pilot_width;
            if schedule.runs(i, width) {
                let before = self.lane.pilot_best;
                self.pilot();
                schedule.record(i, self.lane.pilot_best < before);
                // Rebuilds in proportion to the pilot's work.
                self.rebuild(self.pilot_beam * width / PILOT_WIDTH);
            }
            self.switch_lanes(i);
        }
    }

    /// Lane `i` of [`Run::pilots`] (0: the undisplaced one, which stays)
    /// and the undisplaced lane trade places; twice puts them back.
    fn switch_lanes(&mut self, i: usize) {
        if let Some(other) = i.checked_sub(1).and_then(|d| self.displaced.get_mut(d)) {
            std::mem::swap(&mut self.lane, other);
        }
    }

    /// The displaced lanes for [`Run::pilots`], their first motions moved
    /// by [`displacements`].
    fn displaced(&mut self) {
        self.displaced = displacements(self.search.figures)
            .into_iter()
            .map(Lane::new)
            .collect();
    }

    /// The sector dissection ([`sectors`]): the large common piece with
    /// each figure as the frame, and every sector of what is left dissected
    /// exactly by the repair hook; each with fewer pieces than the best is
    /// an improvement.
    fn sectors(&mut self) {
        let Some(repairer) = self.repair else {
            return;
        };
        let search = self.search;
        let mut tried: Vec<sectors::Plan> = Vec::new();
        for pivot in 0..search.figures.len() {
            if search.stopped() {
                break;
            }
            let plans = search.install(|| sectors::plans(&search.problem, pivot));
            for plan in plans {
                // Another frame often gives the same sectors.
                if search.stopped() || tried.contains(&plan) {
                    continue;
                }
                tried.push(plan.clone());
                // Fewer pieces than the best so far, within the cap.
                let most = self
                    .inc
                    .pieces()
                    .map_or(self.max_pieces, |k| k - 1)
                    .min(self.max_pieces);
                let Some(pieces) =
                    sectors::dissect(search.figures, &plan, most, repairer, search.stop)
                else {
                    continue;
                };
                if let Some((c, s)) = search.candidate_of(&pieces) {
                    let level = c.k - 1;
                    self.inc.improve(search, c, s, level, 0, Via::Sectors);
                }
            }
        }
    }
    /// Guillotine cuts ([`guillotine`]) on two figures that are each a
    /// union of a few boxes, on a grid lattice; an improvement when it has
    /// fewer pieces.
    ///
    /// The rungs of [`guillotine::RUNGS`] in turn: the first
    /// [`BOXES_EAGER_RUNGS`] always, then while each finds fewer pieces
    /// than the rungs before it; the rounds climb the rest, one a round
    /// ([`Run::box_rung`]).
    fn boxes(&mut self) {
        let mut progress = true;
        while self.boxes.is_some()
            && !self.search.stopped()
            && self.box_rung < guillotine::RUNGS.len()
            && (self.box_rung < BOXES_EAGER_RUNGS || progress)
        {
            let before = self.boxes_best;
            self.box_rung();
            progress = self.boxes_best < before;
        }
    }

    /// Whether the guillotine cuts found as few pieces as the best
    /// dissection has.
    fn boxes_hold_the_best(&self) -> bool {
        self.inc.pieces().is_some_and(|k| self.boxes_best <= k)
    }

    /// The next rung of the guillotine cuts, when the figures are boxes
    /// and a rung is left, in each order of [`guillotine::ORDERS`]
    /// (each answer offered to the incumbent as it comes): whether it
    /// improved the best dissection.
    fn box_rung(&mut self) -> bool {
        let search = self.search;
        let (Some(boxes), Some(&rung)) = (&self.boxes, guillotine::RUNGS.get(self.box_rung)) else {
            return false;
        };
        self.box_rung += 1;
        let mut improved = false;
        for order in guillotine::ORDERS {
            let Some(pieces) = search.install(|| boxes.dissect(rung, order, search.stop)) else {
                break;
            };
            // The incumbent keeps the cap on pieces.
            let Some((c, s)) = search.candidate_of(&pieces) else {
                continue;
            };
            self.boxes_best = self.boxes_best.min(c.k);
            let level = c.k - 1;
            improved |= self.inc.improve(search, c, s, level, 0, Via::Boxes);
        }
        improved
    }
    /// Regrouping ([`regroup`]): groups of touching pieces of the best
    /// dissection, the smallest first, cut again exactly with fewer pieces,
    /// for as long as that works.
    fn regroup(&mut self) {
        let Some(repairer) = self.repair else {
            return;
        };
        let search = self.search;
        let mut tried = Vec::new();
        while let Some((best, _)) = self.inc.best.as_ref() {
            if search.stopped() {
                break;
            }
            let Some(pieces) = regroup::regroup_once(
                search.figures,
                &search.problem,
                &best.labels,
                best.k,
                repairer,
                search.stop,
                &mut tried,
            ) else {
                break;
            };
            let Some((c, s)) = search.candidate_of(&pieces) else {
                break;
            };
            let level = c.k - 1;
            if !self.inc.improve(search, c, s, level, 0, Via::Regroup) {
                break;
            }
        }
        // The constructive dissections that tied with the best: a group
        // of one may merge where the best's do not.
        for tie in std::mem::take(&mut self.ties) {
            if search.stopped() {
                break;
            }
            let found = regroup::regroup_once(
                search.figures,
                &search.problem,
                &tie.labels,
                tie.k,
                repairer,
                search.stop,
                &mut Vec::new(),
            );
            let Some((c, s)) = found.and_then(|pieces| search.candidate_of(&pieces)) else {
                continue;
            };
            let level = c.k - 1;
            if self.inc.improve(search, c, s, level, 0, Via::Regroup) {
                self.ties.clear();
                self.regroup();
                return;
            }
        }
    }

    /// Rebuilds of a dissection's tail ([`greedy::rebuild_until`]),
    /// `batches` of [`REBUILDS`], each keeping a random number (up to half)
    /// of the largest pieces, with a random style, drawing its own stream
    /// (so the answer does not depend on the threads). They start from
    /// the best dissection and walk on: a rebuild with no more pieces than
    /// the last one is where the next start (so the walk crosses plateaus);
    /// one with fewer pieces than the best is an improvement.
    fn rebuild(&mut self, batches: usize) -> bool {
        use rand::RngExt;
        let search = self.search;
        let mut improved = false;
        for i in 0..batches * REBUILDS {
            if search.stopped() {
                break;
            }
            if i % REBUILDS == 0 {
                self.rebuild_batch += 1;
            }
            let Some((best, _)) = self.inc.best.as_ref() else {
                return improved;
            };
            let best_k = best.k;
            // A displaced start's walk stays in its own basin.
            let anchor = self.lane.basin.as_ref().unwrap_or(best);
            let from = match self.lane.walk.take() {
                Some(w) if w.k <= anchor.k => w,
                _ => anchor.clone(),
            };
            let batch = self.rebuild_batch;
            let mut rng = super::stream(search.options.seed, batch, super::REBUILD, i % REBUILDS);
            let most = (from.k / 2).max(1);
            let keep = rng.random_range(1..=most);
            let choices = [
                self.lane.pilot_choice,
                greedy::Choice::Connected,
                greedy::Choice::Tidy { slack: 3 },
                greedy::Choice::Tidy { slack: 4 },
                greedy::Choice::Tidy { slack: 6 },
            ];
            let style = greedy::GreedyStyle {
                pivot: rng.random_range(0..search.figures.len()),
                divisor: rng.random_range(1..=2),
                choice: choices[rng.random_range(0..choices.len())],
                start: Point::ORIGIN,
            };
            let found = search.install(|| {
                greedy::rebuild_until(
                    &search.problem,
                    style,
                    (&from, keep),
                    (&mut rng, REBUILD_TOP),
                    search.stop,
                )
            });
            let Some(cand) = found else {
                break;
            };
            if cand.k < best_k {
                improved |= self.offer(cand.clone(), Via::Rebuild);
            } else {
                self.keep_in_basin(&cand);
            }
            self.lane.walk = Some(if cand.k <= from.k { cand } else { from });
        }
        improved
    }

    /// The coarse step (round 0 of large figures): the anytime search on
    /// the figures at lower resolution, lifted ([`Run::lift`]), then, when
    /// the lift is close to a dissection, the climb ([`Run::climb`]).
    fn coarse(&mut self) -> Result<(), SolveError> {
        let Some((cand, mut score)) = self.lift() else {
            return Ok(());
        };
        let search = self.search;
        search.judge(&cand, &mut score);
        let level = cand.k.saturating_sub(1);
        let mut done = false;
        if score.valid {
            done = self
                .inc
                .improve(search, cand.clone(), score, level, 0, Via::Coarse);
        } else if let Some(r) = self.repair {
            let near = Level {
                results: vec![(cand.clone(), score)],
                stopped: false,
            };
            if let Some((c, s)) = search.repair(r, &near, level + 1, 1) {
                done = self.inc.improve(search, c, s, level, 0, Via::Coarse);
            }
        }
        if !done {
            self.climb(cand, score, level)?;
        }
        Ok(())
    }

    /// The dissection of the coarse figures (one round of the anytime
    /// search, below the best so far), lifted and refined at full
    /// resolution.
    fn lift(&self) -> Option<(Candidate, Score)> {
        let (search, options) = (self.search, self.search.options);
        let max_pieces = self.max_pieces;
        let best_pieces = self.inc.pieces().map_or(max_pieces, |k| k - 1);
        let inner_options = Options {
            max_pieces: Some(best_pieces.min(max_pieces)),
            ..options.clone()
        };
        let inner = Anytime {
            idle_rounds: Some(1),
            max_rounds: Some(1),
            ..self.anytime.clone()
        };
        let (stop, repair) = (search.stop, self.repair);
        coarse::from_coarse(
            search.figures,
            &search.problem,
            options,
            options.seed,
            stop,
            |coarse_figures| {
                solve_anytime_with(
                    coarse_figures,
                    &inner_options,
                    &inner,
                    stop,
                    &(),
                    repair,
                    None,
                )
                .ok()?
                .found
            },
        )
    }

    /// Not yet a dissection but close (a repairable distance): climbs the
    /// paper's levels from the lifted candidate at `level` (one more piece
    /// per level, at most CLIMB levels) while that stays below the best. A
    /// lift far from any dissection (curved boundaries the coarse cells cut
    /// differently) is left to the descent.
    fn climb(&mut self, cand: Candidate, score: Score, level: usize) -> Result<(), SolveError> {
        let search = self.search;
        let options = search.options;
        let close = score.mismatch <= 4 * self.near_miss;
        let mut parents = vec![(cand, score)];
        let top = if close { level + CLIMB } else { level };
        let mut level = level + 1;
        while !search.stopped() && level <= top {
            let pieces = level + 1;
            if self.inc.pieces().is_some_and(|k| pieces >= k) || pieces > self.max_pieces {
                break;
            }
            let result = search.level(0, level, From::Lifted(&parents))?;
            self.inc.outcome.explorations += result.results.len();
            if let Some((c, s, _)) =
                search.settle(&result, pieces, self.repair, self.anytime.repair_tries)
            {
                self.inc.improve(search, c, s, level, 0, Via::Coarse);
                break;
            }
            if result.stopped || result.results.is_empty() {
                break;
            }
            parents = result.kept(options.keep);
            level += 1;
        }
        Ok(())
    }

    /// Whether round `round` runs after `idle` rounds without improvement;
    /// if so, reports [`Event::RoundStarted`].
    fn round_starts(&mut self, round: usize, idle: usize) -> bool {
        let best_pieces = self.inc.pieces().unwrap_or(usize::MAX);
        // Look for fewer pieces than the best so far (and no more than the
        // cap); two pieces is the least there can be.
        let target = best_pieces.saturating_sub(self.below).min(self.max_pieces);
        if target < 2 || self.search.stopped() {
            return false;
        }
        let anytime = self.anytime;
        if anytime.idle_rounds.is_some_and(|n| idle >= n)
            || anytime.max_rounds.is_some_and(|n| round >= n)
        {
            return false;
        }
        self.search.observer.on_event(&Event::RoundStarted {
            round,
            max_pieces: target,
        });
        self.inc.outcome.rounds = round + 1;
        true
    }

    /// One round; whether it found fewer pieces. Round 0 of a small figure
    /// runs the paper's ladder first (its schedule reaches the fewest
    /// pieces there), then the descent from what it found; later rounds
    /// descend first. With `descend_only` (large figures, whose ladder ran
    /// on the coarse figures, and mid-size voxel figures beyond the ladder)
    /// the round only descends. With the plateau, the walk ends the round.
    fn round(&mut self, round: usize, descend_only: bool) -> Result<bool, SolveError> {
        let improved = if descend_only {
            self.descend(round)?
        } else if round == 0 {
            let a = self.ladder(round)?;
            self.descend(round)? | a
        } else {
            let a = self.descend(round)?;
            self.ladder(round)? | a
        };
        // The plateau walk: from the incumbent one piece up and down again,
        // and exact repairs of small moves: other dissections with the best
        // count (each seen by the judge), or fewer pieces.
        if self.anytime.plateau && !self.search.stopped() {
            Ok(plateau_walk(self.search, &mut self.inc, round, self.repair)? | improved)
        } else {
            Ok(improved)
        }
    }

    /// The descent: one piece fewer than the incumbent, by merging two of
    /// its pieces and refining (a near miss goes to the repairer, and earns
    /// new attempts with fresh streams), for as long as that works.
    fn descend(&mut self, round: usize) -> Result<bool, SolveError> {
        let search = self.search;
        let mut improved = false;
        let mut attempt = 0;
        let n = search.options.explorations.div_ceil(4).max(1);
        while let Some((parent, _)) = self.inc.best.clone() {
            let pieces = parent.k - 1;
            if pieces < 2 || search.stopped() {
                break;
            }
            let level = pieces - 1;
            let result = search.level(round, level, From::Above(&parent, attempt * n))?;
            self.inc.outcome.explorations += result.results.len();
            match search.settle(&result, pieces, self.repair, self.anytime.repair_tries) {
                Some((c, s, via)) => {
                    if !self.inc.improve(search, c, s, level, round, via) {
                        break;
                    }
                    improved = true;
                    attempt = 0;
                }
                None => {
                    attempt += 1;
                    if result.stopped
                        || attempt >= DESCENT_ATTEMPTS
                        || result.best_mismatch() > self.near_miss
                    {
                        break;
                    }
                }
            }
        }
        Ok(improved)
    }

    /// The ladder: the paper's levels from two pieces up, with this round's
    /// streams, below the best so far (at it, with the plateau).
    fn ladder(&mut self, round: usize) -> Result<bool, SolveError> {
        let search = self.search;
        let target = self
            .inc
            .pieces()
            .unwrap_or(usize::MAX)
            .saturating_sub(self.below)
            .min(self.max_pieces);
        let mut parents: Vec<(Candidate, Score)> = Vec::new();
        let mut ladder_ended = false;
        for level in 1..target {
            if search.stopped() {
                break;
            }
            let pieces = level + 1;
            let result = search.level(round, level, From::Below(&parents))?;
            let outcome = &mut self.inc.outcome;
            outcome.explorations += result.results.len();
            outcome.last_pieces = outcome.last_pieces.max(pieces);
            outcome.best_mismatch = Some(result.best_mismatch());
            if let Some((c, s, via)) =
                search.settle(&result, pieces, self.repair, self.anytime.repair_tries)
            {
                return Ok(self.inc.improve(search, c, s, level, round, via));
            }
            if result.stopped || result.results.is_empty() {
                break;
            }
            parents = result.kept(search.options.keep);
            ladder_ended = level + 1 == target;
        }
        // The plateau: a ladder that found nothing up to the best count
        // goes one level further and descends from there, into other
        // dissections with the best count.
        if self.anytime.plateau && ladder_ended && !search.stopped() {
            let tries = self.anytime.repair_tries;
            return plateau_descents(search, &mut self.inc, round, &parents, self.repair, tries);
        }
        Ok(false)
    }

    /// The outcome (the best dissection is already in it).
    fn finish(mut self) -> Outcome {
        self.inc.outcome.stopped |= self.search.stopped();
        self.inc.outcome
    }
}
