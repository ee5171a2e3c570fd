"""Renders Documentation/images/bunched-curves-384.png: model 384 with L0
from model 381, around its landmark 8 (the outside of the left hind leg's
top). Left: the traced curves (grey) and the straightened ones (black) all
leave the landmark (green) on one side, so one patch wraps almost all the
way round it and the others are slivers. Right: the level-5 remesh after
fold repair, triangles still facing against the surface (cell array Folded)
in red: the fan of needles around the landmark is where most of the folds
that repair leaves on the SHREC'07 models are.

Usage: pvpython render_bunched_curves.py PLUGIN.so DATA_DIR OUTPUT.png
"""
import sys

from paraview.simple import *  # noqa: F401,F403 (ParaView's scripting style)
from render_common import aim, landmarked_shrec, show_curves, show_folds, show_grey, side_by_side

plugin, data, output = sys.argv[1:4]
LoadPlugin(plugin, ns=globals())

landmark = (0.198866, -0.367996, -0.130249)  # landmark 8 of 384 (its .vts)
camera = dict(focus=landmark, position=(landmark[0] + 2.4, landmark[1] + 0.6, landmark[2] - 1.2), scale=0.17)

base = BaseDomainBuilder(Input=landmarked_shrec(globals(), data, "381"))
tracer = FeatureNetTracer(Input=landmarked_shrec(globals(), data, "384"), BaseDomain=base)
straightener = NetStraightener(Input=tracer, BaseDomain=base)
remesher = SemiRegularRemesher(Input=straightener, BaseDomain=base, Level=5, ComputeDistance=0)

layout, (left, right) = side_by_side("bunched curves")

show_grey(OutputPort(straightener, 0), left, edges=False)
show_curves(OutputPort(tracer, 1), left, 0.6, 2)
show_curves(OutputPort(straightener, 1), left, 0.05, 3)

show_grey(OutputPort(remesher, 0), right)
show_folds(OutputPort(remesher, 0), right)

for view in (left, right):
    marker = Show(Sphere(Center=list(landmark), Radius=0.004), view)
    marker.ColorArrayName = [None, ""]
    marker.DiffuseColor = [0.1, 0.7, 0.1]
    aim(view, camera["focus"], camera["position"], scale=camera["scale"])
SaveScreenshot(output, layout, ImageResolution=[1400, 600])
print("wrote", output)
