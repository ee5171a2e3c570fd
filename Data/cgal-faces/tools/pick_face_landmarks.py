#!/usr/bin/python3
"""Writes the landmark files of the CGAL faces collection.

Reads the three open face meshes straight from Debian's libcgal-demo data
archive and places, on every model, the 11 features of FEATURES (see
../README.md) by the rules in MODELS. Each rule is a small geometric question
asked in the model's own frame (forward = where the face looks, up, right =
the model's own right), so that the choice is reproducible and can be
reviewed:

  ("ray", hint, direction)
                     what a click on the picture seen from `direction`
                     picks: the line through `hint` along `direction`,
                     coming from far along `direction`, meets the surface
                     in a triangle; the rule takes that triangle's
                     vertex nearest to the meeting point;
  ("extreme", hint, direction, radius)
                     the vertex furthest along `direction` among the
                     vertices within geodesic distance `radius` of the
                     vertex nearest to `hint` (as in the quadrupeds'
                     pick_landmarks.py);
  ("boundary", direction)
                     the vertex of the boundary loop furthest along
                     `direction`;
  ("boundary-near", hint)
                     the vertex of the boundary loop nearest to `hint`.

Hints are normalised frame coordinates (f, u, r) in [0, 1]: f from the
rearmost to the frontmost point of the bounding box, u from the lowest to
the highest, r from the model's left to its right. Directions are (f, u, r)
vectors; radii are fractions of the bounding-box diagonal. The ray and
extreme rules (the face features) only consider vertices off the boundary.

Usage: /usr/bin/python3 pick_face_landmarks.py [--archive data.tar.gz]
           [--output DIR] [--verbose] [NAME...]
Needs numpy. Without NAME it writes every model in MODELS; the default
output folder is the one above this script. The placements were checked by
eye with render_face_landmarks.py and are verified by check_faces.py.
"""

import argparse
import os
import sys
import tarfile

import numpy

HERE = os.path.dirname(os.path.abspath(__file__))
# The OFF reader, the adjacency, the geodesic ball and the frame are the
# quadruped collection's.
sys.path.insert(0, os.path.join(HERE, "..", "..", "cgal-quadrupeds", "tools"))
from pick_landmarks import Frame, geodesic_ball, neighbours, read_off  # noqa: E402

DEFAULT_ARCHIVE = "/usr/share/doc/libcgal-dev/data.tar.gz"
MESH_MEMBER = "data/meshes/%s.off"

# Feature k, in file order: 7 on the face, then 4 on the boundary loop in
# the loop's own direction (the surface on the left of each boundary edge,
# seen from outside).
FEATURES = [
    "nose tip",
    "right eye (centre of the eye or closed lid)",
    "left eye",
    "right mouth corner",
    "left mouth corner",
    "chin (front of the chin or lower jaw)",
    "forehead centre (midline above the brows)",
    "boundary, front (below the chin: throat; on the mask: the chin's rim)",
    "boundary, left",
    "boundary, back (nape; on the mask: top of the forehead)",
    "boundary, right",
]
INTERIOR = 7  # features 0..6 are inside the surface, 7..10 on its boundary

F, U, R = (1, 0, 0), (0, 1, 0), (0, 0, 1)


def minus(v):
    """The opposite of direction `v`."""
    return tuple(-x for x in v)


def ray(f, u, r, direction=F):
    """Rule: a click at hint (f, u, r) on the picture seen from `direction`
    (f, u or r along `direction` does not matter)."""
    return ("ray", (f, u, r), direction)


def extreme(f, u, r, direction, radius=0.02):
    """Rule: the vertex furthest along `direction` within geodesic `radius`
    of the vertex nearest to hint (f, u, r)."""
    return ("extreme", (f, u, r), direction, radius)


def boundary(direction):
    """Rule: the boundary vertex furthest along `direction`."""
    return ("boundary", direction)


def boundary_near(f, u, r):
    """Rule: the boundary vertex nearest to hint (f, u, r)."""
    return ("boundary-near", (f, u, r))


MODELS = {}

