#!/usr/bin/env pvpython
"""Shows a moreau run in ParaView: bodies as their shapes, contact forces as arrows and the
force network as tubes whose radius and colour follow the normal force (docs/output.md,
"Viewer description"). With bonded contact laws (docs/laws.md), the bonds over it: damaged
ones as tubes from yellow to black (damage 0 to 1), broken ones as thick magenta tubes (while
their grains are within the alert distance; farther apart, a contact and its bond are gone).

    pvbatch scripts/paraview_view.py OUT.xmf --png view.png     # the last frame, as an image
    pvbatch scripts/paraview_view.py OUT.xmf --time 0.1 --png view.png   # the frame at t = 0.1 s
    pvpython scripts/paraview_view.py OUT.xmf --state view.pvsm # for File > Load State
"""
import argparse
import os
import xml.etree.ElementTree as ET

from paraview.simple import (CellDatatoPointData, ColorBy, ExtractBlock, ExtractSurface, GetActiveViewOrCreate,
                             GetColorTransferFunction, Glyph, SaveScreenshot, SaveState, Show, Shrink, Threshold, Tube,
                             XDMFReader)


def typical_arm(network, time):
    """The median length of the force network's arms (centre to contact point: about a
    grain's radius); 0 when there are none."""
    from paraview import servermanager
    from paraview.simple import MergeBlocks
    merged = MergeBlocks(Input=network)
    merged.UpdatePipeline(time)
    data = servermanager.Fetch(merged)
    points = data.GetPoints()
    lengths = []
    for c in range(data.GetNumberOfCells()):
        ids = data.GetCell(c).GetPointIds()
        for k in range(ids.GetNumberOfIds() - 1):
            a, b = points.GetPoint(ids.GetId(k)), points.GetPoint(ids.GetId(k + 1))
            length = sum((a[i] - b[i]) ** 2 for i in range(3)) ** 0.5
            if length > 0:  # a wall's arm ends at the contact point: length 0
                lengths.append(length)
    lengths.sort()
    return lengths[len(lengths) // 2] if lengths else 0.0


def build(xmf, at=None):
    # The legacy XDMF reader: the Xdmf3 readers give the point grids no cells.
    reader = XDMFReader(FileNames=[os.path.abspath(xmf)])
    view = GetActiveViewOrCreate('RenderView')
    times = list(reader.TimestepValues or [0])
    # The last frame, or the first at or after the time asked for.
    time = times[-1] if at is None else next((t for t in times if t >= at - 1e-12), times[-1])
    view.ViewTime = time
    reader.UpdatePipeline(time)  # the bounds are unset before
    # Modelizations with elements (moreau-output/2 scenes that are not rigid-only): each
    # one's grid, its cells drawn over its nodes (a chain's springs as lines, a mesh).
    grids = [g.get('Name') for g in ET.parse(xmf).getroot().find('Domain').findall('Grid')]
    meshes = [name for name in grids if name not in ('bodies', 'shapes', 'contacts', 'force_network', 'rigid')]
    bounds = framed_bounds(reader, meshes, time)
    size = max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4], 1e-9)
    shapes = ExtractBlock(Input=reader, Selectors=['/Root/shapes'])
    shown = Show(shapes, view)
    shown.Representation = 'Surface With Edges'
    shown.Opacity = 0.3
    ColorBy(shown, None)
    for name in meshes:
        block = ExtractBlock(Input=reader, Selectors=['/Root/' + name])
        block.UpdatePipeline(time)
        mesh = Show(block, view)
        mesh.Representation = 'Surface With Edges'
        mesh.LineWidth = 3
        mesh.PointSize = 6
        mesh.AmbientColor = mesh.DiffuseColor = mesh.EdgeColor = [0.8, 0.2, 0.1]
        if 'von_mises' in block.PointData.keys():
            # A deformable body (elastic): its deformed mesh coloured by the nodal von
            # Mises stress, edges kept dark so the elements show.
            ColorBy(mesh, ('POINTS', 'von_mises'))
            mesh.EdgeColor = [0.2, 0.2, 0.2]
            mesh.LineWidth = 1
            mesh.SetScalarBarVisibility(view, True)
        else:
            mesh.ColorArrayName = ['POINTS', '']
    contacts = ExtractBlock(Input=reader, Selectors=['/Root/contacts'])
    contacts.UpdatePipeline(time)
    if contacts.GetDataInformation().GetNumberOfPoints() > 0:
        # Arrows and tubes sized on the grains, not on the scene: a scene's bounds grow with
        # every grain that leaves (a silo's last frame spans metres), which made the tubes
        # wider than the grains. arm: about a grain's radius.
        network = ExtractBlock(Input=reader, Selectors=['/Root/force_network'])
        arm = typical_arm(network, time)
        fmax = max(abs(x) for x in contacts.PointData['normal_force'].GetRange()) or 1
        arrows = Glyph(Input=contacts, GlyphType='Arrow', OrientationArray=['POINTS', 'force'],
                       ScaleArray=['POINTS', 'force'], ScaleFactor=(3 * arm if arm > 0 else 0.015 * size) / fmax)
        ColorBy(Show(arrows, view), ('POINTS', 'normal_force'))
        # Each contact's line has its own points (contacts/network); files from before it
        # share a body's point between its lines, which Shrink 1 separates (a no-op on new
        # files), before the lines' force becomes a point value.
        ends = CellDatatoPointData(Input=Shrink(Input=network, ShrinkFactor=1.0))
        tubes = Tube(Input=ExtractSurface(Input=ends), Scalars=['POINTS', 'normal_force'], VaryRadius='By Scalar',
                     Radius=0.2 * arm if arm > 0 else 0.002 * size, RadiusFactor=4)
        tubes_shown = Show(tubes, view)
        ColorBy(tubes_shown, ('POINTS', 'normal_force'))
        tubes_shown.SetScalarBarVisibility(view, True)
        bonds(network, view, time, size)
    if bounds[5] - bounds[4] < 1e-12 * size:  # a 2D run
        view.InteractionMode = '2D'
    else:  # from the front, a little above, z up
        centre = [(bounds[2 * k] + bounds[2 * k + 1]) / 2 for k in range(3)]
        view.CameraFocalPoint = centre
        view.CameraPosition = [centre[0] + 0.6 * size, centre[1] - 1.5 * size, centre[2] + 0.8 * size]
        view.CameraViewUp = [0, 0, 1]
    view.ResetCamera(*bounds)
    return view


