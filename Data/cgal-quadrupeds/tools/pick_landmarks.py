#!/usr/bin/python3
"""Writes the landmark files of the CGAL quadruped collection.

Reads the meshes straight from Debian's libcgal-demo data archive and, for
every model, places the 21 landmarks of the SHREC'07 four-legged set (see
../README.md) by the rules in MODELS. Each rule is a small geometric
question asked in the model's own anatomical frame, so that the choice is
reproducible and can be reviewed:

  ("tip", hint)                  the geodesic extremity (hoof, nose, tail
                                 tip...) nearest to `hint`;
  ("extreme", hint, direction, radius)
                                 the vertex furthest along `direction` among
                                 the vertices within geodesic distance
                                 `radius` of the vertex nearest to `hint`.

Hints are normalised frame coordinates (f, u, r) in [0, 1]: f from the
rearmost to the frontmost point of the bounding box, u from the lowest to the
highest, r from the animal's left to its right. Directions are (f, u, r)
vectors; radii are fractions of the bounding-box diagonal.

Usage: /usr/bin/python3 pick_landmarks.py [--archive data.tar.gz]
           [--output DIR] [--verbose] [NAME...]
Needs numpy. Without NAME it writes every model in MODELS; the default
output folder is the one above this script. The placements were checked by
eye with render_landmarks.py.
"""

import argparse
import heapq
import os
import sys
import tarfile

import numpy

DEFAULT_ARCHIVE = "/usr/share/doc/libcgal-dev/data.tar.gz"
MESH_MEMBER = "data/meshes/%s.off"

# Feature k of the SHREC'07 four-legged landmark set, in file order.
FEATURES = [
    "nose tip",
    "top of the head (poll), between the ears or horns",
    "right cheek (behind and below the eye)",
    "left cheek",
    "right front leg, outside of its top (elbow)",
    "right front foot tip",
    "right hind leg, outside of its top (stifle)",
    "right hind foot tip",
    "left hind leg, outside of its top",
    "left hind foot tip",
    "left front leg, outside of its top",
    "left front foot tip",
    "middle of the back",
    "base of the tail (top of the rump)",
    "middle of the belly",
    "right eye",
    "left eye",
    "right front leg, inside of its top (armpit)",
    "left front leg, inside of its top",
    "right hind leg, inside of its top (groin)",
    "left hind leg, inside of its top",
]

F, U, R = (1, 0, 0), (0, 1, 0), (0, 0, 1)


def minus(v):
    """The opposite of direction `v`."""
    return tuple(-x for x in v)


def tip(f, u, r):
    """Rule: the geodesic extremity nearest to hint (f, u, r)."""
    return ("tip", (f, u, r))


def extreme(f, u, r, direction, radius=0.04):
    """Rule: the vertex furthest along `direction` within geodesic `radius`
    (a fraction of the bounding-box diagonal) of the vertex nearest to hint
    (f, u, r)."""
    return ("extreme", (f, u, r), direction, radius)


MODELS = {}

# The snout ends in a downward beak below the nose horn: the nose tip is the
# front of the beak, the poll lies between the brow horns in front of the frill.
MODELS["triceratops"] = {
    "frame": ("x", "y"),
    "note": "Frame: forward +x, up +y. Nose tip = front of the beak; poll between the brow horns.",
    "rules": [
        extreme(0.94, 0.33, 0.50, (1, -1, 0), 0.02),  # nose
        extreme(0.87, 0.72, 0.50, U, 0.015),          # poll
        extreme(0.84, 0.47, 0.62, R, 0.02),           # right cheek
        extreme(0.84, 0.47, 0.38, minus(R), 0.02),    # left cheek
        extreme(0.65, 0.45, 0.85, R, 0.03),           # right front, outer
        tip(0.63, 0.01, 0.82),                        # right front foot
        extreme(0.40, 0.50, 0.85, R, 0.03),           # right hind, outer
        tip(0.40, 0.01, 0.94),                        # right hind foot
        extreme(0.40, 0.50, 0.15, minus(R), 0.03),    # left hind, outer
        tip(0.35, 0.05, 0.12),                        # left hind foot
        extreme(0.65, 0.45, 0.15, minus(R), 0.03),    # left front, outer
        tip(0.63, 0.01, 0.18),                        # left front foot
        extreme(0.50, 0.90, 0.50, U, 0.03),           # back
        extreme(0.27, 0.75, 0.50, U, 0.02),           # tail base
        extreme(0.50, 0.30, 0.50, minus(U), 0.04),    # belly
        extreme(0.86, 0.60, 0.60, R, 0.015),          # right eye
        extreme(0.86, 0.60, 0.40, minus(R), 0.015),   # left eye
        extreme(0.65, 0.30, 0.65, minus(R), 0.02),    # right front, inner
        extreme(0.65, 0.30, 0.35, R, 0.02),           # left front, inner
        extreme(0.40, 0.30, 0.65, minus(R), 0.02),    # right hind, inner
        extreme(0.40, 0.30, 0.35, R, 0.02),           # left hind, inner
    ],
}

