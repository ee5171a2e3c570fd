"""consistent-remesh's collection stages, each in a child process.

Once every model is straightened, the collection's remesh, the stages on
it (texture and detail transfer, PCA, blends) and the pictures run on the
collection as a whole. Each runs in a forked child (isolation.run_in_child),
so that a crash inside a library (a segfault, an abort) fails that stage
with the reason instead of killing the run: the report is still written,
with every model's figures up to that stage. The child sends its results
back as text (.vtp) and the figures it made.

CMP_TEST_CRASH (see isolation) names these stages STAGE:collection, STAGE
one of remesh, transfer, details, pca, blend_grid, blend and pictures.
"""

from vtkmodules.vtkCommonDataModel import vtkCompositeDataSet, vtkMultiBlockDataSet

from .isolation import polydata_from_text, polydata_to_text, run_in_child
from .render import run_pictures
from .stages import remesh_collection, run_blend, run_blend_grid, run_details, run_pca, run_transfer
from .vtkio import StageError

# The name CMP_TEST_CRASH knows the collection stages by.
COLLECTION = "collection"


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