def framed_bounds(reader, meshes, time):
    """The box the camera frames: every fixed body's shapes (the apparatus: walls, floors)
    and the shapes of the free bodies whose centre lies within the free bodies' bulk (per
    axis, the quartiles widened by 3 interquartile ranges). A grain that left the scene
    (fell off a silo's floor, flew away) is still drawn but no longer sets the zoom: fitting
    it made a discharge's last frame a few pixels of silo in an empty screen. Without a body
    grid (older files) or shape cells, the whole data's bounds."""
    from paraview import servermanager
    from paraview.simple import MergeBlocks
    everything = reader.GetDataInformation().GetBounds()

    def fetched(selector):
        block = MergeBlocks(Input=ExtractBlock(Input=reader, Selectors=[selector]))
        block.UpdatePipeline(time)
        return servermanager.Fetch(block)

    bodies, cells = fetched('/Root/bodies'), fetched('/Root/shapes')
    fixed, owner = bodies.GetPointData().GetArray('fixed'), cells.GetCellData().GetArray('body')
    if fixed is None or owner is None or bodies.GetNumberOfPoints() == 0 or cells.GetNumberOfCells() == 0:
        return everything
    free = [bodies.GetPoint(b) for b in range(bodies.GetNumberOfPoints()) if not fixed.GetValue(b)]
    fence = []
    for axis in range(3):
        xs = sorted(p[axis] for p in free) or [0.0]
        q1, q3 = xs[len(xs) // 4], xs[(3 * len(xs)) // 4]
        fence.append((q1 - 3 * (q3 - q1), q3 + 3 * (q3 - q1)))
    kept = [b for b in range(bodies.GetNumberOfPoints())
            if fixed.GetValue(b) or all(lo <= bodies.GetPoint(b)[a] <= hi for a, (lo, hi) in enumerate(fence))]
    kept = set(kept)
    box = [float('inf'), -float('inf')] * 3
    for c in range(cells.GetNumberOfCells()):
        if int(owner.GetValue(c)) not in kept:
            continue
        lo_hi = cells.GetCell(c).GetBounds()
        for a in range(3):
            box[2 * a] = min(box[2 * a], lo_hi[2 * a])
            box[2 * a + 1] = max(box[2 * a + 1], lo_hi[2 * a + 1])
    if box[0] > box[1]:
        return everything
    # Modelizations with elements (meshes) are framed whole: they are the apparatus too.
    for name in meshes:
        block = ExtractBlock(Input=reader, Selectors=['/Root/' + name])
        block.UpdatePipeline(time)
        lo_hi = block.GetDataInformation().GetBounds()
        for a in range(3):
            if lo_hi[2 * a] <= lo_hi[2 * a + 1]:
                box[2 * a] = min(box[2 * a], lo_hi[2 * a])
                box[2 * a + 1] = max(box[2 * a + 1], lo_hi[2 * a + 1])
    return tuple(box)


def bonds(network, view, time, size):
    """Over the force network: damaged intact bonds (bond = 1, damage > 0) as tubes from
    yellow to black (damage 0 to 1), broken bonds (bond = 2) as thick magenta tubes."""
    network.UpdatePipeline(time)
    cells = network.GetDataInformation().DataInformation.GetCellDataInformation()
    names = [cells.GetArrayInformation(i).GetName() for i in range(cells.GetNumberOfArrays())]
    if 'bond' not in names:
        return

    def tubes(low, high, array, radius):
        picked = Threshold(Input=network, Scalars=['CELLS', array], LowerThreshold=low, UpperThreshold=high,
                           ThresholdMethod='Between')
        if array != 'bond':
            picked = Threshold(Input=picked, Scalars=['CELLS', 'bond'], LowerThreshold=0.5, UpperThreshold=1.5,
                               ThresholdMethod='Between')
        return Show(Tube(Input=ExtractSurface(Input=Shrink(Input=picked, ShrinkFactor=1.0)), Radius=radius * size), view)

    if 'damage' in names:
        damaged = tubes(1e-3, 1.0, 'damage', 0.004)
        ColorBy(damaged, ('CELLS', 'damage'))
        lut = GetColorTransferFunction('damage')
        lut.RGBPoints = [0.0, 1.0, 0.85, 0.1, 1.0, 0.0, 0.0, 0.0]
        lut.RescaleTransferFunction(0.0, 1.0)
        damaged.SetScalarBarVisibility(view, True)
    broken = tubes(1.5, 2.5, 'bond', 0.006)
    ColorBy(broken, None)
    broken.AmbientColor = broken.DiffuseColor = [1.0, 0.0, 1.0]  # magenta: not on the force or damage maps


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('xmf', help='the OUT.xmf beside a run\'s OUT.h5')
    parser.add_argument('--png', help='save the last frame (or the one at --time) to this image')
    parser.add_argument('--time', type=float, help='show the frame at this time (s) instead of the last')
    parser.add_argument('--state', help='save a ParaView state file (File > Load State)')
    args = parser.parse_args()
    view = build(args.xmf, args.time)
    if args.png:
        SaveScreenshot(args.png, view, ImageResolution=[1200, 900])
    if args.state:
        SaveState(args.state)


if __name__ == '__main__':
    main()
