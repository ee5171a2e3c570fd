"""Renders the faces' detail transfer for the README: the detail model's
remesh, a face's remesh, and that face with the detail model's wavelet
details (levels 3 and 4 on its coarse shape up to level 2), side by side,
each scaled to the same size and seen from the front (+z towards the
viewer, +y up).

    consistent-remesh --collection Data/cgal-faces --details-from lion-head --output OUT
    xvfb-run -a pvpython tools/render_details.py OUT PICTURE.png [--face nefertiti] [--details lion-head]
"""
import argparse

from paraview.simple import CreateView, SaveScreenshot, Show, Text, Transform, XMLPolyDataReader


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("output", help="the folder consistent-remesh wrote")
    parser.add_argument("picture", help="the PNG to write")
    parser.add_argument("--face", default="nefertiti", help="the model that got the details")
    parser.add_argument("--details", default="lion-head", help="the model whose details it got")
    args = parser.parse_args()
    panels = [("%s/%s.remesh.vtp" % (args.output, args.details), args.details),
              ("%s/%s.remesh.vtp" % (args.output, args.face), args.face),
              ("%s/%s.details-from-%s.vtp" % (args.output, args.face, args.details),
               "%s with %s's details" % (args.face, args.details))]
    width, height = 320, 400
    view = CreateView("RenderView")
    view.ViewSize = [width * len(panels), height]
    view.OrientationAxesVisibility = 0
    view.Background = [1, 1, 1]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    x = 0.0
    for path, title in panels:
        reader = XMLPolyDataReader(FileName=[path])
        reader.UpdatePipeline()
        b = reader.GetDataInformation().GetBounds()
        size = max(b[1] - b[0], b[3] - b[2], b[5] - b[4])
        moved = Transform(Input=reader)
        moved.Transform.Scale = [1.0 / size] * 3
        moved.Transform.Translate = [x - 0.5 * (b[0] + b[1]) / size, -0.5 * (b[2] + b[3]) / size,
                                     -0.5 * (b[4] + b[5]) / size]
        shown = Show(moved, view)
        shown.ColorArrayName = ["POINTS", ""]
        shown.DiffuseColor = [0.9, 0.85, 0.7]
        shown.Specular = 0.3
        x += 1.2
    centre = 0.5 * (x - 1.2)
    view.CameraPosition = [centre, 0, 5]
    view.CameraFocalPoint = [centre, 0, 0]
    view.CameraViewUp = [0, 1, 0]
    view.ResetCamera()
    view.GetActiveCamera().Dolly(2.3)
    for k, (_, title) in enumerate(panels):
        label = Text(Text=title)
        shown = Show(label, view)
        shown.WindowLocation = "Any Location"
        shown.Position = [(k + 0.08) / len(panels), 0.02]
        shown.FontSize = 14
        shown.Color = [0, 0, 0]
    SaveScreenshot(args.picture, view, ImageResolution=[width * len(panels), height])


if __name__ == "__main__":
    main()
