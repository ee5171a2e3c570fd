"""Held-out landmark error of consistent-remesh (issue 24, "Correspondence").

  pvpython held_out_landmarks.py --command <build>/bin/consistent-remesh
                                 --output DIR [--data DATA] [--level 5]
                                 [--subsets 3] [--seed 24] [--models ...]
                                 [--config NAME=FLAGS ...]

(pvpython or any Python with ParaView's vtk and numpy.)

The pipeline gets 15 of each model's 21 landmarks; the other 6 are held out.
L0 is built from the first model (--base-domain-from 0) with the 15, and
every model is remeshed (level 5, defaults otherwise). Each held-out
landmark is then carried from model i to model j through the remeshes:

- on model i, the remesh point that stands for the landmark is the point of
  model i's remesh closest to the landmark's true position (the landmark's
  vertex of the input file): a triangle id and barycentric coordinates;
- the same triangle and barycentric coordinates on model j's remesh (one
  connectivity, one vertex order) give the carried point;
- its error is the 3D Euclidean distance from the carried point to model
  j's true landmark position, divided by the square root of model j's
  surface area (of the input mesh).

The mean is over all held-out landmarks and all ordered pairs (i, j), i != j.
The target of issue 24 is a mean below 3 % of sqrt(area).

Subsets are drawn, not chosen: random.Random(seed).sample(range(21), 6) in
turn. A subset whose 15 landmarks make no valid layout (the command fails on
some model with the default options) is redrawn, and counted. The same
subsets are then used for every configuration.

Writes DIR/held_out_landmarks.md and DIR/held_out_landmarks.json, and keeps
each run's output in DIR/runs/<config>-<subset>/.
"""

import argparse
import json
import math
import os
import random
import shutil
import subprocess
import sys
import time

import numpy

LANDMARK_COUNT = 21
HELD_OUT = 6

# The SHREC'07 four-legged models with landmarks and Spot, in this order
# (the first one builds L0).
DEFAULT_MODELS = ["381", "382", "383", "384", "385", "387", "388", "389", "391", "392", "spot"]

DEFAULT_CONFIGS = [
    ("default", []),
    ("no-free-curves", ["--no-free-curves"]),
    ("relax-samples-4", ["--relax-samples", "4"]),
]


# ---------------------------------------------------------------------------
# Input files, read in the file's own vertex order (landmark ids index it;
# the project's reader may weld duplicated points and renumber).

def read_mesh(path):
    """(points (n, 3), triangles (m, 3)) of an .off or .obj file, in the
    file's vertex order; polygons are fan-triangulated."""
    if path.lower().endswith(".off"):
        return _read_off(path)
    if path.lower().endswith(".obj"):
        return _read_obj(path)
    raise ValueError("cannot read %s (.off or .obj only)" % path)


def _read_off(path):
    words = []
    with open(path) as f:
        for line in f:
            words.extend(line.split("#", 1)[0].split())
    if not words or words[0] != "OFF":
        raise ValueError("%s: no OFF header" % path)
    n, m = int(words[1]), int(words[2])
    at = 4
    points = numpy.array(words[at:at + 3 * n], dtype=float).reshape(n, 3)
    at += 3 * n
    triangles = []
    for _ in range(m):
        k = int(words[at])
        ids = [int(w) for w in words[at + 1:at + 1 + k]]
        at += 1 + k
        triangles.extend((ids[0], ids[t], ids[t + 1]) for t in range(1, k - 1))
    return points, numpy.array(triangles, dtype=int)


def _read_obj(path):
    points, triangles = [], []
    with open(path) as f:
        for line in f:
            words = line.split("#", 1)[0].split()
            if not words:
                continue
            if words[0] == "v":
                points.append([float(w) for w in words[1:4]])
            elif words[0] == "f":
                ids = []
                for w in words[1:]:
                    i = int(w.split("/")[0])
                    ids.append(i - 1 if i > 0 else len(points) + i)
                triangles.extend((ids[0], ids[t], ids[t + 1]) for t in range(1, len(ids) - 1))
    return numpy.array(points, dtype=float), numpy.array(triangles, dtype=int)


