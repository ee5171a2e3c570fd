"""ParaView's own readers of .vtp, .ply, .stl and .obj files, as the plugin redefines
them (issue 26): File > Open / OpenDataFile of a damaged or hostile file
gives an error naming the file, never a dead process; good files read as
with VTK's readers.

  pvpython TestPluginHostileFiles.py PLUGIN.so REGRESSIONS_DIR SEEDS_DIR

REGRESSIONS_DIR holds the fuzzing's crashing inputs (vtp/, ply/, stl/), SEEDS_DIR
its seeds. Besides those, seeded mutations of good files (flipped and
inserted bytes, truncations, repeated lines) are opened one after the
other in this one process: a crash fails the test.
"""

import glob
import os
import random
import sys
import tempfile

sys.dont_write_bytecode = True  # keep the source folder clean

from cmp_test_support import ErrorCapture, check, check_contains, check_equal, write_compressed_vtp

from paraview.simple import *  # noqa: F401,F403

# A longer run by hand: more seeds (CMP_HOSTILE_SEED), each in its own
# process (the reads slow down as one process opens thousands of files).
MUTATIONS_PER_SEED = int(os.environ.get("CMP_HOSTILE_MUTATIONS", "40"))


def open_file(path):
    """The public reader proxy ParaView's File > Open uses for `path`."""
    if path.endswith(".ply"):
        return PLYReader(FileNames=[path])  # noqa: F405
    if path.endswith(".stl"):
        return STLReader(FileNames=[path])  # noqa: F405
    if path.endswith(".obj"):
        return WavefrontOBJReader(FileName=path)  # noqa: F405
    return XMLPolyDataReader(FileName=[path])  # noqa: F405


def read(path):
    """(points, cells, error text, core reader class) of `path` read
    through ParaView's reader proxy."""
    proxy = open_file(path)
    series = proxy.GetClientSideObject()  # vtkFileSeriesReader (not for OBJ)
    core = series.GetReader() if series.IsA("vtkFileSeriesReader") else series
    with ErrorCapture(*((series,) if core is series else (series, core))) as errors:
        proxy.UpdatePipeline()
    data = series.GetOutputDataObject(0)
    result = (data.GetNumberOfPoints(), data.GetNumberOfCells(), errors.text, core.GetClassName())
    Delete(proxy)  # noqa: F405
    return result


def vtk_read(path):
    """(points, cells) as VTK's own reader reads a good file."""
    if path.endswith(".ply"):
        from vtkmodules.vtkIOPLY import vtkPLYReader as Reader
    elif path.endswith(".stl"):
        from vtkmodules.vtkIOGeometry import vtkSTLReader as Reader
    elif path.endswith(".obj"):
        from vtkmodules.vtkIOGeometry import vtkOBJReader as Reader
    else:
        from vtkmodules.vtkIOXML import vtkXMLPolyDataReader as Reader
    reader = Reader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput().GetNumberOfPoints(), reader.GetOutput().GetNumberOfCells()


def expect_refused(path, fragment=None):
    points, cells, text, core = read(path)
    what = os.path.basename(path)
    check_equal(points, 0, what + ": output points")
    check(text, what + ": no error message")
    check_contains(text, path, what + ": the message names the file")
    if fragment:
        check_contains(text, fragment, what)
    print("%s refused by %s: %s" % (what, core, text.strip().splitlines()[-1].split(path, 1)[-1][:120]))


def write_sphere_vtp(path):
    from vtkmodules.vtkFiltersSources import vtkSphereSource
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

    sphere = vtkSphereSource()
    sphere.SetThetaResolution(12)
    sphere.SetPhiResolution(8)
    writer = vtkXMLPolyDataWriter()
    writer.SetInputConnection(sphere.GetOutputPort())
    writer.SetDataModeToBinary()  # appended mode does not read back on bookworm
    writer.SetFileName(path)
    writer.Write()


def write_out_of_range_vtp(path):
    """Three points and a triangle using point 7: well formed, so only the
    check of the cells after reading catches it."""
    with open(path, "w") as f:
        f.write('<?xml version="1.0"?>\n'
                '<VTKFile type="PolyData" version="1.0" byte_order="LittleEndian" header_type="UInt64">\n'
                '<PolyData><Piece NumberOfPoints="3" NumberOfVerts="0" NumberOfLines="0" NumberOfStrips="0" '
                'NumberOfPolys="1">\n'
                '<Points><DataArray type="Float32" NumberOfComponents="3" format="ascii">'
                '0 0 0 1 0 0 0 1 0</DataArray></Points>\n'
                '<Polys><DataArray type="Int64" Name="connectivity" format="ascii">0 1 7</DataArray>\n'
                '<DataArray type="Int64" Name="offsets" format="ascii">3</DataArray></Polys>\n'
                '</Piece></PolyData></VTKFile>\n')


