#!/usr/bin/env python3
"""Generate tests/data/reference/lambda.csv: Smith's Lambda(theta_o) for the seven NDF families, with mpmath.

Independent of the Rust code. Each D is written from docs/maths.md's definitions (normalizations by their textbook
closed forms, by mpmath quadrature for Torrance-Sparrow, and mpmath's gammainc for SGD), and Lambda is docs/maths.md's
1D integral
    Lambda(theta_o) = (2 / cos theta_o) int_{pi/2 - theta_o}^{pi/2} D(theta_m) [b sin phi0 - a (pi - phi0)] sin theta_m dtheta_m,
    a = cos theta_o cos theta_m, b = sin theta_o sin theta_m, phi0 = arccos(-a/b),
by mpmath.quad (tanh-sinh) at DPS digits, relative to a first estimate of its scale (mpmath's stopping
test is absolute), the square-root edge theta_m = pi/2 - theta_o an endpoint and the
interval split geometrically towards both ends (so that narrow lobes, far tails and grazing lobes all meet
pieces of their own width). Inputs are the exact doubles written in the file (theta_o as repr of a double,
pi/2 exact). Where a closed form exists (Trowbridge-Reitz, Beckmann, and Phong through the Student-t identity
with the incomplete beta function) the script asserts that the integral agrees with it to CROSS_CHECK relative wherever Lambda is within the double range.

Columns: case_id,curve_json,theta_o,lambda (20 significant digits). The first line is a comment with the
provenance.

Usage: python3 tests/data/lambda_reference_gen.py > tests/data/reference/lambda.csv   (needs mpmath >= 1.3)
"""
import json
import math
import sys

import mpmath
from mpmath import mp, mpf

DPS = 40
mp.dps = DPS
PI = mp.pi
HALF_PI = PI / 2

# Agreement required between the integral and the closed forms (both at DPS digits): far below the 1e-12 the
# Rust code is held to, above the quadrature's own ~1e-30.
CROSS_CHECK = mpf("1e-25")

# Pieces per decade of the geometric split, and how close (relative to the interval) the split goes to each end.
SPLIT_RATIO = 4
EDGE_DEPTH = 40      # 4^-40 ~ 1e-24 of the interval from the square-root edge
GRAZING_DEPTH = 14   # 4^-14 ~ 4e-9 of the interval from theta_m = pi/2

THETA_O = [1e-6] + [math.radians(d) for d in (1, 10, 30, 45, 60, 75, 85, 89, 89.9)]

CURVES = [
    ("trowbridge_reitz", {"alpha_tr": a}) for a in (1e-3, 0.1, 0.3, 0.5, 1.0, 2.0, 10.0)
] + [
    ("beckmann", {"alpha_b": a}) for a in (0.01, 0.1, 0.3, 0.5, 1.0, 5.0)
] + [
    ("phong", {"alpha_p": n}) for n in (0.0, 1.0, 20.0, 200.0, 2000.0, 1e5)
] + [
    ("torrance_sparrow", {"alpha_ts": a}) for a in (0.05, 0.3, 0.552, 1.0, 100.0)
] + [
    ("abc", {"alpha_abc1": a1, "alpha_abc2": a2})
    for a1, a2 in ((23.5, 1.75), (46.942557, 1.75667), (10.0, 0.5), (10.0, 1.0), (10.0, 2.0), (3.0, 0.5),
                   (0.0212, 1000.0), (1.0, 1000.0))
] + [
    ("sgd", {"alpha_sgd1": a1, "alpha_sgd2": a2})
    for a1, a2 in ((0.122506, 0.795078), (0.5, 1.5), (0.2, 0.0), (0.2, 0.5), (2.0, -1.0))
] + [
    ("gtr", {"alpha_gtr": a, "gamma_gtr": g})
    for a, g in ((0.3, 0.5), (0.3, 1.0), (0.3, 2.0), (0.3, 3.0), (2.0, 1.0), (0.05, 1.5))
]


