#!/usr/bin/env pvpython
"""Shows a moreau run in ParaView: bodies as their shapes, contact forces as arrows and the
force network as tubes whose radius and colour follow the normal force (docs/output.md,
"Viewer description").

    pvbatch scripts/paraview_view.py OUT.xmf --png view.png     # the last frame, as an image
    pvpython scripts/paraview_view.py OUT.xmf --state view.pvsm # for File > Load State
"""
import argparse
import os
import xml.etree.ElementTree as ET

from paraview.simple import (CellDatatoPointData, ColorBy, ExtractBlock, ExtractSurface, GetActiveViewOrCreate,
                             Glyph, SaveScreenshot, SaveState, Show, Shrink, Tube, XDMFReader)


def build(xmf):
    # The legacy XDMF reader: the Xdmf3 readers give the point grids no cells.
    reader = XDMFReader(FileNames=[os.path.abspath(xmf)])
    view = GetActiveViewOrCreate('RenderView')
    time = reader.TimestepValues[-1] if reader.TimestepValues else 0
    view.ViewTime = time
    reader.UpdatePipeline(time)  # the bounds are unset before
    bounds = reader.GetDataInformation().GetBounds()
    size = max(bounds[1] - bounds[0], bounds[3] - bounds[2], bounds[5] - bounds[4], 1e-9)
    shapes = ExtractBlock(Input=reader, Selectors=['/Root/shapes'])
    shown = Show(shapes, view)
    shown.Representation = 'Surface With Edges'
    shown.Opacity = 0.3
    ColorBy(shown, None)
    # Modelizations with elements (moreau-output/2 scenes that are not rigid-only): each
    # one's grid, its cells drawn over its nodes (a chain's springs as lines, a mesh).
    grids = [g.get('Name') for g in ET.parse(xmf).getroot().find('Domain').findall('Grid')]
    for name in grids:
        if name not in ('bodies', 'shapes', 'contacts', 'force_network', 'rigid'):
            mesh = Show(ExtractBlock(Input=reader, Selectors=['/Root/' + name]), view)
            mesh.Representation = 'Surface With Edges'
            mesh.LineWidth = 3
            mesh.PointSize = 6
            mesh.ColorArrayName = ['POINTS', '']
            mesh.AmbientColor = mesh.DiffuseColor = mesh.EdgeColor = [0.8, 0.2, 0.1]
    contacts = ExtractBlock(Input=reader, Selectors=['/Root/contacts'])
    contacts.UpdatePipeline(time)
    if contacts.GetDataInformation().GetNumberOfPoints() > 0:
        fmax = max(abs(x) for x in contacts.PointData['normal_force'].GetRange()) or 1
        arrows = Glyph(Input=contacts, GlyphType='Arrow', OrientationArray=['POINTS', 'force'],
                       ScaleArray=['POINTS', 'force'], ScaleFactor=0.015 * size / fmax)
        ColorBy(Show(arrows, view), ('POINTS', 'normal_force'))
        # A body carries several contacts: its point is shared by their lines, so each line
        # gets its own ends (Shrink 1) before the lines' force becomes a point value.
        network = ExtractBlock(Input=reader, Selectors=['/Root/force_network'])
        ends = CellDatatoPointData(Input=Shrink(Input=network, ShrinkFactor=1.0))
        tubes = Tube(Input=ExtractSurface(Input=ends), Scalars=['POINTS', 'normal_force'], VaryRadius='By Scalar',
                     Radius=0.002 * size, RadiusFactor=5)
        tubes_shown = Show(tubes, view)
        ColorBy(tubes_shown, ('POINTS', 'normal_force'))
        tubes_shown.SetScalarBarVisibility(view, True)
    if bounds[5] - bounds[4] < 1e-12 * size:  # a 2D run
        view.InteractionMode = '2D'
    else:  # from the front, a little above, z up
        centre = [(bounds[2 * k] + bounds[2 * k + 1]) / 2 for k in range(3)]
        view.CameraFocalPoint = centre
        view.CameraPosition = [centre[0] + 0.6 * size, centre[1] - 1.5 * size, centre[2] + 0.8 * size]
        view.CameraViewUp = [0, 0, 1]
    view.ResetCamera()
    return view


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('xmf', help='the OUT.xmf beside a run\'s OUT.h5')
    parser.add_argument('--png', help='save the last frame to this image')
    parser.add_argument('--state', help='save a ParaView state file (File > Load State)')
    args = parser.parse_args()
    view = build(args.xmf)
    if args.png:
        SaveScreenshot(args.png, view, ImageResolution=[1200, 900])
    if args.state:
        SaveState(args.state)


if __name__ == '__main__':
    main()
