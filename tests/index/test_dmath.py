"""The core's own sin, cos, atan2, hypot and asin (libdggs/src/dmath.c) are within 1 ulp of mpmath (issue 34).

The core carries these five so that the native and the WebAssembly builds give the same bits, and so the same
ids at exact ties. A thin test binding: dmath.c compiled on its own into a shared library with the build's
floating-point flags (no FMA contraction), called through ctypes. The reference is mpmath at 200 bits; the error
is measured in ulps of the exact value. Random arguments over each domain (the core's ranges and beyond), and
the hard cases: near multiples of pi/2 (the double nearest a multiple of pi/2, Muller's 6381956970095103 2^797),
tiny and huge arguments, signed zeros, subnormals, infinities and nans. ``-m slow`` draws a million arguments per
function.
"""

from __future__ import annotations

import ctypes
import math
import random
import shutil
import subprocess
from pathlib import Path

import mpmath as mp  # the test extra: a missing mpmath fails here, never skips
import numpy as np
import pytest
from hypothesis import example, given, settings
from hypothesis import strategies as st

ROOT = Path(__file__).resolve().parents[2]
SOURCE = ROOT / "libdggs" / "src" / "dmath.c"
FLAGS = ["-O2", "-std=c11", "-ffp-contract=off", "-fno-fast-math", "-fPIC", "-shared"]


@pytest.fixture(scope="module")
def dmath(tmp_path_factory):
    cc = shutil.which("cc") or shutil.which("gcc") or shutil.which("clang")
    assert cc, "a C compiler builds the core; none on PATH"
    lib = tmp_path_factory.mktemp("dmath") / "libdmath.so"
    subprocess.run([cc, *FLAGS, str(SOURCE), "-o", str(lib), "-lm"], check=True)
    so = ctypes.CDLL(str(lib))
    for name, arity in (("sin", 1), ("cos", 1), ("asin", 1), ("atan2", 2), ("hypot", 2)):
        fn = getattr(so, f"dggs_{name}")
        fn.restype = ctypes.c_double
        fn.argtypes = [ctypes.c_double] * arity
    so.dggs_sincos.restype = None
    so.dggs_sincos.argtypes = [ctypes.c_double, ctypes.POINTER(ctypes.c_double), ctypes.POINTER(ctypes.c_double)]
    return so


def _exact(name: str, args: tuple[float, ...]):
    with mp.workprec(200):
        a = [mp.mpf(x) for x in args]
        if name == "hypot":
            return mp.sqrt(a[0] ** 2 + a[1] ** 2)
        if name == "atan2":
            if args[0] == 0:  # mpmath has no signed zero: C's atan2(+-0, x) is +-0, or +-pi where x is negative
                return (mp.pi if math.copysign(1.0, args[1]) < 0 else mp.mpf(0)) * math.copysign(1.0, args[0])
            return mp.atan2(a[0], a[1])
        return getattr(mp, name)(a[0])


def _ulps(got: float, exact) -> float:
    """|got - exact| in units of the last place of the exact value (subnormal spacing below 2^-1022)."""
    if exact == 0:
        return 0.0 if got == 0 else math.inf
    with mp.workprec(200):
        _, e = mp.frexp(exact)
        ulp = mp.ldexp(1, max(int(e) - 53, -1074))
        return float(abs(mp.mpf(got) - exact) / ulp)


def _worst(dmath, name: str, cases) -> tuple[float, tuple]:
    fn = getattr(dmath, f"dggs_{name}")
    worst: tuple[float, tuple] = (0.0, ())
    for args in cases:
        got = fn(*args)
        err = _ulps(got, _exact(name, args))
        if err > worst[0]:
            worst = (err, (args, got))
    return worst


def _nearest_double_to_multiple(k: int) -> float:
    with mp.workprec(300):
        return float(k * mp.pi / 2)


