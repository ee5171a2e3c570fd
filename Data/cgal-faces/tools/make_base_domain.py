#!/usr/bin/python3
"""Writes ../base_domain.obj, the open base domain L0 of the CGAL faces
collection.

L0 is a triangulated disk with one vertex per feature (vertex i = feature i
of the landmark files, see pick_face_landmarks.FEATURES): the 7 face
features inside, the 4 boundary features on its boundary loop. Its 16
triangles (TRIANGLES) were chosen by hand and are the Delaunay
triangulation of the features of the mask (nefertiti) seen from the front,
the one model where a front view shows the whole disk without overlap; the
same triangles are the natural choice on the heads (each face feature joins
its neighbours on the face; the eyes and the forehead join the back of the
boundary loop over the skull; the eyes and mouth corners join the sides of
the loop). check_faces.py verifies all that this needs.

Every triangle is oriented as the surfaces are: counter-clockwise seen from
outside (from the front of the face), so that each boundary edge (a, b) of
L0 runs in the direction of the surfaces' boundary loops, 7 -> 8 -> 9 -> 10
-> 7 (front, left, back, right).

Vertex positions are those of the features on the first model, lion-head
(from ../lion-head.landmarks and the mesh in Debian's libcgal-demo archive);
as for any base domain they are only a picture.

Usage: /usr/bin/python3 make_base_domain.py [--archive data.tar.gz] [--output FILE]
"""

import argparse
import os
import sys
import tarfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import pick_face_landmarks as pick  # noqa: E402

MODEL = "lion-head"

# Features: 0 nose tip, 1 right eye, 2 left eye, 3 right mouth corner,
# 4 left mouth corner, 5 chin, 6 forehead; boundary 7 front, 8 left,
# 9 back, 10 right. Each triangle counter-clockwise seen from outside.
TRIANGLES = [
    (0, 6, 1),   # nose, forehead, right eye
    (0, 2, 6),   # nose, left eye, forehead
    (0, 1, 3),   # nose, right eye, right mouth corner
    (0, 3, 4),   # nose, right and left mouth corners (the upper lip)
    (0, 4, 2),   # nose, left mouth corner, left eye
    (3, 5, 4),   # mouth corners and chin (the lower lip)
    (3, 7, 5),   # right mouth corner, boundary front, chin
    (4, 5, 7),   # left mouth corner, chin, boundary front
    (3, 10, 7),  # right mouth corner, boundary right, boundary front
    (4, 7, 8),   # left mouth corner, boundary front, boundary left
    (1, 10, 3),  # right eye, boundary right, right mouth corner
    (2, 4, 8),   # left eye, left mouth corner, boundary left
    (1, 9, 10),  # right eye, boundary back, boundary right
    (2, 8, 9),   # left eye, boundary left, boundary back
    (1, 6, 9),   # right eye, forehead, boundary back
    (2, 9, 6),   # left eye, boundary back, forehead
]


def read_landmark_ids(path):
    """Ids of a landmark file (`ID` per line, `#` comments)."""
    ids = []
    with open(path) as lines:
        for line in lines:
            words = line.split("#", 1)[0].split()
            if words:
                ids.append(int(words[-1]))
    return ids


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--archive", default=pick.DEFAULT_ARCHIVE)
    parser.add_argument("--output", default=os.path.join(os.path.dirname(HERE), "base_domain.obj"))
    args = parser.parse_args()
    with tarfile.open(args.archive) as archive:
        text = archive.extractfile(pick.MESH_MEMBER % MODEL).read().decode()
    points, _ = pick.read_off(text)
    ids = read_landmark_ids(os.path.join(os.path.dirname(HERE), MODEL + ".landmarks"))
    with open(args.output, "w") as out:
        out.write("# Base domain L0 of the CGAL faces collection: an open disk, vertex i = feature i.\n")
        out.write("# 7 face features inside, 4 boundary features on its boundary loop 7 -> 8 -> 9 -> 10;\n")
        out.write("# triangles counter-clockwise seen from outside, as the surfaces. Positions: the\n")
        out.write("# features on %s. Written by tools/make_base_domain.py.\n" % MODEL)
        for k, v in enumerate(ids):
            x, y, z = points[v]
            out.write("v %.6f %.6f %.6f  # %2d %s\n" % (x, y, z, k, pick.FEATURES[k]))
        for a, b, c in TRIANGLES:
            out.write("f %d %d %d\n" % (a + 1, b + 1, c + 1))
    print("%s: %d vertices, %d triangles" % (args.output, len(ids), len(TRIANGLES)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
