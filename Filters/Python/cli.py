"""consistent-remesh: run the consistent-parameterization pipeline on a
collection of landmarked surfaces and write the results and a JSON report.

Stages per model: read, landmarks, check, check against the base domain,
trace the patch layout (NAME.net.vtp, NAME.curves.vtp), straighten it and
map every patch onto its base triangle (NAME.param.vtp,
NAME.straight-curves.vtp). Then every straightened model is remeshed at once
with one semi-regular connectivity (NAME.remesh.vtp, collection.vtm,
remesh_connectivity.vtp). On the collection of remeshes, on request: the
transfer of one model's attributes onto the others (TARGET.from-NAME.vtp),
principal components (mean.vtp with the modes, pca-coefficients.csv,
pca-variances.csv, pca-aligned.vtm), blends (blend-grid.vtm, blend.vtp), and
PNG pictures of these.

With no --mesh it runs a collection described by a collection.json
(--collection FOLDER), by default the CGAL quadrupeds of Debian's
libcgal-demo with the landmarks and base domain shipped in
Data/cgal-quadrupeds, and every stage that collection asks for, into
./results. Every run writes report.md and report.html, which show the
pictures: inputs.png (each model's patch layout), remeshes.png, and those of
the stages.

Usage:
  consistent-remesh [--collection FOLDER] [--output DIR] [options]
  consistent-remesh --mesh A.off --landmarks A.vts [--mesh B.obj --landmarks B.pinned ...]
                    [--base-domain L0.vtp | --base-domain-from N] [--level J]
                    [--adaptive-tolerance T] [--relax-samples N] [--transfer-from NAME] [--details-from NAME] [--pca K]
                    [--blend] [--blend-weights W0,W1,...] [--blend-alignment MODE]
                    [--no-render] [--view-up AXIS] [--model-timeout SECONDS] [--jobs N] [--timing-arrays]
                    --output DIR
  mpirun -np N consistent-remesh ARGS   (the models shared out over N processes)

A landmark file may mark features missing on its model (-1; see
Documentation/data-formats.md): they are placed from the models that have
them (Missing Landmark Placer) before the base domain is used, and the
report says where; the base domain is built from a model with every
landmark.

Each model is named by its mesh file name without extension. A model that
fails is reported and does not stop the others (its reading and its tracing
and straightening run in child processes, so a crash fails it alone, and so
does a child still running after --model-timeout, an hour by default; up
to --jobs models run at once, by default one per core); the
exit status is 1 if any model failed or a requested stage failed, 2 for
a usage error, 3 if the base domain could not be made and 4 if a collection's meshes cannot be
had (the package is not installed or has changed). If the collection's remeshing fails, every
model taking part in it fails. Pictures need an X display (xvfb-run -a
will do); without one they are skipped, which is said and is no failure.

Every time goes to DIR/timings.json and only there: the other files of two
runs of one command on the same inputs are the same byte for byte (the
.vtp and .vtm files leave out the filters' timing field arrays unless
--timing-arrays).
"""

import os
import sys
import time

from vtkmodules.vtkCommonCore import vtkLogger

from . import collection
from . import report as written_report
from .arguments import parse_arguments, prepare_output_folder
from .figures import describe_base_domain
from .isolation import polydata_from_text, polydata_to_text, run_in_child, run_model_stages
from .ranks import default_jobs, this_job
from .collection_stages import run_collection_stages
from .stages import (
    Model,
    apply_cone_landmarks,
    build_base_domain,
    find_protrusion_cones,
    is_closed,
    check_against_base_domain,
    apply_placed_landmarks,
    load_base_domain,
    place_missing_landmarks,
    read_landmarked_surface,
    straighten_net,
    trace_net,
)
from .summary import print_summary
from .vtkio import StageError, keep_timing_arrays, read_polydata, write_polydata


EXIT_NO_BASE_DOMAIN = 3
EXIT_NO_COLLECTION = 4


