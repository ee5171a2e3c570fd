"""Held-out landmarks: how well the remeshes correspond away from the
landmarks the pipeline is given (issue 24, "Correspondence").

  pvpython TestHeldOutLandmarks.py --command <build>/bin/consistent-remesh
                                   --data <shared data>

Five models of the shared data (the first four SHREC'07 four-legged models
with landmarks, 381 382 383 384, and Spot) get 15 of their 21 landmarks:
features HELD_OUT are left out of their landmark files. consistent-remesh
builds L0 from 381 with the 15 and remeshes all five at level 4, with the
default options. Each held-out landmark is then carried from model i to
model j through the remeshes (the closest point of model i's remesh to the
true landmark, as a triangle and barycentric coordinates, is read on model
j's remesh) and compared, by 3D distance, with model j's true landmark,
over the square root of model j's surface area. The measure is
Testing/Benchmark/held_out_landmarks.py's, which runs the full version
(eleven models, level 5, three subsets, three configurations).

The target is issue 24's: a mean carried error below 3 % of sqrt(area)
over all held-out landmarks and ordered pairs. It is not met: in this
setting the default (free curves, 4 rounds of sample relaxation) gives
7.4 % to 8.2 % as the map changed (worst 24 % to 42 %, on feature 5, a
front hoof), the paper's fixed curves (--no-free-curves) 8.2 %, and the
benchmark (eleven models, level 5, three subsets) 9.8 %, 11.2 % with fixed
curves. So MEAN_BOUND is not the target: it says the correspondence away
from the landmarks has not fallen well behind what fixed curves give (a
broken one gives 33 % or more). Lower it towards 3 % as the map
improves.

HELD_OUT is the first subset drawn by random.Random(24).sample(range(21), 6),
the benchmark's first draw; it was not chosen for its result.

So that the test can fail, it also checks that the measure notices a broken
correspondence: the same points carried through a shuffled triangle order
must come out far above the bound; and the kept landmarks, which are remesh
vertices on every model, must be carried exactly.
"""

import argparse
import os
import random
import sys
import tempfile

sys.dont_write_bytecode = True  # keep the source folder clean

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, "Benchmark"))
import held_out_landmarks as measure  # noqa: E402

from cmp_test_support import check, check_equal  # noqa: E402

MODELS = ["381", "382", "383", "384", "spot"]
HELD_OUT = [5, 6, 12, 17, 18, 19]
LEVEL = 4
# Issue 24's target (not yet met: 7.4 % to 8.2 % in this setting).
TARGET = 0.03
# Not far behind the 8.2 % that --no-free-curves (the paper's fixed curves)
# gives in this setting.
MEAN_BOUND = 0.10
# A broken correspondence carries points to unrelated places (33 % to 41 %
# measured): at least this many times the bound.
BROKEN_FACTOR = 2.5


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--command", required=True)
    parser.add_argument("--data", required=True)
    args = parser.parse_args()

    check_equal(HELD_OUT, sorted(random.Random(24).sample(range(21), 6)), "the first subset of seed 24")
    models = [measure.Model(args.data, name) for name in MODELS]
    kept = [f for f in range(measure.LANDMARK_COUNT) if f not in HELD_OUT]
    with tempfile.TemporaryDirectory(prefix="held-out-landmarks-") as folder:
        output = os.path.join(folder, "out")
        ok, message, seconds = measure.run_command(args.command, models, HELD_OUT, os.path.join(folder, "landmarks"),
                                                   output, LEVEL, [], log=os.path.join(folder, "log.txt"))
        if not ok:
            with open(os.path.join(folder, "log.txt")) as f:
                sys.stdout.write(f.read())
        check(ok, "consistent-remesh with landmarks %s held out: %s" % (HELD_OUT, message))
        for model in models:
            with open(os.path.join(folder, "landmarks", os.path.basename(model.landmarks))) as f:
                check_equal(len([line for line in f if line.strip()]), len(kept),
                            "landmarks given for " + model.name)
        errors, remeshes = measure.measure(models, output, HELD_OUT)

    check_equal(len(errors), len(HELD_OUT) * len(models) * (len(models) - 1), "carried landmarks")
    result = measure.summary(errors)
    worst = result["worst_case"]
    print("held out %s: mean %.2f %%, median %.2f %%, worst %.2f %% (feature %d, %s -> %s), %.0f s"
          % (HELD_OUT, 100 * result["mean"], 100 * result["median"], 100 * result["worst"],
             worst["feature"], worst["from"], worst["to"], seconds))
    for feature, mean in measure.per_feature(errors).items():
        print("  feature %2d: mean %.2f %%" % (feature, 100 * mean))

    # The carrying itself: the kept landmarks are remesh vertices (exact on
    # every model), so they arrive where they are.
    exact = measure.summary(measure.carried_errors(models, remeshes, kept))
    check(exact["worst"] < 1e-6, "a kept landmark is carried %.3g sqrt(area) away from itself" % exact["worst"])

    # A broken correspondence must show: triangle t of the target remesh
    # read as another triangle.
    order = list(range(len(remeshes[0][1])))
    random.Random(1).shuffle(order)
    broken = measure.summary(measure.carried_errors(models, remeshes, HELD_OUT, triangle_order=order))
    print("through a shuffled triangle order: mean %.2f %%" % (100 * broken["mean"]))
    check(broken["mean"] > BROKEN_FACTOR * MEAN_BOUND,
          "a shuffled triangle order gives a mean of only %.2f %% of sqrt(area): the measure cannot tell"
          % (100 * broken["mean"]))

    print("issue 24's target, a mean below %.0f %%: %s" % (100 * TARGET, "met" if result["mean"] < TARGET else "not met"))
    check(result["mean"] < MEAN_BOUND,
          "held-out landmarks %s: mean carried error %.2f %% of sqrt(area), not below %.1f %% (the paper's "
          "fixed curves give 8.2 %% here; issue 24's target is %.0f %%)"
          % (HELD_OUT, 100 * result["mean"], 100 * MEAN_BOUND, 100 * TARGET))


if __name__ == "__main__":
    main()