def surface_area(points, triangles):
    a, b, c = (points[triangles[:, k]] for k in range(3))
    return 0.5 * numpy.linalg.norm(numpy.cross(b - a, c - a), axis=1).sum()


def landmark_lines(path):
    """The non-blank, non-comment lines of a landmark file (line k is
    feature k)."""
    lines = []
    with open(path) as f:
        for line in f:
            if line.split("#", 1)[0].strip():
                lines.append(line.rstrip("\n"))
    return lines


def landmark_vertex_ids(path):
    """The file vertex id of each feature: the first word of a .vts line, the
    last of an `lk ID` line."""
    ids = []
    for line in landmark_lines(path):
        words = line.split("#", 1)[0].split()
        ids.append(int(words[0] if path.lower().endswith(".vts") else words[-1]))
    return ids


def write_reduced_landmarks(path, out_path, held_out):
    """Writes `path` without the lines of the features in `held_out`, in the
    same format (the kept features are renumbered 0..14 in order)."""
    lines = landmark_lines(path)
    if len(lines) != LANDMARK_COUNT:
        raise ValueError("%s has %d landmarks, not %d" % (path, len(lines), LANDMARK_COUNT))
    with open(out_path, "w") as out:
        for k, line in enumerate(lines):
            if k not in held_out:
                out.write(line + "\n")
    return out_path


def model_files(data, name):
    """(mesh, landmarks) of a model of the shared data: a SHREC'07 number or
    spot."""
    if name == "spot":
        return os.path.join(data, "spot", "spot.obj"), os.path.join(data, "spot", "spot_shrec07.pinned")
    folder = os.path.join(data, "shrec07-fourleg")
    return os.path.join(folder, name + ".off"), os.path.join(folder, name + ".vts")


class Model:
    """An input model: its file-order points, surface area and the true
    position of each of the 21 landmarks."""

    def __init__(self, data, name):
        self.name = name
        self.mesh, self.landmarks = model_files(data, name)
        points, triangles = read_mesh(self.mesh)
        self.area = surface_area(points, triangles)
        self.true_positions = points[landmark_vertex_ids(self.landmarks)]


# ---------------------------------------------------------------------------
# Remeshes and the carried error.

