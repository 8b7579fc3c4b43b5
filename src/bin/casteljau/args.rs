//! The command line's arguments: clap-derived plain structs, one per command or shared group.

use crate::work_option::parse_work;
use clap::{Args, Parser, Subcommand};

pub const AFTER_HELP: &str = "\
CURVES: control points as exact numbers (integers, p/q, decimals such as 0.125 or 1.5e-3, hex
floats such as 0x1.8p-3), commas between points: \"x0 y0, x1 y1, x2 y2\". --numbers binary64 reads
each as the f64 nearest to it (0.1 = 3602879701896397/2^55), as float code holds it.
With --input FILE (or '-' / no curve: stdin) each line is one curve; numbers may be separated by
whitespace or commas, read --dim at a time.
Blank lines and lines starting with '#' are skipped.

LIMITS: each answer's cost is estimated from the input (degree, bit lengths, output size) before
work starts, in work units of about 1 ns on a 2-core machine; above --max-work (default 1e10,
~10 s) the curve is refused with exit 2 and the estimate. Sums and products in expressions
(implicit --poly, claim files) are counted as they run (one step per 200 units). Fixed limits:
degree 10,000; number tokens 1,000 characters; input lines 16 MiB; see README, Limits.

EXIT CODES: 0 ok; 1 a check failed; 2 bad input (the message names the token and position).";

