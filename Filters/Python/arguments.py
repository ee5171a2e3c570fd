"""consistent-remesh's command line: the parser, the options a collection
fills in, and the checks that make a wrong command a usage error (exit
status 2) before any work is done."""

import argparse
import math
import os

from . import collection
from . import render
from .stages import BLEND_ALIGNMENTS


DEFAULT_LEVEL = 4
# The remesh levels, 0 to cmp::kMaximumRemeshLevel (SemiRegularRemesher.h), as the
# filters and the plugin take them: a level outside is a usage error, never clamped.
MAX_LEVEL = 8
MAX_SAMPLE_RELAXATION = 32  # the plugin's range; more rounds gain nothing measurable
# The command remeshes the whole collection in one run, so the relaxed
# locations are the collection's own (the filter's default stays 0: remeshers
# run one model at a time would each move them their own way).
DEFAULT_SAMPLE_RELAXATION = 4
WEIGHT_SUM_TOLERANCE = 1e-9  # vtkCMPShapeBlend's
# How long one model's child process (its reading, or its tracing and
# straightening) may run before it is killed and the model fails: an hour,
# far above the minutes the largest models here take on 2 busy cores, so
# that only a hang reaches it.
DEFAULT_MODEL_TIMEOUT = 3600.0


def parse_arguments(argv):
    parser = argparse.ArgumentParser(
        prog="consistent-remesh",
        description="Consistent mesh parameterizations (Praun, Sweldens, Schroeder 2001) of a collection of "
        "landmarked genus-0 surfaces.",
    )
    parser.add_argument("--mesh", action="append", default=[], help="surface file (.off .obj .ply .stl .vtp); repeat")
    parser.add_argument(
        "--landmarks", action="append", default=[], help="landmark file of the preceding --mesh (.vts .pinned .csv)"
    )
    source = parser.add_mutually_exclusive_group()
    source.add_argument("--base-domain", help="base domain L0 (.vtp with FeatureId, or .obj/.off: vertex i = landmark i)")
    source.add_argument("--base-domain-from", type=int, metavar="N",
                        help="build L0 from the N-th model (0-based; the first one with every landmark if it "
                             "misses some)")
    parser.add_argument("--collection", metavar="FOLDER",
                        help="run the collection described by FOLDER/collection.json instead of --mesh and "
                        "--landmarks (with neither, the default: the CGAL quadrupeds of Debian's libcgal-demo, "
                        "remeshed, averaged, analysed, blended and textured, into ./results)")
    parser.add_argument("--level", type=int, metavar="J",
                        help="remesh with L0 refined J times by 1-to-4 quadrisection, 0 to %d (default %d)"
                        % (MAX_LEVEL, DEFAULT_LEVEL))
    parser.add_argument("--adaptive-tolerance", type=float, default=0.0, metavar="T",
                        help="refine adaptively, J being the maximum level: split a triangle while on any model the "
                        "surface is farther than T times that model's bounding-box diagonal from it, and again "
                        "where the placed remesh still is (e.g. 0.002; default 0: uniform)")
    parser.add_argument("--relax-samples", type=int, metavar="N",
                        help="N rounds of sample relaxation (the Semi-Regular Remesher's SampleRelaxationIterations; "
                        "default %d, or the collection's relax_samples; 0: none): remesh vertices move within their "
                        "L0 triangle or edge towards where the models' surface crowds in the parameterization (tails, "
                        "ears), one set of locations for the whole collection" % DEFAULT_SAMPLE_RELAXATION)
    parser.add_argument("--lower-stretch", action="store_true",
                        help="lower the stretch of every patch's map (Net Straightener's LowerStretch): parts "
                        "without landmarks, such as ears and tails, get more remesh vertices, at the price of more "
                        "folded remesh triangles elsewhere")
    parser.add_argument("--free-curves", action=argparse.BooleanOptionalAction, default=True,
                        help="move the curves where one low-distortion map of the whole surface onto L0 puts its "
                        "edges (Net Straightener's FreeCurves, on by default): only the landmarks stay, and tails, "
                        "ears and horns get room fixed curves deny them; --no-free-curves keeps the paper's "
                        "straightened curves, several times faster but far from such parts")
    parser.add_argument("--protrusion-cones", action=argparse.BooleanOptionalAction, default=True,
                        help="give each landmark-free protrusion the collection shares (a tail on at least two "
                        "models) a cone, an extra landmark at its tip and vertex of L0, placed from the others on "
                        "models without it (Protrusion Cones, on by default; a given --base-domain gets the cone "
                        "by splitting its triangle that holds the tip, keeping the others): the map "
                        "then reaches the tips instead of squeezing the tails into a base triangle, where the remesh "
                        "folds; --no-protrusion-cones keeps L0 to the files' landmarks")
    parser.add_argument("--free-curves-max-triangles", type=int, metavar="N",
                        help="free the curves only on surfaces of at most N triangles (Net Straightener's "
                        "FreeCurvesMaximumTriangles, default 150000; 0: no limit): the whole-surface map takes its "
                        "steps on every triangle, a 258K-triangle surface about 16 minutes on 2 cores; above N the "
                        "straightened curves are kept and the report says why")
    parser.add_argument("--no-fold-repair", action="store_true",
                        help="keep every remesh vertex exactly where its model's parameterization puts it (the "
                        "Semi-Regular Remesher's RepairFolds off): by default the vertices of remesh triangles "
                        "that face against the surface are slid a short way along it to unfold them")
    parser.add_argument("--transfer-from", metavar="NAME",
                        help="carry model NAME's point arrays and texture coordinates onto every other remesh "
                        "(TARGET.from-NAME.vtp; TARGET.from-NAME.png with NAME's texture image)")
    parser.add_argument("--details-from", metavar="NAME",
                        help="every other model's coarse shape (levels 0 to 2) with model NAME's finer details, "
                        "by Loop wavelets (TARGET.details-from-NAME.vtp; needs a uniform remesh of level 3 or more)")
    parser.add_argument("--pca", type=int, metavar="K",
                        help="principal components of the remeshes: their mean and K modes of variation "
                        "(mean.vtp with point arrays Mode0.., pca-coefficients.csv, pca-variances.csv, "
                        "pca-aligned.vtm; mean.png, pca-modes.png)")
    parser.add_argument("--blend", action="store_true",
                        help="blend the first three models (the first two if there are two) on a grid of weights "
                        "(blend-grid.vtm, blend-grid.png)")
    parser.add_argument("--blend-weights", nargs="+", metavar="W",
                        help="blend every model with these weights, one per --mesh in order, summing to 1, "
                        "separated by commas or spaces; a weight outside [0, 1] extrapolates (blend.vtp, blend.png)")
    parser.add_argument("--blend-alignment", choices=sorted(BLEND_ALIGNMENTS), metavar="MODE",
                        help="how the models are aligned before --blend and --blend-weights: rigid (default: "
                        "rotations and translations, sizes blend too), equal-volume (also scaled to one volume), "
                        "unit-size (scaled to unit centroid size) or none")
    parser.add_argument("--no-render", action="store_true",
                        help="make no PNG pictures (they need an X display; xvfb-run -a gives one)")
    parser.add_argument("--view-up", metavar="AXIS",
                        help="the models' up axis for the pictures: +y (default), -y, +z, -z, +x or -x")
    parser.add_argument("--output", help="output folder (required with --mesh; default ./results for a collection)")
    parser.add_argument("--model-timeout", type=float, default=DEFAULT_MODEL_TIMEOUT, metavar="SECONDS",
                        help="kill a model's reading, or its tracing and straightening, after SECONDS and fail the "
                        "model \"timed out after SECONDS s\" (default %g, an hour: far above what a model of "
                        "a million triangles takes; 0: no limit)" % DEFAULT_MODEL_TIMEOUT)
    parser.add_argument("--jobs", type=int, metavar="N",
                        help="read, trace and straighten up to N models at once, each in its own process (default: "
                        "the cores this process may use; under mpirun, those shared among the ranks on one machine); "
                        "the files written are the same for any N")
    parser.add_argument("--timing-arrays", action="store_true",
                        help="keep the filters' timing field arrays (TotalSeconds and the like) in the .vtp and "
                        ".vtm files written; without it they are left out, so that every file but timings.json "
                        "is the same byte for byte from run to run")
    args = parser.parse_args(_attach_negative_weights(argv))
    args.collection_data = None
    if args.collection is not None and (args.mesh or args.landmarks):
        parser.error("--collection %s with --mesh or --landmarks: give a collection or models, not both"
                     % args.collection)
    if not args.mesh and not args.landmarks:
        use_collection(parser, args)
    if not args.mesh:
        parser.error("give at least one --mesh with its --landmarks")
    if args.output is None:
        parser.error("the following arguments are required: --output")
    if args.level is None:
        args.level = DEFAULT_LEVEL
    if not args.model_timeout >= 0:
        parser.error("--model-timeout %s: give a number of seconds, 0 or more (0: no limit)" % args.model_timeout)
    if args.free_curves_max_triangles is not None and args.free_curves_max_triangles < 0:
        parser.error("--free-curves-max-triangles %d: give a number of triangles, 0 (no limit) or more"
                     % args.free_curves_max_triangles)
    if args.jobs is not None and args.jobs < 1:
        parser.error("--jobs %d: give a number of models to run at once, 1 or more" % args.jobs)
    if args.relax_samples is None:
        args.relax_samples = DEFAULT_SAMPLE_RELAXATION
    if args.view_up is None:
        args.view_up = "+y"
    if args.blend_alignment is None:
        args.blend_alignment = "rigid"
    if args.blend_alignment not in BLEND_ALIGNMENTS:  # from a collection.json
        parser.error("blend_alignment %s: give one of %s"
                     % (args.blend_alignment, ", ".join(sorted(BLEND_ALIGNMENTS))))
    if len(args.mesh) != len(args.landmarks):
        parser.error("%d --mesh but %d --landmarks: give one landmark file per mesh" % (len(args.mesh), len(args.landmarks)))
    names = [os.path.splitext(os.path.basename(m))[0] for m in args.mesh]
    duplicates = sorted({n for n in names if names.count(n) > 1})
    if duplicates:
        parser.error("two meshes share the name %s; models are named by file name" % ", ".join(duplicates))
    if args.transfer_from is not None and args.transfer_from not in names:
        parser.error("--transfer-from %s: no model is named so (models are named by file name: %s)"
                     % (args.transfer_from, ", ".join(names)))
    if args.details_from is not None and args.details_from not in names:
        parser.error("--details-from %s: no model is named so (models are named by file name: %s)"
                     % (args.details_from, ", ".join(names)))
    if args.details_from is not None and (args.adaptive_tolerance > 0 or args.level < 3):
        parser.error("--details-from: detail transfer needs a uniform remesh (no --adaptive-tolerance) of level 3 "
                     "or more (it keeps the coarse models' levels 0 to 2)")
    count = len(args.mesh)
    if args.pca is not None:
        if count < 2:
            parser.error("--pca %d: principal components need at least two models" % args.pca)
        if not 1 <= args.pca <= count - 1:
            parser.error("--pca %d: give a number of modes from 1 to %d (%d models vary in at most %d direction%s)"
                         % (args.pca, count - 1, count, count - 1, "" if count == 2 else "s"))
    if args.blend and count < 2:
        parser.error("--blend: blending needs at least two models")
    if args.blend_weights is not None:
        args.blend_weights = parse_weights(parser, args.blend_weights, count)
    try:
        args.view_up = render.parse_axis(args.view_up)
    except ValueError as error:
        parser.error("--view-up %s: %s" % (args.view_up, error))
    if args.base_domain is None and args.base_domain_from is None:
        args.base_domain_from = 0
    if args.base_domain_from is not None and not 0 <= args.base_domain_from < len(args.mesh):
        parser.error("--base-domain-from %d: give the 0-based index of one of the %d meshes (0 to %d)"
                     % (args.base_domain_from, len(args.mesh), len(args.mesh) - 1))
    if not 0 <= args.level <= MAX_LEVEL:
        parser.error("--level %d: give a level from 0 to %d (a remesh has 2 + T*4^J/2 vertices for the T "
                     "triangles of L0)" % (args.level, MAX_LEVEL))
    if not (math.isfinite(args.adaptive_tolerance) and args.adaptive_tolerance >= 0):
        parser.error("--adaptive-tolerance %s: give 0 (uniform) or a positive fraction of each model's bounding-box "
                     "diagonal, e.g. 0.002" % args.adaptive_tolerance)
    if not 0 <= args.relax_samples <= MAX_SAMPLE_RELAXATION:
        parser.error("--relax-samples %d: give a number of rounds from 0 (none) to %d (4 is a good choice)"
                     % (args.relax_samples, MAX_SAMPLE_RELAXATION))
    if os.path.exists(args.output) and not os.path.isdir(args.output):
        parser.error("--output %s exists and is not a folder" % args.output)
    return args