def main(argv=None):
    args = parse_arguments(sys.argv[1:] if argv is None else argv)
    ranks = this_job()
    started = time.time()
    clock = time.perf_counter()
    keep_timing_arrays(args.timing_arrays)
    # Errors are collected per model and reported once; the executive's
    # generic "returned failure" log lines would only repeat them.
    vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)
    report = {"models": {}, "command": ["consistent-remesh"] + list(sys.argv[1:] if argv is None else argv)}
    jobs = args.jobs if args.jobs is not None else default_jobs(ranks)
    # Rank 0 unpacks the meshes and makes the output folder; every rank
    # stops on its word if it could not.
    status = None
    if ranks.rank == 0:
        status = _prepare(args, report)
    status = ranks.broadcast(status)
    if status is not None:
        return status
    models = [Model(m, l) for m, l in zip(args.mesh, args.landmarks)]
    mine = [(index, model) for index, model in enumerate(models) if ranks.owns(index)]

    # Each model's files are read, and later traced and straightened, in a
    # child process: a crash on one model's file fails that model alone.
    # Up to `jobs` models run at once.
    def reading(index, model):
        def read():
            print("[%d/%d] %s: reading" % (index + 1, len(models), model.name), flush=True)
            read_landmarked_surface(model)
        return (model, "read", read, ["surface"])

    errors = run_model_stages([reading(index, model) for index, model in mine], jobs, args.model_timeout)
    for position, error in errors.items():
        if error is not None:
            mine[position][1].fail(error)

    cones = _protrusion_cones(args, models, mine, ranks, report)
    _place_missing_landmarks(args, models, mine, ranks, report, cones)
    domain = _base_domain(args, models, ranks, report, cones)

    def processing(index, model):
        step = "[%d/%d] %s:" % (index + 1, len(models), model.name)

        def process():
            if model.surface is None:  # read by another rank
                read_landmarked_surface(model)
            check_against_base_domain(model, domain)
            print("%s tracing the net" % step, flush=True)
            traced = trace_net(model, domain, args.output)
            print("%s straightening the net (traced in %.2f s)" % (step, model.report["seconds"]["trace"]),
                  flush=True)
            straighten_net(model, domain, traced, args.output, args.lower_stretch, args.free_curves,
                           args.free_curves_max_triangles)
            print("%s straightened in %.2f s" % (step, model.report["seconds"]["straighten"]), flush=True)
        # Over several ranks, rank 0 reads the straightened surfaces back
        # from the files that the children wrote, on whichever rank.
        return (model, "process", process, ["parameterized", "curves"] if ranks.size == 1 else [])

    # The models read, in order; each rank takes the next one not yet taken
    # whenever it has a free slot.
    read = sorted(index for part in ranks.all_gather([index for index, model in mine if model.surface is not None])
                  for index in part)
    # The report of each model processed here and, on rank 0, on any rank.
    processed = {}

    def taken(index, model_report):
        """Rank 0: model `index` processed on some rank, with its report. Over
        several ranks its straightened surfaces are read now, while the
        other models run, so that all are ready when the last one is."""
        processed[index] = model_report
        if ranks.size > 1 and "error" not in model_report:
            try:
                _read_straightened(models[index], args.output)
            except StageError as error:
                model_report.update(status="failed", error="cannot read its straightened net back: %s" % error)

    def finished(position, error):
        index = read[position]
        model = models[index]
        if error is not None:
            model.fail(error)
            print("[%d/%d] %s: FAILED: %s" % (index + 1, len(models), model.name, model.report["error"]), flush=True)
        if ranks.rank == 0:
            taken(index, model.report)
        else:
            processed[index] = model.report
            ranks.post((index, model.report))

    def poll():
        ranks.progress()
        for entry in ranks.posts():
            taken(*entry)

    if domain is None:
        for index, model in mine:
            if model.surface is not None:
                model.fail("no base domain: " + report["base_domain"]["error"])
    else:
        counter = ranks.counter()
        run_model_stages([processing(index, models[index]) for index in read], jobs, args.model_timeout,
                         counter.claim, poll if ranks.size > 1 else None, finished)
        while ranks.rank == 0 and len(processed) < len(read):
            for entry in ranks.posts(wait=True):
                taken(*entry)
        counter.free()

    if ranks.size > 1:
        # The figures of the models read here but processed elsewhere (or
        # not at all) to rank 0, which does the rest; the others end with
        # its exit status. A model straightened on another rank than the
        # one that read it keeps the reader's figures and times too (the
        # base domain's).
        parts = ranks.gather([(index, model.report) for index, model in mine if index not in processed])
        if ranks.rank != 0:
            return ranks.end(None)
        ranks.use_every_core()
        for index, model_report in (entry for part in parts for entry in part):
            models[index].report = model_report
        for index, model_report in sorted(processed.items()):
            # Over what its reader found: a model whose processing crashed
            # on another rank than the reader's still has its read figures,
            # in the order one process would have written them.
            model = models[index]
            merged = dict(model.report)
            merged.update(model_report)
            merged["seconds"] = dict(model.report.get("seconds", {}), **model_report.get("seconds", {}))
            model.report = merged
    status = 1
    try:
        status = _collection_stages(args, models, domain, report, started, clock)
    finally:
        ranks.end(status)
    return status