/// casteljau: Bézier curves in exact arithmetic.
#[derive(Parser, Debug)]
#[command(name = "casteljau", version, about, after_help = AFTER_HELP)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands.
#[derive(Subcommand, Debug)]
pub enum Command {
    /// Evaluate b(t) exactly (fraction-free de Casteljau).
    Eval {
        /// Parameter values (repeatable): exact numbers.
        #[arg(long = "t", required = true, allow_hyphen_values = true)]
        t: Vec<String>,
        /// Rational curves.
        #[command(flatten)]
        rational: RationalArgs,
        /// The curve(s) and output form.
        #[command(flatten)]
        curve: CurveArgs,
    },
    /// Split at t (Lemma 2) into the control polygons of [0,t] and [t,1] (`left`/`right`); with
    /// --depth k, repeat: 2^k `pieces` with their parameter intervals.
    Subdivide {
        /// The split parameter.
        #[arg(long = "t", default_value = "1/2", allow_hyphen_values = true)]
        t: String,
        /// Split every piece again, depth times (2^depth pieces, as in seed 001 Fig. 10). Any
        /// explicit depth, 1 included, prints the `pieces` form; without it the `left`/`right`
        /// form.
        #[arg(long)]
        depth: Option<u32>,
        /// Rational curves (depth 1).
        #[command(flatten)]
        rational: RationalArgs,
        /// The curve(s) and output form.
        #[command(flatten)]
        curve: CurveArgs,
    },
    /// Degree elevation: the same curve with `by` more control points.
    Elevate {
        /// How many degrees to add.
        #[arg(long, default_value_t = 1)]
        by: usize,
        /// Rational curves.
        #[command(flatten)]
        rational: RationalArgs,
        /// The curve(s) and output form.
        #[command(flatten)]
        curve: CurveArgs,
    },
    /// Power form: coefficients c_k with b(t) = Σ c_k t^k, and the conversion matrix.
    Power {
        /// The curve(s) and output form.
        #[command(flatten)]
        curve: CurveArgs,
    },
    /// The de Casteljau scheme: every b_i^r(t).
    Triangle {
        /// The parameter.
        #[arg(long = "t", allow_hyphen_values = true)]
        t: String,
        /// The curve(s) and output form.
        #[command(flatten)]
        curve: CurveArgs,
    },
    /// The k-th derivative curve (hodograph for k = 1).
    Derivative {
        /// The order k.
        #[arg(long, default_value_t = 1)]
        order: usize,
        /// The curve(s) and output form.
        #[command(flatten)]
        curve: CurveArgs,
    },
    /// Exact degree reduction: the true degree and the control points of that degree.
    Reduce {
        /// The curve(s) and output form.
        #[command(flatten)]
        curve: CurveArgs,
    },
    /// Every segment of fonts (.ttf .otf .ttc .otc), SVG files (.svg), SVG path data (--path)
    /// or text batches (other files), exactly: one JSON line per segment with its provenance,
    /// control points, classification and flags; a summary per file on stderr.
    Scan(ScanArgs),
    /// Outline QA decided exactly, for fonts (.ttf .otf .ttc .otc), SVG files (.svg) and SVG path
    /// data (--path): per glyph (element), findings of each kind (direction, self_intersection,
    /// overlap, touching, overlapping_segments, missing_extremum, kink, collinear_points,
    /// zero_length_segment, zero_length_handle, degenerate_curve, cusp, loop, bbox) with exact
    /// evidence; text (one line per finding, a summary per file) or --json (one line per
    /// finding); exit 1 when a denied kind is found, 2 for unreadable input and for a file in
    /// which nothing could be checked (every element skipped: nothing checked is not a pass).
    Lint(LintArgs),
    /// Check a float library's answers (JSON Lines: node type, category, loop, cusp,
    /// inflections, parameters, double point) against the exact ones: every disagreement with
    /// the exact and float values and the curve; exit 1 when there is any.
    Check(CheckArgs),
    /// Classify planar curves of degree ≤ 3 exactly: node type, double point, parameters,
    /// segment features on [0,1].
    Classify {
        /// Also print f64 approximations of the exact parameters.
        #[arg(long)]
        float: bool,
        /// `basic` (default): class, node type, double point, exact parameters, segment
        /// features. `full` adds the evidence of cubics: the seed's moving lines with their
        /// proof `P·L ≡ 0`, the proved canonical map and the Loop–Blinn cross-check (slow).
        #[arg(long, value_enum, default_value_t = Detail::Basic)]
        detail: Detail,
        /// A rational cubic (classified projectively).
        #[command(flatten)]
        rational: RationalArgs,
        /// The curve(s) and output form.
        #[command(flatten)]
        curve: CurveArgs,
    },
    /// Remove overlaps from a static TrueType or CFF font and write it: each glyph's region
    /// decided exactly, rounded to the grid and certified; other glyphs stay byte-identical.
    RemoveOverlaps(crate::remove_overlaps::RemoveOverlapsArgs),
    /// Prove or refute that a (rational) curve lies on f = 0: exit 0 proved, 1 counterexample.
    Implicit {
        /// The polynomial f in x, y (and z), e.g. "x^3 - 3*x*y + y^3".
        #[arg(long, allow_hyphen_values = true)]
        poly: String,
        /// Rational curves.
        #[command(flatten)]
        rational: RationalArgs,
        /// The curve(s) and output form.
        #[command(flatten)]
        curve: CurveArgs,
    },
    /// Is the rational curve defined on [a, b] (default [0, 1])? Exact root isolation of the
    /// denominator Σ w_i B_i(t): exit 0 defined, 1 with isolating intervals of its roots.
    Defined {
        /// Start of the interval.
        #[arg(long, default_value = "0", allow_hyphen_values = true)]
        from: String,
        /// End of the interval.
        #[arg(long, default_value = "1", allow_hyphen_values = true)]
        to: String,
        /// Rational curves.
        #[command(flatten)]
        rational: RationalArgs,
        /// The curve(s) and output form.
        #[command(flatten)]
        curve: CurveArgs,
    },
    /// Exact intersections of two curves (or --self: of one curve with itself): parameter pairs
    /// as exact algebraic numbers, the point, transversal or tangent with the contact order,
    /// and shared arcs (overlaps).
    Intersect(IntersectArgs),
    /// The exact winding number of a closed path around a point (or where the point lies on
    /// the path): segments separated by ';', or SVG path data with --svg.
    Winding(WindingArgs),
    /// Boolean operations on filled shapes, exactly: union, intersection, difference, xor, or
    /// simplify (one shape's filled region, overlaps removed). Operands are SVG path data or
    /// .svg files; `simplify` also takes fonts (every glyph, one JSON line each). Prints the
    /// result's SVG path data, or with --json the exact result (contours, pieces, area, ...).
    #[command(after_help = BOOLEAN_HELP)]
    Boolean(BooleanArgs),
    /// The exact arrangement of shapes (SVG path data or .svg files): its vertices, edges (with
    /// each input's winding number on both sides) and faces; --locate finds where points lie.
    Arrange(ArrangeArgs),
    /// The exact bounding box on [0,1] and the stationary points of each coordinate (roots of
    /// x'(t), y'(t); rational curves too), as exact algebraic numbers.
    Bbox {
        /// Rational curves.
        #[command(flatten)]
        rational: RationalArgs,
        /// The curve(s) and output form.
        #[command(flatten)]
        curve: CurveArgs,
    },
    /// The conic of a rational quadratic: ellipse, parabola, hyperbola (from w1² − w0·w2).
    Conic {
        /// Rational curves.
        #[command(flatten)]
        rational: RationalArgs,
        /// The curve(s) and output form.
        #[command(flatten)]
        curve: CurveArgs,
    },
    /// Rational tensor-product Bézier patches: points row-major, (m+1)(n+1) of them.
    Surface {
        /// What to do with the patch.
        #[command(subcommand)]
        op: SurfaceOp,
    },
    /// Rational splines (knot vectors with multiplicities, or the seed's scale ratios): Bézier
    /// segments with proved joins, evaluation, knot insertion and removal, degree elevation,
    /// NURBS surfaces.
    #[command(after_help = KNOT_HELP)]
    Spline {
        /// What to do with the spline.
        #[command(subcommand)]
        op: SplineOp,
    },
    /// Draw curves as standalone SVG (to stdout or -o FILE); every curve of a batch in one figure.
    Plot(PlotArgs),
    /// Write the seed figures that can be reproduced (SVG) and an index.html into DIR.
    Gallery {
        /// The folder.
        dir: std::path::PathBuf,
    },
    /// Check the claim catalogue (default proofs/): one line per claim, exit 0 iff every
    /// verdict is as expected, 1 otherwise, 2 on malformed claim files.
    Prove(ProveArgs),
}

