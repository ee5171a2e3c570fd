"""The wrapped filters used from plain Python (no paraview.simple): every
landmarked SHREC'07 four-legged model gives a 21-vertex base domain, and Spot
survives STL, PLY and VTP round trips through the surface reader.

  PYTHONPATH=<build>/<site-packages> python3 TestPlainVTKPipeline.py DATA
"""

import os
import sys
import tempfile

sys.dont_write_bytecode = True  # keep the source folder clean

from cmp_test_support import (
    OCTAHEDRON_POINTS,
    OCTAHEDRON_TRIANGLES,
    ErrorCapture,
    array_values,
    check,
    check_base_domain,
    check_contains,
    check_equal,
    distance,
    field_value,
    landmark_ids,
    landmarked_shrec_models,
    read_off_header,
    read_pinned,
    read_vts,
    triangles_of,
    write_off,
    write_text,
)

import consistent_mesh
from consistent_mesh import CMPFilters
from vtkmodules.vtkCommonCore import vtkFloatArray
from vtkmodules.vtkIOGeometry import vtkSTLWriter
from vtkmodules.vtkIOPLY import vtkPLYWriter
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter


def update(algorithm, what):
    """Updates `algorithm`, failing with its error messages if it reports any."""
    with ErrorCapture(algorithm) as errors:
        ok = algorithm.GetExecutive().Update()
    check(ok and not errors.messages, "%s failed: %s" % (what, errors.text or "no message"))
    return algorithm.GetOutputDataObject(0)


def read_surface(path, landmark_file=None):
    """Reads `path` (and its landmarks); returns (reader, landmarks or None)."""
    reader = CMPFilters.vtkCMPSurfaceReader()
    reader.SetFileName(path)
    if landmark_file is None:
        update(reader, "reading " + path)
        return reader, None
    landmarks = CMPFilters.vtkCMPLandmarksFromFile()
    landmarks.SetInputConnection(reader.GetOutputPort())
    landmarks.SetLandmarkFile(landmark_file)
    landmarks.SetExpectedLandmarkCount(21)
    update(landmarks, "landmarks of " + path)
    return reader, landmarks


def check_surface_ok(surface, what, domain=None):
    """vtkCMPInputCheck accepts `surface` (and `domain` on port 1)."""
    check_input = CMPFilters.vtkCMPInputCheck()
    check_input.SetInputData(surface)
    if domain is not None:
        check_input.SetInputData(1, domain)
    output = update(check_input, "input check of " + what)
    check_equal(check_input.GetLastError(), "", what + ": GetLastError() after a success")
    check_equal(field_value(output, "InputCheck"), "ok", what + ": InputCheck")


def test_shrec_models(data):
    models = landmarked_shrec_models(data)
    check_equal(len(models), 10, "landmarked SHREC'07 models (381-392 without 386 and 390)")
    reference = None
    for name, off, vts in models:
        vertex_count, face_count = read_off_header(off)
        reader, landmarks = read_surface(off, vts)
        surface = landmarks.GetOutput()
        check_equal(surface.GetNumberOfPoints(), vertex_count, name + ": points")
        check_equal(surface.GetNumberOfCells(), face_count, name + ": triangles")
        check_equal(field_value(reader.GetOutput(), "WeldedPointCount"), 0.0, name + ": WeldedPointCount")
        # Line k of the .vts is feature k, on its vertex, at its position.
        lines = read_vts(vts)
        check_equal(landmark_ids(surface), {k: v for k, (v, _) in enumerate(lines)}, name + ": landmark vertices")
        for k, (v, position) in enumerate(lines):
            check(distance(surface.GetPoint(v), position) < 1e-3, "%s: landmark %d is not where the .vts says" % (name, k))

        builder = CMPFilters.vtkCMPBaseDomainBuilder()
        builder.SetInputConnection(landmarks.GetOutputPort())
        domain = update(builder, name + ": base domain")
        check_base_domain(domain, surface, 21, name + " L0")
        min_angle = field_value(domain, "MinimumAngle")
        check(min_angle is not None and 0.0 < min_angle <= 60.0, "%s: MinimumAngle %r" % (name, min_angle))
        check_surface_ok(surface, name + " against its own L0", domain)
        if reference is None:
            reference = (name, domain)
        else:
            # The collection shares one base domain: every model fits 381's.
            check_surface_ok(surface, "%s against the L0 of %s" % (name, reference[0]), reference[1])
        print("%s: %d points, L0 21 points 38 triangles, minimum angle %.2f" % (name, vertex_count, min_angle))
    return reference[1]


