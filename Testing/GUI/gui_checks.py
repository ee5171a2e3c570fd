"""Runs inside the ParaView GUI at startup (paraview --script): loads the
Python state $CMP_GUI_STATE as File > Load State does (it runs the file),
records what the GUI built in the JSON file $CMP_GUI_CHECKS, fixes the
layout's size so that the screenshot ParaView then compares with the
baseline does not depend on the window, and saves the whole layout for the
documentation. Errors go to the file too, which TestGUIState.py reads: the
GUI would only show them in its output window."""
import json
import os
import traceback

import paraview.simple as simple

# Before the state runs: it would load the plugin itself if the GUI had not.
checks = {"plugin_loaded": hasattr(simple, "FeatureNetTracer")}
try:
    state = os.environ["CMP_GUI_STATE"]
    with open(state) as source:
        exec(compile(source.read(), state, "exec"), {"__file__": state, "__name__": "__main__"})
    checks["sources"] = sorted(simple.GetSources()[key].GetXMLLabel() + ":" + key[0]
                               for key in simple.GetSources())
    remesher = simple.FindSource("Semi-Regular Remesher")
    information = remesher.GetDataInformation()
    checks["remesh"] = {"points": information.GetNumberOfPoints(), "cells": information.GetNumberOfCells()}
    mean = simple.FindSource("Mesh PCA").GetDataInformation()
    checks["mean"] = {"points": mean.GetNumberOfPoints(), "cells": mean.GetNumberOfCells()}
    layout = simple.GetLayouts()[next(iter(simple.GetLayouts()))]
    layout.PreviewMode = [1000, 450]
    for view in simple.GetViews():
        simple.Render(view)
    simple.SaveScreenshot(os.path.join(os.environ["CMP_GUI_OUTPUT"], "layout.png"), layout,
                          ImageResolution=[1000, 450])
except Exception:  # noqa: B902 (everything must reach the file)
    checks["error"] = traceback.format_exc()
with open(os.environ["CMP_GUI_CHECKS"], "w") as out:
    json.dump(checks, out, indent=2)