def _angles(rng: random.Random, n: int) -> list[float]:
    core = [rng.uniform(-2 * math.pi, 2 * math.pi) for _ in range(n)]  # the core: radians of lat/lng and sums
    medium = [rng.uniform(-1e6, 1e6) for _ in range(n // 8)]
    huge = [rng.choice((-1.0, 1.0)) * math.ldexp(rng.uniform(1.0, 2.0), rng.randint(20, 1023)) for _ in range(n // 8)]
    tiny = [rng.choice((-1.0, 1.0)) * math.ldexp(rng.uniform(1.0, 2.0), rng.randint(-1074, -20)) for _ in range(n // 16)]
    return core + medium + huge + tiny


HARD_ANGLES = (
    [_nearest_double_to_multiple(k) for k in range(-64, 65)]
    + [math.nextafter(_nearest_double_to_multiple(k), d) for k in range(1, 65) for d in (0.0, math.inf)]
    + [_nearest_double_to_multiple(k) for k in (10**6, 10**9, 10**12, 2**40 + 1, 10**15)]
    + [6381956970095103 * 2.0**797, -6381956970095103 * 2.0**797, 1e22, 1e300, 1.7976931348623157e308]
    + [math.pi / 4, math.nextafter(math.pi / 4, 1), math.nextafter(math.pi / 4, 0), 2.0**-26, 2.0**-27]
    + [5e-324, -5e-324, 2.2250738585072014e-308, 0.0, -0.0, 2.0**20, math.nextafter(2.0**20, 0)]
)


def _unit_args(rng: random.Random, n: int) -> list[float]:
    plain = [rng.uniform(-1.0, 1.0) for _ in range(n)]
    near_one = [rng.choice((-1.0, 1.0)) * (1.0 - rng.uniform(0.0, 0.05)) for _ in range(n // 8)]
    near_half = [rng.choice((-1.0, 1.0)) * rng.uniform(0.45, 0.55) for _ in range(n // 8)]
    tiny = [math.ldexp(rng.uniform(1.0, 2.0), -rng.randint(1, 1074)) for _ in range(n // 16)]
    return plain + near_one + near_half + tiny


HARD_UNIT = [0.0, -0.0, 1.0, -1.0, 0.5, -0.5, 0.975, math.nextafter(0.975, 0), math.nextafter(1.0, 0), 2.0**-26,
             math.nextafter(0.5, 0), 5e-324, 2.0**-1022]


def _pairs(rng: random.Random, n: int) -> list[tuple[float, float]]:
    plain = [(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)) for _ in range(n)]
    scaled = [
        (math.ldexp(rng.uniform(-1.0, 1.0), rng.randint(-1074, 1023)), math.ldexp(rng.uniform(-1, 1), rng.randint(-1074, 1023)))
        for _ in range(n // 8)
    ]
    close = [(rng.uniform(-1.0, 1.0) * 1e-9, rng.uniform(-1.0, 1.0)) for _ in range(n // 16)]
    close += [(rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0) * 1e-9) for _ in range(n // 16)]
    ones = [(v, v * rng.choice((1.0, -1.0)) * (1 + rng.uniform(-1e-6, 1e-6))) for v in (rng.uniform(0.1, 10) for _ in range(n // 16))]
    return plain + scaled + close + ones


HARD_PAIRS = [
    (a, b)
    for a in (0.0, -0.0, 1.0, -1.0, 5e-324, -5e-324, 1e308, -1e308, 2.0**-60, 3.0)
    for b in (0.0, -0.0, 1.0, -1.0, 5e-324, -5e-324, 1e308, -1e308, 2.0**60, 3.0)
] + [(1.0, 2.0**-61), (1.0, -(2.0**-61)), (2.0**-61, -1.0), (0.4375, 1.0), (0.6875, 1.0), (1.1875, 1.0), (2.4375, 1.0)]


@pytest.mark.parametrize("name", ["sin", "cos"])
def test_sin_cos_within_an_ulp(dmath, name):
    cases = [(x,) for x in _angles(random.Random(34), 20_000) + HARD_ANGLES]
    err, where = _worst(dmath, name, cases)
    assert err <= 1.0, (name, err, where)


def test_asin_within_an_ulp(dmath):
    cases = [(x,) for x in _unit_args(random.Random(35), 20_000) + HARD_UNIT]
    err, where = _worst(dmath, "asin", cases)
    assert err <= 1.0, (err, where)


@pytest.mark.parametrize("name", ["atan2", "hypot"])
def test_atan2_hypot_within_an_ulp(dmath, name):
    err, where = _worst(dmath, name, _pairs(random.Random(36), 20_000) + HARD_PAIRS)
    assert err <= 1.0, (name, err, where)


SHIM = """
#include "dmath.h"
void many1(int f, const double *x, double *r, long n) {
    for (long i = 0; i < n; i++) r[i] = f == 0 ? dggs_sin(x[i]) : f == 1 ? dggs_cos(x[i]) : dggs_asin(x[i]);
}
void many2(int f, const double *y, const double *x, double *r, long n) {
    for (long i = 0; i < n; i++) r[i] = f == 0 ? dggs_atan2(y[i], x[i]) : dggs_hypot(y[i], x[i]);
}
"""


@pytest.fixture(scope="module")
def many(tmp_path_factory):
    """The five over arrays: a loop in C beside dmath.c (ctypes one call at a time would take minutes)."""
    cc = shutil.which("cc") or shutil.which("gcc") or shutil.which("clang")
    tmp = tmp_path_factory.mktemp("dmath_many")
    (tmp / "shim.c").write_text(SHIM)
    lib = tmp / "libmany.so"
    subprocess.run([cc, *FLAGS, f"-I{SOURCE.parent}", str(tmp / "shim.c"), str(SOURCE), "-o", str(lib), "-lm"], check=True)
    return ctypes.CDLL(str(lib))


@pytest.mark.slow
@pytest.mark.parametrize("name", ["sin", "cos", "asin", "atan2", "hypot"])
def test_millions_of_arguments_each(many, name):
    """Two million arguments a function: the x87 long double (64-bit significand) libm estimates each error to
    2^-10 ulp; every argument estimated above 0.9 ulp is measured again with mpmath, which decides."""
    rng = np.random.default_rng(3400)
    n = 2_000_000
    ld = np.longdouble
    if name in ("sin", "cos"):
        args = [np.concatenate([rng.uniform(-2 * np.pi, 2 * np.pi, n - n // 4), rng.uniform(-1e6, 1e6, n // 8),
                                np.ldexp(rng.uniform(1, 2, n // 8), rng.integers(20, 1023, n // 8))])]
        ref = (np.sin if name == "sin" else np.cos)(args[0].astype(ld))
    elif name == "asin":
        args = [np.concatenate([rng.uniform(-1, 1, n - n // 4), 1 - rng.uniform(0, 0.05, n // 8),
                                rng.uniform(0.45, 0.55, n // 8)])]
        ref = np.arcsin(args[0].astype(ld))
    else:
        y = np.concatenate([rng.uniform(-1, 1, n - n // 4), np.ldexp(rng.uniform(-1, 1, n // 4), rng.integers(-1000, 1000, n // 4))])
        x = np.concatenate([rng.uniform(-1, 1, n - n // 4), np.ldexp(rng.uniform(-1, 1, n // 4), rng.integers(-1000, 1000, n // 4))])
        args = [y, x]
        ref = np.arctan2(y.astype(ld), x.astype(ld)) if name == "atan2" else np.hypot(y.astype(ld), x.astype(ld))
    got = np.empty(n)
    ptr = [a.ctypes.data_as(ctypes.POINTER(ctypes.c_double)) for a in [*args, got]]
    if name in ("sin", "cos", "asin"):
        many.many1(("sin", "cos", "asin").index(name), *ptr, ctypes.c_long(n))
    else:
        many.many2(("atan2", "hypot").index(name), *ptr, ctypes.c_long(n))
    ulp = np.spacing(np.abs(ref.astype(np.float64))).astype(ld)
    estimate = np.abs(got.astype(ld) - ref) / ulp
    suspects = np.flatnonzero(~(estimate <= 0.9))
    assert suspects.size < n // 1000, f"{suspects.size} of {n} arguments estimated above 0.9 ulp"
    for i in suspects:
        a = tuple(float(v[i]) for v in args)
        err = _ulps(float(got[i]), _exact(name, a))
        assert err <= 1.0, (name, a, float(got[i]), err)


def _same(a: float, b: float) -> bool:
    return (math.isnan(a) and math.isnan(b)) or (a == b and math.copysign(1.0, a) == math.copysign(1.0, b))


def test_special_values_follow_c_annex_f(dmath):
    """Signed zeros, infinities and nans as C11 Annex F (and IEEE 754-2019 9.2) have them."""
    inf, nan, pi = math.inf, math.nan, math.pi
    want = [
        (("sin", (0.0,)), 0.0), (("sin", (-0.0,)), -0.0), (("sin", (inf,)), nan), (("sin", (-inf,)), nan), (("sin", (nan,)), nan),
        (("cos", (0.0,)), 1.0), (("cos", (-0.0,)), 1.0), (("cos", (inf,)), nan), (("cos", (nan,)), nan),
        (("asin", (0.0,)), 0.0), (("asin", (-0.0,)), -0.0), (("asin", (1.0,)), pi / 2), (("asin", (-1.0,)), -pi / 2),
        (("asin", (1.5,)), nan), (("asin", (-inf,)), nan), (("asin", (nan,)), nan),
        (("atan2", (0.0, 0.0)), 0.0), (("atan2", (-0.0, 0.0)), -0.0), (("atan2", (0.0, -0.0)), pi),
        (("atan2", (-0.0, -0.0)), -pi), (("atan2", (0.0, -1.0)), pi), (("atan2", (-0.0, -1.0)), -pi),
        (("atan2", (-0.0, 1.0)), -0.0), (("atan2", (1.0, 0.0)), pi / 2), (("atan2", (-1.0, -0.0)), -pi / 2),
        (("atan2", (inf, inf)), pi / 4), (("atan2", (-inf, -inf)), -3 * pi / 4), (("atan2", (1.0, -inf)), pi),
        (("atan2", (-1.0, inf)), -0.0), (("atan2", (inf, 1.0)), pi / 2), (("atan2", (nan, 1.0)), nan),
        (("atan2", (1.0, nan)), nan),
        (("hypot", (inf, nan)), inf), (("hypot", (nan, -inf)), inf), (("hypot", (nan, 1.0)), nan),
        (("hypot", (-0.0, 0.0)), 0.0), (("hypot", (-3.0, 4.0)), 5.0), (("hypot", (1e308, 1e308)), math.hypot(1e308, 1e308)),
        (("hypot", (5e-324, 0.0)), 5e-324),
    ]
    for (name, args), expected in want:
        got = getattr(dmath, f"dggs_{name}")(*args)
        assert _same(got, expected), (name, args, got, expected)


def test_sincos_is_sin_and_cos(dmath):
    s, c = ctypes.c_double(), ctypes.c_double()
    for x in _angles(random.Random(37), 2_000) + HARD_ANGLES + [math.inf, math.nan]:
        dmath.dggs_sincos(x, ctypes.byref(s), ctypes.byref(c))
        assert _same(s.value, dmath.dggs_sin(x)) and _same(c.value, dmath.dggs_cos(x)), x


finite = st.floats(allow_nan=False, allow_infinity=False)


@settings(max_examples=500, deadline=None)
@given(x=finite)
@example(x=math.pi / 2)
@example(x=-0.0)
@example(x=6381956970095103 * 2.0**797)
@example(x=2.0**20)
def test_sin_odd_cos_even_and_pythagoras(dmath, x):
    """sin(-x) = -sin(x) and cos(-x) = cos(x) bit for bit; sin^2 + cos^2 within 4 ulps of 1."""
    s, c = dmath.dggs_sin(x), dmath.dggs_cos(x)
    assert _same(dmath.dggs_sin(-x), -s) and _same(dmath.dggs_cos(-x), c)
    assert abs(s * s + c * c - 1.0) <= 4 * 2.0**-53


@settings(max_examples=500, deadline=None)
@given(y=finite, x=finite)
@example(y=1.0, x=1.0)
@example(y=-0.0, x=-1.0)
@example(y=1e-300, x=1e300)
@example(y=1.0, x=-(2.0**-60))
def test_atan2_and_hypot_symmetries(dmath, y, x):
    """atan2(-y, x) = -atan2(y, x); atan2 of a negative x is pi minus that of -x (to an ulp); hypot is symmetric
    and sign-blind, and no smaller than either argument."""
    a = dmath.dggs_atan2(y, x)
    assert _same(dmath.dggs_atan2(-y, x), -a)
    assert -math.pi <= a <= math.pi
    if x < 0 and y > 0:
        assert abs(a - (math.pi - dmath.dggs_atan2(y, -x))) <= 2 * math.ulp(math.pi)
    h = dmath.dggs_hypot(y, x)
    assert _same(h, dmath.dggs_hypot(x, y)) and _same(h, dmath.dggs_hypot(-y, -x))
    assert h >= max(abs(x), abs(y))


@settings(max_examples=500, deadline=None)
@given(x=st.floats(min_value=-1.0, max_value=1.0))
@example(x=1.0)
@example(x=0.5)
@example(x=-0.975)
@example(x=-0.0)
def test_asin_odd_and_inverts_sin(dmath, x):
    a = dmath.dggs_asin(x)
    assert _same(dmath.dggs_asin(-x), -a)
    assert abs(a) <= math.pi / 2 + 1e-15
    assert abs(dmath.dggs_sin(a) - x) <= 2 * math.ulp(1.0)


def test_constants_are_mpmaths():
    """dmath.c's pi/2 pieces, pi, 2/pi and the words of 2/pi, recomputed at 2000 bits (as dmath_constants.py)."""
    import re

    text = SOURCE.read_text()
    defined = {m[1]: float.fromhex(m[2]) for m in re.finditer(r"#define (\w+) (0x[0-9a-fp.+-]+)", text)}
    with mp.workprec(2000):
        pio2 = mp.pi / 2
        assert abs(mp.mpf(defined["P1"]) + defined["P2"] + defined["P3"] + defined["P3T"] - pio2) < mp.mpf(2) ** -155
        for name in ("P1", "P2", "P3"):  # 33 significant bits: n * Pk exact for |n| < 2^20
            assert int(mp.mpf(defined[name]) * 2 ** (52 - math.frexp(defined[name])[1] + 1)) % 2**20 == 0, name
        assert defined["P1T"] == float(pio2 - defined["P1"])
        for name, v in (("PIO2", pio2), ("PI", mp.pi)):
            assert defined[f"{name}_HI"] == float(v) and defined[f"{name}_LO"] == float(v - mp.mpf(float(v)))
        assert defined["INV_PIO2"] == float(2 / mp.pi) and defined["PIO4"] == float(mp.pi / 4)
        words = [int(w, 16) for w in re.findall(r"0x([0-9a-f]{8})u", text.split("TWO_OVER_PI[40] = {")[1])[:40]]
        assert mp.mpf(sum(w * mp.mpf(2) ** (-32 * (k + 1)) for k, w in enumerate(words))) - 2 / mp.pi < 0
        assert 2 / mp.pi - sum(w * mp.mpf(2) ** (-32 * (k + 1)) for k, w in enumerate(words)) < mp.mpf(2) ** -1280
    inline = (SOURCE.parent / "dmath_inline.h").read_text()  # the inlined small-angle sin and cos's bound
    assert float.fromhex(re.search(r"#define DMATH_PIO4 (0x[0-9a-fp.+-]+)", inline)[1]) == defined["PIO4"]