def _read_straightened(model, folder):
    """Sets the straightened surface and curves of `model` from the files
    its processing wrote (NAME.param.vtp and NAME.straight-curves.vtp): the
    surfaces it had, but for the timing field arrays that no file or figure
    takes from them. Raises StageError if they cannot be read."""
    model.parameterized, model.curves = [read_polydata(os.path.join(folder, model.name + suffix))
                                         for suffix in (".param.vtp", ".straight-curves.vtp")]


def _prepare(args, report):
    """Unpacks a collection's meshes and makes the output folder: None, or
    the exit status if either cannot be done (said on stderr)."""
    # The meshes first: a missing package leaves no empty output folder.
    if args.collection_data is not None:
        data = args.collection_data
        print("%s: %s" % (data.title, data.description), flush=True)
        try:
            data.unpack(lambda message: print(message, flush=True))
        except collection.CollectionError as error:
            print("consistent-remesh: %s" % error, file=sys.stderr)
            return EXIT_NO_COLLECTION
        report["collection"] = {"title": data.title, "description": data.description, "folder": data.folder,
                                "meshes": data.cache}
    problem = prepare_output_folder(args.output)
    if problem:
        print("consistent-remesh: %s" % problem, file=sys.stderr)
        return 2
    return None


def _all_surfaces(models, order):
    """The models at `order`, each with its surface: those another rank
    read are read here too (in a child process of rank 0)."""
    for index in order:
        if models[index].surface is None:
            read_landmarked_surface(models[index])
    return [models[index] for index in order]