# A maneless lion's head and neck, the neck cut by an oblique plane (low at the
# throat, high at the nape) that leans to its left. The mouth is open: a
# mouth corner is where the upper and lower lips meet at the back of the
# opening; the chin is the front of the lower jaw. The head is turned a
# little to its right.
MODELS["lion-head"] = {
    "frame": ("z", "y"),
    "note": "Frame: forward +z, up +y, right -x. Open mouth; neck cut obliquely, low at the throat.",
    "rules": [
        extreme(0.95, 0.37, 0.60, F, 0.02),                 # nose tip
        ray(0.80, 0.626, 0.80, F),                          # right eye
        ray(0.80, 0.636, 0.415, F),                         # left eye
        ray(0.605, 0.383, 0.90, R),                         # right mouth corner
        ray(0.655, 0.39, 0.30, minus(R)),                   # left mouth corner
        extreme(0.66, 0.22, 0.58, (1, -1, 0), 0.02),        # chin
        ray(0.80, 0.76, 0.595, F),                          # forehead
        boundary(minus(U)),                                 # boundary front (lowest)
        boundary(minus(R)),                                 # boundary left
        boundary((-1, 0.3, 0)),                             # boundary back (nape)
        boundary(R),                                        # boundary right
    ],
}

# A bald man's head with horns, fangs and a third eye in the forehead,
# cut at the bottom of the neck by a horizontal plane. The forehead point
# is between the brows and the third eye's socket.
MODELS["mannequin-devil"] = {
    "frame": ("-y", "z"),
    "note": "Frame: forward -y, up +z, right -x. Horns, fangs, a third eye; neck cut horizontally.",
    "rules": [
        ray(0.95, 0.46, 0.483, F),                          # nose tip
        ray(0.80, 0.601, 0.642, F),                         # right eye
        ray(0.80, 0.601, 0.319, F),                         # left eye
        ray(0.80, 0.355, 0.64, F),                          # right mouth corner
        ray(0.80, 0.355, 0.31, F),                          # left mouth corner
        extreme(0.85, 0.23, 0.51, (1, -0.5, 0), 0.02),      # chin
        ray(0.80, 0.70, 0.485, F),                          # forehead
        boundary(F),                                        # boundary front (throat)
        boundary(minus(R)),                                 # boundary left
        boundary(minus(F)),                                 # boundary back (nape)
        boundary(R),                                        # boundary right
    ],
}

# A coarse face mask (299 vertices): the boundary loop is the mask's rim,
# the chin at its bottom and the top of the forehead at its top. Eyes are
# shallow sockets, hence eye centres (not corners) on every model.
MODELS["nefertiti"] = {
    "frame": ("z", "y"),
    "note": "Frame: forward +z, up +y, right -x. A face mask: the boundary is its rim.",
    "rules": [
        extreme(0.95, 0.42, 0.50, F, 0.05),                 # nose tip
        ray(0.80, 0.63, 0.71, F),                           # right eye
        ray(0.80, 0.63, 0.29, F),                           # left eye
        ray(0.80, 0.26, 0.63, F),                           # right mouth corner
        ray(0.80, 0.26, 0.37, F),                           # left mouth corner
        extreme(0.85, 0.10, 0.50, F, 0.05),                 # chin
        ray(0.80, 0.82, 0.50, F),                           # forehead
        boundary(minus(U)),                                 # boundary front (chin's rim)
        boundary(minus(R)),                                 # boundary left
        boundary_near(0.50, 1.00, 0.50),                    # boundary back (top)
        boundary(R),                                        # boundary right
    ],
}


def boundary_loop(triangles):
    """The boundary loop as a list of vertices, in the direction in which
    each boundary edge (a, b) appears in its triangle (surface on the
    left). Raises ValueError unless there is exactly one loop."""
    half = set()
    for a, b, c in triangles:
        half.update(((a, b), (b, c), (c, a)))
    following = {}
    for a, b in half:
        if (b, a) not in half:
            if a in following:
                raise ValueError("vertex %d is on the boundary twice" % a)
            following[a] = b
    if not following:
        raise ValueError("no boundary")
    start = min(following)
    loop = [start]
    while following[loop[-1]] != start:
        loop.append(following[loop[-1]])
    if len(loop) != len(following):
        raise ValueError("%d boundary loops" % (1 + (len(following) > len(loop))))
    return loop


def click(coordinates, triangles, hint, direction, on_boundary):
    """The interior vertex nearest to where the line through `hint` along
    `direction` first meets the surface, coming from far along
    `direction`: what a click at `hint` on a picture seen from `direction`
    selects."""
    a, b, c = (coordinates[triangles[:, k]] for k in range(3))
    origin = hint + 1e3 * direction
    towards = -direction
    # Moller-Trumbore, for every triangle at once.
    ab, ac = b - a, c - a
    p = numpy.cross(towards, ac)
    det = numpy.einsum("ij,ij->i", ab, p)
    ok = numpy.abs(det) > 1e-15
    inverse = numpy.where(ok, 1.0 / numpy.where(ok, det, 1.0), 0.0)
    t_vec = origin - a
    u = numpy.einsum("ij,ij->i", t_vec, p) * inverse
    q = numpy.cross(t_vec, ab)
    v = (q @ towards) * inverse
    t = numpy.einsum("ij,ij->i", ac, q) * inverse
    hit = ok & (u >= 0) & (v >= 0) & (u + v <= 1) & (t > 0)
    if not hit.any():
        raise ValueError("the ray through %s misses the surface" % hint)
    first = numpy.flatnonzero(hit)[numpy.argmin(t[hit])]
    point = origin + t[first] * towards
    corners = [int(w) for w in triangles[first] if not on_boundary[w]]
    if not corners:
        raise ValueError("the ray through %s hits a triangle with no interior vertex" % hint)
    return min(corners, key=lambda w: numpy.linalg.norm(coordinates[w] - point))


