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