def test_input_check_errors(domain, tmp):
    """GetLastError() and the error event agree when a check fails."""
    octahedron = write_off(os.path.join(tmp, "octahedron.off"), OCTAHEDRON_POINTS, OCTAHEDRON_TRIANGLES)
    reader = CMPFilters.vtkCMPSurfaceReader()
    reader.SetFileName(octahedron)
    landmarks = CMPFilters.vtkCMPLandmarksFromFile()
    landmarks.SetInputConnection(reader.GetOutputPort())
    landmarks.SetLandmarkFile(write_text(os.path.join(tmp, "six.txt"), "0\n1\n2\n3\n4\n5\n"))
    check_input = CMPFilters.vtkCMPInputCheck()
    check_input.SetInputConnection(landmarks.GetOutputPort())
    check_input.SetInputData(1, domain)
    with ErrorCapture(check_input) as errors:
        check_input.Update()
    expected = "base domain has 21 vertices but the surface has 6 landmarks"
    check_contains(check_input.GetLastError(), expected, "GetLastError()")
    check_contains(errors.text, expected, "error event")
    check_equal(check_input.GetOutput().GetNumberOfPoints(), 0, "output of a failed check")


def write(writer, polydata, path):
    writer.SetInputData(polydata)
    writer.SetFileName(path)
    check_equal(writer.Write(), 1, "writing " + path)
    return path


def check_same_geometry(copy, original, tolerance, what):
    """Same triangles in the same order, on the same positions."""
    check_equal(copy.GetNumberOfCells(), original.GetNumberOfCells(), what + ": triangles")
    for t, (a, b) in enumerate(zip(triangles_of(copy), triangles_of(original))):
        for k in range(3):
            d = distance(copy.GetPoint(a[k]), original.GetPoint(b[k]))
            check(d <= tolerance, "%s: corner %d of triangle %d moved by %g" % (what, k, t, d))


