"""Reading the ASCII VTU and PVD files of a run from the postprocess test scripts."""
import os
import xml.etree.ElementTree as ET


def numbers(element):
    return [float(x) for x in element.text.split()]


def collection(name, directory="results"):
    """The (time, file) records of the PVD collection name."""
    root = ET.parse(os.path.join(directory, name)).getroot()
    return [(float(d.get("timestep")), d.get("file")) for d in root.iter("DataSet")]


def read_surface(name, directory="results"):
    """The points, cells (by array name) and point fields (per point, a list
    of its components) of the ASCII VTU name, and the names of the fields
    whose length does not match the points."""
    piece = ET.parse(os.path.join(directory, name)).getroot().find(".//Piece")
    n_points = int(piece.get("NumberOfPoints"))
    raw = numbers(piece.find("Points/DataArray"))
    points = [raw[i:i + 3] for i in range(0, len(raw), 3)]
    cells = {e.get("Name"): [int(float(x)) for x in e.text.split()] for e in piece.find("Cells")}
    fields, wrong = {}, []
    for e in piece.find("PointData"):
        values = numbers(e)
        components = int(e.get("NumberOfComponents", "1"))
        if len(values) != n_points * components:
            wrong.append(f"{name} {e.get('Name')}: {len(values)} values for {n_points} points")
        fields[e.get("Name")] = [values[i:i + components] for i in range(0, len(values), components)]
    return points, cells, fields, wrong