def read_remesh(path):
    """(points (n, 3), triangles (m, 3)) of a remesh .vtp."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    polydata = reader.GetOutput()
    if polydata.GetNumberOfCells() == 0:
        raise ValueError("%s has no triangles" % path)
    points = vtk_to_numpy(polydata.GetPoints().GetData()).astype(float)
    polys = polydata.GetPolys()
    offsets = vtk_to_numpy(polys.GetOffsetsArray())
    if not numpy.all(numpy.diff(offsets) == 3):
        raise ValueError("%s has cells that are not triangles" % path)
    triangles = vtk_to_numpy(polys.GetConnectivityArray()).reshape(-1, 3).astype(int)
    return points, triangles


def closest_points(points, triangles, queries):
    """For each query point, the closest point of the triangle surface as
    (triangle id, barycentric coordinates (3,))."""
    from vtkmodules.vtkCommonCore import reference, vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
    from vtkmodules.vtkCommonDataModel import vtkStaticCellLocator

    vtk_points = vtkPoints()
    vtk_points.SetDataTypeToDouble()
    for p in points:
        vtk_points.InsertNextPoint(*p)
    cells = vtkCellArray()
    for t in triangles:
        cells.InsertNextCell(3, [int(v) for v in t])
    polydata = vtkPolyData()
    polydata.SetPoints(vtk_points)
    polydata.SetPolys(cells)
    locator = vtkStaticCellLocator()
    locator.SetDataSet(polydata)
    locator.BuildLocator()

    result = []
    for q in queries:
        closest = [0.0, 0.0, 0.0]
        cell, sub, dist2 = reference(0), reference(0), reference(0.0)
        locator.FindClosestPoint([float(x) for x in q], closest, cell, sub, dist2)
        t = int(cell)
        result.append((t, barycentric(points[triangles[t]], numpy.array(closest))))
    return result


def barycentric(corners, x):
    """The barycentric coordinates of x (on or by the triangle `corners`,
    (3, 3)) in that triangle, clamped to it."""
    a, b, c = corners
    e1, e2, d = b - a, c - a, x - a
    g = numpy.array([[e1 @ e1, e1 @ e2], [e1 @ e2, e2 @ e2]])
    try:
        u, v = numpy.linalg.solve(g, [d @ e1, d @ e2])
    except numpy.linalg.LinAlgError:  # a degenerate triangle: its nearest corner
        w = numpy.zeros(3)
        w[int(numpy.argmin(numpy.linalg.norm(corners - x, axis=1)))] = 1.0
        return w
    w = numpy.clip(numpy.array([1.0 - u - v, u, v]), 0.0, 1.0)
    return w / w.sum()


def carried_errors(models, remeshes, held_out, triangle_order=None):
    """The carried error of every held-out feature and ordered pair (i, j):
    a list of dicts. `remeshes[i]` is (points, triangles) of model i's
    remesh. `triangle_order`, when given, reads triangle t of the remesh of
    model j as triangle triangle_order[t] (a broken correspondence, to check
    that the measure notices it)."""
    first = remeshes[0][1]
    for model, (_, triangles) in zip(models, remeshes):
        if not numpy.array_equal(triangles, first):
            raise ValueError("the remesh of %s has another connectivity than %s's" % (model.name, models[0].name))
    located = [closest_points(p, t, model.true_positions[held_out]) for model, (p, t) in zip(models, remeshes)]
    errors = []
    for i, source in enumerate(models):
        for j, target in enumerate(models):
            if i == j:
                continue
            points, triangles = remeshes[j]
            for k, feature in enumerate(held_out):
                t, w = located[i][k]
                if triangle_order is not None:
                    t = triangle_order[t]
                carried = w @ points[triangles[t]]
                d = float(numpy.linalg.norm(carried - target.true_positions[feature]))
                errors.append({"from": source.name, "to": target.name, "feature": int(feature),
                               "distance": d, "per_sqrt_area": d / math.sqrt(target.area)})
    return errors


def summary(errors):
    values = numpy.array([e["per_sqrt_area"] for e in errors])
    worst = max(errors, key=lambda e: e["per_sqrt_area"])
    return {"mean": float(values.mean()), "median": float(numpy.median(values)),
            "p90": float(numpy.percentile(values, 90)), "worst": float(values.max()),
            "worst_case": worst, "count": int(values.size)}


def per_feature(errors):
    features = sorted({e["feature"] for e in errors})
    return {f: float(numpy.mean([e["per_sqrt_area"] for e in errors if e["feature"] == f])) for f in features}


# ---------------------------------------------------------------------------
# Runs of the command.

def run_command(command, models, held_out, landmark_folder, output, level, flags, log=None, reuse=False):
    """Runs the command on `models` with the held-out landmarks removed.
    Returns (ok, message, seconds): ok when every model was remeshed. With
    `reuse`, a finished earlier run in `output` of the same arguments is
    read again instead (seconds then come from its report)."""
    os.makedirs(landmark_folder, exist_ok=True)
    arguments = [command]
    for model in models:
        reduced = os.path.join(landmark_folder, os.path.basename(model.landmarks))
        write_reduced_landmarks(model.landmarks, reduced, held_out)
        arguments += ["--mesh", model.mesh, "--landmarks", reduced]
    arguments += ["--base-domain-from", "0", "--level", str(level), "--no-render"] + list(flags)
    arguments += ["--output", output]
    if reuse and log and os.path.exists(log):
        with open(log) as f:
            if f.readline().rstrip("\n") == " ".join(arguments):
                return _check_run(models, output, 0, "the earlier run") + (_logged_seconds(log),)
    if os.path.exists(output):
        shutil.rmtree(output)
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PV_PLUGIN_PATH")}
    start = time.time()
    result = subprocess.run(arguments, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            universal_newlines=True)
    seconds = time.time() - start
    if log:
        with open(log, "w") as f:
            f.write(" ".join(arguments) + "\n\n" + result.stdout + "\n# seconds %.1f\n" % seconds)
    last = (result.stdout.strip().splitlines() or [""])[-1]
    return _check_run(models, output, result.returncode, last) + (seconds,)


def _check_run(models, output, status, last_line):
    report_path = os.path.join(output, "report.json")
    if status != 0 or not os.path.exists(report_path):
        return False, "exit status %d: %s" % (status, last_line)
    with open(report_path) as f:
        report = json.load(f)
    if report.get("failed"):
        return False, "failed models: %s" % report["failed"]
    for model in models:
        if not os.path.exists(remesh_path(output, model)):
            return False, "no remesh of %s" % model.name
    return True, "ok"


def _logged_seconds(log):
    """The time a logged run took (its last line, "# seconds N"), or 0."""
    with open(log) as f:
        lines = f.read().strip().splitlines()
    if lines and lines[-1].startswith("# seconds "):
        return float(lines[-1].split()[-1])
    return 0.0


def effective_settings(output):
    """What the run did, from its report (defaults change): free curves,
    rounds of sample relaxation, fold repair, level."""
    with open(os.path.join(output, "report.json")) as f:
        report = json.load(f)
    free = {m.get("straighten", {}).get("free_curves") for m in report["models"].values()}
    remesh = report["remesh"]
    return {"free_curves": free.pop() if len(free) == 1 else sorted(free, key=str),
            "relax_samples": remesh.get("sample_relaxation_rounds"),
            "fold_repair": remesh.get("fold_repair"), "level": remesh.get("level")}


def remesh_path(output, model):
    return os.path.join(output, model.name + ".remesh.vtp")


def measure(models, output, held_out):
    remeshes = [read_remesh(remesh_path(output, m)) for m in models]
    return carried_errors(models, remeshes, held_out), remeshes


def draw_subsets(rng):
    """An endless sequence of sorted 6-landmark subsets of 0..20."""
    while True:
        yield sorted(rng.sample(range(LANDMARK_COUNT), HELD_OUT))


def parse_config(text):
    name, _, flags = text.partition("=")
    return name, flags.split()


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--command", required=True, help="consistent-remesh")
    parser.add_argument("--output", required=True, help="output folder")
    parser.add_argument("--data", default=os.environ.get("CMP_SHARED_DATA_DIR", "/work/shared/data"),
                        help="the shared data folder (default $CMP_SHARED_DATA_DIR)")
    parser.add_argument("--level", type=int, default=5)
    parser.add_argument("--subsets", type=int, default=3, help="number of valid subsets (default 3)")
    parser.add_argument("--seed", type=int, default=24)
    parser.add_argument("--models", nargs="+", default=DEFAULT_MODELS)
    parser.add_argument("--config", action="append", type=parse_config,
                        help="NAME=FLAGS, e.g. 'fixed=--no-free-curves' (repeat; default: default, "
                             "no-free-curves, relax-samples-4)")
    parser.add_argument("--max-draws", type=int, default=20)
    parser.add_argument("--reuse", action="store_true",
                        help="read the runs already in OUTPUT/runs again where their command line is the same")
    args = parser.parse_args(argv)
    configs = args.config or DEFAULT_CONFIGS
    command = os.path.abspath(args.command)

    models = [Model(args.data, name) for name in args.models]
    os.makedirs(args.output, exist_ok=True)
    runs = os.path.join(args.output, "runs")

    # Draw the subsets with the first configuration; a subset on which it
    # fails is redrawn.
    rng = random.Random(args.seed)
    subsets, redrawn, results = [], [], {}
    first_name, first_flags = configs[0]
    for draws, held_out in enumerate(draw_subsets(rng)):
        if len(subsets) == args.subsets:
            break
        if draws >= args.max_draws:
            sys.exit("held_out_landmarks: %d draws gave only %d valid subsets" % (draws, len(subsets)))
        s = len(subsets)
        ok, message, seconds, result = run_and_measure(args, command, models, runs, first_name, first_flags, s,
                                                       held_out)
        if not ok:
            print("  redrawn: %s" % message, flush=True)
            redrawn.append({"held_out": held_out, "reason": message})
            continue
        subsets.append(held_out)
        results[(first_name, s)] = result

    for name, flags in configs[1:]:
        for s, held_out in enumerate(subsets):
            ok, message, seconds, result = run_and_measure(args, command, models, runs, name, flags, s, held_out)
            if not ok:
                print("  failed: %s" % message, flush=True)
                result = {"errors": [], "seconds": seconds, "status": message}
            results[(name, s)] = result

    write_results(args, configs, models, subsets, redrawn, results)


def run_and_measure(args, command, models, runs, name, flags, s, held_out):
    """Runs configuration `name` on subset `s` and measures it: (ok, message,
    seconds, the result's entry)."""
    output = os.path.join(runs, "%s-%d" % (name, s))
    print("subset %s: running %s" % (held_out, name), flush=True)
    ok, message, seconds = run_command(command, models, held_out, os.path.join(runs, "landmarks-%d" % s),
                                       output, args.level, flags, log=output + ".log", reuse=args.reuse)
    if not ok:
        return ok, message, seconds, None
    errors, _ = measure(models, output, held_out)
    print("  mean %.2f %%, worst %.2f %% (%.0f s)" % (100 * summary(errors)["mean"], 100 * summary(errors)["worst"],
                                                  seconds), flush=True)
    return ok, message, seconds, {"errors": errors, "seconds": seconds, "status": "ok",
                                  "settings": effective_settings(output)}


def write_results(args, configs, models, subsets, redrawn, results):
    table = {"level": args.level, "seed": args.seed, "models": [m.name for m in models],
             "subsets": subsets, "redrawn": redrawn, "configs": {}}
    lines = ["# Held-out landmark error", "",
             "%d models (%s), L0 from %s, level %d; %d of %d landmarks held out; subsets drawn with "
             "random.Random(%d).sample(range(%d), %d), %d redrawn." % (
                 len(models), " ".join(m.name for m in models), models[0].name, args.level, HELD_OUT,
                 LANDMARK_COUNT, args.seed, LANDMARK_COUNT, HELD_OUT, len(redrawn)), "",
             "Error: 3D distance from the carried point to the true landmark over sqrt(area) of the "
             "target model; mean and worst over held-out landmarks and ordered pairs i != j. Target: "
             "mean < 3 %.", "",
             "| configuration | subset | held out | mean % | median % | 90th % | worst % | worst case | run as | seconds |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for name, flags in configs:
        entry = {"flags": flags, "subsets": []}
        pooled = []
        for s, held_out in enumerate(subsets):
            r = results.get((name, s))
            if r is None or r["status"] != "ok":
                status = r["status"] if r else "not run"
                entry["subsets"].append({"held_out": held_out, "status": status})
                lines.append("| %s | %d | %s | %s | | | | | | |" % (name, s, held_out, status))
                continue
            pooled += r["errors"]
            sm = summary(r["errors"])
            entry["subsets"].append({"held_out": held_out, "status": "ok", "seconds": r["seconds"],
                                     "settings": r["settings"], "summary": sm,
                                     "per_feature": per_feature(r["errors"]), "errors": r["errors"]})
            w = sm["worst_case"]
            settings = r["settings"]
            run_as = "%s curves, relax %s" % ("free" if settings["free_curves"] is True else
                                             "fixed" if settings["free_curves"] is False else settings["free_curves"],
                                             settings["relax_samples"])
            lines.append("| %s | %d | %s | %.2f | %.2f | %.2f | %.2f | feature %d, %s -> %s | %s | %.0f |" % (
                name, s, held_out, 100 * sm["mean"], 100 * sm["median"], 100 * sm["p90"], 100 * sm["worst"],
                w["feature"], w["from"], w["to"], run_as, r["seconds"]))
        if pooled:
            sm = summary(pooled)
            entry["all"] = {k: v for k, v in sm.items()}
            w = sm["worst_case"]
            lines.append("| **%s** | all | | **%.2f** | %.2f | %.2f | **%.2f** | feature %d, %s -> %s | | |" % (
                name, 100 * sm["mean"], 100 * sm["median"], 100 * sm["p90"], 100 * sm["worst"],
                w["feature"], w["from"], w["to"]))
        table["configs"][name] = entry
    if redrawn:
        lines += ["", "Redrawn subsets:", ""] + ["- %s: %s" % (r["held_out"], r["reason"]) for r in redrawn]
    with open(os.path.join(args.output, "held_out_landmarks.json"), "w") as f:
        json.dump(table, f, indent=1)
    with open(os.path.join(args.output, "held_out_landmarks.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