def _protrusion_cones(args, models, mine, ranks, report):
    """With --protrusion-cones (the default), finds the landmark-free
    protrusions the collection shares (Protrusion Cones, in a child process
    on rank 0) and gives each a cone: a landmark after the files' features
    at its tip on the models that have it, missing on the others (placed
    next, from the models that have it), and a vertex of L0, built from
    --base-domain-from's model or the given --base-domain (whose triangle
    holding the tip is split). Returns L0 with the cones as text, or None
    when there are none (not asked, files that miss landmarks, closed and
    open surfaces mixed, fewer than two models, or no protrusion shared;
    a collection of surfaces with boundaries gets them on its open L0). Every
    rank learns the result; a failure is said and the run goes on without
    cones."""
    if not args.protrusion_cones:
        return None
    gathered = ranks.all_gather([(index, bool(model.report.get("missing_landmarks")), is_closed(model.surface))
                                 for index, model in mine if model.surface is not None])
    readable = {index: (misses, closed) for part in gathered for index, misses, closed in part}
    # Open and closed models mixed: the ones that do not fit L0 fail later,
    # alone; the cones are not worth a failure of the whole step for them.
    if (len(readable) < 2 or (args.base_domain is None and args.base_domain_from not in readable) or
            any(misses for misses, _ in readable.values()) or
            len({closed for _, closed in readable.values()}) > 1):
        return None
    order = sorted(readable)
    result = None
    start = time.perf_counter()
    if ranks.rank == 0:
        def find():
            if args.base_domain is not None:
                return find_protrusion_cones(_all_surfaces(models, order), 0, load_base_domain(args.base_domain))
            return find_protrusion_cones(_all_surfaces(models, order), order.index(args.base_domain_from))
        try:
            result = run_in_child("cones", "collection", find, "finding protrusions", args.model_timeout)
        except StageError as error:
            result = str(error)
    result = ranks.broadcast(result)
    seconds = round(time.perf_counter() - start, 4)
    if isinstance(result, str):
        report["protrusion_cones"] = {"error": result, "seconds": seconds}
        if ranks.rank == 0:
            print("no protrusion cones: %s" % result, flush=True)
        return None
    first, roots, tips, found, domain, without = result
    report["protrusion_cones"] = {
        "cones": [{"feature": first + i, "root": root,
                   "models": [models[index].name for position, index in enumerate(order) if tips[position][i] >= 0]}
                  for i, root in enumerate(roots)],
        "seconds": seconds}
    if without:
        report["protrusion_cones"]["without_cone"] = [{"root": root, "apart": models[order[position]].name}
                                                      for root, position in without]
    for position, index in enumerate(order):
        model = models[index]
        if roots:
            model.cones = tips[position]  # a model read again (on rank 0 under MPI) gets them too
        if model.surface is None:
            continue
        model.report["protrusions"] = [{"vertex": vertex, "nearest_landmark": nearest}
                                       for vertex, nearest in found[position]]
        if roots:
            missing = apply_cone_landmarks(model, tips[position])
            model.report["cone_landmarks"] = {str(first + i): vertex for i, vertex in enumerate(tips[position])
                                              if vertex >= 0}
            if missing:
                model.missing = missing
                model.report["missing_landmarks"] = missing
    if ranks.rank == 0:
        for root, position in without:
            print("no protrusion cone by landmark %d: %s's protrusion leaves the body elsewhere than the other "
                  "models' (its tip lies in a base triangle beside none of theirs)" % (root, models[order[position]].name),
                  flush=True)
        for i, root in enumerate(roots):
            having = [models[index].name for position, index in enumerate(order) if tips[position][i] >= 0]
            print("protrusion cone: feature %d at the tip of the landmark-free protrusion nearest to landmark %d "
                  "(found on %s%s)" % (first + i, root, ", ".join(having),
                                       "; placed on the others" if len(having) < len(order) else ""), flush=True)
    return domain if roots else None


