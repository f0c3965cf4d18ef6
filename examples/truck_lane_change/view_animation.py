"""The truck's lane-change animation in ParaView, the camera following it.

Usage (ParaView's Python; the animation of `flexmb run truck.yaml --out DIR --animation`):
  pvpython view_animation.py DIR/animation/anim.pvd
      sets the scene up in ParaView (or run it from the GUI's Python shell):
      the camera follows the truck along the 155 m course
  xvfb-run -a pvbatch view_animation.py DIR/animation/anim.pvd --png OUT [--stride N] [--frame-only]
      renders every N-th frame to OUT/frame_NNNNN.png without a display and
      writes OUT/camera.json (time, focal point, the truck's bounds per image)

The scene: the road (the corridor's lines, cell data body_id 0) in grey;
the frame (body_id --frame-body, 1 for the truck of truck.yaml: the first
body) coloured by von_mises, over the whole run's range; the other parts
(cab, cargo box, axles, wheels, ...) at opacity --opacity (0.25) so that the
frame shows through the cargo box, or hidden with --frame-only. The camera
looks at the centre of the truck's bounding box from behind, to the left
and above (--offset, metres in world axes), at every frame: it follows the
truck, not the whole course. In the ParaView GUI the same follows from the
camera track's "Follow Data" mode on the truck, which the script sets up.
"""
import argparse
import json
import os

from paraview.simple import (ColorBy, CreateView, GetCameraTrack, GetColorTransferFunction, PVDReader, Render,
                             SaveScreenshot, Show, Threshold)


def threshold(source, low, high):
    t = Threshold(Input=source)
    t.Scalars = ["CELLS", "body_id"]
    t.ThresholdMethod = "Between"
    t.LowerThreshold = low
    t.UpperThreshold = high
    return t


def main():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("pvd", help="anim.pvd of a lane-change run")
    p.add_argument("--png", help="render the frames to this directory (headless: xvfb-run -a pvbatch ...)")
    p.add_argument("--stride", type=int, default=1, help="every N-th frame (--png)")
    p.add_argument("--frame-only", action="store_true", help="hide the parts other than the frame")
    p.add_argument("--frame-body", type=int, default=1, help="body_id of the frame (1)")
    p.add_argument("--opacity", type=float, default=0.25, help="opacity of the other parts (0.25)")
    p.add_argument("--offset", type=float, nargs=3, default=[-14.0, 9.0, 7.0],
                   help="camera position from the truck's centre, world axes [m]")
    p.add_argument("--size", type=int, nargs=2, default=[960, 540], help="image size [px]")
    a = p.parse_args()
    if a.stride < 1:
        p.error("--stride must be at least 1")

    reader = PVDReader(FileName=os.path.abspath(a.pvd))
    reader.UpdatePipelineInformation()
    times = list(reader.TimestepValues) or [0.0]
    fb = a.frame_body
    road = threshold(reader, 0, 0)
    frame = threshold(reader, fb, fb)
    truck = threshold(reader, 1, 1e9)
    parts = [threshold(reader, 1, fb - 1)] if fb > 1 else []
    parts.append(threshold(reader, fb + 1, 1e9))

    view = CreateView("RenderView")
    view.ViewSize = a.size
    view.OrientationAxesVisibility = 0
    road_display = Show(road, view)
    ColorBy(road_display, None)
    road_display.AmbientColor = road_display.DiffuseColor = [0.55, 0.55, 0.55]
    frame_display = Show(frame, view)
    ColorBy(frame_display, ("CELLS", "von_mises"))
    frame_display.RescaleTransferFunctionToDataRangeOverTime()
    frame_display.SetScalarBarVisibility(view, True)
    GetColorTransferFunction("von_mises").ApplyPreset("Jet", True)
    for part in parts:
        d = Show(part, view)
        ColorBy(d, None)
        d.AmbientColor = d.DiffuseColor = [0.75, 0.78, 0.85]
        d.Opacity = a.opacity
        d.Visibility = 0 if a.frame_only else 1
    Render(view)  # paraview.simple resets the camera to the whole scene at the first render: before aiming

    def aim(t):
        truck.UpdatePipeline(t)
        b = truck.GetDataInformation().GetBounds()
        c = [0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5])]
        view.ViewTime = t
        view.CameraFocalPoint = c
        view.CameraPosition = [c[k] + a.offset[k] for k in range(3)]
        view.CameraViewUp = [0.0, 0.0, 1.0]
        return c, list(b)

    if not a.png:
        # interactive: the camera track follows the truck in ParaView's animation
        aim(times[0])
        cue = GetCameraTrack(view=view)
        cue.Mode = "Follow-data"
        cue.DataSource = truck
        Render(view)
        return
    os.makedirs(a.png, exist_ok=True)
    record = []
    for k in range(0, len(times), a.stride):
        t = times[k]
        c, b = aim(t)
        Render(view)
        SaveScreenshot(os.path.join(a.png, "frame_%05d.png" % k), view, ImageResolution=a.size)
        record.append({"frame": k, "time": t, "focal_point": c, "truck_bounds": b})
    with open(os.path.join(a.png, "camera.json"), "w") as f:
        json.dump(record, f, indent=1)
    print("%d images in %s" % (len(record), a.png))


if __name__ in ("__main__", "__vtkconsole__"):
    main()
