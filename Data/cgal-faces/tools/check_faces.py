#!/usr/bin/python3
"""Checks the CGAL faces collection: the three open meshes, their landmark
files and the open base domain L0, everything the boundary support needs
from them. Prints what it measured and, last, OK or the problems (exit
status 0 or 1).

  /usr/bin/python3 check_faces.py [--archive data.tar.gz | --meshes DIR] [--folder FOLDER]

Reads ../collection.json (or FOLDER/collection.json with --folder); the meshes come from the first existing
archive path of the collection (or --archive), or, with --meshes, from
DIR/data/meshes/NAME.off (the unpacked archive). Needs numpy only, and
nothing from the other tools of this folder (an independent check).

What it checks:
- each mesh: the member's SHA-256 is the collection's; a triangle mesh
  with no repeated point, no degenerate triangle, consistently oriented
  (each directed edge in at most one triangle), edge- and vertex-manifold,
  connected, every point used, one boundary loop, V - E + F = 1 (a disk);
- each landmark file: one line per L0 vertex, ids in range and distinct,
  each comment's feature number and position those of the line and of the
  vertex; the features on the boundary loop are exactly L0's boundary
  vertices (at least 4), every other feature is off the boundary;
- boundary order: walking each mesh's boundary loop in its own direction
  (the direction in which each boundary edge (a, b) appears in its triangle,
  the surface on the left seen from outside) meets the boundary features in
  the cyclic order of L0's boundary loop, walked the same way;
- L0 (base_domain.obj): vertex i at feature i of the first model; a
  consistently oriented, edge- and vertex-manifold, connected triangulation
  with V - E + F = 1 and one boundary loop, whose interior vertices are the
  other features; no interior edge joins two boundary features;
- orientation when laid on the surfaces: every L0 triangle has, at the
  landmarks of every model, a normal on the same side as the surface's
  normals at its corners (smoothed over 3 % of the diagonal); on the mask
  (nefertiti), whose front view shows the whole disk, L0 laid flat at its
  landmarks seen from the front has no flipped triangle.
"""

import argparse
import hashlib
import json
import os
import sys
import tarfile

import numpy

HERE = os.path.dirname(os.path.abspath(__file__))
# The model whose front view is a chart of the whole disk (a face mask):
# L0 must lay flat on it without a flipped triangle.
FLAT_MODEL = "nefertiti"


class Problems:
    """Collects the problems found."""

    def __init__(self):
        self.found = []

    def require(self, condition, message):
        if not condition:
            self.found.append(message)
            print("  PROBLEM: " + message)
        return condition


# ---------------------------------------------------------------- reading

def parse_off(text):
    """Points and triangles of an OFF text (polygons must be triangles)."""
    words = []
    for line in text.splitlines():
        words += line.split("#", 1)[0].split()
    if not words or words[0] != "OFF":
        raise ValueError("not an OFF file")
    nv, nf = int(words[1]), int(words[2])
    points = numpy.array(words[4:4 + 3 * nv], float).reshape(nv, 3)
    faces = numpy.array(words[4 + 3 * nv:4 + 3 * nv + 4 * nf], int).reshape(nf, 4)
    if not (faces[:, 0] == 3).all():
        raise ValueError("a polygon that is not a triangle")
    return points, faces[:, 1:]


def parse_obj(path):
    """Points and triangles of an OBJ file (`v` and `f` records, 1-based or
    negative indices, `#` comments)."""
    points, triangles = [], []
    with open(path) as lines:
        for line in lines:
            words = line.split("#", 1)[0].split()
            if not words:
                continue
            if words[0] == "v":
                points.append([float(x) for x in words[1:4]])
            elif words[0] == "f":
                ids = [int(w.split("/")[0]) for w in words[1:]]
                ids = [i - 1 if i > 0 else len(points) + i for i in ids]
                if len(ids) != 3:
                    raise ValueError("%s: a face that is not a triangle" % path)
                triangles.append(ids)
    return numpy.array(points, float), numpy.array(triangles, int).reshape(-1, 3)


def parse_landmarks(path):
    """(id, comment) per landmark line of a landmark file."""
    entries = []
    with open(path) as lines:
        for line in lines:
            data, _, comment = line.partition("#")
            words = data.split()
            if words:
                entries.append((int(words[-1]), comment.strip()))
    return entries


def comment_feature_and_position(comment):
    """The feature number and the (x y z) position of a landmark comment
    '# K name (x y z)'."""
    number = int(comment.split()[0])
    inside = comment[comment.rindex("(") + 1:comment.rindex(")")]
    return number, numpy.array([float(x) for x in inside.split()])


# ------------------------------------------------------------- topology

