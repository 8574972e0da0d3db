"""What ParaView reads from an interface .pvd (scripts/interface_vtk), time by time: run by
pvbatch, it opens the file with ParaView's own reader for it (OpenDataFile), and for every time
the reader offers saves the points, the cells and the point arrays to an .npz for the caller to
check against interface.h5 (tests/apps/test_interface_vtk.py).

Usage: pvbatch paraview_interface_read.py FILE.pvd OUT.npz
"""
import sys

import numpy as np
from paraview import servermanager
from paraview.simple import OpenDataFile
from vtk.util.numpy_support import vtk_to_numpy

pvd, npz = sys.argv[1:3]
reader = OpenDataFile(pvd)
times = list(reader.TimestepValues)
saved = {"times": np.array(times), "reader": np.array(reader.GetXMLName())}
for k, t in enumerate(times):
    reader.UpdatePipeline(t)
    grid = servermanager.Fetch(reader)
    while not grid.IsA("vtkDataSet"):  # a composite output: its first leaf
        grid = grid.GetBlock(0)
    saved["points_%d" % k] = vtk_to_numpy(grid.GetPoints().GetData())
    saved["types_%d" % k] = vtk_to_numpy(grid.GetCellTypesArray())
    saved["connectivity_%d" % k] = vtk_to_numpy(grid.GetCells().GetConnectivityArray())
    data = grid.GetPointData()
    for j in range(data.GetNumberOfArrays()):
        saved["%s_%d" % (data.GetArrayName(j), k)] = vtk_to_numpy(data.GetArray(j))
np.savez(npz, **saved)
print("read %d times with %s" % (len(times), reader.GetXMLName()))