MODELS["camel"] = {
    "frame": ("z", "y"),
    "note": "Frame: forward +z, up +y. A dromedary standing; the back landmark is on the hump.",
    "rules": [
        tip(0.98, 0.95, 0.50),                        # nose
        extreme(0.85, 1.00, 0.50, U, 0.015),          # poll
        extreme(0.83, 0.89, 0.60, R, 0.015),          # right cheek
        extreme(0.83, 0.89, 0.40, minus(R), 0.015),   # left cheek
        extreme(0.58, 0.58, 0.80, R, 0.03),           # right front, outer
        tip(0.62, 0.00, 0.86),                        # right front foot
        extreme(0.18, 0.60, 0.80, R, 0.03),           # right hind, outer
        tip(0.15, 0.00, 0.90),                        # right hind foot
        extreme(0.18, 0.60, 0.20, minus(R), 0.03),    # left hind, outer
        tip(0.15, 0.00, 0.10),                        # left hind foot
        extreme(0.58, 0.58, 0.20, minus(R), 0.03),    # left front, outer
        tip(0.62, 0.00, 0.13),                        # left front foot
        extreme(0.38, 0.90, 0.50, U, 0.02),           # back
        extreme(0.06, 0.74, 0.50, minus(F), 0.02),    # tail base
        extreme(0.40, 0.50, 0.50, minus(U), 0.04),    # belly
        extreme(0.865, 0.97, 0.60, R, 0.015),         # right eye
        extreme(0.865, 0.97, 0.40, minus(R), 0.015),  # left eye
        extreme(0.58, 0.47, 0.60, minus(R), 0.02),    # right front, inner
        extreme(0.58, 0.47, 0.40, R, 0.02),           # left front, inner
        extreme(0.20, 0.50, 0.60, minus(R), 0.02),    # right hind, inner
        extreme(0.20, 0.50, 0.40, R, 0.02),           # left hind, inner
    ],
}

# The bull charges with its head turned hard to its left: on the head, the
# snout points to -r and the head's right side faces forward.
MODELS["bull"] = {
    "frame": ("-x", "y"),
    "note": "Frame: forward -x, up +y. The head is turned to the bull's left.",
    "rules": [
        extreme(0.82, 0.60, 0.05, minus(R)),          # nose
        extreme(0.83, 0.88, 0.20, U),                 # poll
        extreme(0.90, 0.63, 0.30, F, 0.02),           # right cheek
        extreme(0.75, 0.65, 0.32, minus(F)),          # left cheek
        extreme(0.70, 0.45, 0.74, R, 0.02),           # right front, outer
        tip(0.79, 0.07, 0.97),                        # right front foot
        extreme(0.20, 0.45, 0.80, R),                 # right hind, outer
        tip(0.32, 0.07, 0.80),                        # right hind foot
        extreme(0.15, 0.45, 0.30, minus(R)),          # left hind, outer
        tip(0.19, 0.00, 0.33),                        # left hind foot
        extreme(0.76, 0.35, 0.48, minus(R), 0.02),    # left front, outer
        tip(0.95, 0.03, 0.61),                        # left front foot
        extreme(0.50, 0.72, 0.55, U),                 # back
        extreme(0.08, 0.72, 0.55, minus(F)),          # tail base
        extreme(0.50, 0.30, 0.55, minus(U)),          # belly
        extreme(0.90, 0.72, 0.22, F),                 # right eye
        extreme(0.75, 0.75, 0.18, minus(F)),          # left eye
        extreme(0.71, 0.33, 0.68, minus(U), 0.02),    # right front, inner
        extreme(0.73, 0.30, 0.58, R, 0.02),           # left front, inner
        extreme(0.22, 0.35, 0.60, minus(R)),          # right hind, inner
        extreme(0.17, 0.35, 0.45, R),                 # left hind, inner
    ],
}