class Surface:
    """Topology of a triangle mesh: directed edges, boundary, loops."""

    def __init__(self, points, triangles):
        self.points = points
        self.triangles = triangles
        self.halfedges = {}
        self.repeated_halfedges = []
        for t, (a, b, c) in enumerate(triangles):
            for edge in ((a, b), (b, c), (c, a)):
                edge = (int(edge[0]), int(edge[1]))
                if edge in self.halfedges:
                    self.repeated_halfedges.append(edge)
                self.halfedges[edge] = t
        self.edges = {tuple(sorted(e)) for e in self.halfedges}
        self.boundary_halfedges = [e for e in self.halfedges if (e[1], e[0]) not in self.halfedges]
        self.boundary_vertices = {a for a, _ in self.boundary_halfedges}

    def euler(self):
        return len(self.points) - len(self.edges) + len(self.triangles)

    def degenerate_triangles(self):
        t = self.triangles
        return int(((t[:, 0] == t[:, 1]) | (t[:, 1] == t[:, 2]) | (t[:, 2] == t[:, 0])).sum())

    def non_manifold_vertices(self):
        """Vertices whose triangles do not form one fan (their link is not
        one path or one cycle)."""
        link = {}
        for a, b, c in self.triangles:
            for v, x, y in ((a, b, c), (b, c, a), (c, a, b)):
                link.setdefault(int(v), []).append((int(x), int(y)))
        bad = []
        for v, edges in link.items():
            following = {}
            ok = True
            for x, y in edges:
                if x in following:
                    ok = False
                following[x] = y
            if ok:
                starts = set(following) - set(following.values())
                if len(starts) > 1:
                    ok = False
                else:
                    start = starts.pop() if starts else next(iter(following))
                    seen, x = 0, start
                    while x in following and seen <= len(following):
                        x = following[x]
                        seen += 1
                        if x == start:
                            break
                    ok = seen == len(following)
            if not ok:
                bad.append(v)
        return bad

    def components(self):
        """Number of connected components (through shared vertices)."""
        parent = list(range(len(self.points)))

        def root(v):
            while parent[v] != v:
                parent[v] = parent[parent[v]]
                v = parent[v]
            return v
        for a, b, c in self.triangles:
            for x, y in ((a, b), (b, c)):
                rx, ry = root(int(x)), root(int(y))
                if rx != ry:
                    parent[rx] = ry
        used = numpy.unique(self.triangles)
        return len({root(int(v)) for v in used})

    def loops(self):
        """The boundary loops, each a vertex list in the loop direction
        (each boundary edge (a, b) as it appears in its triangle); None if a
        vertex starts two boundary edges (a pinched boundary)."""
        following = {}
        for a, b in self.boundary_halfedges:
            if a in following:
                return None
            following[a] = b
        loops, left = [], set(following)
        while left:
            start = min(left)
            loop = [start]
            left.discard(start)
            while following[loop[-1]] != start:
                loop.append(following[loop[-1]])
                left.discard(loop[-1])
            loops.append(loop)
        return loops

    def vertex_normals(self):
        """Area-weighted vertex normals (unit)."""
        corners = self.points[self.triangles]
        areas = numpy.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
        normals = numpy.zeros_like(self.points)
        for k in range(3):
            numpy.add.at(normals, self.triangles[:, k], areas)
        return normals / numpy.maximum(numpy.linalg.norm(normals, axis=1), 1e-300)[:, None]


def check_topology(problems, name, surface, want_loops=1):
    """The checks shared by the meshes and L0; returns the single boundary
    loop (or None)."""
    t = surface.triangles
    problems.require(len(t) > 0, "%s: no triangles" % name)
    problems.require(t.min() >= 0 and t.max() < len(surface.points), "%s: a triangle refers to no point" % name)
    problems.require(len(numpy.unique(t)) == len(surface.points), "%s: %d points are in no triangle"
                     % (name, len(surface.points) - len(numpy.unique(t))))
    problems.require(surface.degenerate_triangles() == 0, "%s: %d triangles repeat a vertex"
                     % (name, surface.degenerate_triangles()))
    problems.require(not surface.repeated_halfedges, "%s: directed edges %s appear in two triangles (not "
                     "consistently oriented, or an edge in more than two triangles)"
                     % (name, surface.repeated_halfedges[:5]))
    bad = surface.non_manifold_vertices()
    problems.require(not bad, "%s: non-manifold vertices %s" % (name, bad[:10]))
    problems.require(surface.components() == 1, "%s: %d connected components" % (name, surface.components()))
    loops = surface.loops()
    problems.require(loops is not None, "%s: a vertex starts two boundary edges" % name)
    problems.require(loops is not None and len(loops) == want_loops, "%s: %s boundary loops, not %d"
                     % (name, "?" if loops is None else len(loops), want_loops))
    problems.require(surface.euler() == 1, "%s: V - E + F = %d, not 1 (a disk)" % (name, surface.euler()))
    print("  V %d, E %d, F %d, V - E + F = %d; %s boundary loop(s) of %s edges" % (
        len(surface.points), len(surface.edges), len(t), surface.euler(),
        "?" if loops is None else len(loops), "?" if loops is None else [len(x) for x in loops]))
    return loops[0] if loops and len(loops) == 1 else None


