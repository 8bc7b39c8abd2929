"""Opens an `sph run --vtu` series with ParaView's own readers (run with pvpython) and checks it against
the run's plain CSV files: the time of every step, the point count, the field names and every value; then
opens one particle CSV with ParaView's CSV reader (no comment line: its first row is the header).
usage: pvpython read_pvd.py OUT_DIR"""
import csv
import json
import os
import sys

from paraview import servermanager as sm
from paraview.simple import CSVReader, PVDReader
from vtkmodules.util.numpy_support import vtk_to_numpy


def fail(msg):
    print("FAIL " + msg)
    sys.exit(1)


def close(a, b, tol=1e-12):
    return abs(a - b) <= tol * max(1.0, abs(a), abs(b))


out = sys.argv[1]
meta = json.load(open(os.path.join(out, "csv_meta.json")))
reader = PVDReader(FileName=os.path.join(out, "particles.pvd"))
times = list(reader.TimestepValues)
want = [p["t"] for p in meta["particles"]]
if len(times) != len(want) or not all(close(a, b) for a, b in zip(times, want)):
    fail("time steps %s, expected %s" % (times, want))
for t, entry in zip(times, meta["particles"]):
    reader.UpdatePipeline(t)
    data = sm.Fetch(reader)
    if data.IsA("vtkMultiBlockDataSet"):
        data = data.GetBlock(0)
    with open(os.path.join(out, entry["file"])) as f:
        rows = list(csv.DictReader(f))
    if data.GetNumberOfPoints() != len(rows):
        fail("t = %g: %d points, the CSV has %d rows" % (t, data.GetNumberOfPoints(), len(rows)))
    if data.GetNumberOfCells() != len(rows):
        fail("t = %g: %d vertex cells for %d points" % (t, data.GetNumberOfCells(), len(rows)))
    pd = data.GetPointData()
    names = {pd.GetArrayName(i) for i in range(pd.GetNumberOfArrays())}
    needed = {"velocity", "id", "kind"} | (set(rows[0]) - {"id", "x", "y", "z", "vx", "vy", "vz", "kind"})
    if not needed <= names:
        fail("t = %g: fields %s, missing %s" % (t, sorted(names), sorted(needed - names)))
    if pd.GetArray("velocity").GetNumberOfComponents() != 3:
        fail("velocity is not a 3-vector")
    points = vtk_to_numpy(data.GetPoints().GetData())
    vel = vtk_to_numpy(pd.GetArray("velocity"))
    ids = vtk_to_numpy(pd.GetArray("id"))
    arrays = {name: vtk_to_numpy(pd.GetArray(name)) for name in needed - {"velocity", "id", "kind"}}
    for r, row in enumerate(rows):
        if int(ids[r]) != int(row["id"]):
            fail("row %d: id %d, CSV %s" % (r, ids[r], row["id"]))
        for k, c in enumerate("xyz"):
            if not close(points[r][k], float(row[c])):
                fail("particle %s: %s = %r, CSV %s" % (row["id"], c, points[r][k], row[c]))
            if not close(vel[r][k], float(row["v" + c])):
                fail("particle %s: v%s = %r, CSV %s" % (row["id"], c, vel[r][k], row["v" + c]))
        for name, values in arrays.items():
            if not close(values[r], float(row[name])):
                fail("particle %s: %s = %r, CSV %s" % (row["id"], name, values[r], row[name]))
    print("t = %g: %d points, fields %s" % (t, len(rows), " ".join(sorted(names))))

first = os.path.join(out, meta["particles"][0]["file"])
table_reader = CSVReader(FileName=[first])
table_reader.UpdatePipeline()
table = sm.Fetch(table_reader)
with open(first) as f:
    header = f.readline().strip().split(",")
    count = sum(1 for _ in f)
columns = [table.GetColumnName(i) for i in range(table.GetNumberOfColumns())]
if columns != header or table.GetNumberOfRows() != count:
    fail("ParaView's CSV reader: columns %s and %d rows, expected %s and %d" % (columns, table.GetNumberOfRows(), header, count))
print("CSV reader: %d rows, columns %s" % (count, ",".join(columns)))
print("ok")
