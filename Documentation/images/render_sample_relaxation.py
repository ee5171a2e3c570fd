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
from render_common import aim, landmarked_shrec, show_grey, side_by_side

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

layout, views = side_by_side("sample relaxation")
for view, rounds in zip(views, (0, 4)):
    remesher = SemiRegularRemesher(Input=straightener, BaseDomain=base, Level=5, SampleRelaxationIterations=rounds)
    show_grey(OutputPort(remesher, 0), view)
    aim(view, camera["focus"], camera["position"], camera["up"], scale=camera["scale"])
SaveScreenshot(output, layout, ImageResolution=[1400, 600])
print("wrote", output)
