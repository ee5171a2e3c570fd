"""Placed-landmark error of consistent-remesh (issue 27 A, "Missing landmarks").

  pvpython missing_landmarks.py --command <build>/bin/consistent-remesh
                                --output DIR [--data DATA] [--level 5]
                                [--runs 3] [--seed 27] [--models ...]
                                [--base-domain L0.vtp]

(pvpython or any Python with numpy.)

Each run takes landmarks away from models where we know them: 1 or 2 each
(drawn) from 3 of the models (drawn), written as -1 in their .vts files, and
runs the command on every model with L0 given (by default the shared
four-legged template, layouts/fourleg-381.vtp). consistent-remesh places
the missing landmarks from the models that have them and remeshes every
model. The error of a placed landmark is the 3D distance from its position
(report.json's placed_landmarks) to the true landmark's, over the square
root of the model's surface area. The target of issue 27 is a mean below
5 % and a worst below 12 %, every model remeshed, and every other figure of
the collection as it was: each run is compared with one run on the complete
files (largest change of a model's Hausdorff distance, folds and flips).

Writes DIR/missing_landmarks.md and DIR/missing_landmarks.json, and keeps
each run's output in DIR/runs/.
"""

import argparse
import json
import math
import os
import random
import subprocess
import sys
import time

import numpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from held_out_landmarks import Model  # noqa: E402  (same folder)

DEFAULT_MODELS = ["381", "382", "383", "384", "385", "387", "388", "389"]
FEATURES = 21


def write_landmarks(model, folder, missing):
    """`model`'s .vts with the features `missing` written as -1."""
    with open(model.landmarks) as f:
        lines = f.read().splitlines()
    for feature in missing:
        lines[feature] = "-1"
    path = os.path.join(folder, os.path.basename(model.landmarks))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")
    return path


def run(command, models, landmark_paths, output, level, base_domain, log):
    arguments = [command]
    for model, path in zip(models, landmark_paths):
        arguments += ["--mesh", model.mesh, "--landmarks", path]
    arguments += ["--base-domain", base_domain, "--level", str(level), "--no-render", "--output", output]
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PV_PLUGIN_PATH")}
    start = time.time()
    result = subprocess.run(arguments, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            universal_newlines=True)
    seconds = time.time() - start
    with open(log, "w") as f:
        f.write(" ".join(arguments) + "\n\n" + result.stdout + "\n# seconds %.1f\n" % seconds)
    with open(os.path.join(output, "report.json")) as f:
        report = json.load(f)
    with open(os.path.join(output, "timings.json")) as f:
        timings = json.load(f)
    return report, timings, seconds, result.returncode


