"""consistent-remesh's collection stages, in child processes.

Once every model is straightened, the collection's remesh, the stages on
it (texture and detail transfer, PCA, blends) and the pictures run on the
collection as a whole: all of them in one forked child
(run_collection_stages), which sends back only its figures. Should that
child crash inside a library (a segfault, an abort), they run again, each
in a child of its own (the *_isolated functions, ISOLATED), so that the
crash fails that stage alone with the reason instead of killing the run:
the report is still written, with every model's figures up to that stage.
Those children send their results back as text (.vtp) with their figures.

CMP_TEST_CRASH (see isolation) names these stages STAGE:collection, STAGE
one of remesh, transfer, details, pca, blend_grid, blend and pictures: the
stage crashes in the shared child and again in its own.
"""

from types import SimpleNamespace

from vtkmodules.vtkCommonDataModel import vtkCompositeDataSet, vtkMultiBlockDataSet

from .isolation import crash_for_the_test, polydata_from_text, polydata_to_text, run_in_child
from .render import run_pictures
from .stages import remesh_collection, run_blend, run_blend_grid, run_details, run_pca, run_transfer
from .vtkio import StageError

# The name CMP_TEST_CRASH knows the collection stages by.
COLLECTION = "collection"
# How run_in_child's message of a child that died begins.
CRASHED = "crashed while "


def _in_child(stage, doing, function, failed):
    """function() in a child; `failed(message)` if the child crashed, timed
    out or had a bug (a StageError with its message)."""
    try:
        return run_in_child(stage, COLLECTION, function, doing)
    except StageError as error:
        return failed(str(error))


def remesh_isolated(ready, domain, level, adaptive_tolerance, output_folder, repair_folds, sample_relaxation):
    """stages.remesh_collection in a child: the same remeshes (a multiblock
    named by model) and figures, and each model's "remesh" figures and
    time set as it sets them. Raises StageError if the stage failed or its
    child crashed."""
    def child():
        remeshes, figures = remesh_collection(ready, domain, level, adaptive_tolerance, output_folder,
                                              repair_folds, sample_relaxation)
        blocks = [polydata_to_text(remeshes.GetBlock(i)) for i in range(remeshes.GetNumberOfBlocks())]
        return figures, [(m.report["remesh"], m.report["seconds"]["remesh"]) for m in ready], blocks

    figures, per_model, blocks = run_in_child("remesh", COLLECTION, child, "remeshing the collection")
    remeshes = vtkMultiBlockDataSet()
    for index, (model, (model_figures, seconds), text) in enumerate(zip(ready, per_model, blocks)):
        model.report["remesh"] = model_figures
        model.report["seconds"]["remesh"] = seconds
        remeshes.SetBlock(index, polydata_from_text(text))
        remeshes.GetMetaData(index).Set(vtkCompositeDataSet.NAME(), model.name)
    return remeshes, figures


def transfer_isolated(source_name, ready, remeshes, domain, output_folder):
    """stages.run_transfer in a child: the stage's figures."""
    return _in_child("transfer", "transferring the texture",
                     lambda: run_transfer(source_name, ready, remeshes, domain, output_folder),
                     lambda message: {"source": source_name, "error": message})


def details_isolated(source_name, ready, remeshes, output_folder):
    """stages.run_details in a child: the stage's figures."""
    return _in_child("details", "transferring the details",
                     lambda: run_details(source_name, ready, remeshes, output_folder),
                     lambda message: {"source": source_name, "error": message})


def pca_isolated(modes, ready, remeshes, output_folder):
    """stages.run_pca in a child: the figures and the mean (None if the
    stage failed)."""
    def child():
        figures, mean = run_pca(modes, ready, remeshes, output_folder)
        return figures, polydata_to_text(mean)

    figures, mean = _in_child("pca", "analysing the collection (PCA)", child,
                              lambda message: ({"requested_modes": modes, "error": message}, None))
    return figures, polydata_from_text(mean)


def blend_grid_isolated(ready, remeshes, output_folder, alignment):
    """stages.run_blend_grid in a child: the figures and (entries, grid)
    for the picture (None if the stage failed)."""
    def child():
        figures, made = run_blend_grid(ready, remeshes, output_folder, alignment)
        if made is None:
            return figures, None
        entries, grid = made
        return figures, ([(column, row, polydata_to_text(surface), label)
                          for column, row, surface, label in entries], grid)

    names = [m.name for m in ready[:3]]
    figures, made = _in_child("blend_grid", "blending the models on a grid", child,
                              lambda message: ({"models": names, "error": message}, None))
    if made is None:
        return figures, None
    entries, grid = made
    return figures, ([(column, row, polydata_from_text(text), label) for column, row, text, label in entries], grid)


def blend_isolated(weights, models, ready, remeshes, output_folder, alignment):
    """stages.run_blend in a child: the figures and the blend (None if the
    stage failed)."""
    def child():
        figures, blend = run_blend(weights, models, ready, remeshes, output_folder, alignment)
        return figures, polydata_to_text(blend)

    named = {m.name: w for m, w in zip(models, weights)}
    figures, blend = _in_child("blend", "blending the models", child,
                               lambda message: ({"weights": named, "error": message}, None))
    return figures, polydata_from_text(blend)


def pictures_isolated(args, stages, models):
    """render.run_pictures in a child: the report's "renders"."""
    return _in_child("pictures", "drawing the pictures", lambda: run_pictures(args, stages, models),
                     lambda message: {"files": [], "seconds": 0.0, "errors": {"pictures": message}})


def _direct(stage, function):
    """`function` as it is, but for the CMP_TEST_CRASH hook of `stage`."""
    def run(*arguments):
        crash_for_the_test(stage, COLLECTION)
        return function(*arguments)
    return run


# The stages run in the process that calls them (the shared child) ...
DIRECT = SimpleNamespace(remesh=_direct("remesh", remesh_collection), transfer=_direct("transfer", run_transfer),
                         details=_direct("details", run_details), pca=_direct("pca", run_pca),
                         blend_grid=_direct("blend_grid", run_blend_grid), blend=_direct("blend", run_blend),
                         pictures=_direct("pictures", run_pictures))
# ... and each in a child of its own.
ISOLATED = SimpleNamespace(remesh=remesh_isolated, transfer=transfer_isolated, details=details_isolated,
                           pca=pca_isolated, blend_grid=blend_grid_isolated, blend=blend_isolated,
                           pictures=pictures_isolated)


def run_collection_stages(work, models):
    """`work(DIRECT)` (the collection's stages, returning the report's
    entries they make and filling the models' reports) in one child: its
    entries, the models' reports set as the child left them. If that child
    crashed (died by a signal or exited abnormally), `work(ISOLATED)` here
    instead, each stage in a child of its own, so that the crash fails its
    stage alone; any other StageError (a bug) is raised."""
    def child():
        entries = work(DIRECT)
        return entries, [model.report for model in models]

    try:
        entries, reports = run_in_child("collection", COLLECTION, child, "running the collection's stages")
    except StageError as error:
        if not str(error).startswith(CRASHED):
            raise  # a bug, not a crash: running the stages again would hide it
        print("the collection's stages %s; running them again, each in a process of its own" % error, flush=True)
        return work(ISOLATED)
    for model, report in zip(models, reports):
        model.report = report
    return entries
