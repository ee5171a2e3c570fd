"""Renders Documentation/images/base-domain-381.png: model 381 with the base
domain L0 that Base Domain Builder makes from its 21 landmarks.

Usage: pvpython render_base_domain.py PLUGIN.so DATA_DIR OUTPUT.png
"""
import sys

from paraview.simple import *  # noqa: F401,F403 (ParaView's scripting style)
from render_common import white_view

plugin, data, output = sys.argv[1:4]
LoadPlugin(plugin, ns=globals())

surface = ConsistentMeshSurfaceReader(FileName=data + "/shrec07-fourleg/381.off")
landmarked = LandmarksFromFile(Input=surface, LandmarkFile=data + "/shrec07-fourleg/381.vts")
base = BaseDomainBuilder(Input=landmarked)

view = white_view(1200, 600)

shown = Show(surface, view)
shown.DiffuseColor = [0.8, 0.8, 0.82]
shown.Opacity = 0.5

edges = Show(base, view)
edges.SetRepresentationType("Wireframe")
edges.AmbientColor = edges.DiffuseColor = [0.75, 0.1, 0.1]
edges.LineWidth = 3

# A second proxy: Show() of the same source would reuse the wireframe.
landmarks = Show(ExtractSurface(Input=base), view)
landmarks.SetRepresentationType("Points")
landmarks.RenderPointsAsSpheres = 1
landmarks.PointSize = 14
landmarks.AmbientColor = landmarks.DiffuseColor = [0.1, 0.2, 0.8]

view.CameraPosition = [0.6, -0.5, 3.0]
view.CameraViewUp = [0, 1, 0]
view.ResetCamera()
view.CameraParallelScale = 0.5
GetActiveCamera().Zoom(1.8)
SaveScreenshot(output, view, ImageResolution=[1200, 600])
print("wrote", output)
