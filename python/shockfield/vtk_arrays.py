"""The data arrays of a VTK XML file (.vti/.vtp) as shockfield writes it — and as ParaView saves
it: ascii, inline base64 ("binary"), appended raw or base64, uncompressed or compressed with
vtkZLibDataCompressor (zlib blocks: a header [blocks, block size, last block size, compressed
sizes...] then the blocks); and of a .pvtp (particles in pieces, [output] vtk_pieces): its
pieces' arrays joined. Uses only numpy and the standard library.

    arrays = read_vtk_arrays("fields/particles_000000100.vtp")
    arrays["velocity"]   # numpy array, shape (n, 3)
"""
import base64
import os
import re
import zlib

import numpy as np

_TYPES = {"Int8": "i1", "UInt8": "u1", "Int16": "i2", "UInt16": "u2", "Int32": "i4", "UInt32": "u4",
          "Int64": "i8", "UInt64": "u8", "Float32": "f4", "Float64": "f8"}


def _attributes(tag):
    return dict(re.findall(rb'(\w+)="([^"]*)"', tag))


def _decode(block, header, endian, compressed):
    """The raw bytes of one array from its stored bytes (header included)."""
    h = np.dtype(endian + header)
    if not compressed:
        size = int(np.frombuffer(block[:h.itemsize], h)[0])
        return block[h.itemsize:h.itemsize + size]
    blocks = int(np.frombuffer(block[:h.itemsize], h)[0])
    head = np.frombuffer(block[:(3 + blocks) * h.itemsize], h).astype(int)
    pos, out = (3 + blocks) * h.itemsize, []
    for size in head[3:]:
        out.append(zlib.decompress(block[pos:pos + size]))
        pos += size
    return b"".join(out)


def _base64_array(text, header, endian, compressed):
    """Inline base64: the header and the data are encoded one after the other, as VTK writes them."""
    h = np.dtype(endian + header)
    chars = lambda nbytes: ((nbytes + 2) // 3) * 4  # noqa: E731
    first = base64.b64decode(text[:chars(h.itemsize)])
    head_bytes = (3 + int(np.frombuffer(first[:h.itemsize], h)[0])) * h.itemsize if compressed else h.itemsize
    head = base64.b64decode(text[:chars(head_bytes)])
    return _decode(head + base64.b64decode(text[chars(head_bytes):]), header, endian, compressed)


def _piece_arrays(path, markup):
    """The arrays of a .pvtp's pieces joined in piece order; the vertex cells (one per point, as
    shockfield writes them) numbered over the whole."""
    folder = os.path.dirname(path)
    pieces = [read_vtk_arrays(os.path.join(folder, _attributes(m.group(1))[b"Source"].decode()))
              for m in re.finditer(rb"<Piece\b([^>]*)>", markup)]
    if not pieces:
        raise ValueError(f"{path}: a PPolyData without pieces")
    out = {name: np.concatenate([p[name] for p in pieces]) for name in pieces[0]
           if name not in ("connectivity", "offsets")}
    n = len(out["points"])
    out["connectivity"], out["offsets"] = np.arange(n, dtype=np.int64), np.arange(1, n + 1, dtype=np.int64)
    return out


def read_vtk_arrays(path):
    """{name: numpy array} of every DataArray (points, point and cell data); arrays with k > 1
    components have shape (n, k)."""
    with open(path, "rb") as f:
        data = f.read()
    start = data.find(b"<AppendedData")
    markup = data if start < 0 else data[:start]
    if re.search(rb'<VTKFile[^>]*type="PPolyData"', markup):
        return _piece_arrays(path, markup)
    vtkfile = _attributes(re.search(rb"<VTKFile[^>]*>", markup).group(0))
    endian = "<" if vtkfile.get(b"byte_order", b"LittleEndian") == b"LittleEndian" else ">"
    header = "u8" if vtkfile.get(b"header_type") == b"UInt64" else "u4"
    compressed = vtkfile.get(b"compressor") == b"vtkZLibDataCompressor"
    if b"compressor" in vtkfile and not compressed:
        raise ValueError(f"{path}: compressor {vtkfile[b'compressor'].decode()} is not read (only zlib)")
    appended = b""
    if start >= 0:
        section = data[start:]
        encoding = _attributes(section[:section.find(b">")]).get(b"encoding", b"raw")
        appended = section[section.find(b"_") + 1:]
        if encoding == b"base64":
            raise ValueError(f"{path}: appended base64 data is not read (save as raw)")
    out = {}
    for m in re.finditer(rb"<DataArray([^>]*?)(/>|>(.*?)</DataArray>)", markup, re.S):
        a = _attributes(m.group(1))
        dtype = np.dtype(endian + _TYPES[a[b"type"].decode()])
        fmt = a.get(b"format", b"ascii")
        if fmt == b"ascii":
            values = np.array(m.group(3).split(), dtype=float).astype(dtype)
        elif fmt == b"binary":
            text = re.sub(rb"\s", b"", m.group(3))
            values = np.frombuffer(_base64_array(text, header, endian, compressed), dtype)
        else:
            values = np.frombuffer(_decode(appended[int(a[b"offset"]):], header, endian, compressed), dtype)
        k = int(a.get(b"NumberOfComponents", b"1"))
        out[a[b"Name"].decode()] = values.reshape(-1, k) if k > 1 else values
    return out