# A sitting teddy bear. Its frame is that of a quadruped rearing up: forward
# is towards the head (+y), up is its back (-z). Its legs point forward like
# a quadruped's legs point down; its arms stick out sideways, so the outer
# and inner tops of an arm are on its back and chest sides. It has no
# snout, eyes or tail: those features are placed on the smooth face, and
# the tail base at the geodesic tip at the bottom of the back.
MODELS["bear"] = {
    "frame": ("y", "-z"),
    "note": "Frame: forward (head) +y, up (back) -z. A sitting teddy: arms are the front legs.",
    "rules": [
        extreme(0.80, 0.15, 0.50, minus(U), 0.03),    # nose
        extreme(0.95, 0.50, 0.50, F, 0.02),           # poll
        extreme(0.75, 0.35, 0.72, R, 0.02),           # right cheek
        extreme(0.75, 0.35, 0.28, minus(R), 0.02),    # left cheek
        extreme(0.56, 0.80, 0.75, U, 0.01),           # right front (arm), outer
        tip(0.59, 0.66, 0.96),                        # right front foot (hand)
        extreme(0.22, 0.55, 0.85, R, 0.02),           # right hind, outer
        tip(0.09, 0.33, 0.98),                        # right hind foot
        extreme(0.22, 0.55, 0.15, minus(R), 0.02),    # left hind, outer
        tip(0.08, 0.55, 0.04),                        # left hind foot
        extreme(0.56, 0.80, 0.25, U, 0.01),           # left front (arm), outer
        tip(0.58, 0.45, 0.02),                        # left front foot (hand)
        extreme(0.40, 0.95, 0.50, U, 0.03),           # back
        tip(0.13, 0.92, 0.48),                        # tail base
        extreme(0.35, 0.05, 0.50, minus(U), 0.04),    # belly
        extreme(0.85, 0.20, 0.60, minus(U), 0.01),    # right eye
        extreme(0.85, 0.20, 0.40, minus(U), 0.01),    # left eye
        extreme(0.56, 0.30, 0.75, minus(U), 0.01),    # right front (arm), inner
        extreme(0.56, 0.30, 0.25, minus(U), 0.01),    # left front (arm), inner
        extreme(0.15, 0.20, 0.65, minus(R), 0.02),    # right hind, inner
        extreme(0.15, 0.20, 0.35, R, 0.02),           # left hind, inner
    ],
}

# The same kind of teddy, standing on its left leg with the right leg kicked
# back, the left arm pointing forward and the right arm sideways.
MODELS["bear_bis"] = {
    "frame": ("y", "-z"),
    "note": "Frame: forward (head) +y, up (back) -z. A teddy on one leg: arms are the front legs.",
    "rules": [
        extreme(0.80, 0.35, 0.35, minus(U), 0.03),    # nose
        extreme(0.95, 0.69, 0.33, F, 0.02),           # poll
        extreme(0.75, 0.50, 0.55, R, 0.02),           # right cheek
        extreme(0.75, 0.50, 0.15, minus(R), 0.02),    # left cheek
        extreme(0.45, 0.80, 0.75, U, 0.01),           # right front (arm), outer
        tip(0.42, 0.71, 0.97),                        # right front foot (hand)
        extreme(0.25, 0.60, 0.85, R, 0.02),           # right hind, outer
        tip(0.17, 0.90, 0.84),                        # right hind foot
        extreme(0.20, 0.60, 0.10, minus(R), 0.02),    # left hind, outer
        tip(0.02, 0.82, 0.15),                        # left hind foot
        extreme(0.52, 0.35, 0.08, minus(R), 0.01),    # left front (arm), outer
        tip(0.52, 0.05, 0.06),                        # left front foot (hand)
        extreme(0.40, 0.85, 0.45, U, 0.03),           # back
        extreme(0.15, 0.85, 0.45, U, 0.02),           # tail base
        extreme(0.38, 0.25, 0.45, minus(U), 0.04),    # belly
        extreme(0.85, 0.40, 0.43, minus(U), 0.01),    # right eye
        extreme(0.85, 0.40, 0.25, minus(U), 0.01),    # left eye
        extreme(0.45, 0.55, 0.75, minus(U), 0.01),    # right front (arm), inner
        extreme(0.52, 0.35, 0.25, R, 0.01),           # left front (arm), inner
        extreme(0.15, 0.50, 0.60, minus(R), 0.02),    # right hind, inner
        extreme(0.15, 0.55, 0.30, R, 0.02),           # left hind, inner
    ],
}

