"""Writes the fuzz targets' small seed files into seeds/ beside this script:
an octahedron and a coarse sphere in every form the readers take (OFF and
OBJ variants by hand, PLY, STL and VTP by VTK's writers in each of their
modes), so that every reader's success path is in the corpus from the
start. The shared models and Data/ seed the corpus too (see CMakeLists.txt);
they are large, these are small. Run with pvpython; the files are kept in
the repository, so this is only needed to change them.

  pvpython Testing/Fuzz/make_seeds.py
"""

import os

from vtkmodules.vtkCommonCore import vtkFloatArray, vtkPoints, vtkStringArray, vtkUnsignedCharArray
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkIOGeometry import vtkSTLWriter
from vtkmodules.vtkIOPLY import vtkPLYWriter
from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

HERE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "seeds")
OCTAHEDRON_POINTS = [(1, 0, 0), (-1, 0, 0), (0, 1, 0), (0, -1, 0), (0, 0, 1), (0, 0, -1)]
OCTAHEDRON_TRIANGLES = [(0, 2, 4), (2, 1, 4), (1, 3, 4), (3, 0, 4), (2, 0, 5), (1, 2, 5), (3, 1, 5), (0, 3, 5)]


def write(folder, name, text, mode="w"):
    os.makedirs(os.path.join(HERE, folder), exist_ok=True)
    with open(os.path.join(HERE, folder, name), mode) as out:
        out.write(text)


def octahedron():
    points = vtkPoints()
    for p in OCTAHEDRON_POINTS:
        points.InsertNextPoint(p)
    polys = vtkCellArray()
    for t in OCTAHEDRON_TRIANGLES:
        polys.InsertNextCell(3, t)
    surface = vtkPolyData()
    surface.SetPoints(points)
    surface.SetPolys(polys)
    return surface


def sphere():
    source = vtkSphereSource()
    source.SetThetaResolution(6)
    source.SetPhiResolution(5)
    source.Update()
    surface = vtkPolyData()
    surface.DeepCopy(source.GetOutput())
    # Point colours and texture coordinates, which PLY and VTP keep.
    colours = vtkUnsignedCharArray()
    colours.SetName("RGB")
    colours.SetNumberOfComponents(3)
    tcoords = vtkFloatArray()
    tcoords.SetName("TCoords")
    tcoords.SetNumberOfComponents(2)
    for i in range(surface.GetNumberOfPoints()):
        colours.InsertNextTuple3(i * 7 % 256, i * 13 % 256, i * 29 % 256)
        tcoords.InsertNextTuple2(i / surface.GetNumberOfPoints(), 0.5)
    surface.GetPointData().SetScalars(colours)
    surface.GetPointData().SetTCoords(tcoords)
    names = vtkStringArray()
    names.SetName("Source")
    names.InsertNextValue("sphere")
    names.InsertNextValue("seed")
    surface.GetFieldData().AddArray(names)
    return surface


def main():
    # OFF and OBJ by hand: comments, an empty line, a quad, colours per face.
    write("off", "octahedron.off", "OFF\n# an octahedron\n6 8 12\n" +
          "".join("%g %g %g\n" % p for p in OCTAHEDRON_POINTS) +
          "".join("3 %d %d %d\n" % t for t in OCTAHEDRON_TRIANGLES))
    write("off", "quads.off", "OFF\n\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
          "4 0 3 2 1 255 0 0\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n")
    write("obj", "octahedron.obj", "# an octahedron\n" + "".join("v %g %g %g\n" % p for p in OCTAHEDRON_POINTS) +
          "".join("f %d %d %d\n" % tuple(i + 1 for i in t) for t in OCTAHEDRON_TRIANGLES))
    write("obj", "textured.obj", "mtllib none.mtl\no cube\n" +
          "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n" +
          "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\ng side\nusemtl m\ns off\n" +
          "f 1/1/1 4/4/1 3/3/1 2/2/1\nf 5/1 6/2 7/3 8/4\nf -8/1/1 -7/2/1 -3/3/1 -4/4/1\n"
          "f 2/2 3/3 7/3 6/2\nf 3//1 4//1 8//1 7//1\nf 4/4 1/1 5/1 8/4\n")
    for name, surface in (("octahedron", octahedron()), ("sphere", sphere())):
        for mode, configure in (("ascii", lambda w: w.SetFileTypeToASCII()),
                                ("binary-le", lambda w: (w.SetFileTypeToBinary(), w.SetDataByteOrderToLittleEndian())),
                                ("binary-be", lambda w: (w.SetFileTypeToBinary(), w.SetDataByteOrderToBigEndian()))):
            writer = vtkPLYWriter()
            configure(writer)
            if surface.GetPointData().GetScalars() is not None:
                writer.SetArrayName("RGB")
                writer.SetColorModeToDefault()
            writer.SetInputData(surface)
            os.makedirs(os.path.join(HERE, "ply"), exist_ok=True)
            writer.SetFileName(os.path.join(HERE, "ply", "%s-%s.ply" % (name, mode)))
            writer.Write()
        for mode in ("ascii", "binary"):
            writer = vtkSTLWriter()
            writer.SetFileTypeToASCII() if mode == "ascii" else writer.SetFileTypeToBinary()
            writer.SetInputData(surface)
            os.makedirs(os.path.join(HERE, "stl"), exist_ok=True)
            writer.SetFileName(os.path.join(HERE, "stl", "%s-%s.stl" % (name, mode)))
            writer.Write()
        for mode, data_mode, compressed, encode in (("ascii", 0, False, False), ("binary", 1, False, False),
                                                   ("binary-zlib", 1, True, False), ("appended", 2, False, False),
                                                   ("appended-base64-zlib", 2, True, True)):
            writer = vtkXMLPolyDataWriter()
            writer.SetDataMode(data_mode)
            if not compressed:
                writer.SetCompressorTypeToNone()
            writer.SetEncodeAppendedData(encode)
            writer.SetInputData(surface)
            os.makedirs(os.path.join(HERE, "vtp"), exist_ok=True)
            writer.SetFileName(os.path.join(HERE, "vtp", "%s-%s.vtp" % (name, mode)))
            writer.Write()
    # Landmarks on the octahedron's points, in each format.
    write("vts", "octahedron.vts", "# id x y z\n" + "".join("%d %g %g %g\n" % ((i,) + p)
                                                          for i, p in enumerate(OCTAHEDRON_POINTS)))
    write("pinned", "octahedron.pinned", "".join("lk %d\n" % i for i in range(6)))
    write("pinned", "ids.txt", "# plain ids\n5\n4\n3\n")
    write("csv", "octahedron.csv", "x,y,z\n" + "".join("%g,%g,%g\n" % p for p in OCTAHEDRON_POINTS))


if __name__ == "__main__":
    main()
