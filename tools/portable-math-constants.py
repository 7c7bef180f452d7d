#!/usr/bin/env python3
"""Prints the constants of src/MagnusBall/Runtime/PortableMath.cs that are not fdlibm's published ones, and the
expected values of PortableMathTests.HardReductions_AreCorrectlyRounded, from mpmath at high precision.
   python3 tools/portable-math-constants.py        (needs python3-mpmath)"""
from mpmath import mp, mpf, pi, log, floor, sin, cos

mp.prec = 4000
d = float


def truncate(v, nbits):
    """v cut to its first nbits significant bits (the Cody-Waite pieces of pi/2)."""
    e = int(floor(mp.log(abs(v), 2)))
    scale = mpf(2) ** (nbits - 1 - e)
    return floor(v * scale) / scale


pio2 = pi / 2
rest = pio2
for i in (1, 2, 3):
    piece = truncate(rest, 33)
    tail = rest - piece
    print(f"Pio2_{i} = {d(piece)!r}  Pio2_{i}t = {d(tail)!r}")
    rest = tail
print(f"Pio2Hi = {d(pio2)!r}  Pio2Lo = {d(pio2 - d(pio2))!r}  InvPio2 = {d(2 / pi)!r}")
print(f"Ln2Hi53 = {d(log(2))!r}  Ln2Lo53 = {d(log(2) - d(log(2)))!r}")
print(f"ThirdHi = {d(mpf(1) / 3)!r}  ThirdLo = {d(mpf(1) / 3 - d(mpf(1) / 3))!r}")
words = 20
P = int(floor(2 / pi * mpf(2) ** (64 * words)))
print("TwoOverPi = " + ", ".join("0x%016XUL" % ((P >> (64 * (words - 1 - i))) & (2**64 - 1)) for i in range(words)))
for x in (mpf(6381956970095103) * mpf(2) ** 797, mpf(1e22), mpf(1e300), mpf(1.7976931348623157e308), mpf(1647099.3291652855)):
    print(f"x = {d(x)!r}: sin {d(sin(x))!r}, cos {d(cos(x))!r}")