# Not in the default collection: Consistent Mesh Surface Reader welds the
# cow's two coincident points 44 and 2903 (where the tail touches the rump)
# into a non-manifold vertex. The landmarks are ready for when it does not.
MODELS["cow"] = {
    "frame": ("x", "y"),
    "note": "Frame: forward +x, up +y. A standing cow with horns, ears, udder and a hanging tail.",
    "rules": [
        tip(0.99, 0.78, 0.45),                        # nose
        extreme(0.86, 0.95, 0.50, U, 0.015),          # poll
        extreme(0.84, 0.75, 0.65, R, 0.015),          # right cheek
        extreme(0.84, 0.75, 0.35, minus(R), 0.015),   # left cheek
        extreme(0.62, 0.35, 0.90, R, 0.03),           # right front, outer
        tip(0.64, 0.01, 0.78),                        # right front foot
        extreme(0.14, 0.40, 0.90, R, 0.03),           # right hind, outer
        tip(0.16, 0.00, 0.82),                        # right hind foot
        extreme(0.14, 0.40, 0.10, minus(R), 0.03),    # left hind, outer
        tip(0.16, 0.00, 0.18),                        # left hind foot
        extreme(0.62, 0.35, 0.10, minus(R), 0.03),    # left front, outer
        tip(0.64, 0.01, 0.22),                        # left front foot
        extreme(0.45, 0.95, 0.50, U, 0.03),           # back
        extreme(0.06, 0.86, 0.50, minus(F), 0.01),    # tail base
        extreme(0.45, 0.25, 0.50, minus(U), 0.04),    # belly
        extreme(0.90, 0.82, 0.64, R, 0.015),          # right eye
        extreme(0.90, 0.82, 0.36, minus(R), 0.015),   # left eye
        extreme(0.62, 0.27, 0.62, minus(R), 0.02),    # right front, inner
        extreme(0.62, 0.27, 0.38, R, 0.02),           # left front, inner
        extreme(0.16, 0.28, 0.62, minus(R), 0.02),    # right hind, inner
        extreme(0.16, 0.28, 0.38, R, 0.02),           # left hind, inner
    ],
}


def read_off(text):
    """Points and triangles of an OFF file's text (triangles only)."""
    words = []
    for line in text.splitlines():
        words += line.split("#", 1)[0].split()
    if words[0] != "OFF":
        raise ValueError("not an OFF file")
    nv, nf = int(words[1]), int(words[2])
    points = numpy.array(words[4:4 + 3 * nv], float).reshape(nv, 3)
    faces = numpy.array(words[4 + 3 * nv:4 + 3 * nv + 4 * nf], int).reshape(nf, 4)
    if not (faces[:, 0] == 3).all():
        raise ValueError("not a triangle mesh")
    return points, faces[:, 1:]


def neighbours(points, triangles):
    """Adjacency lists of (neighbour, edge length) per vertex."""
    edges = numpy.concatenate([triangles[:, [0, 1]], triangles[:, [1, 2]], triangles[:, [2, 0]]])
    edges = numpy.unique(numpy.sort(edges, axis=1), axis=0)
    lengths = numpy.linalg.norm(points[edges[:, 0]] - points[edges[:, 1]], axis=1)
    adjacency = [[] for _ in range(len(points))]
    for (a, b), length in zip(edges, lengths):
        adjacency[a].append((b, length))
        adjacency[b].append((a, length))
    return adjacency


def geodesic_ball(adjacency, source, radius=numpy.inf):
    """Graph distances from `source` to every vertex closer than `radius`."""
    distance = {source: 0.0}
    queue = [(0.0, source)]
    while queue:
        d, v = heapq.heappop(queue)
        if d > distance[v]:
            continue
        for w, length in adjacency[v]:
            nd = d + length
            if nd <= radius and nd < distance.get(w, numpy.inf):
                distance[w] = nd
                heapq.heappush(queue, (nd, w))
    return distance