/// Patch operations.
#[derive(Subcommand, Debug)]
pub enum SurfaceOp {
    /// S(u, v): the closed form (41), checked against de Casteljau u-then-v and v-then-u.
    Eval {
        /// Parameter u.
        #[arg(long, allow_hyphen_values = true)]
        u: String,
        /// Parameter v.
        #[arg(long, allow_hyphen_values = true)]
        v: String,
        /// The patch.
        #[command(flatten)]
        patch: PatchArgs,
    },
    /// Split at u = U (or v = V).
    Subdivide {
        /// Split in u here.
        #[arg(long, allow_hyphen_values = true)]
        u: Option<String>,
        /// Split in v here.
        #[arg(long, allow_hyphen_values = true)]
        v: Option<String>,
        /// The patch.
        #[command(flatten)]
        patch: PatchArgs,
    },
    /// Degree elevation in u and v.
    Elevate {
        /// Degrees added in u.
        #[arg(long, default_value_t = 0)]
        u_by: usize,
        /// Degrees added in v.
        #[arg(long, default_value_t = 0)]
        v_by: usize,
        /// The patch.
        #[command(flatten)]
        patch: PatchArgs,
    },
    /// The contour z = C as an exact implicit polynomial in (u, v), and a sampled polyline.
    Contour {
        /// The height C.
        #[arg(long, allow_hyphen_values = true)]
        z: String,
        /// Sample the contour on an N×N grid (f64 segments, for plots).
        #[arg(long, default_value_t = 0)]
        polyline: usize,
        /// The patch.
        #[command(flatten)]
        patch: PatchArgs,
    },
}

/// A patch given as a curve line of (m+1)(n+1) points.
#[derive(Args, Debug)]
pub struct PatchArgs {
    /// Degrees "m,n" (rows along u, columns along v).
    #[arg(long)]
    pub degree: String,
    /// Weights, row-major (default all 1).
    #[command(flatten)]
    pub rational: RationalArgs,
    /// The control net, row-major, and output form (3D by default).
    #[command(flatten)]
    pub curve: CurveArgs,
}

/// How much `classify` computes.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Detail {
    /// What users decide with: exact classification and parameters.
    Basic,
    /// Also the moving lines, the proved canonical map and the Loop–Blinn cross-check.
    Full,
}

