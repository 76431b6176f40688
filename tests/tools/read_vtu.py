#!/usr/bin/python3
"""Independent reader of feticon's VTK XML UnstructuredGrid (.vtu) files, for the io unit tests.

Usage: read_vtu.py FILE.vtu
Prints one JSON object: NumberOfPoints, NumberOfCells, and for "points", "cells" (connectivity,
offsets, types), "point_data" and "cell_data" every array's type, component count, number of
values, sum, min and max. Uses only xml.etree, base64 and numpy, so it checks the file against the
VTK format description, not against feticon's own code.

Binary arrays: base64 of a byte-count header (header_type, UInt32 by default) followed by the data.
Both VTK encodings are accepted: header and data in one base64 stream (as VTK writes), or the
header encoded separately (its '=' padding then ends the first chunk).
"""
import base64
import json
import sys
import xml.etree.ElementTree as ElementTree

import numpy

TYPES = {
    "Int8": "i1", "UInt8": "u1", "Int16": "i2", "UInt16": "u2", "Int32": "i4", "UInt32": "u4",
    "Int64": "i8", "UInt64": "u8", "Float32": "f4", "Float64": "f8",
}


def decode_binary(text, dtype, header_dtype):
    text = "".join(text.split())
    header_size = header_dtype.itemsize
    raw = base64.b64decode(text)
    n_bytes = int(numpy.frombuffer(raw[:header_size], header_dtype)[0])
    if len(raw) == header_size + n_bytes:
        data = raw[header_size:]
    else:
        # Header encoded on its own: its base64 length is a multiple of 4 characters.
        header_chars = 4 * ((header_size + 2) // 3)
        data = base64.b64decode(text[header_chars:])
    if len(data) != n_bytes:
        raise ValueError(f"header says {n_bytes} bytes, decoded {len(data)}")
    return numpy.frombuffer(data, dtype)


def read_array(element, byte_order, header_dtype):
    prefix = "<" if byte_order == "LittleEndian" else ">"
    dtype = numpy.dtype(prefix + TYPES[element.get("type")])
    data_format = element.get("format")
    if data_format == "binary":
        values = decode_binary(element.text or "", dtype, header_dtype)
    elif data_format == "ascii":
        values = numpy.array((element.text or "").split(), dtype=dtype)
    else:
        raise ValueError(f"unsupported DataArray format {data_format!r}")
    return values


def parse(path):
    """The root of the .vtu at `path`, its byte order and the dtype of its binary headers."""
    root = ElementTree.parse(path).getroot()
    byte_order = root.get("byte_order", "LittleEndian")
    header_dtype = numpy.dtype(("<" if byte_order == "LittleEndian" else ">") +
                               TYPES[root.get("header_type", "UInt32")])
    return root, byte_order, header_dtype


def point_data(path):
    """Every PointData array of the .vtu at `path` by name, vectors as (points, components)."""
    root, byte_order, header_dtype = parse(path)
    arrays = {}
    for element in root.findall("UnstructuredGrid/Piece/PointData/DataArray"):
        values = read_array(element, byte_order, header_dtype)
        components = int(element.get("NumberOfComponents", "1"))
        arrays[element.get("Name")] = values.reshape(-1, components) if components > 1 else values
    return arrays


def points(path):
    """The point coordinates of the .vtu at `path`, (points, 3)."""
    root, byte_order, header_dtype = parse(path)
    element = root.find("UnstructuredGrid/Piece/Points/DataArray")
    return read_array(element, byte_order, header_dtype).reshape(-1, 3)


def describe(element, values):
    summary = {
        "type": element.get("type"),
        "components": int(element.get("NumberOfComponents", "1")),
        "n_values": int(values.size),
    }
    if values.size:
        as_float = values.astype(numpy.float64)
        summary.update(sum=float(as_float.sum()), min=float(as_float.min()), max=float(as_float.max()))
    return summary


def main(path):
    root, byte_order, header_dtype = parse(path)
    if root.get("type") != "UnstructuredGrid":
        raise ValueError(f"not an UnstructuredGrid file: type={root.get('type')!r}")
    if root.get("compressor"):
        raise ValueError("compressed data are not supported by this reader")
    piece = root.find("UnstructuredGrid/Piece")
    result = {
        "NumberOfPoints": int(piece.get("NumberOfPoints")),
        "NumberOfCells": int(piece.get("NumberOfCells")),
    }
    for section, key in (("Points", "points"), ("Cells", "cells"), ("PointData", "point_data"),
                         ("CellData", "cell_data")):
        arrays = {}
        for element in piece.findall(section + "/DataArray"):
            values = read_array(element, byte_order, header_dtype)
            arrays[element.get("Name")] = describe(element, values)
        result[key] = arrays
    print(json.dumps(result, indent=1))


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: read_vtu.py FILE.vtu")
    main(sys.argv[1])