def geodesic_tips(points, adjacency, diagonal):
    """Vertices farthest (along the surface) from the body's centre within
    a geodesic ball of 8% of the diagonal: hooves, nose, tail, horns, ears."""
    centre = int(numpy.argmin(numpy.linalg.norm(points - points.mean(axis=0), axis=1)))
    from_centre = geodesic_ball(adjacency, centre)
    depth = numpy.array([from_centre[v] for v in range(len(points))])
    covered = numpy.zeros(len(points), bool)
    tips = []
    for v in numpy.argsort(-depth):
        if covered[v]:
            continue
        ball = geodesic_ball(adjacency, int(v), 0.08 * diagonal)
        if all(depth[w] <= depth[v] for w in ball):
            tips.append(int(v))
        covered[list(ball)] = True
    return tips


class Frame:
    """The model's anatomical frame: forward, up and right axes, and the
    bounding box in those axes."""

    def __init__(self, points, forward, up):
        axis = {"x": 0, "y": 1, "z": 2}
        def unit(name):
            v = numpy.zeros(3)
            v[axis[name[-1]]] = -1.0 if name.startswith("-") else 1.0
            return v
        f, u = unit(forward), unit(up)
        self.rotation = numpy.stack([f, u, numpy.cross(f, u)])
        self.coordinates = points @ self.rotation.T
        self.low = self.coordinates.min(axis=0)
        self.high = self.coordinates.max(axis=0)

    def point(self, hint):
        """Frame coordinates of normalised hint (f, u, r)."""
        return self.low + numpy.asarray(hint) * (self.high - self.low)


def pick(rule, frame, adjacency, tips, diagonal):
    """The vertex that `rule` (see tip() and extreme()) selects."""
    hint = frame.point(rule[1])
    if rule[0] == "tip":
        return min(tips, key=lambda v: numpy.linalg.norm(frame.coordinates[v] - hint))
    _, _, direction, radius = rule
    start = int(numpy.argmin(numpy.linalg.norm(frame.coordinates - hint, axis=1)))
    ball = list(geodesic_ball(adjacency, start, radius * diagonal))
    heights = frame.coordinates[ball] @ numpy.asarray(direction, float)
    return ball[int(numpy.argmax(heights))]


def landmarks_of(name, text, verbose=False):
    """The 21 landmark ids of model `name` whose OFF text is `text`, and
    its points."""
    model = MODELS[name]
    points, triangles = read_off(text)
    diagonal = numpy.linalg.norm(points.max(axis=0) - points.min(axis=0))
    frame = Frame(points, *model["frame"])
    adjacency = neighbours(points, triangles)
    tips = geodesic_tips(points, adjacency, diagonal)
    ids = [pick(rule, frame, adjacency, tips, diagonal) for rule in model["rules"]]
    if verbose:
        normalised = (frame.coordinates - frame.low) / (frame.high - frame.low)
        for k, v in enumerate(ids):
            print("  %2d %6d f=%.2f u=%.2f r=%.2f" % ((k, v) + tuple(normalised[v])))
    if len(set(ids)) != len(ids):
        raise ValueError("%s: two features on one vertex: %s" % (name, ids))
    return ids, points


def write_landmarks(path, name, ids, points):
    """Writes a landmark file: one id per line, each commented with its
    feature and position."""
    with open(path, "w") as out:
        out.write("# Landmarks of %s, libcgal-demo 5.5.1: %s inside\n" % (name, MESH_MEMBER % name))
        out.write("# /usr/share/doc/libcgal-dev/data.tar.gz (0-based ids into that file's points).\n")
        out.write("# The 21 features of the SHREC'07 four-legged set; written by tools/pick_landmarks.py.\n")
        out.write("# %s\n" % MODELS[name]["note"])
        for k, (v, feature) in enumerate(zip(ids, FEATURES)):
            x, y, z = points[v]
            out.write("%-6d # %2d %s (%.4g %.4g %.4g)\n" % (v, k, feature, x, y, z))


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--archive", default=DEFAULT_ARCHIVE)
    parser.add_argument("--output", default=os.path.dirname(here))
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
