"""Reading the ASCII VTU and PVD files of a run from the postprocess test scripts."""
import base64
import math
import os
import struct
import xml.etree.ElementTree as ET
import zlib


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


def active_nodes(surface):
    """The active nodes of a contact-surface VTU's point fields (read_surface()),
    each a dict of its pressure, stick flag and tangential traction (x, y)."""
    return [{"pressure": p[0], "stick": s[0], "tangential_traction_x": tx[0],
             "tangential_traction_y": ty[0]}
            for p, a, s, tx, ty in zip(surface["contact_pressure"], surface["active"],
                                       surface["stick"], surface["tangential_traction_x"],
                                       surface["tangential_traction_y"]) if a[0] == 1]


def _decode(text, kind):
    """A data array of deal.II's compressed binary VTU: a base64 header of
    UInt32 (number of blocks, block size, last block size, the compressed
    size of each block), then the base64 zlib blocks."""
    text = "".join(text.split())
    count = struct.unpack("<I", base64.b64decode(text[:8])[:4])[0]
    header_length = 4 * math.ceil(4 * (3 + count) / 3)
    sizes = struct.unpack(f"<{3 + count}I", base64.b64decode(text[:header_length]))[3:]
    data, raw, start = b"", base64.b64decode(text[header_length:]), 0
    for size in sizes:
        data += zlib.decompress(raw[start:start + size])
        start += size
    code = {"Float32": "f", "Float64": "d", "Int32": "i", "UInt8": "B"}[kind]
    return struct.unpack(f"<{len(data) // struct.calcsize(code)}{code}", data)


def read_volume(name, directory="results"):
    """The points and point fields (per point, a list of its components;
    cell data such as material_id is a point field of deal.II's patches)
    of all pieces of the PVTU name, written by deal.II's DataOut
    (compressed; single precision)."""
    points, fields = [], {}
    for source in ET.parse(os.path.join(directory, name)).getroot().iter("Piece"):
        root = ET.parse(os.path.join(directory, source.get("Source"))).getroot()
        assert root.get("header_type", "UInt32") == "UInt32"
        piece = root.find(".//Piece")
        raw = _decode(piece.find("Points/DataArray").text, piece.find("Points/DataArray").get("type"))
        points += [list(raw[i:i + 3]) for i in range(0, len(raw), 3)]
        for e in piece.find("PointData"):
            values = _decode(e.text, e.get("type"))
            components = int(e.get("NumberOfComponents", "1"))
            fields.setdefault(e.get("Name"), []).extend(
                list(values[i:i + components]) for i in range(0, len(values), components))
    return points, fields


def tied_volume(name, references, directory="results"):
    """The tying fields of the volume PVTU name at the tied slave nodes.

    references: the reference positions of the tied slave nodes (3
    coordinates each). Returns, per reference, the (traction, normal
    traction) of the volume points there in the slave body's cells (the
    one material whose points carry a tying traction), and a list of
    problems: a tying traction off the slave surface or in cells of more
    than one material, a slave node the volume lacks, no master point at
    the interface that shows zero. Positions match to 1e-6 of the model
    size (the volume is single precision)."""
    points, fields = read_volume(name, directory)
    problems = [f"{name}: no field {f}" for f in ("tying_traction", "tying_normal_traction")
                if f not in fields]
    if problems:
        return [], problems
    size = max(max(p[d] for p in points) - min(p[d] for p in points) for d in range(3))
    close = lambda a, b: all(abs(a[d] - b[d]) <= 1e-6 * size for d in range(3))
    where = [next((r for r, x in enumerate(references) if close(p, x)), None) for p in points]
    carrying = [k for k, t in enumerate(fields["tying_traction"])
                if any(t) or fields["tying_normal_traction"][k][0] != 0]
    slave = {fields["material_id"][k][0] for k in carrying}
    if len(slave) != 1:
        problems.append(f"{name}: tying traction in cells of materials {sorted(slave)}")
    problems += [f"{name}: tying traction {fields['tying_traction'][k]} at {points[k]}, "
                 f"off the tied slave surface" for k in carrying if where[k] is None]
    values = [[] for _ in references]
    master_zero = False
    for k, r in enumerate(where):
        if r is None:
            continue
        if fields["material_id"][k][0] in slave:
            values[r].append((fields["tying_traction"][k], fields["tying_normal_traction"][k][0]))
        else:
            master_zero = True
    problems += [f"{name}: no slave point at {x}" for x, v in zip(references, values) if not v]
    if not master_zero:
        problems.append(f"{name}: no master point on the interface with zero tying traction")
    return values, problems