def mutate(data, rng):
    """One seeded damage of `data` (bytes)."""
    data = bytearray(data)
    kind = rng.randrange(5)
    if kind == 0:  # flipped bytes
        for _ in range(rng.randint(1, 8)):
            data[rng.randrange(len(data))] ^= 1 << rng.randrange(8)
    elif kind == 1:  # truncated
        del data[rng.randrange(1, len(data)):]
    elif kind == 2:  # inserted bytes
        at = rng.randrange(len(data))
        data[at:at] = bytes(rng.randrange(256) for _ in range(rng.randint(1, 16)))
    elif kind == 3:  # a number made extreme
        digits = [i for i, c in enumerate(data) if chr(c).isdigit()]
        if digits:
            at = rng.choice(digits)
            data[at:at + 1] = rng.choice([b"2147483648", b"99999999999", b"-1", b"4294967295"])
    else:  # a line repeated or deleted
        lines = bytes(data).split(b"\n")
        i = rng.randrange(len(lines))
        if rng.random() < 0.5:
            lines.insert(i, lines[i])
        else:
            del lines[i]
        data = bytearray(b"\n".join(lines))
    return bytes(data)


def main():
    plugin, regressions, seeds = sys.argv[1:4]
    LoadPlugin(plugin, ns=globals())  # noqa: F405
    with tempfile.TemporaryDirectory(prefix="cmp-hostile-") as tmp:
        # ParaView's File > Open path for .vtp goes through the checked class.
        good_vtp = os.path.join(tmp, "sphere.vtp")
        write_sphere_vtp(good_vtp)
        opened = OpenDataFile(good_vtp)  # noqa: F405
        check_equal(opened.GetXMLName(), "XMLPolyDataReader", "OpenDataFile(.vtp) proxy")
        check_equal(opened.GetClientSideObject().GetReader().GetClassName(), "vtkCMPCheckedXMLPolyDataReader",
                    "the reader behind ParaView's .vtp proxy")
        Delete(opened)  # noqa: F405

        # Good files read as VTK reads them.
        compressed = os.path.join(tmp, "octahedron-zlib.vtp")
        write_compressed_vtp(compressed, 24)
        good = [good_vtp, compressed] + sorted(glob.glob(os.path.join(seeds, "ply", "*.ply")) +
                                               glob.glob(os.path.join(seeds, "stl", "*.stl")) +
                                               glob.glob(os.path.join(seeds, "obj", "*.obj")))
        for path in good:
            points, cells, text, core = read(path)
            check_equal(text, "", os.path.basename(path) + ": error messages")
            check_equal((points, cells), vtk_read(path), os.path.basename(path) + ": points and cells")
            print("%s read by %s: %d points, %d cells" % (os.path.basename(path), core, points, cells))

        # The fuzzing's crashing inputs, a hostile compressed offset and ids
        # out of range: errors, no output.
        for path in sorted(glob.glob(os.path.join(regressions, "vtp", "*.vtp")) +
                           glob.glob(os.path.join(regressions, "ply", "*.ply")) +
                           glob.glob(os.path.join(regressions, "stl", "*.stl"))):
            expect_refused(path)
        hostile = os.path.join(tmp, "compressed-offset-2-41.vtp")
        write_compressed_vtp(hostile, 2 ** 41)
        expect_refused(hostile)
        out_of_range = os.path.join(tmp, "point-id-out-of-range.vtp")
        write_out_of_range_vtp(out_of_range)
        expect_refused(out_of_range, "point id 7")

        # Seeded damage of every good file, all in this process.
        rng = random.Random(int(os.environ.get("CMP_HOSTILE_SEED", "26")))
        counts = {"read": 0, "refused": 0}
        for path in good:
            original = open(path, "rb").read()
            base, ext = os.path.splitext(os.path.basename(path))
            for i in range(MUTATIONS_PER_SEED):
                damaged = os.path.join(tmp, "%s-%03d%s" % (base, i, ext))
                with open(damaged, "wb") as f:
                    f.write(mutate(original, rng))
                points, _, text, _ = read(damaged)
                counts["read" if points > 0 and not text else "refused"] += 1
                if text:
                    check_contains(text, damaged, "a damaged file's message names it")
                os.remove(damaged)
        print("damaged files: %(read)d read, %(refused)d refused, none crashed" % counts)
    print("ok")


if __name__ == "__main__":
    main()