/// How `--knots` and `--ratios` describe a spline (shown by `spline --help`).
pub const KNOT_HELP: &str = "\
KNOTS: a degree-n spline with control points P_0..P_m takes the standard knot vector of
m + n + 2 non-decreasing exact numbers (--knots \"0 0 0 0 1 2 3 3 3 3\": clamped cubic, 6 points),
its domain is [t_n, t_(m+1)]; interior knots may repeat up to n + 1 times (multiplicity mu gives
C^(n-mu) there). The first and the last knot never influence the curve.
RATIOS (the seed's form): --ratios \"l_0 .. l_(m+n-1)\" are the knot intervals, all > 0: the knots
are t_0 = 0, t_(j+1) = t_j + l_j, i.e. the knot vector without its last knot.
BATCH: one spline per line, either a control polygon (with --knots/--ratios/--weights for all
lines) or a JSON object {\"degree\":3,\"knots\":[...],\"weights\":[...],\"points\":[[x,y],...]} with
exact numbers as JSON numbers or strings (\"1/3\"); \"ratios\" instead of \"knots\", and
\"homogeneous\": true for points given as [w*x, w*y, w] (w = 0: at infinity).";

/// Spline operations.
#[derive(Subcommand, Debug)]
pub enum SplineOp {
    /// The rational Bézier segments of the spline, with their weights and the continuity at
    /// each join (C^(n-mu), proved).
    ToBezier {
        /// `boehm` (knot insertion, any degree and knot vector), `seed` (the seed's rational
        /// interpolation formulas: cubic (25)-(29), quadratic (53) corrected; positive ratios
        /// only) or `seed-printed` ((53) as printed).
        #[arg(long, value_enum, default_value_t = Method::Boehm)]
        method: Method,
        /// The spline.
        #[command(flatten)]
        spline: SplineArgs,
    },
    /// Prove the segments: equal to the NURBS on each span, each join C^(n-mu), seed = Boehm.
    Check {
        /// The spline.
        #[command(flatten)]
        spline: SplineArgs,
    },
    /// Evaluate by de Boor's recursion at parameters of the domain (knots included).
    Eval {
        /// Parameter values (repeatable).
        #[arg(long = "u", required = true, allow_hyphen_values = true)]
        u: Vec<String>,
        /// The spline.
        #[command(flatten)]
        spline: SplineArgs,
    },
    /// Insert a knot (Boehm): the same curve with more control points.
    Insert {
        /// Which knot, how often.
        #[command(flatten)]
        knot: KnotArgs,
        /// The spline.
        #[command(flatten)]
        spline: SplineArgs,
    },
    /// Remove an interior knot exactly, only when the curve stays the same (exit 1 otherwise).
    Remove {
        /// Which knot, how often.
        #[command(flatten)]
        knot: KnotArgs,
        /// The spline.
        #[command(flatten)]
        spline: SplineArgs,
    },
    /// Degree elevation: the same curve one degree higher (clamped at the domain ends).
    Elevate {
        /// The spline.
        #[command(flatten)]
        spline: SplineArgs,
    },
    /// A tensor-product NURBS surface → rational Bézier patches, proved equal to the surface
    /// with each join's continuity.
    Surface {
        /// Degrees "p,q" (rows along u, columns along v).
        #[arg(long)]
        degree: String,
        /// Knot vector in u (m + p + 2 knots for m + 1 rows).
        #[arg(long, allow_hyphen_values = true)]
        knots_u: String,
        /// Knot vector in v (l + q + 2 knots for l + 1 columns).
        #[arg(long, allow_hyphen_values = true)]
        knots_v: String,
        /// Weights, row-major (default all 1), or --homogeneous.
        #[command(flatten)]
        rational: RationalArgs,
        /// The control net, row-major, (m+1)(l+1) points (3D by default), and output form.
        #[command(flatten)]
        curve: CurveArgs,
    },
}

/// How `spline to-bezier` converts (a closed set: clap refuses anything else before work starts).
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// Boehm knot insertion (any degree and knot vector).
    Boehm,
    /// The seed's rational interpolation formulas, (53) corrected.
    Seed,
    /// The seed's formulas with (53) as printed.
    SeedPrinted,
}

impl From<Method> for casteljau::spline::Conversion {
    fn from(m: Method) -> Self {
        use casteljau::proof::Reading;
        match m {
            Method::Boehm => casteljau::spline::Conversion::Boehm,
            Method::Seed => casteljau::spline::Conversion::Seed(Reading::Corrected),
            Method::SeedPrinted => casteljau::spline::Conversion::Seed(Reading::AsPrinted),
        }
    }
}

/// A kind of segment `scan --only` keeps (a closed set: clap refuses anything else).
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum OnlyKind {
    /// A cusp on [0, 1].
    Cusp,
    /// A loop on [0, 1].
    Loop,
    /// An inflection on [0, 1].
    Inflection,
    /// Real degree below the written degree.
    Degenerate,
    /// A control point on its end point.
    #[value(name = "zero_length_handle")]
    ZeroLengthHandle,
    /// A cusp, loop or inflection exactly at t = 0 or 1.
    Endpoint,
    /// A piece that is not a polynomial Bézier curve.
    Skipped,
    /// A piece that could not be read.
    Error,
}

/// A knot to insert or remove, and how many times.
#[derive(Args, Debug)]
pub struct KnotArgs {
    /// The knot.
    #[arg(long, allow_hyphen_values = true)]
    pub knot: String,
    /// How many times.
    #[arg(long, default_value_t = 1)]
    pub times: usize,
}

/// A rational spline: its degree, knots (or the seed's scale ratios) and weights.
#[derive(Args, Debug)]
pub struct SplineArgs {
    /// The degree n.
    #[arg(long, default_value_t = 3)]
    pub degree: usize,
    /// The knot vector: m + n + 2 non-decreasing exact numbers for m + 1 control points.
    #[arg(long, allow_hyphen_values = true, conflicts_with = "ratios")]
    pub knots: Option<String>,
    /// Scale ratios (knot intervals, > 0): m + n of them for m + 1 control points; the knots
    /// are their partial sums from 0 (the knot vector without its last knot).
    #[arg(long, allow_hyphen_values = true)]
    pub ratios: Option<String>,
    /// Weights (default all 1), or --homogeneous.
    #[command(flatten)]
    pub rational: RationalArgs,
    /// The control polygon (or JSON Lines splines), and output form.
    #[command(flatten)]
    pub curve: CurveArgs,
}

/// `plot`: what to draw and where.
#[derive(Args, Debug)]
pub struct PlotArgs {
    /// Draw and label the control polygon.
    #[arg(long)]
    pub polygon: bool,
    /// Overlay the de Casteljau construction at this parameter.
    #[arg(long, allow_hyphen_values = true)]
    pub construction: Option<String>,
    /// Overlay repeated subdivision at this parameter (with --depth).
    #[arg(long = "subdivide", allow_hyphen_values = true)]
    pub subdivide_at: Option<String>,
    /// Depth of --subdivide.
    #[arg(long, default_value_t = 1)]
    pub depth: u32,
    /// Mark classification features (double point, cusp, inflections, loop, E, canonical frame).
    #[arg(long)]
    pub features: bool,
    /// A family of curves varying one weight, e.g. "w1=1,3,4" (needs --weights for the rest).
    #[arg(long)]
    pub weights_family: Option<String>,
    /// Grid lines at integer coordinates.
    #[arg(long)]
    pub grid: bool,
    /// A title.
    #[arg(long)]
    pub title: Option<String>,
    /// Image width in pixels.
    #[arg(long, default_value_t = 480)]
    pub width: u32,
    /// Write the SVG here instead of stdout.
    #[arg(long, short)]
    pub output: Option<std::path::PathBuf>,
    /// Rational curves.
    #[command(flatten)]
    pub rational: RationalArgs,
    /// The curve(s).
    #[command(flatten)]
    pub curve: CurveArgs,
}

/// `prove`: which claims, and where the reports go.
#[derive(Args, Debug)]
pub struct ProveArgs {
    /// Claim files or folders (default: proofs/).
    pub paths: Vec<std::path::PathBuf>,
    /// Only claims whose id contains this text.
    #[arg(long)]
    pub filter: Option<String>,
    /// One JSON object per claim.
    #[arg(long)]
    pub json: bool,
    /// Also write a JUnit XML report to this file.
    #[arg(long)]
    pub junit: Option<std::path::PathBuf>,
    /// Regenerate the catalogue's README (default proofs/README.md) from this run.
    #[arg(long, num_args = 0..=1, default_missing_value = "proofs/README.md")]
    pub write_readme: Option<std::path::PathBuf>,
    /// Threads checking claims (0: all cores; never more than the cores or the claims); the
    /// report keeps the catalogue's order.
    #[arg(long, default_value_t = 0)]
    pub threads: usize,
    /// No progress line on a terminal.
    #[arg(long, short)]
    pub quiet: bool,
    /// Work budget per claim, in work units (about 1 ns each on a 2-core machine of 2026): a
    /// claim whose expressions need more evaluation steps is reported as malformed (exit 2).
    #[arg(long, default_value_t = casteljau::work::DEFAULT_MAX_WORK, value_parser = parse_work)]
    pub max_work: f64,
}

impl CurveArgs {
    /// The `--max-work` budget.
    pub fn budget(&self) -> casteljau::work::Budget {
        casteljau::work::Budget::new(self.max_work, "--max-work")
    }
}

/// Weights of a rational curve (for eval, subdivide, elevate, implicit, conic, classify).
#[derive(Args, Debug, Clone)]
pub struct RationalArgs {
    /// Weights w0..wn (exact numbers, one per control point): a rational curve.
    #[arg(long, allow_hyphen_values = true)]
    pub weights: Option<String>,
    /// Read control points as homogeneous "w·x w·y w" (w = 0: a point at infinity, a direction).
    #[arg(long)]
    pub homogeneous: bool,
}

/// Where the curves come from, and the output form.
#[derive(Args, Debug)]
pub struct CurveArgs {
    /// One curve, e.g. "0 0, 1 2, 2 0". Omit to read --input or stdin.
    #[arg(allow_hyphen_values = true)]
    pub curve: Option<String>,
    /// A batch file, one curve per line ('-' for stdin).
    #[arg(long, short)]
    pub input: Option<String>,
    /// Dimension of the control points (2 or 3; any ≥ 1 works).
    #[arg(long, default_value_t = 2)]
    pub dim: usize,
    /// JSON Lines output with exact strings.
    #[arg(long)]
    pub json: bool,
    /// Threads answering a batch (0: all cores; never more than the cores, one for a single
    /// curve). Output stays in input order.
    #[arg(long, default_value_t = 0)]
    pub threads: usize,
    /// No progress line on a terminal.
    #[arg(long, short)]
    pub quiet: bool,
    /// Work budget per curve, in work units (about 1 ns each on a 2-core machine of 2026): an
    /// answer whose estimated cost exceeds it is refused (exit 2) before any work starts.
    #[arg(long, default_value_t = casteljau::work::DEFAULT_MAX_WORK, value_parser = parse_work)]
    pub max_work: f64,
    /// How the numbers of the control points, --weights and --t/--from/--to are read: `exact`
    /// (0.1 is 1/10) or `binary64` (every number is the f64 nearest to it, taken exactly, as
    /// your float code holds it: 0.1 is 3602879701896397/2^55). Hex floats (0x1.8p-3) are
    /// exact binary values in both modes.
    #[arg(long, value_enum, default_value_t = Numbers::Exact)]
    pub numbers: Numbers,
}

/// `--numbers`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Numbers {
    /// Every number is the exact rational it spells.
    Exact,
    /// Every number is the nearest IEEE-754 binary64 value (ties to even), taken exactly.
    Binary64,
}

impl From<Numbers> for casteljau::num::NumberMode {
    fn from(n: Numbers) -> Self {
        match n {
            Numbers::Exact => casteljau::num::NumberMode::Exact,
            Numbers::Binary64 => casteljau::num::NumberMode::Binary64,
        }
    }
}

/// `casteljau scan`.
#[derive(Args, Debug)]
pub struct ScanArgs {
    /// Font files (.ttf, .otf, .ttc, .otc), SVG files (.svg) or text batches (one curve per line).
    pub files: Vec<String>,
    /// SVG path data to scan, e.g. "M0 0 C1 2 3 2 4 0 Z" (reported as file "<path>").
    #[arg(long, allow_hyphen_values = true)]
    pub path: Option<String>,
    /// Only segments of these kinds (comma-separated): cusp, loop, inflection (on [0,1]),
    /// degenerate, zero_length_handle, endpoint (a cusp, loop or inflection exactly at t = 0 or 1),
    /// skipped, error.
    #[arg(long, value_enum, value_delimiter = ',')]
    pub only: Vec<OnlyKind>,
    /// How SVG and text numbers are read: `exact` (0.1 is 1/10) or `binary64` (the f64 nearest
    /// to it, exactly). Font coordinates are always the font's exact values.
    #[arg(long, value_enum, default_value_t = Numbers::Exact)]
    pub numbers: Numbers,
    /// Threads (0: all cores; never more than the cores). Output stays in file order.
    #[arg(long, default_value_t = 0)]
    pub threads: usize,
    /// Work budget of reading an SVG file, in work units (about 1 ns each): the exact products
    /// of its transforms and the copies of its <use> elements are charged before they are
    /// computed; over it, the file is refused (exit 2).
    #[arg(long, default_value_t = casteljau::work::DEFAULT_MAX_WORK, value_parser = parse_work)]
    pub max_work: f64,
    /// An instance of a variable CFF2 font, in user coordinates: "wght=700,wdth=80" (other axes
    /// at their defaults; coordinates are the format's exact 16.16 blend). glyf instances are
    /// refused (their deltas are applied in f32 by every font crate).
    #[arg(long)]
    pub variation: Option<String>,
    /// No summary and no progress on stderr.
    #[arg(long, short)]
    pub quiet: bool,
    /// Accepted and ignored: scan always writes JSON Lines (the flag every other JSON-writing
    /// command takes, so scripts may pass it to all of them).
    #[arg(long)]
    pub json: bool,
}

/// `casteljau lint`.
#[derive(Args, Debug)]
pub struct LintArgs {
    /// Font files (.ttf .otf .ttc .otc) and SVG files (.svg).
    pub files: Vec<String>,
    /// SVG path data to check, e.g. "M0 0 H10 V10 Z" (reported as file "<path>").
    #[arg(long, allow_hyphen_values = true)]
    pub path: Option<String>,
    /// One JSON object per finding and line (the summary goes to stderr).
    #[arg(long)]
    pub json: bool,
    /// Also write a self-contained HTML report (summary tables, every flagged glyph drawn).
    #[arg(long)]
    pub html: Option<std::path::PathBuf>,
    /// Only these kinds (comma-separated).
    #[arg(long, value_delimiter = ',', value_parser = parse_kind)]
    pub only: Vec<casteljau::lint::Kind>,
    /// Not these kinds (comma-separated).
    #[arg(long, value_delimiter = ',', value_parser = parse_kind)]
    pub ignore: Vec<casteljau::lint::Kind>,
    /// The kinds that fail the run (exit 1), comma-separated, or "none"; findings explained by
    /// rounding never fail it. Default: direction, self_intersection, overlapping_segments,
    /// zero_length_segment.
    #[arg(long, value_delimiter = ',')]
    pub deny: Option<Vec<String>>,
    /// The orientation of outer contours (holes the other way), in the file's own coordinates
    /// (ccw: positive signed area). Default: cw for TrueType glyf fonts, ccw for CFF, CFF2, SVG
    /// and path data.
    #[arg(long, value_enum)]
    pub direction: Option<OrientationArg>,
    /// The kink angle in degrees (0 < angle < 90): a node whose tangents turn by less than this,
    /// but not by zero, is a kink (decided exactly against the binary64 value of its tangent).
    #[arg(long, default_value_t = 10.0)]
    pub kink_angle: f64,
    /// Ignore missing extrema that reach less than this many units beyond the segment's end
    /// points (an exact number, compared exactly).
    #[arg(long, allow_hyphen_values = true)]
    pub extremum_min: Option<String>,
    /// Fonts: only these glyphs (names, comma-separated); an unknown name is an error.
    #[arg(long, value_delimiter = ',')]
    pub glyphs: Vec<String>,
    /// An instance of a variable CFF2 font, in user coordinates: "wght=700,wdth=80".
    #[arg(long)]
    pub variation: Option<String>,
    /// How SVG numbers are read: `exact` (0.1 is 1/10) or `binary64`.
    #[arg(long, value_enum, default_value_t = Numbers::Exact)]
    pub numbers: Numbers,
    /// Work budget per glyph, in work units (about 1 ns each): a glyph whose arrangement is
    /// estimated to cost more is refused (an error line, exit 2) before it starts. Reading an SVG
    /// file (the exact products of its transforms, the copies of its <use> elements) is charged
    /// against it as a whole.
    #[arg(long, default_value_t = casteljau::work::DEFAULT_MAX_WORK, value_parser = parse_work)]
    pub max_work: f64,
    /// Threads (0: all cores; never more than the cores, one for --path). Output stays in glyph
    /// order.
    #[arg(long, default_value_t = 0)]
    pub threads: usize,
    /// No summary and no progress on stderr (text mode keeps its summary on stdout).
    #[arg(long, short)]
    pub quiet: bool,
}

fn parse_kind(s: &str) -> Result<casteljau::lint::Kind, String> {
    s.trim().parse().map_err(|e: casteljau::Error| e.to_string())
}

/// `casteljau check`.
#[derive(Args, Debug)]
pub struct CheckArgs {
    /// The float library's answers, one JSON object per curve (fields: node_type, category,
    /// loop, cusp, inflections, inflection_parameters, cusp_parameters,
    /// self_intersection_parameters, double_point; optional points and line).
    #[arg(long)]
    pub against: String,
    /// The curves, one per line (the batch format); optional when every answer has "points".
    pub curves: Option<String>,
    /// Absolute tolerance on parameters t: a float parameter agrees with an exact one within it.
    #[arg(long, default_value_t = 1e-9)]
    pub tol: f64,
    /// Absolute tolerance on each coordinate of the double point.
    #[arg(long, default_value_t = 1e-9)]
    pub point_tol: f64,
    /// How CURVES and string coordinates are read (`exact` or `binary64`); JSON number
    /// coordinates are always the f64 they denote.
    #[arg(long, value_enum, default_value_t = Numbers::Exact)]
    pub numbers: Numbers,
    /// JSON Lines output (one object per disagreement).
    #[arg(long)]
    pub json: bool,
    /// No summary on stderr.
    #[arg(long, short)]
    pub quiet: bool,
}

/// `casteljau intersect`.
#[derive(Args, Debug)]
pub struct IntersectArgs {
    /// The first curve, e.g. "0 0, 1 2, 2 0".
    #[arg(allow_hyphen_values = true)]
    pub a: Option<String>,
    /// The second curve (omit with --self).
    #[arg(allow_hyphen_values = true)]
    pub b: Option<String>,
    /// Self-intersections of one curve (pairs s < t).
    #[arg(long = "self")]
    pub self_intersection: bool,
    /// Every real parameter, not only [0, 1] (`--domain all`).
    #[arg(long = "all")]
    pub all: bool,
    /// Weights of the first curve (a rational curve).
    #[arg(long, allow_hyphen_values = true)]
    pub weights_a: Option<String>,
    /// Also draw the pair with its intersections, tangencies and overlaps into this SVG file.
    #[arg(long)]
    pub plot: Option<std::path::PathBuf>,
    /// Work budget per pair, in work units (about 1 ns each): a pair whose estimated cost exceeds
    /// it is refused (exit 2) before any work starts.
    #[arg(long, default_value_t = casteljau::work::DEFAULT_MAX_WORK, value_parser = parse_work)]
    pub max_work: f64,
    /// Weights of the second curve.
    #[arg(long, allow_hyphen_values = true)]
    pub weights_b: Option<String>,
    /// Batch input ("A ; B" per line, one curve with --self), output form, threads, numbers.
    #[command(flatten)]
    pub batch: BatchOptions,
}

/// The batch options of commands whose lines are not single curves (`intersect`, `winding`).
#[derive(Args, Debug)]
pub struct BatchOptions {
    /// A batch file, one question per line ('-' for stdin).
    #[arg(long, short)]
    pub input: Option<String>,
    /// JSON Lines output with exact strings.
    #[arg(long)]
    pub json: bool,
    /// Threads answering a batch (0: all cores; never more than the cores).
    #[arg(long, default_value_t = 0)]
    pub threads: usize,
    /// No progress line on a terminal.
    #[arg(long, short)]
    pub quiet: bool,
    /// How numbers are read: `exact` or `binary64` (as for the other commands).
    #[arg(long, value_enum, default_value_t = Numbers::Exact)]
    pub numbers: Numbers,
}

impl BatchOptions {
    /// The batch reader's arguments, with `line` as the single question (or `--input`).
    pub fn curve_args(&self, line: Option<String>) -> CurveArgs {
        CurveArgs {
            curve: line,
            input: self.input.clone(),
            dim: 2,
            json: self.json,
            threads: self.threads,
            quiet: self.quiet,
            max_work: casteljau::work::DEFAULT_MAX_WORK,
            numbers: self.numbers,
        }
    }
}

/// `casteljau winding`.
#[derive(Args, Debug)]
pub struct WindingArgs {
    /// The query point "x y".
    #[arg(long, allow_hyphen_values = true)]
    pub point: String,
    /// The closed path: segments separated by ';' ("0 0, 1 2, 2 0 ; 2 0, 0 0"), or SVG path data
    /// with --svg. Omit to read --input (one path per line).
    #[arg(allow_hyphen_values = true)]
    pub path: Option<String>,
    /// The path is SVG path data ("M0 0 Q1 2 2 0 Z"); every subpath is closed as SVG fills it and
    /// the windings add up.
    #[arg(long)]
    pub svg: bool,
    /// Work budget per path, in work units (about 1 ns each): a path whose estimated cost exceeds
    /// it is refused (exit 2) before any work starts.
    #[arg(long, default_value_t = casteljau::work::DEFAULT_MAX_WORK, value_parser = parse_work)]
    pub max_work: f64,
    /// Batch input (one path per line), output form, threads, numbers.
    #[command(flatten)]
    pub batch: BatchOptions,
}

/// `boolean --help`: operands, output, conventions and exit codes.
pub const BOOLEAN_HELP: &str = "\
OPERANDS: SVG path data (\"M0 0 H2 V2 H0 Z\"; an open subpath is closed by a line, as SVG fills it)
or an .svg file (every shape of the document, transforms applied, all contours as one shape;
elliptical arcs, circles and ellipses are refused naming the element). An empty operand is the
empty shape. union, intersection, difference and xor take A B; simplify takes A, or font files
(.ttf .otf .ttc .otc): every glyph (or --glyphs), one answer per glyph in glyph order.
BATCH: --input FILE holds one question per line, \"A ; B\" (A alone for simplify).
OUTPUT: the result's SVG path data, one line per answer (an empty result is an empty line);
--json: op, fill, then the exact result's fields: contours, path, area (exact, or null when
irrational), area_float, parents, orientation, pieces (per contour, the input pieces: input,
contour, segment, exact parameters from/to). Fonts add file, glyph, glyph_id, contours_before,
changed. Outer contours run counter-clockwise (holes clockwise) unless --direction cw; fonts
default to their own convention (cw for TrueType glyf outlines, ccw for CFF).
--against RESULT: a float library's result, decided against the exact one (contour count and
nesting, a witness point farther than --tol from the exact boundary, a boundary distance bound):
\"agree\" or \"disagree: ...\" per question, with --json a \"verdict\" object; exit 1 on any
disagreement.
EXIT CODES: 0 ok; 1 a result disagrees (--against); 2 bad input, an unknown glyph, a glyph that
could not be answered, or a question over --max-work.";

