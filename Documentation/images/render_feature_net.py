"""Renders Documentation/images/feature-net-MODEL.png: a SHREC'07 model with
the patch layout traced by Feature Net Tracer, using L0 from model 381.

Usage: pvpython render_feature_net.py PLUGIN.so DATA_DIR MODEL OUTPUT.png
"""
import sys

from paraview.simple import *  # noqa: F401,F403 (ParaView's scripting style)
from render_common import landmarked_shrec, white_view

plugin, data, model, output = sys.argv[1:5]
LoadPlugin(plugin, ns=globals())


base = BaseDomainBuilder(Input=landmarked_shrec(globals(), data, "381"))
tracer = FeatureNetTracer(Input=landmarked_shrec(globals(), data, model), BaseDomain=base)

view = white_view(1200, 700)

patches = Show(OutputPort(tracer, 0), view)
ColorBy(patches, ("CELLS", "PatchId"))
lut = GetColorTransferFunction("PatchId")
lut.ApplyPreset("Rainbow Uniform", True)
lut.RescaleTransferFunction(0, 37)
patches.SetScalarBarVisibility(view, False)

curves = Show(OutputPort(tracer, 1), view)
curves.SetRepresentationType("Wireframe")
curves.ColorArrayName = [None, ""]
curves.AmbientColor = curves.DiffuseColor = [0.05, 0.05, 0.05]
curves.LineWidth = 3

view.CameraPosition = [0.6, -0.5, 3.0]
view.CameraViewUp = [0, 1, 0]
view.ResetCamera()
GetActiveCamera().Zoom(1.6)
SaveScreenshot(output, view, ImageResolution=[1200, 700])
print("wrote", output)
