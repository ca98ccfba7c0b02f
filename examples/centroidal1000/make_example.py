#!/usr/bin/env python3
"""Writes the 1,000-site centroidal example: sites.txt (uniform random centres in the unit cube, weight 0)
and masses.txt (random target volumes, uniform in [1, 3] before normalising to sum 1, printed round-trip).
Deterministic: Python's Mersenne Twister with seed 20240618."""
import random

random.seed(20240618)
n = 1000
with open("sites.txt", "w") as f:
    f.write("# 1,000 sites uniform in the unit cube, weight 0 (make_example.py)\n")
    for _ in range(n):
        f.write("%r %r %r 0\n" % (random.random(), random.random(), random.random()))
raw = [random.uniform(1, 3) for _ in range(n)]
total = sum(raw)
with open("masses.txt", "w") as f:
    f.write("# random target volumes, fractions of the unit cube summing to 1 (make_example.py)\n")
    for m in raw:
        f.write("%r\n" % (m / total))
