"""Renders Documentation/images/straightened-net-MODEL.png: a SHREC'07 model
with the patch layout traced by Feature Net Tracer (thin grey curves) and
straightened by Net Straightener (patches and thick black curves), using L0
from model 381.

Usage: pvpython render_straightened_net.py PLUGIN.so DATA_DIR MODEL OUTPUT.png
"""
import sys

from paraview.simple import *  # noqa: F401,F403 (ParaView's scripting style)
from render_common import landmarked_shrec, show_curves, white_view

plugin, data, model, output = sys.argv[1:5]
LoadPlugin(plugin, ns=globals())


base = BaseDomainBuilder(Input=landmarked_shrec(globals(), data, "381"))
tracer = FeatureNetTracer(Input=landmarked_shrec(globals(), data, model), BaseDomain=base)
straightener = NetStraightener(Input=tracer, BaseDomain=base)

view = white_view(1200, 700)

patches = Show(OutputPort(straightener, 0), view)
ColorBy(patches, ("CELLS", "PatchId"))
lut = GetColorTransferFunction("PatchId")
lut.ApplyPreset("Rainbow Uniform", True)
lut.RescaleTransferFunction(0, 37)
patches.SetScalarBarVisibility(view, False)

show_curves(OutputPort(tracer, 1), view, 0.55, 1.5)
show_curves(OutputPort(straightener, 1), view, 0.05, 3)

view.CameraPosition = [0.6, -0.5, 3.0]
view.CameraViewUp = [0, 1, 0]
view.ResetCamera()
GetActiveCamera().Zoom(1.6)
SaveScreenshot(output, view, ImageResolution=[1200, 700])
print("wrote", output)
