"""Renders Documentation/images/lower-stretch-MODEL.png: a SHREC'07 model
remeshed at level 5 with L0 from its own landmarks, Net Straightener's
LowerStretch off (left) and on (right).

- 381 (the default): horns and ears carry no landmark; off, their patch map
  crushes them and the remesh gives them a few large triangles; on, the
  far horn is sampled finely.
- 385: the long thin tail carries no landmark (its "tail tip" landmark sits
  at the root); off, the remesh leaves it out; on, progressive steps give
  it part of its share of the base triangle.

Usage: pvpython render_lower_stretch.py PLUGIN.so DATA_DIR OUTPUT.png [MODEL]
"""
import sys

from paraview.simple import *  # noqa: F401,F403 (ParaView's scripting style)
from render_common import aim, landmarked_shrec, show_grey, side_by_side

plugin, data, output = sys.argv[1:4]
model = sys.argv[4] if len(sys.argv) > 4 else "381"
# Where to look from: focal point, position, and whether to project in
# parallel (scale) or in perspective (view angle).
cameras = {
    "381": dict(focus=[0.62, 0.33, 0.12], position=[1.55, 0.75, 0.9], angle=30),  # the head, front and above
    "385": dict(focus=[-0.68, -0.05, 0.0], position=[-0.68, -0.05, 3.0], scale=0.42),  # the tail, from the side
}
camera = cameras[model]
LoadPlugin(plugin, ns=globals())

animal = landmarked_shrec(globals(), data, model)
base = BaseDomainBuilder(Input=animal)
tracer = FeatureNetTracer(Input=animal, BaseDomain=base)

layout, views = side_by_side("lower stretch")
for view, lower in zip(views, (0, 1)):
    straightener = NetStraightener(Input=tracer, BaseDomain=base, LowerStretch=lower)
    remesher = SemiRegularRemesher(Input=straightener, BaseDomain=base, Level=5)
    show_grey(OutputPort(remesher, 0), view)
    aim(view, camera["focus"], camera["position"], scale=camera.get("scale"), angle=camera.get("angle"))
SaveScreenshot(output, layout, ImageResolution=[1400, 600])
print("wrote", output)
