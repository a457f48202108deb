#!/usr/bin/env python3
"""Generate tests/data/reference/gtr.csv: Generalized Trowbridge-Reitz values computed with mpmath.

Independent of the Rust code: D = c / (alpha^2 cos^2(theta) + sin^2(theta))^gamma with the textbook
normalization c = (gamma - 1)(alpha^2 - 1) / (pi (1 - (alpha^2)^(1 - gamma))) and its limits at gamma = 1
(c = (alpha^2 - 1) / (pi ln alpha^2)) and alpha = 1 (c = 1/pi), evaluated with enough extra digits to absorb
the textbook form's cancellation near alpha = 1 and gamma = 1, from the exact doubles written in the file.
The generator checks c against docs/maths.md's exprel form and, for a few ordinary lobes, the normalization
2 pi int_0^(pi/2) D sin cos dtheta = 1 by mpmath quadrature.

Grid: alpha_gtr log-spaced over [1e-150, 1e3] plus 1 and 1 +- 1e-9, 1 +- 1e-6; gamma_gtr from the smallest
positive double to 100 plus 1, 1 +- 1e-9, 0.5, 1.5, 2, 3, 10; theta at 0, 1e-8, ordinary angles, near pi/2,
the double nearest pi/2, and points scaled to the lobe's width (near 0 for alpha < 1, near grazing for
alpha > 1).

Usage: python3 tests/data/gtr_reference_gen.py > tests/data/reference/gtr.csv   (needs mpmath >= 1.3)
"""
import json
import math

from mpmath import mp, mpf

mp.dps = 60
PI = mp.pi
HALF_PI = 1.5707963267948966  # the double nearest pi/2 (slightly below it)

# Digits carried through the textbook normalization: it cancels by up to |(1 - gamma) ln alpha^2| ~ 1e-18
# (gamma and alpha both 1e-9 from 1), so 60 + 18 digits are needed; 120 leaves a wide margin.
NORM_DPS = 120

ALPHAS = [1e-150, 1e-100, 1e-50, 1e-20, 1e-8, 1e-4, 0.01, 0.1, 0.5, 1 - 1e-6, 1 - 1e-9, 1.0, 1 + 1e-9,
          1 + 1e-6, 2.0, 10.0, 100.0, 1e3]
GAMMAS = [5e-324, 1e-300, 1e-6, 1e-3, 0.1, 0.5, 1 - 1e-9, 1.0, 1 + 1e-9, 1.5, 2.0, 3.0, 10.0, 31.6, 100.0]
THETA_FIXED = [0.0, 1e-8, 0.1, 0.35, 0.7, 1.0, 1.25, 1.5, 1.5707963, HALF_PI]


def thetas(alpha, gamma):
    """Fixed angles plus 0.5, 1 and 3 lobe widths from the peak when the lobe is narrower than 0.1 rad."""
    ts = set(THETA_FIXED)
    if alpha != 1.0:
        # (1 + k t)^-gamma with t = sin^2 (alpha < 1) or cos^2 (alpha > 1) and k = max(alpha^2, alpha^-2) - 1
        # falls by 1/e at t ~ 1/(k max(gamma, 1)).
        k = max(alpha * alpha, 1.0 / (alpha * alpha)) - 1.0
        width = 1.0 / math.sqrt(k * max(gamma, 1.0))
        if width < 0.1:
            for m in (0.5, 1.0, 3.0):
                t = m * width
                ts.add(t if alpha < 1.0 else HALF_PI - t)
    return sorted(ts)


def norm_textbook(a, g):
    """c, the textbook form with its two limits, at NORM_DPS digits."""
    with mp.workdps(NORM_DPS):
        a2, g = mpf(a) ** 2, mpf(g)
        if a2 == 1:
            c = 1 / PI
        elif g == 1:
            c = (a2 - 1) / (PI * mp.log(a2))
        else:
            c = (g - 1) * (a2 - 1) / (PI * (1 - a2 ** (1 - g)))
        return +c


def norm_exprel(a, g):
    """c = exprel(L) / (pi exprel((1 - gamma) L)), L = ln alpha^2 (docs/maths.md), as a cross-check."""
    def exprel(x):
        return mpf(1) if x == 0 else mp.expm1(x) / x

    big_l = mp.log(mpf(a) ** 2)
    return exprel(big_l) / (PI * exprel((1 - mpf(g)) * big_l))


def gtr(a, g, c, t):
    a, g, t = mpf(a), mpf(g), mpf(t)
    q = a ** 2 * mp.cos(t) ** 2 + mp.sin(t) ** 2
    return c * mp.exp(-g * mp.log(q))


def fmt(v):
    return mp.nstr(v, 20, min_fixed=-5, max_fixed=5) if v != 0 else "0.0"


for a, g in [(0.3, 1.5), (0.5, 0.5), (2.0, 3.0), (1 + 1e-6, 1.0)]:
    c = norm_textbook(a, g)
    mass = 2 * PI * mp.quad(lambda t: gtr(a, g, c, t) * mp.sin(t) * mp.cos(t), [0, PI / 4, PI / 2])
    assert abs(mass - 1) < mpf("1e-40"), (a, g, mass)

print("case_id,curve_json,theta,value")
for i, a in enumerate(ALPHAS):
    for j, g in enumerate(GAMMAS):
        c = norm_textbook(a, g)
        assert abs(norm_exprel(a, g) / c - 1) < mpf("1e-45"), (a, g)
        cj = json.dumps({"ndf": "gtr", "alpha_gtr": a, "gamma_gtr": g}, separators=(",", ":"))
        for k, t in enumerate(thetas(a, g)):
            print('gtr-%02d-%02d-%02d,"%s",%s,%s' % (i, j, k, cj.replace('"', '""'), repr(t), fmt(gtr(a, g, c, t))))