/// A boolean operation (a closed set: clap refuses anything else).
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Operation {
    /// A ∪ B.
    Union,
    /// A ∩ B.
    Intersection,
    /// A − B.
    Difference,
    /// A △ B (in exactly one of them).
    Xor,
    /// The filled region of A alone, overlaps removed.
    Simplify,
}

impl From<Operation> for casteljau::shape::BooleanOp {
    fn from(o: Operation) -> Self {
        use casteljau::shape::BooleanOp;
        match o {
            Operation::Union => BooleanOp::Union,
            Operation::Intersection => BooleanOp::Intersection,
            Operation::Difference => BooleanOp::Difference,
            Operation::Xor => BooleanOp::Xor,
            Operation::Simplify => BooleanOp::Simplify,
        }
    }
}

/// `--fill`.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fill {
    /// Inside where the winding number is not 0 (SVG's and the fonts' default).
    Nonzero,
    /// Inside where the winding number is odd.
    Evenodd,
}

impl From<Fill> for casteljau::path::FillRule {
    fn from(f: Fill) -> Self {
        match f {
            Fill::Nonzero => casteljau::path::FillRule::NonZero,
            Fill::Evenodd => casteljau::path::FillRule::EvenOdd,
        }
    }
}

/// `--direction`.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum OrientationArg {
    /// Outer contours counter-clockwise, holes clockwise (SVG, CFF).
    Ccw,
    /// Outer contours clockwise, holes counter-clockwise (TrueType).
    Cw,
}

