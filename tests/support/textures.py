"""Texture files that must be refused, made small on disk."""
import struct
import zlib
from pathlib import Path


def _chunk(kind: bytes, data: bytes) -> bytes:
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


def huge_png(path: Path, side: int = 50000) -> Path:
    """A valid all-black 1-bit PNG of side x side pixels (50000: 2.5 billion
    pixels, about 300 KB on disk). Written row block by row block: Pillow
    would hold the whole 312 MB image to save it."""
    row = bytes(1 + (side + 7) // 8)  # filter byte 0, then the bits
    packer = zlib.compressobj(9)
    block = row * 1000
    data = [packer.compress(block) for _ in range(side // 1000)]
    data += [packer.compress(row * (side % 1000)), packer.flush()]
    header = struct.pack(">IIBBBBB", side, side, 1, 0, 0, 0, 0)  # 1-bit grey
    path.write_bytes(b"\x89PNG\r\n\x1a\n" + _chunk(b"IHDR", header)
                     + _chunk(b"IDAT", b"".join(data)) + _chunk(b"IEND", b""))
    return path
