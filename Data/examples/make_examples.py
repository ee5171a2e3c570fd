"""Generates the small example collection shipped in Data/examples: three
genus-0 shapes of different geometry and sampling, each with the same six
landmarks (the tips along +x, -x, +y, -y, +z, -z), in three file formats.

Usage: /usr/bin/python3 make_examples.py   (needs numpy; writes next to itself)
"""
import os

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))


def icosphere(levels):
    t = (1 + 5 ** 0.5) / 2
    points = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t),
              (0, -1, -t), (0, 1, -t), (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
             (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5),
             (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    points = [np.array(p, float) / np.linalg.norm(p) for p in points]
    for _ in range(levels):
        midpoint = {}
        def middle(a, b):
            key = (min(a, b), max(a, b))
            if key not in midpoint:
                p = points[a] + points[b]
                points.append(p / np.linalg.norm(p))
                midpoint[key] = len(points) - 1
            return midpoint[key]
        refined = []
        for a, b, c in faces:
            ab, bc, ca = middle(a, b), middle(b, c), middle(c, a)
            refined += [(a, ab, ca), (ab, b, bc), (ca, bc, c), (ab, bc, ca)]
        faces = refined
    return np.array(points), np.array(faces)


def tips(points):
    """Vertices furthest along +x, -x, +y, -y, +z, -z: landmarks 0..5."""
    return [int(np.argmax(points[:, 0])), int(np.argmin(points[:, 0])), int(np.argmax(points[:, 1])),
            int(np.argmin(points[:, 1])), int(np.argmax(points[:, 2])), int(np.argmin(points[:, 2]))]


def shapes():
    sphere, faces3 = icosphere(3)
    yield "blob", sphere * (1 + 0.15 * np.sin(3 * sphere[:, [0]]) * np.cos(2 * sphere[:, [1]])), faces3
    fine, faces4 = icosphere(4)
    yield "capsule", fine * np.array([2.0, 0.8, 0.7]), faces4
    peanut = sphere * np.array([1.6, 1.0, 1.0])
    peanut[:, 1:] *= (0.65 + 0.35 * np.abs(sphere[:, [0]]))
    yield "peanut", peanut, faces3


def write_off(path, points, faces):
    with open(path, "w") as out:
        out.write("OFF\n%d %d 0\n" % (len(points), len(faces)))
        out.writelines("%.6f %.6f %.6f\n" % tuple(p) for p in points)
        out.writelines("3 %d %d %d\n" % tuple(f) for f in faces)


def write_obj(path, points, faces):
    with open(path, "w") as out:
        out.writelines("v %.6f %.6f %.6f\n" % tuple(p) for p in points)
        out.writelines("f %d %d %d\n" % tuple(f + 1) for f in faces)


def main():
    for name, points, faces in shapes():
        landmarks = tips(points)
        assert len(set(landmarks)) == 6, name
        if name == "blob":
            write_off(os.path.join(HERE, name + ".off"), points, faces)
            with open(os.path.join(HERE, name + ".vts"), "w") as out:
                out.writelines("%d %.6f %.6f %.6f\n" % ((v,) + tuple(points[v])) for v in landmarks)
        elif name == "capsule":
            write_obj(os.path.join(HERE, name + ".obj"), points, faces)
            with open(os.path.join(HERE, name + ".pinned"), "w") as out:
                out.writelines("lk %d\n" % v for v in landmarks)
        else:
            write_off(os.path.join(HERE, name + ".off"), points, faces)
            with open(os.path.join(HERE, name + ".csv"), "w") as out:
                out.write("x,y,z\n")
                out.writelines("%.4f,%.4f,%.4f\n" % tuple(points[v]) for v in landmarks)


if __name__ == "__main__":
    main()