def cyclic_sequence(loop, marked):
    """The marked vertices in the order a walk along `loop` meets them."""
    return [v for v in loop if v in marked]


def same_cycle(a, b):
    """Whether sequences a and b are the same cycle (same direction, any
    rotation)."""
    if len(a) != len(b):
        return False
    if not a:
        return True
    if a[0] not in b:
        return False
    k = b.index(a[0])
    return list(a) == list(b[k:]) + list(b[:k])


def ccw_area(p, q, r, normal):
    """Signed area of triangle (p, q, r) seen from `normal`."""
    return 0.5 * numpy.cross(q - p, r - p) @ normal


def smoothed_normals(surface, normals, vertices, radius):
    """Mean vertex normal within Euclidean `radius` of each vertex."""
    result = []
    for v in vertices:
        near = numpy.linalg.norm(surface.points - surface.points[v], axis=1) <= radius
        n = normals[near].sum(axis=0)
        result.append(n / numpy.linalg.norm(n))
    return numpy.array(result)


# ----------------------------------------------------------------- main

def open_meshes(collection, args):
    """A function NAME, MEMBER -> bytes of the mesh."""
    if args.meshes:
        return lambda member: open(os.path.join(args.meshes, member), "rb").read(), args.meshes
    paths = [args.archive] if args.archive else collection["archive"]["paths"]
    for path in paths:
        if os.path.exists(path):
            archive = tarfile.open(path)
            return lambda member: archive.extractfile(member).read(), path
    raise SystemExit("no archive: %s (install %s)" % (", ".join(paths), collection["archive"]["package"]))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--archive", help="the libcgal-demo data.tar.gz")
    parser.add_argument("--meshes", help="a folder holding data/meshes/NAME.off (the unpacked archive)")
    parser.add_argument("--folder", default=os.path.dirname(HERE), help="the collection (default: the one "
                        "above this script)")
    args = parser.parse_args()
    folder = args.folder
    problems = Problems()

    with open(os.path.join(folder, "collection.json")) as description:
        collection = json.load(description)
    read_member, source = open_meshes(collection, args)
    print("meshes from %s" % source)

    # L0 first: it says which features are on the boundary and in what order.
    domain_path = os.path.join(folder, collection["base_domain"])
    print("L0 %s" % collection["base_domain"])
    domain_points, domain_triangles = parse_obj(domain_path)
    domain = Surface(domain_points, domain_triangles)
    domain_loop = check_topology(problems, "L0", domain)
    features = len(domain_points)
    boundary_features = set(domain_loop or [])
    interior_features = set(range(features)) - boundary_features
    problems.require(len(boundary_features) >= 4, "L0: %d boundary vertices, fewer than 4" % len(boundary_features))
    boundary_edges = {tuple(sorted(h)) for h in domain.boundary_halfedges}
    chords = sorted(e for e in domain.edges if e[0] in boundary_features and e[1] in boundary_features
                    and e not in boundary_edges)
    problems.require(not chords, "L0: interior edges %s join two boundary features" % chords)
    print("  boundary loop %s, interior vertices %s, triangles %s" % (
        " -> ".join(map(str, domain_loop or [])), sorted(interior_features),
        " ".join("(%d,%d,%d)" % tuple(t) for t in domain_triangles)))

    first_positions = None
    for index, model in enumerate(collection["models"]):
        name = model["name"]
        print("%s (%s)" % (name, model["member"]))
        data = read_member(model["member"])
        digest = hashlib.sha256(data).hexdigest()
        problems.require(digest == model["sha256"], "%s: SHA-256 %s, the collection says %s"
                         % (name, digest, model["sha256"]))
        points, triangles = parse_off(data.decode())
        surface = Surface(points, triangles)
        unique_points = len(numpy.unique(points, axis=0))
        problems.require(unique_points == len(points), "%s: %d points repeat another's coordinates (the "
                         "reader would weld them)" % (name, len(points) - unique_points))
        loop = check_topology(problems, name, surface)
        diagonal = numpy.linalg.norm(points.max(axis=0) - points.min(axis=0))

        entries = parse_landmarks(os.path.join(folder, model["landmarks"]))
        ids = [v for v, _ in entries]
        if not problems.require(len(ids) == features, "%s: %d landmarks, L0 has %d vertices"
                                % (name, len(ids), features)):
            continue
        if not problems.require(all(0 <= v < len(points) for v in ids), "%s: an id out of range" % name):
            continue
        problems.require(len(set(ids)) == len(ids), "%s: two features on one vertex: %s" % (name, ids))
        for k, (v, comment) in enumerate(entries):
            number, position = comment_feature_and_position(comment)
            problems.require(number == k, "%s: line %d's comment names feature %d" % (name, k, number))
            problems.require(numpy.linalg.norm(position - points[v]) <= 1e-3 * diagonal,
                             "%s: feature %d's comment gives %s, vertex %d is at %s"
                             % (name, k, position, v, points[v]))
        on_boundary = {k for k, v in enumerate(ids) if v in surface.boundary_vertices}
        problems.require(on_boundary == boundary_features,
                         "%s: features %s are on the boundary, L0's boundary vertices are %s"
                         % (name, sorted(on_boundary), sorted(boundary_features)))
        if loop is not None:
            feature_of = {v: k for k, v in enumerate(ids)}
            met = [feature_of[v] for v in cyclic_sequence(loop, set(ids))]
            arcs = []
            positions = [loop.index(ids[k]) for k in met]
            for a, b in zip(positions, positions[1:] + positions[:1]):
                arcs.append((b - a) % len(loop))
            problems.require(same_cycle(met, domain_loop or []),
                             "%s: its boundary loop meets features %s, L0's loop is %s"
                             % (name, met, domain_loop))
            print("  boundary loop meets features %s (edges between them: %s); L0's loop %s: %s" % (
                " -> ".join(map(str, met)), arcs, " -> ".join(map(str, domain_loop or [])),
                "same cycle, same direction" if same_cycle(met, domain_loop or []) else "DIFFERENT"))
        landmark_points = points[ids]
        if index == 0:
            first_positions = landmark_points
        gaps = numpy.linalg.norm(landmark_points[:, None] - landmark_points[None], axis=2)
        gaps[numpy.arange(features), numpy.arange(features)] = numpy.inf
        print("  smallest distance between two landmarks: %.1f %% of the diagonal" % (100 * gaps.min() / diagonal))

        # Orientation of L0 laid on this model: each L0 triangle's normal at
        # the landmarks against the surface's normals at its corners
        # (smoothed over 3 % of the diagonal).
        normals = smoothed_normals(surface, surface.vertex_normals(), ids, 0.03 * diagonal)
        disagree = []
        for t in domain_triangles:
            a, b, c = landmark_points[t]
            if numpy.cross(b - a, c - a) @ normals[t].sum(axis=0) <= 0:
                disagree.append(tuple(t))
        problems.require(not disagree, "%s: L0 triangles %s, laid at its landmarks, face into the surface"
                         % (name, disagree))
        print("  L0 laid on it: %d of %d triangles face outwards like the surface at their corners" % (
            len(domain_triangles) - len(disagree), len(domain_triangles)))

        if name == FLAT_MODEL:
            # The mask seen from its mean normal (its front): L0 laid flat
            # at the landmarks must have no flipped triangle.
            corners = points[triangles]
            areas = numpy.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0])
            front = areas.sum(axis=0)
            front /= numpy.linalg.norm(front)
            flipped_surface = int((areas @ front < 0).sum())
            flat = [ccw_area(*landmark_points[t], front) for t in domain_triangles]
            flipped = [tuple(t) for t, a in zip(domain_triangles, flat) if a <= 0]
            problems.require(not flipped, "%s: L0 laid flat at its landmarks, seen from the front, has "
                             "flipped triangles %s" % (name, flipped))
            print("  seen from the front (%d of its %d triangles face away there): L0 laid flat at its "
                  "landmarks has %d flipped triangles, smallest signed area %.3g %% of the largest area" % (
                      flipped_surface, len(triangles), len(flipped), 100 * min(flat) / max(numpy.abs(flat))))

    if first_positions is not None:
        error = numpy.abs(domain_points - first_positions).max()
        scale = numpy.linalg.norm(first_positions.max(axis=0) - first_positions.min(axis=0))
        problems.require(error <= 1e-5 * scale, "L0: vertex positions differ from the first model's landmarks "
                         "by up to %g" % error)
        print("L0 vertex i is at feature i of %s (largest difference %.2g)" % (collection["models"][0]["name"], error))

    if problems.found:
        print("%d PROBLEM%s:" % (len(problems.found), "" if len(problems.found) == 1 else "S"))
        for problem in problems.found:
            print("  " + problem)
        return 1
    print("OK")
    return 0


if __name__ == "__main__":
    sys.exit(main())