def pick(rule, frame, triangles, adjacency, loop, on_boundary, diagonal):
    """The vertex that `rule` (see ray(), extreme(), boundary()) selects."""
    if rule[0] == "boundary":
        heights = frame.coordinates[loop] @ numpy.asarray(rule[1], float)
        return loop[int(numpy.argmax(heights))]
    hint = frame.point(rule[1])
    if rule[0] == "boundary-near":
        return loop[int(numpy.argmin(numpy.linalg.norm(frame.coordinates[loop] - hint, axis=1)))]
    direction = numpy.asarray(rule[2], float)
    direction /= numpy.linalg.norm(direction)
    if rule[0] == "ray":
        return click(frame.coordinates, triangles, hint, direction, on_boundary)
    inside = numpy.flatnonzero(~on_boundary)
    start = int(inside[numpy.argmin(numpy.linalg.norm(frame.coordinates[inside] - hint, axis=1))])
    ball = [v for v in geodesic_ball(adjacency, start, rule[3] * diagonal) if not on_boundary[v]]
    heights = frame.coordinates[ball] @ direction
    return ball[int(numpy.argmax(heights))]


def landmarks_of(name, text, verbose=False):
    """The landmark ids of model `name` whose OFF text is `text`, and its
    points."""
    model = MODELS[name]
    points, triangles = read_off(text)
    diagonal = numpy.linalg.norm(points.max(axis=0) - points.min(axis=0))
    frame = Frame(points, *model["frame"])
    adjacency = neighbours(points, triangles)
    loop = boundary_loop(triangles)
    on_boundary = numpy.zeros(len(points), bool)
    on_boundary[loop] = True
    ids = [pick(rule, frame, triangles, adjacency, loop, on_boundary, diagonal) for rule in model["rules"]]
    if verbose:
        normalised = (frame.coordinates - frame.low) / (frame.high - frame.low)
        for k, v in enumerate(ids):
            where = "loop position %d of %d" % (loop.index(v), len(loop)) if on_boundary[v] else ""
            print("  %2d %6d f=%.3f u=%.3f r=%.3f %s" % ((k, v) + tuple(normalised[v]) + (where,)))
    if len(set(ids)) != len(ids):
        raise ValueError("%s: two features on one vertex: %s" % (name, ids))
    return ids, points


def write_landmarks(path, name, ids, points):
    """Writes a landmark file: one id per line, each commented with its
    feature and position."""
    with open(path, "w") as out:
        out.write("# Landmarks of %s, libcgal-demo 5.5.1: %s inside\n" % (name, MESH_MEMBER % name))
        out.write("# /usr/share/doc/libcgal-dev/data.tar.gz (0-based ids into that file's points).\n")
        out.write("# 7 face features, then 4 on the boundary loop in its direction (surface on the left);\n")
        out.write("# written by tools/pick_face_landmarks.py.\n")
        out.write("# %s\n" % MODELS[name]["note"])
        for k, (v, feature) in enumerate(zip(ids, FEATURES)):
            x, y, z = points[v]
            out.write("%-6d # %2d %s (%.4g %.4g %.4g)\n" % (v, k, feature, x, y, z))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--archive", default=DEFAULT_ARCHIVE)
    parser.add_argument("--output", default=os.path.dirname(HERE))
    parser.add_argument("--verbose", action="store_true", help="print each pick in frame coordinates")
    parser.add_argument("names", nargs="*", default=list(MODELS))
    args = parser.parse_args()
    with tarfile.open(args.archive) as archive:
        for name in args.names:
            text = archive.extractfile(MESH_MEMBER % name).read().decode()
            ids, points = landmarks_of(name, text, args.verbose)
            write_landmarks(os.path.join(args.output, name + ".landmarks"), name, ids, points)
            print(name, " ".join(map(str, ids)))
    return 0


if __name__ == "__main__":
    sys.exit(main())
