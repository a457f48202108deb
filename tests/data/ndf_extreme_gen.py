#!/usr/bin/env python3
"""Generate tests/data/ndf_extreme.csv: NDF values at extreme parameters, computed with mpmath.

Independent of the Rust code: every value comes from the textbook formula of docs/maths.md evaluated at
60 significant digits from the exact doubles written in the file (parameters and theta), with the
normalization N computed in high precision (closed form where it exists, its removable-singularity
limit at a2 = 1 and 2, Dawson + Faddeeva for Torrance-Sparrow).

Usage: python3 tests/data/ndf_extreme_gen.py > tests/data/ndf_extreme.csv   (needs mpmath >= 1.3)
"""
import json
import math

from mpmath import mp, mpf, mpc

mp.dps = 60
PI = mp.pi
HALF_PI = 1.5707963267948966  # the double nearest pi/2 (slightly below it)

THETA_FIXED = [0.0, 1e-300, 1e-8, 1e-4, 0.01, 0.1, 0.35, 0.7, 1.0, 1.25, 1.5, 1.57, 1.570796,
               1.5707963267, HALF_PI]


def thetas(width):
    """Fixed grid plus points around a lobe of angular scale `width` (near 0) and near grazing."""
    ts = set(THETA_FIXED)
    for k in (0.5, 1.0, 3.0):
        t = k * width
        if 0.0 < t < HALF_PI:
            ts.add(float(repr(t)))
            g = HALF_PI - t
            if 0.0 < g:
                ts.add(g)
    return sorted(ts)


def ln_cos(t):
    t = mpf(t)
    return mp.log1p(-2 * mp.sin(t / 2) ** 2)


def tan2(t):
    return mp.tan(mpf(t)) ** 2


def phong(a, t):
    a = mpf(a)
    return (a + 2) / (2 * PI) * mp.exp(a * ln_cos(t))


def beckmann(a, t):
    a = mpf(a)
    return mp.exp(-tan2(t) / a ** 2 - 4 * ln_cos(t)) / (PI * a ** 2)


def tr(a, t):
    a = mpf(a)
    t = mpf(t)
    q = mp.sin(t) ** 2 + a ** 2 * mp.cos(t) ** 2
    return a ** 2 / (PI * q ** 2)


def ts_norm(a):
    a = mpf(a)
    z = mpc(a, PI / (2 * a))
    w = mp.exp(-z ** 2) * mp.erfc(-1j * z)
    dawson = mp.sqrt(PI) / 2 * mp.exp(-a ** 2) * mp.erfi(a)
    return PI * a * (dawson + mp.sqrt(PI) / 2 * mp.exp(-PI ** 2 / (4 * a ** 2)) * w.imag)


def abc_norm(a1, a2):
    # The closed form cancels like a1^2 for small a1: add that many digits.
    with mp.workdps(mp.dps + 2 * max(0, int(-math.log10(a1)))):
        return +abc_norm_exact(mpf(a1), mpf(a2))


def abc_norm_exact(a1, a2):
    u = 1 + a1
    if a2 == 1:
        return 2 * PI / a1 ** 2 * (u * mp.log(u) - a1)
    if a2 == 2:
        return 2 * PI / a1 ** 2 * (a1 - mp.log(u))
    return 2 * PI / a1 ** 2 * (u * (u ** (1 - a2) - 1) / (1 - a2) - (u ** (2 - a2) - 1) / (2 - a2))


def abc(a1, a2, n, t):
    a1, a2 = mpf(a1), mpf(a2)
    one_minus_cos = 2 * mp.sin(mpf(t) / 2) ** 2
    return mp.exp(-a2 * mp.log1p(a1 * one_minus_cos)) / n


def sgd(a1, a2, g, t):
    a1, a2 = mpf(a1), mpf(a2)
    x = tan2(t)
    p22 = mp.exp((a2 - 1) * mp.log(a1) - (a1 ** 2 + x) / a1 - a2 * mp.log(a1 ** 2 + x)) / g
    return p22 * mp.exp(-4 * ln_cos(t)) / PI


def fmt(v):
    return mp.nstr(v, 20, min_fixed=-5, max_fixed=5) if v != 0 else "0.0"


rows = []


def emit(family, params, width, f):
    curve = {"ndf": family}
    curve.update(params)
    cj = json.dumps(curve, separators=(",", ":"))
    for i, t in enumerate(thetas(width)):
        rows.append((f"x-{family}-{len(rows)}", cj, repr(t), fmt(f(t))))


for a in [0.0, 1e-8, 0.5, 3.0, 100.0, 1e4, 1e6, 1e8, 1e12, 1e100, 1e300, 1.7976931348623157e308]:
    emit("phong", {"alpha_p": a}, min(1.0, math.sqrt(2.0 / max(a, 1e-300))), lambda t, a=a: phong(a, t))

for a in [1e-150, 1e-4, 1e-3, 0.01, 0.1, 0.7071, 1.0, 10.0, 100.0, 1e3, 1e4]:
    emit("beckmann", {"alpha_b": a}, a if a < 1 else 1.0 / a, lambda t, a=a: beckmann(a, t))

for a in [1e-150, 1e-3, 0.01, 0.1, 0.25, 0.5, 1.0, 3.0, 10.0, 26.6, 30.0, 100.0, 1e3, 1e8, 1e150]:
    n = ts_norm(a)
    emit("torrance_sparrow", {"alpha_ts": a}, min(a, 1.0),
         lambda t, a=a, n=n: mp.exp(-(mpf(t) / mpf(a)) ** 2) / n)

for a in [1e-150, 1e-4, 1e-3, 0.01, 0.1, 0.5, 0.999999999, 1.0, 2.0, 10.0, 100.0, 1e3, 1e4]:
    emit("trowbridge_reitz", {"alpha_tr": a}, a if a < 1 else 1.0 / a, lambda t, a=a: tr(a, t))

ABC_A2 = [1e-3, 0.5, 1 - 1e-9, 1.0, 1 + 1e-9, 1.75, 2 - 1e-9, 2.0, 2 + 1e-9, 10.0, 1000.0, 1e4]
for a1 in [1e-300, 1e-6, 1e-3, 0.1, 0.5, 1.0, 1.718281828, 10.0, 1e3, 1e6, 1e100]:
    for a2 in ABC_A2 + ([1e100] if a1 >= 1e100 or a1 <= 1e-6 else []):
        n = abc_norm(a1, a2)
        emit("abc", {"alpha_abc1": a1, "alpha_abc2": a2},
             min(1.0, math.sqrt(2.0 / (a1 * max(a2, 1.0)))),
             lambda t, a1=a1, a2=a2, n=n: abc(a1, a2, n, t))

for a1 in [1e-6, 1e-3, 0.01, 0.1, 0.5, 1.0, 5.0, 50.0, 1e3, 1e6]:
    for a2 in [-10.0, -1.0, 0.0, 0.5, 1.0 - 1e-9, 1.0, 1.5, 2.0, 2.0 + 1e-9, 2.5, 3.0, 10.0]:
        g = mp.gammainc(1 - mpf(a2), mpf(a1))
        width = math.sqrt(a1) if a2 < 1 else a1
        emit("sgd", {"alpha_sgd1": a1, "alpha_sgd2": a2}, min(width, 1.0),
             lambda t, a1=a1, a2=a2, g=g: sgd(a1, a2, g, t))

print("case_id,curve_json,theta,value")
for cid, cj, t, v in rows:
    print('%s,"%s",%s,%s' % (cid, cj.replace('"', '""'), t, v))
