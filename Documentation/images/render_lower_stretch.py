"""Renders Documentation/images/lower-stretch-381.png: model 381 remeshed at
level 5 with L0 from its own landmarks, Net Straightener's LowerStretch off
(left) and on (right). Horns and ears carry no landmark: off, their patch
map crushes them and the remesh gives them a few large triangles; on, the
far horn is sampled finely.

Usage: pvpython render_lower_stretch.py PLUGIN.so DATA_DIR OUTPUT.png
"""
import sys

from paraview.simple import *  # noqa: F401,F403 (ParaView's scripting style)
from render_common import landmarked_shrec, white_view

plugin, data, output = sys.argv[1:4]
LoadPlugin(plugin, ns=globals())

cow = landmarked_shrec(globals(), data, "381")
base = BaseDomainBuilder(Input=cow)
tracer = FeatureNetTracer(Input=cow, BaseDomain=base)

layout = CreateLayout("lower stretch")
layout.SplitHorizontal(0, 0.5)
for cell, lower in ((1, 0), (2, 1)):
    straightener = NetStraightener(Input=tracer, BaseDomain=base, LowerStretch=lower)
    remesher = SemiRegularRemesher(Input=straightener, BaseDomain=base, Level=5)
    view = white_view(700, 600)
    AssignViewToLayout(view=view, layout=layout, hint=cell)
    shown = Show(OutputPort(remesher, 0), view)
    shown.SetRepresentationType("Surface With Edges")
    shown.ColorArrayName = [None, ""]
    shown.DiffuseColor = [0.85, 0.85, 0.85]
    shown.EdgeColor = [0.25, 0.25, 0.25]
    # The head, from the front and a little above.
    view.CameraFocalPoint = [0.62, 0.33, 0.12]
    view.CameraPosition = [1.55, 0.75, 0.9]
    view.CameraViewUp = [0, 1, 0]
    view.CameraViewAngle = 30
SaveScreenshot(output, layout, ImageResolution=[1400, 600])
print("wrote", output)
