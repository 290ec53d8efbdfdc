#!/usr/bin/env python3
"""Reads bpmkit's VTK output with VTK's own XML readers (those ParaView uses) and prints what they
found as JSON, for tests/io/vtk_paraview_test.cpp to compare with the model.

usage: read_vtk_frame.py FILE.vtp|FILE.pvd ...
A .vtp gives its counts, points, cell point ids and every point, cell and field data array; a .pvd
gives its DataSets (timestep, part, file, parsed as XML; each file read as above for its point
and cell counts) and the number of parts (ParaView's blocks). Any error or warning VTK reports
makes the script fail (exit 1) with it. Exit 77: the vtk module (Debian: python3-vtk9) is missing.
"""
import json
import os
import sys
import xml.etree.ElementTree as ElementTree

try:
    import vtk
except ImportError as error:
    print(f"python3 cannot import vtk ({error}): apt-get install python3-vtk9", file=sys.stderr)
    sys.exit(77)

# VTK reports problems (a bad zlib block, a missing array) through the output window, not by
# raising: collect them and fail.
messages = vtk.vtkStringOutputWindow()
vtk.vtkOutputWindow.SetInstance(messages)


def arrays(data):
    out = {}
    for k in range(data.GetNumberOfArrays()):
        a = data.GetAbstractArray(k)
        if isinstance(a, vtk.vtkStringArray):
            values = [a.GetValue(i) for i in range(a.GetNumberOfValues())]
            out[a.GetName()] = {"type": "String", "values": values}
        else:
            n = a.GetNumberOfTuples() * a.GetNumberOfComponents()
            out[a.GetName()] = {"type": a.GetDataTypeAsString(),
                                "components": a.GetNumberOfComponents(),
                                "values": [a.GetValue(i) for i in range(n)]}
    return out


def read_vtp(path):
    reader = vtk.vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    d = reader.GetOutput()
    cells = []
    for c in range(d.GetNumberOfCells()):
        ids = vtk.vtkIdList()
        d.GetCellPoints(c, ids)
        cells.append([ids.GetId(i) for i in range(ids.GetNumberOfIds())])
    return {
        "points": d.GetNumberOfPoints(),
        "lines": d.GetNumberOfLines(),
        "polys": d.GetNumberOfPolys(),
        "xyz": [d.GetPoint(i)[k] for i in range(d.GetNumberOfPoints()) for k in range(3)],
        "cells": cells,
        "point_data": arrays(d.GetPointData()),
        "cell_data": arrays(d.GetCellData()),
        "field_data": arrays(d.GetFieldData()),
    }


def read_pvd(path):
    # VTK has no .pvd reader (ParaView's vtkPVDReader is not in VTK): parse it as XML and read each
    # DataSet's file as ParaView would, relative to the .pvd.
    datasets = [dict(e.attrib) for e in ElementTree.parse(path).getroot().iter("DataSet")]
    folder = os.path.dirname(path)
    for d in datasets:
        data = read_vtp(os.path.join(folder, d["file"]))
        d["points"], d["cells"] = data["points"], len(data["cells"])
    return {"datasets": datasets, "parts": len({d["part"] for d in datasets})}


result = {}
for name in sys.argv[1:]:
    result[name] = read_pvd(name) if name.endswith(".pvd") else read_vtp(name)
report = messages.GetOutput()
if "ERROR" in report or "Warning" in report:
    print(report, file=sys.stderr)
    sys.exit(1)
print(json.dumps(result))
