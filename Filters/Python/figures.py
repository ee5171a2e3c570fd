"""The figures of consistent-remesh's report, read back from the VTK
outputs of its stages: field-data values, table columns, landmarks."""

import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy

from . import array_names


def field_reader(data):
    """A function giving the first value of a field array of `data`."""
    field = data.GetFieldData()
    return lambda name: field.GetArray(name).GetValue(0)


def significant(value, digits=6):
    return float("%.*g" % (digits, value))


def folds_near_landmark(remesh):
    """The remesher's FoldsNearFeature as {"landmark": folds}, landmarks with
    folds only, most folds first: where folds stay after repair ({} for a
    remesh without the array)."""
    counts = remesh.GetFieldData().GetArray(array_names.FOLDS_NEAR_FEATURE_ARRAY)
    if counts is None:
        return {}
    pairs = [(feature, int(counts.GetValue(feature))) for feature in range(counts.GetNumberOfTuples())]
    pairs = sorted((pair for pair in pairs if pair[1] > 0), key=lambda pair: (-pair[1], pair[0]))
    return {str(feature): folds for feature, folds in pairs}


def table_column(table, name):
    column = table.GetColumnByName(name)
    return [column.GetValue(row) for row in range(table.GetNumberOfRows())]


def landmark_points(surface):
    """The point ids of landmarks 0, 1, ... of `surface` (Check Inputs has
    made sure each feature is on one vertex)."""
    features = vtk_to_numpy(surface.GetPointData().GetArray(array_names.FEATURE_ID_ARRAY))
    points = numpy.flatnonzero(features >= 0)
    return points[numpy.argsort(features[points])]


def landmark_count(surface):
    return len(landmark_points(surface))


def edge_count(polydata):
    """The distinct edges of a polydata's triangles (3T/2 for a closed one)."""
    edges = set()
    for cell in range(polydata.GetNumberOfCells()):
        ids = polydata.GetCell(cell).GetPointIds()
        count = ids.GetNumberOfIds()
        for k in range(count):
            a, b = ids.GetId(k), ids.GetId((k + 1) % count)
            edges.add((min(a, b), max(a, b)))
    return len(edges)


def describe_base_domain(domain, source):
    report = {
        "source": source,
        "vertices": domain.GetNumberOfPoints(),
        "triangles": domain.GetNumberOfCells(),
        "edges": edge_count(domain),
    }
    loops = domain.GetNumberOfPoints() - report["edges"] + report["triangles"]
    if loops != 2:
        # A sphere with holes: V - E + F = 2 - holes.
        report["boundary_loops"] = 2 - loops
    for name, key in ((array_names.MINIMUM_ANGLE_FIELD, "min_angle_degrees"),
                      (array_names.MEAN_SHAPE_QUALITY_FIELD, "mean_shape_quality")):
        array = domain.GetFieldData().GetArray(name)
        if array is not None:
            report[key] = round(array.GetValue(0), 4)
    return report
