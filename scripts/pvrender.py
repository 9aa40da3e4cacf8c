# ParaView (pvbatch) script: open a seflex .pvd time series, go to a time step, render it to PNG.
# Run through scripts/pvrender.sh, which finds pvbatch and ParaView's Python and a virtual display:
#   scripts/pvrender.sh series.pvd out.png [step]      (step: index, default the last one)
# Prints "points=<n> cells=<n> steps=<n> time=<t>" so callers can check what ParaView read.
import sys
from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetAnimationScene, OpenDataFile, Render,
                             ResetCamera, SaveScreenshot, Show, UpdatePipeline)

pvd, png = sys.argv[1], sys.argv[2]
reader = OpenDataFile(pvd)
if reader is None:
    raise SystemExit("ParaView could not open " + pvd)
times = list(reader.TimestepValues) if hasattr(reader.TimestepValues, "__len__") else [reader.TimestepValues]
step = int(sys.argv[3]) if len(sys.argv) > 3 else len(times) - 1
t = times[step]
scene = GetAnimationScene()
scene.UpdateAnimationUsingDataTimeSteps()
scene.AnimationTime = t
UpdatePipeline(time=t, proxy=reader)
info = reader.GetDataInformation()
view = GetActiveViewOrCreate("RenderView")
view.ViewSize = [800, 600]
view.ViewTime = t
display = Show(reader, view)
ColorBy(display, ("POINTS", "elastic_displacement", "Magnitude"))
view.CameraPosition = [3.0, -2.0, 2.5]
view.CameraViewUp = [0.0, 0.0, 1.0]
ResetCamera(view)
Render(view)
SaveScreenshot(png, view, ImageResolution=[800, 600])
print("points=%d cells=%d steps=%d time=%g" % (info.GetNumberOfPoints(), info.GetNumberOfCells(), len(times), t))
