"""Helpers shared by the Python tests (pvpython, pvbatch or the plain Python
the wrapping was built for): explicit checks, capture of VTK error messages,
small hand-made surfaces and mesh inspection.

Checks raise AssertionError with a message that says what was expected, so an
uncaught failure ends the script with a traceback and exit status 1.
"""

import os

# A closed, consistently oriented octahedron: vertex 0 +x, 1 -x, 2 +y, 3 -y,
# 4 +z, 5 -z; every triangle is counter-clockwise seen from outside.
OCTAHEDRON_POINTS = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
OCTAHEDRON_TRIANGLES = [
    (0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4),
    (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5),
]
# A closed, consistently oriented regular tetrahedron.
TETRAHEDRON_POINTS = [(1, 1, 1), (1, -1, -1), (-1, 1, -1), (-1, -1, 1)]
TETRAHEDRON_TRIANGLES = [(0, 1, 2), (0, 3, 1), (0, 2, 3), (1, 3, 2)]


def check(condition, message):
    """Fails with `message` unless `condition` holds."""
    if not condition:
        raise AssertionError(message)


def check_equal(actual, expected, what):
    """Fails unless `actual == expected`, naming `what`."""
    if actual != expected:
        raise AssertionError("%s: expected %r, got %r" % (what, expected, actual))


def check_contains(text, fragment, what):
    """Fails unless `fragment` occurs in `text`."""
    if fragment not in text:
        raise AssertionError("%s: expected a message containing %r, got %r" % (what, fragment, text))


def write_off(path, points, triangles):
    """Writes a triangle surface as an OFF file and returns `path`."""
    with open(path, "w") as out:
        out.write("OFF\n%d %d 0\n" % (len(points), len(triangles)))
        for p in points:
            out.write("%r %r %r\n" % tuple(float(c) for c in p))
        for t in triangles:
            out.write("3 %d %d %d\n" % tuple(t))
    return path


def write_text(path, text):
    with open(path, "w") as out:
        out.write(text)
    return path


def read_off_header(path):
    """Returns (vertex_count, face_count) from an OFF file's header."""
    words = []
    with open(path) as f:
        for line in f:
            words += line.split("#", 1)[0].split()
            if len(words) >= 3:
                break
    check(len(words) >= 3 and words[0] == "OFF", "%s does not start with an OFF header" % path)
    return int(words[1]), int(words[2])


def read_vts(path):
    """Returns the (vertex_id, (x, y, z)) lines of a .vts landmark file."""
    landmarks = []
    with open(path) as f:
        for line in f:
            words = line.split()
            if words:
                landmarks.append((int(words[0]), tuple(float(w) for w in words[1:4])))
    return landmarks


def read_pinned(path):
    """Returns the vertex ids of a .pinned landmark file ("lk ID" per line)."""
    ids = []
    with open(path) as f:
        for line in f:
            words = line.split()
            if words:
                ids.append(int(words[-1]))
    return ids


class ErrorCapture:
    """Collects the messages that `vtkErrorMacro` sends from the given VTK
    objects while the `with` block runs (an ErrorEvent observer also keeps
    them out of the output window)."""

    def __init__(self, *objects):
        from vtkmodules.util.misc import calldata_type
        from vtkmodules.util.vtkConstants import VTK_STRING

        self.messages = []
        self._objects = objects
        self._tags = []

        @calldata_type(VTK_STRING)
        def on_error(_obj, _event, message):
            self.messages.append(str(message))

        self._callback = on_error

    def __enter__(self):
        from vtkmodules.vtkCommonCore import vtkCommand

        for obj in self._objects:
            self._tags.append((obj, obj.AddObserver(vtkCommand.ErrorEvent, self._callback)))
        return self

    def __exit__(self, *exc):
        for obj, tag in self._tags:
            obj.RemoveObserver(tag)
        self._tags = []
        return False

    @property
    def text(self):
        return "\n".join(self.messages)


def array_values(array):
    """All components of all tuples of a vtkDataArray, as a flat list."""
    n = array.GetNumberOfTuples() * array.GetNumberOfComponents()
    return [array.GetValue(i) for i in range(n)]