def prepare_output_folder(folder):
    """Creates `folder` if need be and makes sure files can be written in
    it, before any work is done: None, or what is wrong."""
    try:
        os.makedirs(folder, exist_ok=True)
    except OSError as error:
        return "cannot create the output folder: %s" % error
    # os.access says yes to root on a read-only file system: try a file.
    probe = os.path.join(folder, ".consistent-remesh-write-test")
    try:
        with open(probe, "w"):
            pass
        os.remove(probe)
    except OSError as error:
        return "cannot write in the output folder %s: %s" % (folder, error.strerror or error)
    return None


def use_collection(parser, args):
    """Fills the models and, where not given, the options from a collection
    (the default one if --collection is not given); its meshes are only
    unpacked by main."""
    try:
        data = collection.Collection(args.collection or collection.default_folder())
    except collection.CollectionError as error:
        parser.error(str(error))
    args.collection_data = data
    args.mesh, args.landmarks = data.mesh_paths(), data.landmark_paths()
    if args.base_domain is None and args.base_domain_from is None:
        args.base_domain = data.base_domain
    stages = data.stages
    for option in ("level", "relax_samples", "pca", "transfer_from", "view_up", "blend_alignment"):
        if getattr(args, option) is None and stages.get(option) is not None:
            setattr(args, option, stages[option])
    args.blend = args.blend or bool(stages.get("blend"))
    if args.output is None:
        args.output = "results"


