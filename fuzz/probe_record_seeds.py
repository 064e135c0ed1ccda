"""Seed corpus of the probe_record fuzzer: a first byte choosing the format (0 WAV, 1 CSV) and a
small record with x1, y1, x2, y2 and a keyphasor."""

import math
import pathlib
import struct
import sys

folder = pathlib.Path(sys.argv[1])
folder.mkdir(parents=True, exist_ok=True)
frames = []
for i in range(400):
    t = i / 5000
    key = 1.0 if (t * 50) % 1.0 < 0.1 else 0.0
    frames.append([math.cos(t * 900), math.sin(t * 900), math.cos(t * 400), -math.sin(t * 400), key])
data = b"".join(struct.pack("<f", v) for f in frames for v in f)
wav = b"RIFF" + struct.pack("<I", 36 + len(data)) + b"WAVEfmt " + struct.pack(
    "<IHHIIHH", 16, 3, 5, 5000, 5000 * 20, 20, 32) + b"data" + struct.pack("<I", len(data)) + data
(folder / "seed_wav").write_bytes(b"\x00" + wav)
csv = "t_s,x1_m,y1_m,x2_m,y2_m,keyphasor\n" + "".join(
    f"{i / 5000}," + ",".join(f"{v:.6g}" for v in f) + "\n" for i, f in enumerate(frames))
(folder / "seed_csv").write_bytes(b"\x01" + csv.encode())