def triangles_of(polydata):
    """The cells of `polydata` as point-id tuples; fails on non-triangles."""
    from vtkmodules.vtkCommonCore import vtkIdList

    ids = vtkIdList()
    triangles = []
    for c in range(polydata.GetNumberOfCells()):
        polydata.GetCellPoints(c, ids)
        check_equal(ids.GetNumberOfIds(), 3, "number of points of cell %d" % c)
        triangles.append(tuple(ids.GetId(k) for k in range(3)))
    return triangles


def unique_edges(triangles):
    return {tuple(sorted((t[k], t[(k + 1) % 3]))) for t in triangles for k in range(3)}


def distance(a, b):
    return sum((x - y) ** 2 for x, y in zip(a, b)) ** 0.5


def check_base_domain(domain, surface=None, landmark_count=21, what="base domain"):
    """Checks that `domain` is a closed genus-0 triangulation with one point
    per landmark (FeatureId f on point f) and, given the landmarked `surface`
    it was built from, that point f sits on the surface's landmark f."""
    f = landmark_count
    check_equal(domain.GetNumberOfPoints(), f, what + ": points")
    check_equal(domain.GetNumberOfCells(), 2 * f - 4, what + ": triangles")
    triangles = triangles_of(domain)
    edges = unique_edges(triangles)
    check_equal(len(edges), 3 * f - 6, what + ": unique edges")
    # Closed and consistently oriented: each directed edge exactly once.
    directed = [(t[k], t[(k + 1) % 3]) for t in triangles for k in range(3)]
    check_equal(len(set(directed)), len(directed), what + ": distinct directed edges")
    check(all((b, a) in set(directed) for a, b in directed), what + ": an edge has no opposite half-edge")
    feature = domain.GetPointData().GetArray("FeatureId")
    check(feature is not None, what + ": no FeatureId point array")
    check_equal(sorted(array_values(feature)), list(range(f)), what + ": FeatureId values")
    if surface is not None:
        positions = landmark_positions(surface)
        for p in range(f):
            fid = int(feature.GetValue(p))
            d = distance(domain.GetPoint(p), positions[fid])
            check(d < 1e-9, "%s: point %d (feature %d) is %g away from the surface's landmark" % (what, p, fid, d))


def landmark_ids(surface):
    """The FeatureId array of `surface` as {feature: point id}; fails on
    duplicates."""
    feature = surface.GetPointData().GetArray("FeatureId")
    check(feature is not None, "the surface has no FeatureId point array")
    check_equal(feature.GetNumberOfTuples(), surface.GetNumberOfPoints(), "FeatureId tuples")
    result = {}
    for v in range(feature.GetNumberOfTuples()):
        f = int(feature.GetValue(v))
        if f >= 0:
            check(f not in result, "feature %d is on vertices %d and %d" % (f, result.get(f, -1), v))
            result[f] = v
        else:
            check_equal(f, -1, "FeatureId of vertex %d" % v)
    return result


def landmark_positions(surface):
    return {f: surface.GetPoint(v) for f, v in landmark_ids(surface).items()}


def field_value(dataset, name):
    """The first value of field array `name`, or None if it is missing."""
    array = dataset.GetFieldData().GetAbstractArray(name)
    if array is None:
        return None
    return array.GetValue(0)


def required_field(dataset, name):
    """The first value of field array `name`; fails the check if it is missing."""
    value = field_value(dataset, name)
    check(value is not None, "no field array " + name)
    return value


def white_view(width, height):
    """A render view with a white background and no orientation axes, for
    pictures whose covered pixels a test counts."""
    from paraview import simple
    view = simple.CreateView("RenderView")
    view.ViewSize = [width, height]
    view.OrientationAxesVisibility = 0
    view.Background = [1, 1, 1]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    return view


def screenshot_pixels(view, image):
    """Saves `view` to the PNG `image` and returns it as an (h, w, 3) array."""
    from paraview import simple
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOImage import vtkPNGReader
    width, height = view.ViewSize
    simple.SaveScreenshot(image, view, ImageResolution=[width, height])
    reader = vtkPNGReader()
    reader.SetFileName(image)
    reader.Update()
    data = reader.GetOutput()
    columns, rows, _ = data.GetDimensions()
    return vtk_to_numpy(data.GetPointData().GetScalars()).reshape(rows, columns, -1)[:, :, :3]