def ndf(family, p):
    """D(theta) for theta an mpf, normalized over projected area (docs/maths.md)."""
    if family == "trowbridge_reitz":
        a2 = mpf(p["alpha_tr"]) ** 2
        return lambda t: a2 / (PI * (mp.sin(t) ** 2 + a2 * mp.cos(t) ** 2) ** 2)
    if family == "beckmann":
        a2 = mpf(p["alpha_b"]) ** 2
        return lambda t: mp.exp(-mp.tan(t) ** 2 / a2) / (PI * a2 * mp.cos(t) ** 4)
    if family == "phong":
        n = mpf(p["alpha_p"])
        return lambda t: (n + 2) / (2 * PI) * mp.cos(t) ** n
    if family == "torrance_sparrow":
        a = mpf(p["alpha_ts"])
        pts = sorted({mpf(0), HALF_PI} | {a * k for k in (1, 3, 10) if a * k < HALF_PI})
        norm = 2 * PI * mp.quad(lambda t: mp.exp(-(t / a) ** 2) * mp.sin(t) * mp.cos(t), pts)
        return lambda t: mp.exp(-(t / a) ** 2) / norm
    if family == "abc":
        a1, a2 = mpf(p["alpha_abc1"]), mpf(p["alpha_abc2"])
        u = 1 + a1
        if a2 == 1:
            norm = 2 * PI / a1 ** 2 * (u * mp.log(u) - a1)
        elif a2 == 2:
            norm = 2 * PI / a1 ** 2 * (a1 - mp.log(u))
        else:
            norm = 2 * PI * (u ** (2 - a2) - 1 + a1 * (a2 - 2)) / (a1 ** 2 * (a2 - 2) * (a2 - 1))
        return lambda t: (1 + a1 * (1 - mp.cos(t))) ** (-a2) / norm
    if family == "sgd":
        a1, a2 = mpf(p["alpha_sgd1"]), mpf(p["alpha_sgd2"])
        gam = mp.gammainc(1 - a2, a1)

        def d(t):
            x = mp.tan(t) ** 2
            p22 = a1 ** (a2 - 1) * mp.exp(-(a1 ** 2 + x) / a1) / (gam * (a1 ** 2 + x) ** a2)
            return p22 / (PI * mp.cos(t) ** 4)
        return d
    if family == "gtr":
        a2, g = mpf(p["alpha_gtr"]) ** 2, mpf(p["gamma_gtr"])
        if g == 1:
            c = (a2 - 1) / (PI * mp.log(a2))
        else:
            c = (g - 1) * (a2 - 1) / (PI * (1 - a2 ** (1 - g)))
        return lambda t: c / (a2 * mp.cos(t) ** 2 + mp.sin(t) ** 2) ** g
    raise ValueError(family)


def lambda_integral(d, theta_o):
    """docs/maths.md's 1D integral at DPS digits."""
    to = mpf(theta_o)
    if to == 0:
        return mpf(0)
    edge = HALF_PI - to
    co, so = mp.cos(to), mp.sin(to)

    def integrand(tm):
        a, b = co * mp.cos(tm), so * mp.sin(tm)
        if a >= b:
            return mpf(0)
        phi0 = mp.acos(-a / b)
        return d(tm) * (b * mp.sin(phi0) - a * (PI - phi0)) * mp.sin(tm)

    pts = {edge, HALF_PI}
    pts |= {edge + to * mpf(SPLIT_RATIO) ** -k for k in range(1, EDGE_DEPTH + 1)}
    pts |= {HALF_PI - to * mpf(SPLIT_RATIO) ** -k for k in range(1, GRAZING_DEPTH + 1)}
    pts = sorted(pts)
    # mpmath's quadrature stops on an absolute error of ~10^-DPS: a far tail (Lambda ~ 1e-135) would be
    # "converged" at once. A first pass gives the integral's scale; the second integrates relative to it.
    scale = mp.quad(integrand, pts)
    if scale == 0:
        return mpf(0)
    return 2 / co * scale * mp.quad(lambda tm: integrand(tm) / scale, pts)


def closed_form(family, p, theta_o):
    """Lambda by the closed forms of docs/maths.md, or None. At 2 DPS digits: the Beckmann and Phong forms cancel
    for narrow lobes (by ~2a^2 and ~(n + 3) cos^2 theta_o)."""
    with mp.workdps(2 * DPS):
        to = mpf(theta_o)
        if to == 0:
            return mpf(0)
        if family == "trowbridge_reitz":
            x = (mpf(p["alpha_tr"]) * mp.tan(to)) ** 2
            return +(x / (2 * (mp.sqrt(1 + x) + 1)))
        if family == "beckmann":
            a = mp.cot(to) / mpf(p["alpha_b"])
            return +(mp.exp(-a * a) / (2 * a * mp.sqrt(PI)) - mp.erfc(a) / 2)
        if family == "phong":
            n = mpf(p["alpha_p"])
            beta = (n + 3) / 2
            x = mp.sin(to) ** 2
            try:
                beta_inc = mp.betainc((n + 2) / 2, 0.5, 0, x)
            except ValueError:  # mpmath's hypergeometric series gives up for n = 1e5 near grazing
                return None
            bracket = mp.sin(to) ** (n + 1) / (n + 1) - mp.cot(to) / 2 * beta_inc
            return +(mp.gamma(beta) / (mp.gamma(beta - 0.5) * mp.sqrt(PI)) * mp.tan(to) * bracket)
    return None


def fmt(v):
    return mp.nstr(v, 20, min_fixed=-5, max_fixed=5) if v != 0 else "0.0"


print("# Generated by tests/data/lambda_reference_gen.py with mpmath %s at %d digits (docs/maths.md's 1D integral)"
      % (mpmath.__version__, DPS))
print("case_id,curve_json,theta_o,lambda")
for i, (family, p) in enumerate(CURVES):
    d = ndf(family, p)
    cj = json.dumps(dict({"ndf": family}, **p), separators=(",", ":"))
    for k, to in enumerate(THETA_O):
        lam = lambda_integral(d, to)
        ref = closed_form(family, p, to)
        # Below the double range the tests compare absolutely; there the closed form's exponent (a^2 ~ 1e16 at
        # theta_o = 1e-6) needs more digits than either side carries.
        if ref is not None and ref != lam and abs(ref) > mpf("1e-300"):
            assert abs(lam - ref) <= CROSS_CHECK * abs(ref), (family, p, to, lam, ref)
        print('%s-%02d-%02d,"%s",%s,%s' % (family, i, k, cj.replace('"', '""'), repr(to), fmt(lam)))
        sys.stdout.flush()
