"""Renders Documentation/images/sample-relaxation-MODEL.png: a SHREC'07
model remeshed at level 5 with L0 from its own landmarks, the Semi-Regular
Remesher's SampleRelaxationIterations 0 (left) and 4 (right).

- 389 (the default): the dog's tail carries no landmark, and the mean
  value map crowds it into a corner of its base triangle; the regular
  grid stops short of the tip, the relaxed samples reach it.

Usage: pvpython render_sample_relaxation.py PLUGIN.so DATA_DIR OUTPUT.png [MODEL]
"""
import sys

from paraview.simple import *  # noqa: F401,F403 (ParaView's scripting style)
from render_common import landmarked_shrec, white_view

plugin, data, output = sys.argv[1:4]
model = sys.argv[4] if len(sys.argv) > 4 else "389"
# Where to look from: focal point, position, parallel scale.
cameras = {
    "389": dict(focus=[0.0, 0.42, 0.22], position=[3.0, 0.42, 0.22], up=[0, 0, 1], scale=0.22),  # the tail
}
camera = cameras[model]
LoadPlugin(plugin, ns=globals())

animal = landmarked_shrec(globals(), data, model)
base = BaseDomainBuilder(Input=animal)
tracer = FeatureNetTracer(Input=animal, BaseDomain=base)
straightener = NetStraightener(Input=tracer, BaseDomain=base)

layout = CreateLayout("sample relaxation")
layout.SplitHorizontal(0, 0.5)
for cell, rounds in ((1, 0), (2, 4)):
    remesher = SemiRegularRemesher(Input=straightener, BaseDomain=base, Level=5, SampleRelaxationIterations=rounds)
    view = white_view(700, 600)
    AssignViewToLayout(view=view, layout=layout, hint=cell)
    shown = Show(OutputPort(remesher, 0), view)
    shown.SetRepresentationType("Surface With Edges")
    shown.ColorArrayName = [None, ""]
    shown.DiffuseColor = [0.85, 0.85, 0.85]
    shown.EdgeColor = [0.25, 0.25, 0.25]
    view.CameraFocalPoint = camera["focus"]
    view.CameraPosition = camera["position"]
    view.CameraViewUp = camera["up"]
    view.CameraParallelProjection = 1
    view.CameraParallelScale = camera["scale"]
SaveScreenshot(output, layout, ImageResolution=[1400, 600])
print("wrote", output)
