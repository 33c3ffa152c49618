"""PFM files as numpy arrays, for the bench scripts."""
import numpy as np


def read_pfm(path):
    """rows top to bottom, float64, 3 channels (PF) or 1 (Pf)"""
    with open(path, "rb") as f:
        kind = f.readline().strip()
        w, h = map(int, f.readline().split())
        f.readline()
        n = 3 if kind == b"PF" else 1
        return np.frombuffer(f.read(), dtype="<f4").reshape(h, w, n)[::-1].astype(np.float64)


def write_pfm(path, image):
    """image: rows top to bottom, 3 channels"""
    h, w = image.shape[:2]
    with open(path, "wb") as f:
        f.write(b"PF\n%d %d\n-1.0\n" % (w, h))
        f.write(np.ascontiguousarray(image[::-1, :, :3], dtype="<f4").tobytes())