def figures(report):
    """Per model: (Hausdorff / diagonal, corner folds, centroid flips)."""
    out = {}
    for name, model in report["models"].items():
        remesh = model.get("remesh", {})
        out[name] = (remesh.get("hausdorff_per_diagonal"), remesh.get("flipped_triangles"),
                     remesh.get("centroid_flips"))
    return out


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--command", required=True)
    parser.add_argument("--output", required=True)
    parser.add_argument("--data", default=os.environ.get("CMP_SHARED_DATA_DIR", "/work/shared/data"))
    parser.add_argument("--level", type=int, default=5)
    parser.add_argument("--runs", type=int, default=3)
    parser.add_argument("--seed", type=int, default=27)
    parser.add_argument("--models", nargs="+", default=DEFAULT_MODELS)
    parser.add_argument("--base-domain", default=None, help="default: DATA/layouts/fourleg-381.vtp")
    args = parser.parse_args(argv)
    command = os.path.abspath(args.command)
    base_domain = args.base_domain or os.path.join(args.data, "layouts", "fourleg-381.vtp")
    models = [Model(args.data, name) for name in args.models]
    runs = os.path.join(args.output, "runs")
    os.makedirs(runs, exist_ok=True)

    print("complete files", flush=True)
    complete, _, complete_seconds, status = run(command, models, [m.landmarks for m in models],
                                                os.path.join(runs, "complete"), args.level, base_domain,
                                                os.path.join(runs, "complete.log"))
    if status != 0:
        sys.exit("the run on the complete files failed (exit status %d)" % status)
    before = figures(complete)

    rng = random.Random(args.seed)
    results = []
    for r in range(args.runs):
        chosen = sorted(rng.sample(range(len(models)), 3))
        missing = {i: sorted(rng.sample(range(FEATURES), rng.choice([1, 2]))) for i in chosen}
        folder = os.path.join(runs, "landmarks-%d" % r)
        os.makedirs(folder, exist_ok=True)
        paths = [write_landmarks(m, folder, missing.get(i, [])) if i in missing else m.landmarks
                 for i, m in enumerate(models)]
        print("run %d: %s" % (r, ", ".join("%s misses %s" % (models[i].name, missing[i]) for i in chosen)),
              flush=True)
        report, timings, seconds, status = run(command, models, paths, os.path.join(runs, "run-%d" % r),
                                               args.level, base_domain, os.path.join(runs, "run-%d.log" % r))
        errors = []
        for i in chosen:
            model = models[i]
            placed = report["models"][model.name].get("placed_landmarks", [])
            for entry in placed:
                d = numpy.linalg.norm(numpy.array(entry["position"]) - model.true_positions[entry["feature"]])
                errors.append({"model": model.name, "feature": entry["feature"],
                               "per_sqrt_area": float(d / math.sqrt(model.area)),
                               "spread": entry["spread_per_sqrt_area"]})
        after = figures(report)
        remeshed = sum(1 for m in report["models"].values() if m.get("status") == "ok")
        change = max(abs((after[n][0] or 0) - (before[n][0] or 0)) for n in before)
        fold_change = sum((after[n][1] or 0) - (before[n][1] or 0) for n in before)
        flip_change = sum((after[n][2] or 0) - (before[n][2] or 0) for n in before)
        placing = timings.get("placement", {}).get("seconds")
        result = {"missing": {models[i].name: missing[i] for i in chosen}, "errors": errors,
                  "placed": len(errors), "asked": sum(map(len, missing.values())), "remeshed": remeshed,
                  "models": len(models), "status": status, "seconds": seconds, "placement_seconds": placing,
                  "largest_hausdorff_change": change, "fold_change": fold_change, "flip_change": flip_change}
        values = [e["per_sqrt_area"] for e in errors] or [float("nan")]
        print("  placed %d of %d, mean %.2f %%, worst %.2f %%; %d of %d remeshed; Hausdorff moved at most "
              "%.3f %% of the diagonal, folds %+d, flips %+d; %.0f s (placing %s s)"
              % (len(errors), result["asked"], 100 * numpy.mean(values), 100 * numpy.max(values), remeshed,
                 len(models), 100 * change, fold_change, flip_change, seconds, placing), flush=True)
        results.append(result)

    every = [e["per_sqrt_area"] for r in results for e in r["errors"]]
    lines = ["# Placed-landmark error", "",
             "%d models (%s), L0 %s, level %d; per run 1 or 2 landmarks taken from 3 models (seed %d). "
             "Error: distance from the placed to the true landmark over sqrt(area). Target: mean < 5 %%, "
             "worst < 12 %%. The complete files took %.0f s." % (
                 len(models), " ".join(m.name for m in models), base_domain, args.level, args.seed,
                 complete_seconds), "",
             "| run | missing | placed | mean % | worst % | remeshed | Hausdorff change (% of diagonal) | folds | "
             "flips | seconds (placing) |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r, result in enumerate(results):
        values = [e["per_sqrt_area"] for e in result["errors"]] or [float("nan")]
        lines.append("| %d | %s | %d of %d | %.2f | %.2f | %d of %d | %.3f | %+d | %+d | %.0f (%s) |" % (
            r, "; ".join("%s: %s" % (n, f) for n, f in result["missing"].items()), result["placed"],
            result["asked"], 100 * numpy.mean(values), 100 * numpy.max(values), result["remeshed"],
            result["models"], 100 * result["largest_hausdorff_change"], result["fold_change"],
            result["flip_change"], result["seconds"], result["placement_seconds"]))
    lines.append("| **all** | | %d | **%.2f** | **%.2f** | | | | | |" % (
        len(every), 100 * numpy.mean(every), 100 * numpy.max(every)))
    with open(os.path.join(args.output, "missing_landmarks.md"), "w") as f:
        f.write("\n".join(lines) + "\n")
    with open(os.path.join(args.output, "missing_landmarks.json"), "w") as f:
        json.dump({"level": args.level, "seed": args.seed, "base_domain": base_domain,
                   "models": [m.name for m in models], "complete": before, "runs": results}, f, indent=2)
    print("\n".join(lines))


if __name__ == "__main__":
    main()
