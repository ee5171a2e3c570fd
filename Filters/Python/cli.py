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
                    [--no-render] [--view-up AXIS] [--model-timeout SECONDS] [--timing-arrays]
                    --output DIR

Each model is named by its mesh file name without extension. A model that
fails is reported and does not stop the others (its reading and its tracing
and straightening run in child processes, so a crash fails it alone, and so
does a child still running after --model-timeout, an hour by default); the
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
from .isolation import polydata_from_text, polydata_to_text, run_in_child, run_model_stage
from .render import run_pictures
from .stages import (
    Model,
    build_base_domain,
    check_against_base_domain,
    load_base_domain,
    read_landmarked_surface,
    remesh_collection,
    run_blend,
    run_blend_grid,
    run_details,
    run_pca,
    run_transfer,
    straighten_net,
    trace_net,
)
from .summary import print_summary
from .vtkio import StageError, keep_timing_arrays, write_polydata


EXIT_NO_BASE_DOMAIN = 3
EXIT_NO_COLLECTION = 4


def main(argv=None):
    args = parse_arguments(sys.argv[1:] if argv is None else argv)
    started = time.time()
    clock = time.perf_counter()
    keep_timing_arrays(args.timing_arrays)
    # Errors are collected per model and reported once; the executive's
    # generic "returned failure" log lines would only repeat them.
    vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)
    report = {"models": {}, "command": ["consistent-remesh"] + list(sys.argv[1:] if argv is None else argv)}
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
    models = [Model(m, l) for m, l in zip(args.mesh, args.landmarks)]

    # Each model's files are read, and later traced and straightened, in a
    # child process: a crash on one model's file fails that model alone.
    for index, model in enumerate(models):
        print("[%d/%d] %s: reading" % (index + 1, len(models), model.name), flush=True)
        try:
            run_model_stage(model, "read", lambda: read_landmarked_surface(model), ["surface"],
                            args.model_timeout)
        except StageError as error:
            model.fail(error)

    domain = None
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
        report["base_domain"] = describe_base_domain(domain, source)
        write_polydata(domain, os.path.join(args.output, "base_domain.vtp"))
    except StageError as error:
        report["base_domain"] = {"error": str(error)}
        domain = None

    for index, model in enumerate(models):
        if model.surface is None:
            continue
        if domain is None:
            model.fail("no base domain: " + report["base_domain"]["error"])
            continue
        step = "[%d/%d] %s:" % (index + 1, len(models), model.name)

        def process():
            check_against_base_domain(model, domain)
            print("%s tracing the net" % step, flush=True)
            traced = trace_net(model, domain, args.output)
            print("%s straightening the net (traced in %.2f s)" % (step, model.report["seconds"]["trace"]),
                  flush=True)
            straighten_net(model, domain, traced, args.output, args.lower_stretch, args.free_curves)
            print("%s straightened in %.2f s" % (step, model.report["seconds"]["straighten"]), flush=True)

        try:
            run_model_stage(model, "process", process, ["parameterized", "curves"], args.model_timeout)
        except StageError as error:
            model.fail(error)
            print("%s FAILED: %s" % (step, model.report["error"]), flush=True)

    # One run of the remesher for the whole collection: one connectivity.
    ready = [m for m in models if m.parameterized is not None]
    remeshes = None
    report["remesh"] = {"level": args.level, "adaptive_tolerance": args.adaptive_tolerance,
                        "models": [m.name for m in ready]}
    if ready:
        adaptive = " (adaptive, tolerance %g)" % args.adaptive_tolerance if args.adaptive_tolerance > 0 else ""
        print("remeshing %d model%s at level %d%s"
              % (len(ready), "" if len(ready) == 1 else "s", args.level, adaptive), flush=True)
        try:
            remeshes, figures = remesh_collection(ready, domain, args.level, args.adaptive_tolerance, args.output,
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
            report["transfer"] = run_transfer(args.transfer_from, ready, remeshes, domain, args.output)
        if args.details_from is not None:
            report["details"] = run_details(args.details_from, ready, remeshes, args.output)

    # What each stage's pictures need, for the stages that gave a result.
    stages = {}
    if "transfer" in report and "error" not in report["transfer"]:
        stages["transfer"] = (report["transfer"], remeshes)
    if args.pca is not None:
        report["pca"], mean = run_pca(args.pca, ready, remeshes, args.output)
        if mean is not None:
            stages["pca"] = (mean, report["pca"])
    if args.blend:
        report["blend_grid"], grid = run_blend_grid(ready, remeshes, args.output, args.blend_alignment)
        if grid is not None:
            stages["blend_grid"] = (grid, report["blend_grid"]["models"])
    if args.blend_weights is not None:
        report["blend"], blend = run_blend(args.blend_weights, models, ready, remeshes, args.output,
                                           args.blend_alignment)
        if blend is not None:
            stages["blend"] = (blend, args.blend_weights)
    if ready:
        stages["overview"] = (ready, remeshes)
        report["renders"] = run_pictures(args, stages, models)

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