impl From<OrientationArg> for casteljau::shape::Orientation {
    fn from(o: OrientationArg) -> Self {
        match o {
            OrientationArg::Ccw => casteljau::shape::Orientation::Ccw,
            OrientationArg::Cw => casteljau::shape::Orientation::Cw,
        }
    }
}

/// `casteljau boolean`.
#[derive(Args, Debug)]
pub struct BooleanArgs {
    /// The operation.
    #[arg(value_enum)]
    pub op: Operation,
    /// The operands: SVG path data or .svg files (A B; A alone for simplify), or with simplify
    /// font files (.ttf .otf .ttc .otc). Omit to read --input.
    pub operands: Vec<String>,
    /// The fill rule of every input (and of an --against result).
    #[arg(long, value_enum, default_value_t = Fill::Nonzero)]
    pub fill: Fill,
    /// The orientation of the result's outer contours (holes run the other way). Default: ccw,
    /// and for fonts the font's convention (cw for TrueType glyf outlines, ccw for CFF).
    #[arg(long, value_enum)]
    pub direction: Option<OrientationArg>,
    /// Fonts: only these glyphs (names, comma-separated); an unknown name is an error.
    #[arg(long, value_delimiter = ',')]
    pub glyphs: Vec<String>,
    /// A float library's result to decide against the exact one: SVG path data, or a file (one
    /// question: its first line that is not a '#' comment; --input: one path per question line,
    /// '#' lines skipped, an empty line is the empty result; fonts: JSON Lines with "glyph" (the
    /// name) or "glyph_id", and "path" or "error", optionally "file").
    #[arg(long)]
    pub against: Option<String>,
    /// The tolerance of --against, an exact number in the inputs' coordinate units (font units
    /// for fonts): a witness point must be farther than it from the exact boundary, and the
    /// boundaries at most this far apart.
    #[arg(long, default_value = "1/1000")]
    pub tol: String,
    /// Also draw the inputs, the result and the arrangement's vertices into this SVG file (one
    /// question only).
    #[arg(long)]
    pub plot: Option<std::path::PathBuf>,
    /// Work budget per question (per glyph for fonts), in work units (about 1 ns each): a
    /// question whose arrangement is estimated to cost more is refused (exit 2) before it starts.
    #[arg(long, default_value_t = casteljau::work::DEFAULT_MAX_WORK, value_parser = parse_work)]
    pub max_work: f64,
    /// Batch input ("A ; B" per line, A alone for simplify), output form, threads, numbers.
    #[command(flatten)]
    pub batch: BatchOptions,
}

/// `casteljau arrange`.
#[derive(Args, Debug)]
pub struct ArrangeArgs {
    /// The shapes: SVG path data or .svg files (input 0, 1, ... in this order).
    #[arg(required = true)]
    pub shapes: Vec<String>,
    /// Where a point "x y" lies: a vertex, an edge (with the parameter) or a face (with each
    /// input's winding number there). Repeatable.
    #[arg(long, allow_hyphen_values = true)]
    pub locate: Vec<String>,
    /// The whole arrangement as JSON (vertices, edges, faces, locations); without it, a summary.
    #[arg(long)]
    pub json: bool,
    /// Work budget, in work units (about 1 ns each): an arrangement estimated to cost more is
    /// refused (exit 2) before it starts.
    #[arg(long, default_value_t = casteljau::work::DEFAULT_MAX_WORK, value_parser = parse_work)]
    pub max_work: f64,
    /// How numbers are read: `exact` (0.1 is 1/10) or `binary64` (the f64 nearest to it).
    #[arg(long, value_enum, default_value_t = Numbers::Exact)]
    pub numbers: Numbers,
}
