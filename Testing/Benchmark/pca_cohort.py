"""Mesh PCA of a large cohort (issue 28): time and peak memory of the
alignment and principal components of M remeshes of about N vertices each,
in one process or spread over the ranks of an MPI job, each rank holding
only its share of the models.

  pvbatch pca_cohort.py [--models 1000] [--vertices 20000] [--modes 10] [--output FILE.md]
  mpirun -np 2 pvbatch --symmetric pca_cohort.py [same options]

(PYTHONPATH: the consistent_mesh package, build/lib/python3.11/site-packages.)

The models are one connectivity (a torus of side x side vertices, side the
square root of N rounded up), each smoothly deformed by its own seeded
coefficients, then scaled, rotated and moved at random: what a collection
of remeshes looks like to Mesh PCA. Model i is made by rank i mod R alone,
so no process ever holds every model; Mesh PCA (its default alignment,
rigid to equal volume, then the principal components) combines the ranks
through the VTK controller (its Gram matrix is M x M, summed over ranks).

Prints, and appends to --output, one row: ranks, models, vertices, modes,
the filter's time (wall clock from a barrier before Update() to one after
it), the filter's own PCASeconds on rank 0 and its alignment iterations,
the peak resident memory of the largest rank and of all ranks
together (ru_maxrss of each process, which includes building the models),
and the first mode's explained variance ratio (the same for any number of
ranks: a check that the ranks made one collection).
"""

import argparse
import math
import resource
import sys
import time

sys.dont_write_bytecode = True

import numpy
from consistent_mesh import CMPFilters as cmp
from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkCompositeDataSet, vtkMultiBlockDataSet, vtkPolyData
from vtkmodules.vtkParallelCore import vtkDummyController, vtkMultiProcessController


def torus(side):
    """The rest shape (side * side, 3) and its triangles as a vtkCellArray."""
    u, v = numpy.meshgrid(numpy.arange(side) * 2 * math.pi / side, numpy.arange(side) * 2 * math.pi / side,
                          indexing="ij")
    u, v = u.ravel(), v.ravel()
    points = numpy.stack([(2 + numpy.cos(v)) * numpy.cos(u), (2 + numpy.cos(v)) * numpy.sin(u), numpy.sin(v)], 1)
    i, j = numpy.meshgrid(numpy.arange(side), numpy.arange(side), indexing="ij")
    a = (i * side + j).ravel()
    b = (((i + 1) % side) * side + j).ravel()
    c = (((i + 1) % side) * side + (j + 1) % side).ravel()
    d = (i * side + (j + 1) % side).ravel()
    triangles = numpy.concatenate([numpy.stack([a, b, c], 1), numpy.stack([a, c, d], 1)])
    cells = vtkCellArray()
    offsets = numpy.arange(0, 3 * len(triangles) + 1, 3, dtype=numpy.int64)
    cells.SetData(numpy_to_vtkIdTypeArray(offsets, deep=True),
                  numpy_to_vtkIdTypeArray(triangles.ravel().astype(numpy.int64), deep=True))
    return points, cells


def model(index, rest, cells):
    """Model `index`: the rest shape deformed by 6 smooth fields with
    coefficients seeded by the index, then scaled, rotated and moved."""
    random = numpy.random.default_rng(28_000 + index)
    x, y, z = rest[:, 0], rest[:, 1], rest[:, 2]
    fields = [numpy.stack(f, 1) for f in ((x, 0 * x, 0 * x), (0 * y, y, 0 * y), (0 * z, 0 * z, z),
                                           (0 * x, 0 * x, 0.3 * x * y), (0.2 * z * z, 0 * z, 0 * z),
                                           (0 * y, 0.1 * numpy.sin(2 * x), 0 * y))]
    points = rest.copy()
    for weight, field in zip(random.normal(0.0, [0.2, 0.15, 0.1, 0.08, 0.05, 0.03]), fields):
        points += weight * field
    q = random.normal(size=4)
    q /= numpy.linalg.norm(q)
    w, a, b, c = q
    rotation = numpy.array([[1 - 2 * (b * b + c * c), 2 * (a * b - c * w), 2 * (a * c + b * w)],
                            [2 * (a * b + c * w), 1 - 2 * (a * a + c * c), 2 * (b * c - a * w)],
                            [2 * (a * c - b * w), 2 * (b * c + a * w), 1 - 2 * (a * a + b * b)]])
    points = random.uniform(0.5, 2.0) * points @ rotation.T + random.normal(0.0, 3.0, 3)
    surface = vtkPolyData()
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(points, deep=True))
    surface.SetPoints(vtk_points)
    surface.SetPolys(cells)
    return surface


def peak_megabytes():
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--models", type=int, default=1000)
    parser.add_argument("--vertices", type=int, default=20000)
    parser.add_argument("--modes", type=int, default=10)
    parser.add_argument("--output", help="Markdown file to append the row to (rank 0)")
    args = parser.parse_args()
    controller = vtkMultiProcessController.GetGlobalController() or vtkDummyController()
    rank, ranks = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()
    side = int(math.ceil(math.sqrt(args.vertices)))
    rest, cells = torus(side)

    collection = vtkMultiBlockDataSet()
    collection.SetNumberOfBlocks(args.models)
    for index in range(args.models):
        collection.GetMetaData(index).Set(vtkCompositeDataSet.NAME(), "model%d" % index)
        if index % ranks == rank:
            collection.SetBlock(index, model(index, rest, cells))

    pca = cmp.vtkCMPMeshPCA()
    pca.SetController(controller)
    pca.SetInputData(collection)
    pca.SetNumberOfModes(args.modes)
    controller.Barrier()
    start = time.perf_counter()
    if not pca.GetExecutive().Update():
        raise SystemExit("rank %d: Mesh PCA failed" % rank)
    controller.Barrier()
    seconds = time.perf_counter() - start

    memory = vtkDoubleArray()
    memory.InsertNextValue(peak_megabytes())
    memories = vtkDoubleArray()
    controller.AllGather(memory, memories)
    peaks = [memories.GetValue(r) for r in range(ranks)]
    if rank != 0:
        return 0
    mean = pca.GetOutputDataObject(0)
    field = mean.GetFieldData()

    def value(name):
        array = field.GetArray(name)
        return array.GetValue(0) if array is not None else float("nan")

    if mean.GetPointData().GetArray("Mode0") is None:
        raise SystemExit("no Mode0 array on the mean")
    ratios = field.GetArray("ExplainedVarianceRatio")
    first = ratios.GetValue(0) if ratios is not None else float("nan")
    row = ("| %d | %d | %d | %d | %.1f | %.1f | %d | %.0f | %.0f | %.4f |"
           % (ranks, args.models, side * side, int(value("ModeCount")), seconds, value("PCASeconds"),
              int(value("AlignmentIterations")), max(peaks), sum(peaks), first))
    print("| ranks | models | vertices | modes | seconds | filter s (rank 0) | alignment iterations "
          "| peak MB (largest rank) | peak MB (all ranks) | mode 0 variance ratio |")
    print(row, flush=True)
    if args.output:
        with open(args.output, "a") as f:
            f.write(row + "\n")
    return 0


if __name__ == "__main__":
    # Not sys.exit(): pvbatch must end its MPI itself after the script.
    main()
