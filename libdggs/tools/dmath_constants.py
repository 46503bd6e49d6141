"""Print the constants of libdggs/src/dmath.c, computed with mpmath at 2000 bits (C99 hex-float literals).

pi/2 in three 33-bit pieces and a rounded tail (Cody-Waite: n times a piece is exact for |n| < 2^20), pi/2 - P1
rounded, pi/2, pi and pi/4 as head and tail, 2/pi, 3 pi/4, atan(1/2), atan(1), atan(3/2) as head and tail, and
the first 40 32-bit words of 2/pi (Payne-Hanek). Compare by eye with dmath.c's #defines and tables::

    python libdggs/tools/dmath_constants.py
"""

from __future__ import annotations

import mpmath as mp


def _truncate(v, bits: int):
    """v > 0 cut to its first ``bits`` significant bits."""
    e = int(mp.floor(mp.log(v, 2)))
    scale = mp.mpf(2) ** (bits - 1 - e)
    return mp.floor(v * scale) / scale


def _hex(v) -> str:
    return float(v).hex()


def main() -> None:
    mp.mp.prec = 2000
    pio2 = mp.pi / 2
    p1 = _truncate(pio2, 33)
    p2 = _truncate(pio2 - p1, 33)
    p3 = _truncate(pio2 - p1 - p2, 33)
    print(f"P1 {_hex(p1)}  P1T {_hex(pio2 - p1)}  P2 {_hex(p2)}  P3 {_hex(p3)}  P3T {_hex(pio2 - p1 - p2 - p3)}")
    for name, v in (("PIO2", pio2), ("PI", mp.pi), ("PIO4", mp.pi / 4)):
        print(f"{name}_HI {_hex(v)}  {name}_LO {_hex(v - mp.mpf(float(v)))}")
    print(f"INV_PIO2 {_hex(2 / mp.pi)}  3PIO4 {_hex(3 * mp.pi / 4)}")
    for a in ("0.5", "1", "1.5"):
        v = mp.atan(mp.mpf(a))
        print(f"atan({a}) HEAD {_hex(v)}  TAIL {_hex(v - mp.mpf(float(v)))}")
    t, words = 2 / mp.pi, []
    for _ in range(40):
        t *= 2**32
        w = int(mp.floor(t))
        words.append(w)
        t -= w
    print("TWO_OVER_PI", ", ".join(f"0x{w:08x}u" for w in words))


if __name__ == "__main__":
    main()