def load_plugin_proxies(plugin):
    """Loads the plugin and returns the namespace its proxy functions were
    added to (paraview.simple's)."""
    from paraview import simple
    names = vars(simple)
    simple.LoadPlugin(plugin, ns=names)
    return names


def plugin_test_setup():
    """The --plugin and --data arguments of a plugin test, with the plugin
    loaded: returns (shared data folder, proxy namespace)."""
    import argparse
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--data", required=True)
    args = parser.parse_args()
    return args.data, load_plugin_proxies(args.plugin)


def landmarked_shrec_with_x(names, data, model):
    """`landmarked_shrec()` plus a made-up point array, as a user would add
    one: X, the x coordinate, to check that point data is carried."""
    from paraview import simple
    return simple.Calculator(Input=landmarked_shrec(names, data, model), ResultArrayName="X", Function="coordsX")


def landmarked_shrec(names, data, model):
    """A SHREC'07 model read and given its landmarks, as a GUI user builds it."""
    folder = os.path.join(data, "shrec07-fourleg")
    reader = names["ConsistentMeshSurfaceReader"](FileName=os.path.join(folder, model + ".off"))
    return names["LandmarksFromFile"](Input=reader, LandmarkFile=os.path.join(folder, model + ".vts"))


def shared_data(argv_value=None):
    """The shared data folder, from the argument or CMP_SHARED_DATA_DIR."""
    path = argv_value or os.environ.get("CMP_SHARED_DATA_DIR", "")
    check(path and os.path.isdir(path), "shared data folder not found: %r" % path)
    return path


def landmarked_shrec_models(data):
    """[(name, off_path, vts_path)] for every SHREC'07 model with landmarks."""
    folder = os.path.join(data, "shrec07-fourleg")
    models = []
    for name in sorted(os.listdir(folder)):
        if name.endswith(".off"):
            vts = os.path.join(folder, name[:-4] + ".vts")
            if os.path.exists(vts):
                models.append((name[:-4], os.path.join(folder, name), vts))
    return models


def write_compressed_vtp(path, last_offset):
    """An octahedron as a zlib-compressed .vtp whose Polys offsets end at
    `last_offset` instead of 24. With a huge last offset VTK 9.2's XML
    reader aborts the process ("Unable to allocate" the connectivity it
    claims); the Surface Reader's check refuses the file first."""
    import base64
    import struct
    import zlib

    def array(name, vtk_type, values, code, components=1):
        raw = struct.pack("<%d%s" % (len(values), code), *values)
        packed = zlib.compress(raw)
        header = struct.pack("<QQQQ", 1, len(raw), len(raw), len(packed))
        return '<DataArray type="%s" Name="%s" NumberOfComponents="%d" format="binary">%s%s</DataArray>' % (
            vtk_type, name, components, base64.b64encode(header).decode(), base64.b64encode(packed).decode())

    points = [coordinate for point in OCTAHEDRON_POINTS for coordinate in point]
    connectivity = [index for triangle in OCTAHEDRON_TRIANGLES for index in triangle]
    offsets = [3 * (i + 1) for i in range(len(OCTAHEDRON_TRIANGLES))]
    offsets[-1] = last_offset
    return write_text(path, "".join([
        '<?xml version="1.0"?>\n<VTKFile type="PolyData" version="1.0" byte_order="LittleEndian" '
        'header_type="UInt64" compressor="vtkZLibDataCompressor">\n<PolyData>\n',
        '<Piece NumberOfPoints="%d" NumberOfVerts="0" NumberOfLines="0" NumberOfStrips="0" NumberOfPolys="%d">\n'
        % (len(OCTAHEDRON_POINTS), len(OCTAHEDRON_TRIANGLES)),
        "<Points>%s</Points>\n" % array("Points", "Float64", points, "d", 3),
        "<Polys>%s%s</Polys>\n" % (array("connectivity", "Int64", connectivity, "q"),
                                   array("offsets", "Int64", offsets, "q")),
        "</Piece>\n</PolyData>\n</VTKFile>\n"]))


def timeout_factor():
    """CMP_TEST_TIMEOUT_FACTOR, which ctest passes to these tests and by which
    it multiplies their timeouts (1 when a test is run by hand): a time limit
    inside a test must be scaled the same way."""
    value = os.environ.get("CMP_TEST_TIMEOUT_FACTOR", "1")
    return int(value) if value.isdigit() and int(value) > 0 else 1