def _place_missing_landmarks(args, models, mine, ranks, report, cones=None):
    """Places the landmarks some models' files mark missing (-1) from the
    models that have them (Missing Landmark Placer, in a child process on
    rank 0), so that every model gets the full base domain. A model whose
    features cannot be placed fails with the reason; the others go on. A
    --base-domain-from model that misses landmarks gives way to the first
    one that has them all (said, and in the report)."""
    # The reading children leave what is missing in the report.
    gathered = ranks.all_gather([(index, model.report.get("missing_landmarks", [])) for index, model in mine
                                 if model.surface is not None])
    readable = dict(entry for part in gathered for entry in part)
    missing = {index: features for index, features in readable.items() if features}
    if not missing:
        return
    for index in sorted(missing):
        models[index].missing = missing[index]
    complete = [index for index in sorted(readable) if index not in missing]
    if args.base_domain is None and cones is None and args.base_domain_from in missing and complete:
        report["base_domain_from"] = {"asked": models[args.base_domain_from].name,
                                      "reason": "it misses landmarks %s" % ", ".join(
                                          map(str, missing[args.base_domain_from])),
                                      "used": models[complete[0]].name}
        if ranks.rank == 0:
            print("base domain from %s instead of %s, which misses landmarks %s"
                  % (models[complete[0]].name, models[args.base_domain_from].name,
                     ", ".join(map(str, missing[args.base_domain_from]))), flush=True)
        args.base_domain_from = complete[0]
    order = sorted(readable)
    result = None
    start = time.perf_counter()
    if ranks.rank == 0:
        def place():
            source = order.index(args.base_domain_from) if args.base_domain is None and \
                args.base_domain_from in complete else -1
            # The L0 the models will be mapped over, where it is known now,
            # judges the climbs to tips.
            if cones is not None:
                domain = polydata_from_text(cones)
            elif args.base_domain is not None:
                domain = load_base_domain(args.base_domain)
            else:
                domain = None
            return place_missing_landmarks(_all_surfaces(models, order), source, domain)
        print("placing %d missing landmark%s on %d model%s from the others"
              % (sum(map(len, missing.values())), "" if sum(map(len, missing.values())) == 1 else "s",
                 len(missing), "" if len(missing) == 1 else "s"), flush=True)
        try:
            result = run_in_child("place", "collection", place, "placing the missing landmarks",
                                  args.model_timeout)
        except StageError as error:
            result = str(error)
    result = ranks.broadcast(result)
    report["placement"] = {"models": [models[index].name for index in sorted(missing)],
                           "seconds": round(time.perf_counter() - start, 4)}
    if isinstance(result, str):
        report["placement"]["error"] = result
    for position, index in enumerate(order):
        if index not in missing:
            continue
        model = models[index]
        if isinstance(result, str):
            error, entries = "its missing landmarks could not be placed: %s" % result, []
        else:
            entries, error = result[position]
            error = error and "its missing landmarks could not be placed: " + error
        model.placed = {entry["feature"]: entry["vertex"] for entry in entries}
        if model.surface is not None:
            model.report["placed_landmarks"] = entries
            if error:
                model.fail(error)
            else:
                apply_placed_landmarks(model, model.placed)
        if ranks.rank == 0:
            for entry in entries:
                climb = entry.get("climbed_per_sqrt_area") or 0.0
                if entry.get("climb_undone"):
                    tip = entry.get("tip_distortion")
                    judged = ("; kept there, not climbed to the peak nearby: %s's map over L0 settles only so, "
                              "distortion %.3g against %s" % (model.name, entry["mapped_distortion"],
                                                              "no map" if tip is None else "%.3g" % tip))
                else:
                    judged = ""
                print("  %s: feature %d placed at vertex %d (the models that have it agree within %.1f%% of "
                      "the square root of its area%s%s)" % (model.name, entry["feature"], entry["vertex"],
                                                            100 * entry["spread_per_sqrt_area"],
                                                            "; it climbed %.1f%% from there to the tip they have "
                                                            "it at" % (100 * climb) if climb > 0 else "", judged),
                      flush=True)
            if error:
                print("  %s: FAILED: %s" % (model.name, error), flush=True)


def _base_domain(args, models, ranks, report, cones=None):
    """Reads (rank 0) or builds (the rank of --base-domain-from's model) the
    base domain, or takes the one Protrusion Cones built (`cones`, text),
    writes base_domain.vtp and fills report["base_domain"], on every rank:
    the base domain, or None if it could not be had."""
    if cones is not None:
        domain = polydata_from_text(cones)
        if args.base_domain is not None:
            source = "%s, with protrusion cones" % args.base_domain
            said = args.base_domain
        else:
            source = "built from %s, with protrusion cones" % models[args.base_domain_from].name
            said = "from %s" % models[args.base_domain_from].name
        if ranks.rank == 0:
            print("base domain %s, with %d protrusion cone%s" % (
                said, len(report["protrusion_cones"]["cones"]),
                "" if len(report["protrusion_cones"]["cones"]) == 1 else "s"), flush=True)
            write_polydata(domain, os.path.join(args.output, "base_domain.vtp"))
        report["base_domain"] = describe_base_domain(domain, source)
        return domain
    if args.base_domain is not None:
        root = 0
    else:
        root = ranks.owner(args.base_domain_from)
    made = None
    if ranks.rank == root:
        try:
            if args.base_domain is not None:
                domain = polydata_from_text(run_in_child("read", "base domain",
                                                         lambda: polydata_to_text(load_base_domain(args.base_domain)),
                                                         "reading the base domain", args.model_timeout))
                source = args.base_domain
            else:
                model = models[args.base_domain_from]
                if model.surface is None:
                    raise StageError("model %s, which should give the base domain, failed: %s"
                                     % (model.name, model.report["error"]))
                print("base domain from %s" % model.name, flush=True)
                domain = build_base_domain(model)
                source = "built from %s" % model.name
            write_polydata(domain, os.path.join(args.output, "base_domain.vtp"))
            made = (polydata_to_text(domain) if ranks.size > 1 else domain, source, None)
        except StageError as error:
            made = (None, None, str(error))
    domain, source, error = ranks.broadcast(made, root)
    if error is not None:
        report["base_domain"] = {"error": error}
        return None
    if ranks.size > 1:
        domain = polydata_from_text(domain)
    report["base_domain"] = describe_base_domain(domain, source)
    return domain


