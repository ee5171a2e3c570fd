"""The Python package's array names (consistent_mesh.array_names) are the filters'
(Filters/VTK/vtkCMPArrayNames.h): the same constants, in the same order,
with the same values; kFeatureIdArray in C++ is FEATURE_ID_ARRAY in Python.
Usage: python3 TestArrayNames.py HEADER NAMES_PY"""

import re
import sys


def python_name(constant):
    words = re.sub(r"(?<=[a-z0-9])(?=[A-Z])|(?<=[A-Z])(?=[A-Z][a-z])", "_", constant[1:])
    return words.upper()


def main(header, module):
    cpp = [(python_name(c), v) for c, v in re.findall(r'constexpr const char\* (k\w+) = "(\w+)";', open(header).read())]
    python = re.findall(r'^([A-Z][A-Z0-9_]*) = "(\w+)"$', open(module).read(), re.M)
    own = [pair for pair in python if pair[0] == "DISPLACEMENT_ARRAY"]  # consistent-remesh's own
    python = [pair for pair in python if pair not in own]
    if not cpp:
        print("no names found in %s" % header)
        return 1
    if cpp != python:
        for index, (a, b) in enumerate(zip(cpp + [None] * len(python), python + [None] * len(cpp))):
            if a != b:
                print("entry %d: C++ %s, Python %s" % (index, a, b))
                break
        print("consistent_mesh.array_names does not match vtkCMPArrayNames.h (%d and %d names)" % (len(python), len(cpp)))
        return 1
    print("%d array names agree" % len(cpp))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))
