"""The ParaView GUI test: paraview itself, under Xvfb, loads the plugin,
opens the state file Data/cgal-quadrupeds/quadrupeds-state.py (the whole
pipeline on the default collection), and its screenshot of the active view
must match the baseline within ParaView's image threshold. ParaView's test
options do the comparison: a test script of no events (no_events.xml; the
GUI's Python test scripts are event recordings, not code) followed by
--test-baseline. --state cannot go with --script, so gui_checks.py, run by
--script, loads the state.

  pvpython TestGUIState.py --paraview PARAVIEW --xvfb-run XVFB_RUN
      --plugin-dir DIR --state STATE --baseline PNG --output DIR

With --rebaseline the test image is copied over the baseline (after a
change that alters the picture on purpose; look at it first).
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
THRESHOLD = 10  # ParaView's image difference threshold, its tests' default
MODELS = ["triceratops", "camel", "bull", "bear", "bear_bis"]
REMESH_VERTICES = 4866  # level 4 on the 38 triangles of L0


def fail(message):
    print("FAILED: " + message)
    sys.exit(1)


def main():
    parser = argparse.ArgumentParser()
    for option in ("--paraview", "--xvfb-run", "--plugin-dir", "--state", "--baseline", "--output"):
        parser.add_argument(option, required=True)
    parser.add_argument("--rebaseline", action="store_true")
    args = parser.parse_args()
    shutil.rmtree(args.output, ignore_errors=True)
    os.makedirs(args.output)
    checks_file = os.path.join(args.output, "checks.json")
    # The plugin must come from --plugins, not from a developer's own path.
    environment = {k: v for k, v in os.environ.items() if k != "PV_PLUGIN_PATH"}
    environment.update(CMP_GUI_CHECKS=checks_file, CMP_GUI_OUTPUT=args.output,
                       CMP_GUI_STATE=os.path.abspath(args.state))
    command = [args.xvfb_run, "-a", "-s", "-screen 0 1400x900x24", args.paraview, "--dr",
               "--plugin-search-paths=" + args.plugin_dir, "--plugins=ConsistentMeshParameterizations",
               "--script=" + os.path.join(HERE, "gui_checks.py"), "--test-script=" + os.path.join(HERE, "no_events.xml"),
               "--test-baseline=" + args.baseline, "--test-threshold=%d" % THRESHOLD,
               "--test-directory=" + args.output, "--exit"]
    # Below ctest's timeout (300 s times the same factor): a report, not a kill.
    factor = os.environ.get("CMP_TEST_TIMEOUT_FACTOR", "1")
    factor = int(factor) if factor.isdigit() and int(factor) > 0 else 1
    result = subprocess.run(command, env=environment, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                            universal_newlines=True, timeout=240 * factor)
    log = result.stdout
    with open(os.path.join(args.output, "paraview.log"), "w") as out:
        out.write(log)
    if not os.path.exists(checks_file):
        fail("the GUI did not run the test script (exit status %d):\n%s" % (result.returncode, log[-3000:]))
    with open(checks_file) as f:
        checks = json.load(f)
    if "error" in checks:
        fail("in the GUI: " + checks["error"])
    if not checks["plugin_loaded"]:
        fail("the GUI did not load the plugin")
    for name in MODELS:
        if "Consistent Mesh Surface Reader:" + name not in checks["sources"]:
            fail("no reader for %s in the pipeline: %s" % (name, checks["sources"]))
    for label in ("Feature Net Tracer", "Net Straightener", "Semi-Regular Remesher", "Mesh PCA", "Shape Blend"):
        if label + ":" + label not in checks["sources"]:
            fail("no %s in the pipeline: %s" % (label, checks["sources"]))
    remesh = checks["remesh"]
    if (remesh["points"], remesh["cells"]) != (5 * REMESH_VERTICES, 5 * 2 * (REMESH_VERTICES - 2)):
        fail("the remesher made %d points and %d cells, not five remeshes of %d vertices"
             % (remesh["points"], remesh["cells"], REMESH_VERTICES))
    if checks["mean"]["points"] != REMESH_VERTICES:
        fail("the mean has %d points" % checks["mean"]["points"])
    if args.rebaseline:
        shutil.copy(os.path.join(args.output, os.path.basename(args.baseline)), args.baseline)
        print("baseline replaced by " + os.path.join(args.output, os.path.basename(args.baseline)))
        return 0
    error = re.search(r'<DartMeasurement name="ImageError" type="numeric/double">([^<]+)<', log)
    if result.returncode != 0 or error is None:
        fail("the screenshot does not match %s (ParaView exit status %d; images in %s):\n%s"
             % (args.baseline, result.returncode, args.output, log[-2000:]))
    print("GUI state: plugin loaded, %d sources, remeshes %d points, image error %s (threshold %d)"
          % (len(checks["sources"]), remesh["points"], error.group(1), THRESHOLD))
    return 0


if __name__ == "__main__":
    sys.exit(main())