def _collection_stages(args, models, domain, report, started, clock):
    """Rank 0's part once every model is straightened: the collection's
    remesh, the stages on it and the pictures, all in one child process
    (a crash there makes them run again, each in a child of its own, so
    that it fails that stage alone: collection_stages), then the report;
    the exit status."""
    ready = [m for m in models if m.parameterized is not None]
    report.update(run_collection_stages(lambda stages: _collection_work(args, models, ready, domain, stages),
                                        models))
    for model in models:
        report["models"][model.name] = model.report
    failed = [m.name for m in models if m.report.get("status") != "ok"]
    report["failed"] = failed
    try:
        written_report.write(report, args.output,
                             {"started": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime(started)),
                              "seconds": round(time.perf_counter() - clock, 4)})
    except OSError as error:
        print("consistent-remesh: cannot write the report: %s" % error, file=sys.stderr)
        return 1

    print_summary(models, report)
    print("report: %s" % ", ".join(os.path.join(args.output, name) for name in written_report.FILES))
    if domain is None:
        return EXIT_NO_BASE_DOMAIN
    # A requested stage that failed is a failure too; pictures skipped for
    # want of a display are not.
    stage_failed = any("error" in report.get(key, {})
                       for key in ("transfer", "details", "pca", "blend_grid", "blend"))
    return 1 if failed or stage_failed or "errors" in report.get("renders", {}) else 0


def _collection_work(args, models, ready, domain, stages):
    """The collection's stages, run with `stages` (collection_stages.DIRECT
    or ISOLATED): the report's entries they make. Fills the models' reports."""
    # One run of the remesher for the whole collection: one connectivity.
    remeshes = None
    report = {}
    report["remesh"] = {"level": args.level, "adaptive_tolerance": args.adaptive_tolerance,
                        "models": [m.name for m in ready]}
    if ready:
        adaptive = " (adaptive, tolerance %g)" % args.adaptive_tolerance if args.adaptive_tolerance > 0 else ""
        print("remeshing %d model%s at level %d%s"
              % (len(ready), "" if len(ready) == 1 else "s", args.level, adaptive), flush=True)
        try:
            remeshes, figures = stages.remesh(ready, domain, args.level, args.adaptive_tolerance, args.output,
                                              not args.no_fold_repair, args.relax_samples)
            report["remesh"].update(figures)
            for model in ready:
                model.report["status"] = "ok"
        except StageError as error:
            remeshes = None
            report["remesh"]["error"] = str(error)
            for model in ready:
                model.fail("remeshing the collection failed: %s" % error)
        if args.transfer_from is not None:
            report["transfer"] = stages.transfer(args.transfer_from, ready, remeshes, domain, args.output)
        if args.details_from is not None:
            report["details"] = stages.details(args.details_from, ready, remeshes, args.output)

    # What each stage's pictures need, for the stages that gave a result.
    drawn = {}
    if "transfer" in report and "error" not in report["transfer"]:
        drawn["transfer"] = (report["transfer"], remeshes)
    if args.pca is not None:
        report["pca"], mean = stages.pca(args.pca, ready, remeshes, args.output)
        if mean is not None:
            drawn["pca"] = (mean, report["pca"])
    if args.blend:
        report["blend_grid"], grid = stages.blend_grid(ready, remeshes, args.output, args.blend_alignment)
        if grid is not None:
            drawn["blend_grid"] = (grid, report["blend_grid"]["models"])
    if args.blend_weights is not None:
        report["blend"], blend = stages.blend(args.blend_weights, models, ready, remeshes, args.output,
                                              args.blend_alignment)
        if blend is not None:
            drawn["blend"] = (blend, args.blend_weights)
    if ready:
        drawn["overview"] = (ready, remeshes)
        report["renders"] = stages.pictures(args, drawn, models)

    return report
