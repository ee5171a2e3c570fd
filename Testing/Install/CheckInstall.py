"""Checks of the installed project (Testing/Install/CMakeLists.txt):

  pvpython CheckInstall.py plugin PREFIX PLUGIN.so   the installed plugin loads
  python   CheckInstall.py import PREFIX             the installed package imports
  pvpython CheckInstall.py remeshes FOLDER COUNT     remesh_collection's outputs

The first two also check that every CMP library the process mapped comes
from PREFIX (found by its RPATHs, not from the build tree)."""
import os
import sys


def check_mapped_from(prefix):
    prefix = os.path.realpath(prefix) + os.sep
    with open("/proc/self/maps") as maps:
        mapped = {line.split()[-1] for line in maps if "CMPFilters" in line or "ConsistentMesh" in line}
    outside = sorted(path for path in mapped if not os.path.realpath(path).startswith(prefix))
    if not mapped or outside:
        sys.exit("CMP libraries loaded from outside %s: %s" % (prefix, outside or "none loaded"))
    print("loaded from the install:", *sorted(mapped), sep="\n  ")


def check_plugin(prefix, plugin):
    import paraview.simple as simple
    simple.LoadPlugin(plugin, ns=globals())
    print(globals()["BaseDomainBuilder"])
    check_mapped_from(prefix)


def check_import(prefix):
    import consistent_mesh
    from consistent_mesh import vtkCMPBaseDomainBuilder
    print(vtkCMPBaseDomainBuilder().GetClassName(), "from", consistent_mesh.__file__)
    if not os.path.realpath(consistent_mesh.__file__).startswith(os.path.realpath(prefix) + os.sep):
        sys.exit("consistent_mesh imported from outside %s" % prefix)
    check_mapped_from(prefix)


def check_remeshes(folder, count):
    """collection.vtm has COUNT remeshes with one connectivity, mean.vtp too."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataReader, vtkXMLPolyDataReader
    import numpy

    def triangles(polydata):
        polys = polydata.GetPolys()
        return (polydata.GetNumberOfPoints(), vtk_to_numpy(polys.GetOffsetsArray()),
                vtk_to_numpy(polys.GetConnectivityArray()))

    for name in ("collection.vtm", "mean.vtp"):
        if not os.path.isfile(os.path.join(folder, name)):
            sys.exit("no %s in %s" % (name, folder))
    collection = vtkXMLMultiBlockDataReader()
    collection.SetFileName(os.path.join(folder, "collection.vtm"))
    collection.Update()
    blocks = collection.GetOutput()
    meshes = [triangles(blocks.GetBlock(b)) for b in range(blocks.GetNumberOfBlocks())]
    mean = vtkXMLPolyDataReader()
    mean.SetFileName(os.path.join(folder, "mean.vtp"))
    mean.Update()
    meshes.append(triangles(mean.GetOutput()))
    if len(meshes) != count + 1:
        sys.exit("%d remeshes in collection.vtm, not %d" % (len(meshes) - 1, count))
    points, offsets, connectivity = meshes[0]
    for other in meshes[1:]:
        if other[0] != points or not numpy.array_equal(other[1], offsets) \
                or not numpy.array_equal(other[2], connectivity):
            sys.exit("the remeshes and the mean do not share one connectivity")
    print("%d remeshes and their mean: one connectivity, %d vertices, %d triangles"
          % (count, points, len(offsets) - 1))


if __name__ == "__main__":
    command, arguments = sys.argv[1], sys.argv[2:]
    if command == "plugin":
        check_plugin(*arguments)
    elif command == "import":
        check_import(*arguments)
    elif command == "remeshes":
        check_remeshes(arguments[0], int(arguments[1]))
    else:
        sys.exit("unknown check %r" % command)