def _attach_negative_weights(argv):
    """argparse takes '--blend-weights -0.5,1.5' for two options; with the
    weights attached by '=' they are the option's value."""
    fixed = []
    for word in argv:
        if fixed and fixed[-1] == "--blend-weights" and word.startswith("-") and "," in word:
            fixed[-1] += "=" + word
        else:
            fixed.append(word)
    return fixed


def parse_weights(parser, words, count):
    """The --blend-weights words (commas or spaces between weights) as
    floats, or a usage error."""
    given = " ".join(words)
    texts = [text for word in words for text in word.split(",") if text.strip()]
    weights = []
    for text in texts:
        try:
            weights.append(float(text))
        except ValueError:
            parser.error("--blend-weights %s: '%s' is not a number" % (given, text.strip()))
        if not math.isfinite(weights[-1]):
            parser.error("--blend-weights %s: '%s' is not a finite number" % (given, text.strip()))
    if len(weights) != count:
        parser.error("--blend-weights %s: give one weight per model: %d weight%s for %d models"
                     % (given, len(weights), "" if len(weights) == 1 else "s", count))
    total = math.fsum(weights)
    if abs(total - 1.0) > WEIGHT_SUM_TOLERANCE:
        parser.error("--blend-weights %s: the weights must sum to 1 (an affine combination), but they sum to %.12g"
                     % (given, total))
    return weights