def test_round_trips(data, tmp):
    obj = os.path.join(data, "spot", "spot.obj")
    pinned = os.path.join(data, "spot", "spot_shrec07.pinned")
    _, landmarks = read_surface(obj, pinned)
    spot = landmarks.GetOutput()
    check_equal(spot.GetNumberOfPoints(), 2930, "spot.obj points")
    check_equal(spot.GetNumberOfCells(), 5856, "spot.obj triangles")
    landmark_vertices = read_pinned(pinned)
    check_equal(landmark_ids(spot), dict(enumerate(landmark_vertices)), "spot landmark vertices")
    float_tolerance = 1e-6  # Spot is about one unit across; STL and PLY store floats

    # STL repeats the points of every triangle: 17568 in the file, 2930 welded.
    for binary in (True, False):
        writer = vtkSTLWriter()
        writer.SetFileType(2 if binary else 1)
        kind = "binary STL" if binary else "ASCII STL"
        stl = write(writer, spot, os.path.join(tmp, "spot-%s.stl" % ("binary" if binary else "ascii")))
        reader, _ = read_surface(stl)
        surface = reader.GetOutput()
        check_equal(surface.GetNumberOfPoints(), 2930, kind + ": points after welding")
        check_equal(field_value(surface, "WeldedPointCount"), 3 * 5856 - 2930, kind + ": WeldedPointCount")
        file_map = surface.GetFieldData().GetArray("FileToMeshPointId")
        check(file_map is not None, kind + ": no FileToMeshPointId field array")
        check_equal(file_map.GetNumberOfTuples(), 3 * 5856, kind + ": FileToMeshPointId tuples")
        check_same_geometry(surface, spot, float_tolerance, kind)
        check_surface_ok(surface, kind)

    # Landmark ids index the file's points: give each landmark as the id of
    # the last STL corner that repeats it, and FileToMeshPointId maps it back.
    triangles = triangles_of(spot)
    last_corner = {}
    for t, triangle in enumerate(triangles):
        for k, v in enumerate(triangle):
            last_corner[v] = 3 * t + k
    stl_ids = write_text(os.path.join(tmp, "spot-stl.txt"), "".join("%d\n" % last_corner[v] for v in landmark_vertices))
    _, stl_landmarks = read_surface(os.path.join(tmp, "spot-binary.stl"), stl_ids)
    welded = stl_landmarks.GetOutput()
    for f, v in landmark_ids(welded).items():
        d = distance(welded.GetPoint(v), spot.GetPoint(landmark_vertices[f]))
        check(d <= float_tolerance, "STL landmark %d is %g away from Spot's" % (f, d))
    builder = CMPFilters.vtkCMPBaseDomainBuilder()
    builder.SetInputData(welded)
    check_base_domain(update(builder, "base domain of the STL copy"), welded, 21, "STL copy L0")
    print("STL: 17568 file points welded to 2930, landmarks mapped through FileToMeshPointId")

    # PLY keeps the shared points, so Spot's landmark file still applies.
    ply = write(vtkPLYWriter(), spot, os.path.join(tmp, "spot.ply"))
    reader, ply_landmarks = read_surface(ply, pinned)
    check_equal(reader.GetOutput().GetNumberOfPoints(), 2930, "PLY points")
    check_equal(field_value(reader.GetOutput(), "WeldedPointCount"), 0.0, "PLY WeldedPointCount")
    check_same_geometry(reader.GetOutput(), spot, float_tolerance, "PLY")
    check_equal(landmark_ids(ply_landmarks.GetOutput()), landmark_ids(spot), "PLY landmark vertices")
    check_surface_ok(ply_landmarks.GetOutput(), "PLY")

    # VTP keeps point and cell data arrays. Inline binary: appended VTP files
    # are unreadable with this system's VTK and expat (see the report).
    extra = vtkFloatArray()
    extra.SetName("Height")
    for v in range(spot.GetNumberOfPoints()):
        extra.InsertNextValue(spot.GetPoint(v)[1])
    spot.GetPointData().AddArray(extra)
    writer = vtkXMLPolyDataWriter()
    writer.SetDataModeToBinary()
    vtp = write(writer, spot, os.path.join(tmp, "spot.vtp"))
    reader, _ = read_surface(vtp)
    copy = reader.GetOutput()
    check_equal(copy.GetNumberOfPoints(), 2930, "VTP points")
    check_same_geometry(copy, spot, 0.0, "VTP")
    for name in ("FeatureId", "Height"):
        array = copy.GetPointData().GetArray(name)
        check(array is not None, "VTP: point array %s was dropped" % name)
        check_equal(array_values(array), array_values(spot.GetPointData().GetArray(name)), "VTP: point array " + name)
    corners = copy.GetCellData().GetArray("CornerTCoords")
    check(corners is not None, "VTP: cell array CornerTCoords was dropped")
    check_equal(array_values(corners), array_values(spot.GetCellData().GetArray("CornerTCoords")), "VTP: CornerTCoords")
    # The FeatureId read from the VTP is accepted as the surface's landmarks.
    builder = CMPFilters.vtkCMPBaseDomainBuilder()
    builder.SetInputData(copy)
    check_base_domain(update(builder, "base domain of the VTP copy"), copy, 21, "VTP copy L0")
    print("PLY and VTP: 2930 points, point data kept")


def test_extensions():
    for name in ("a.off", "b.OBJ", "c.ply", "d.Stl", "dir.x/e.vtp"):
        check(CMPFilters.vtkCMPSurfaceReader.CanReadExtension(name), "CanReadExtension(%r)" % name)
    for name in ("a.vtk", "b.offx", "off", "dir.off/mesh", ""):
        check(not CMPFilters.vtkCMPSurfaceReader.CanReadExtension(name), "not CanReadExtension(%r)" % name)
    # The package re-exports the classes of its CMPFilters module.
    check(consistent_mesh.vtkCMPBaseDomainBuilder is CMPFilters.vtkCMPBaseDomainBuilder, "package exports")


def main():
    data = sys.argv[1]
    test_extensions()
    domain = test_shrec_models(data)
    with tempfile.TemporaryDirectory(prefix="cmp-plain-vtk-") as tmp:
        test_input_check_errors(domain, tmp)
        test_round_trips(data, tmp)
    print("plain VTK pipeline: ok")
    return 0


if __name__ == "__main__":
    sys.exit(main())
