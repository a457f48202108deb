#!/usr/bin/env python3
"""Generate reference/student_t_d.csv and reference/student_t_lambda.csv: D(theta) and Smith's Lambda(theta_o) of the Student-t slope distribution (STD,
Ribardiere, Bringier, Meneveaux, Simonot 2017; docs/maths.md "Student-t slope distribution, STD"), with mpmath.

Independent of the Rust code. Every input is the exact double written in the file (parameters and angles, pi/2 as
the double nearest it, 1.5707963267948966, slightly below pi/2; cos of it is 6.12e-17, not 0).

D, docs/maths.md's definition taken literally,
    D = (gamma - 1)^gamma / (pi alpha^2 cos^4(theta) (gamma - 1 + tan^2(theta)/alpha^2)^gamma),
at DPS + log10(gamma) + 10 digits (so that gamma - 1 + tan^2/alpha^2 keeps tan^2/alpha^2 to DPS digits even at
gamma = 1.8e308), cross-checked against exp(-gamma log1p(t/(gamma - 1)))/(pi alpha^2 cos^4), t = tan^2/alpha^2,
at DPS digits (CROSS_CHECK_D).

Lambda by two routes, asserted to agree to CROSS_CHECK_LAMBDA wherever Lambda lies in the double range:
1. quadrature of the definition, Lambda = (1/mu) int_mu^inf (q - mu) P2(q) dq, mu = cot(theta_o), with the 1D slope
   density of docs/maths.md
       P2(q) = (gamma - 1)^gamma Gamma(gamma - 1/2) / (sqrt(pi) alpha Gamma(gamma)) (gamma - 1 + q^2/alpha^2)^(1/2 - gamma)
             = K exp((1/2 - gamma) log1p(q^2 / (alpha^2 (gamma - 1)))),
       K = (gamma - 1)^(1/2) Gamma(gamma - 1/2) / (sqrt(pi) alpha Gamma(gamma))   (K at DPS + 2 log10(gamma) digits),
   by mpmath.quad (tanh-sinh) at DPS digits over [mu, Q] split geometrically from mu (pieces of every scale from a
   thousandth of the decay length to Q), plus the tail [Q, inf) through q = Q y^(-1/(2 gamma - 3)), which turns the
   q^(2 - 2 gamma) tail into a bounded integrand on y in (0, 1] (gamma near 1.5 puts half of Lambda at astronomically
   large slopes: Lambda ~ 1/(2 gamma - 3)); and, as lambda_reference_gen.py does, a first pass for the scale and a
   second one relative to it (mpmath's stopping test is absolute).
2. the closed form through the regularized incomplete beta function (the Student-t tail; docs/maths.md's Phong formula is
   its case alpha = sqrt(2/(n + 2)), gamma = (n + 4)/2): with m = mu/(alpha sqrt(gamma - 1)) and w = 1/(1 + m^2),
       Lambda = C w^(gamma - 3/2) / (2 (gamma - 3/2) m) - I_w(gamma - 1, 1/2) / 2,  C = Gamma(gamma - 1/2)/(sqrt(pi) Gamma(gamma - 1)),
   at DPS + 2 log10(gamma) + 20 digits (the difference cancels by up to ~2 gamma). mpmath's betainc gives up for
   huge gamma where I_w is far below the double range (those rows rely on route 1 alone), and at tiny w
   (alpha = 1e-150, theta_o = 1e-6), where the same form rearranged into positive terms with mpmath's hyp2f1 stands
   in for it.

The exact limits at theta = pi/2 itself (not representable, so not in the file): D -> 0 for gamma > 2, alpha^2/pi for
gamma = 2 (Trowbridge-Reitz), +inf for gamma < 2 (D ~ (gamma-1)^gamma alpha^(2 gamma - 2) cos^(2 gamma - 4)/pi);
Lambda -> +inf (~ C alpha sqrt(gamma - 1) tan(theta_o) / (2 gamma - 3)). At the double nearest pi/2 every value is
finite and is what the file holds.

Grid: alpha in {1e-3, 0.01, 0.1, 0.3, 0.7071, 1, 2, 10} x gamma in {1.5000001, 1.501, 1.6, 2, 3, 10, 100, 1e3, 1e6,
1e8}, plus the domain's corners (alpha = 1e-150 and 1e4; gamma = the double after 1.5, 1e12, 1e16, 1e100, 1e300 and
the largest double). D at fixed angles, points scaled to a narrow lobe, the off-normal peak where there is one, and
points near grazing for super-rough lobes; Lambda at fixed angles and where a = cot(theta_o)/alpha is 1, 3 and 8.

Columns: case_id,curve_json,quantity,theta,value with quantity D or lambda (theta is theta_o for lambda), 20
significant digits; values below the double range are written exactly and parse to 0.0 (compare absolutely below
1e-280). The first line is a comment with the provenance. --quantity D (or lambda) writes only that quantity in the
four columns of tests/data/ndf_extreme.csv (case_id,curve_json,theta,value) or tests/data/reference/lambda.csv
(case_id,curve_json,theta_o,lambda).

Usage (from tests/data; needs mpmath >= 1.3; ~5 minutes each):
       python3 student_t_reference_gen.py --quantity D > reference/student_t_d.csv
       python3 student_t_reference_gen.py --quantity lambda > reference/student_t_lambda.csv
       python3 student_t_reference_gen.py   (both, with a quantity column)
"""
import argparse
import json
import math
import sys

import mpmath
from mpmath import mp, mpf

DPS = 50
mp.dps = DPS
PI = mp.pi
HALF_PI = 1.5707963267948966  # the double nearest pi/2 (slightly below it)
F64_MAX = 1.7976931348623157e308
AFTER_1_5 = 1.5000000000000002  # the double after 1.5

CROSS_CHECK_D = mpf("1e-40")
# Quadrature against closed form: far below the 1e-12 the Rust code is held to, above the quadrature's own ~1e-30
# (heavy tails near grazing, where tanh-sinh at 50 digits reaches ~1e-30).
CROSS_CHECK_LAMBDA = mpf("1e-25")

ALPHAS = [1e-3, 0.01, 0.1, 0.3, 0.7071, 1.0, 2.0, 10.0]
GAMMAS = [1.5000001, 1.501, 1.6, 2.0, 3.0, 10.0, 100.0, 1e3, 1e6, 1e8]
CORNERS = [(1e-150, AFTER_1_5), (1e-150, 3.0), (1e-150, 1e8), (1e-150, F64_MAX),
           (1e4, AFTER_1_5), (1e4, 2.0), (1e4, 1e8), (1e4, F64_MAX),
           (0.3, AFTER_1_5), (0.3, 1e12), (0.3, 1e16), (0.3, 1e100), (0.3, 1e300), (0.3, F64_MAX)]

THETA_D = [0.0, 1e-8, 0.35, 0.7, 1.0, 1.5, 1.5707963, HALF_PI]
THETA_D_CORNER = [0.0, 1e-300, 0.7, 1.5, HALF_PI]
THETA_LAMBDA = [1e-6, 0.1, math.pi / 4, 1.0, 1.3, 1.5, 1.5707963, HALF_PI]
THETA_LAMBDA_CORNER = [1e-6, 0.7, 1.5, HALF_PI]
LAMBDA_A = (1.0, 3.0, 8.0)


def digits(g):
    """Decimal digits gamma occupies above 1 (extra precision for gamma - 1 + x at gamma up to 1.8e308)."""
    return max(0, int(math.log10(g)) + 1)


def d_literal(a, g, t):
    """docs/maths.md's D, taken literally, at enough digits that (gamma - 1 + tan^2/alpha^2) keeps its small part."""
    with mp.workdps(DPS + digits(g) + 10):
        a, g, t = mpf(a), mpf(g), mpf(t)
        v = (g - 1) ** g / (PI * a ** 2 * mp.cos(t) ** 4 * (g - 1 + mp.tan(t) ** 2 / a ** 2) ** g)
    return +v


def d_log1p(a, g, t):
    a, g, t = mpf(a), mpf(g), mpf(t)
    return mp.exp(-g * mp.log1p(mp.tan(t) ** 2 / (a ** 2 * (g - 1)))) / (PI * a ** 2 * mp.cos(t) ** 4)


def density(a, g):
    """P2(q) = K exp((1/2 - gamma) log1p(q^2/(alpha^2 (gamma - 1)))), K at high precision."""
    with mp.workdps(DPS + 2 * digits(g) + 20):
        am, gm = mpf(a), mpf(g)
        k = mp.sqrt(gm - 1) * mp.gamma(gm - mpf(1) / 2) / (mp.sqrt(PI) * am * mp.gamma(gm))
        s2 = am ** 2 * (gm - 1)
        expo = mpf(1) / 2 - gm
    k, s2, expo = +k, +s2, +expo
    return (lambda q: k * mp.exp(expo * mp.log1p(q * q / s2))), s2


def lambda_quad(a, g, theta_o):
    """Route 1: the definition by quadrature (module docstring)."""
    to = mpf(theta_o)
    if to == 0:
        return mpf(0)
    mu = mp.cot(to)
    p2, s2 = density(a, g)
    gm = mpf(g)
    s = mp.sqrt(s2)
    h = (s2 + mu * mu) / ((2 * gm - 1) * mu)  # 1/|d ln P2/dq| at q = mu
    # Feature scales: the decay length at mu, the Student-t scale s and the Gaussian core alpha (large gamma).
    scale = min(h, s, mpf(a))
    q_end = mu + 256 * h
    pts = {mu, q_end}
    d = scale / 1024
    while mu + d < q_end:
        pts.add(mu + d)
        d *= 8
    pts = sorted(pts)
    f = lambda q: (q - mu) * p2(q)
    p = 2 * gm - 3

    def tail(y):  # q = Q y^(-1/p), dq = (Q/p) y^(-1/p - 1) dy
        q = q_end * y ** (-1 / p)
        return f(q) * q / (p * y)

    def integral(norm):
        body = mp.quad(lambda q: f(q) / norm, pts)
        tl = mp.quad(lambda y: tail(y) / norm, [0, mpf(1) / 2 ** 20, mpf(1) / 1024, 1])
        return body + tl

    first = integral(mpf(1))
    if first == 0:
        return mpf(0)
    return first * integral(first) / mu


def lambda_beta(a, g, theta_o):
    """Route 2: the incomplete-beta closed form, or None where mpmath's betainc gives up or Lambda lies far below
    the double range (w^(gamma - 3/2) < e^-800, where betainc can take minutes to give up)."""
    if theta_o > 0:
        ln_m = -(math.log(math.tan(theta_o)) + math.log(a) + 0.5 * math.log(g - 1))
        ln_1p_m2 = 2 * ln_m if ln_m > 20 else math.log1p(math.exp(2 * ln_m))
        if (g - 1.5) * ln_1p_m2 > 800:
            return None
    with mp.workdps(DPS + 2 * digits(g) + 20):
        am, gm, to = mpf(a), mpf(g), mpf(theta_o)
        if to == 0:
            return mpf(0)
        half = mpf(1) / 2
        m = mp.cot(to) / (am * mp.sqrt(gm - 1))
        w = 1 / (1 + m * m)
        c = mp.gamma(gm - half) / (mp.sqrt(PI) * mp.gamma(gm - 1))
        try:
            tail = mp.betainc(gm - 1, half, 0, w, regularized=True) / 2
        except (mpmath.libmp.NoConvergence, ValueError, ZeroDivisionError):
            return lambda_hyp2f1(a, g, theta_o) if w < mpf(1) / 2 else None
        v = c * w ** (gm - 3 * half) / (2 * (gm - 3 * half) * m) - tail
    return +v


def lambda_hyp2f1(a, g, theta_o):
    """Route 2's fallback where betainc gives up at small w: the same closed form rearranged into positive terms,
    Lambda = x Gamma(gamma - 1/2)/(4 sqrt(pi) Gamma(gamma)) w^(gamma - 3/2) (1/(gamma - 3/2) + w 2F1(1, gamma - 1/2;
    gamma + 1; w)/gamma), x = 1/m (the form student_t.rs evaluates, here by mpmath's hyp2f1)."""
    with mp.workdps(DPS + 2 * digits(g) + 20):
        am, gm, to = mpf(a), mpf(g), mpf(theta_o)
        half = mpf(1) / 2
        m = mp.cot(to) / (am * mp.sqrt(gm - 1))
        w = 1 / (1 + m * m)
        e = 1 / (gm - 3 * half) + w * mp.hyp2f1(1, gm - half, gm + 1, w) / gm
        v = mp.gamma(gm - half) / (4 * mp.sqrt(PI) * mp.gamma(gm) * m) * w ** (gm - 3 * half) * e
    return +v


def fmt(v):
    return mp.nstr(v, 20, min_fixed=-5, max_fixed=5) if v != 0 else "0.0"


def peak(a, g):
    """The off-normal maximum: tan^2 = (2 alpha^2 (gamma - 1) - gamma)/(gamma - 2) for gamma > 2 and 2 alpha^2
    (gamma - 1) > gamma (docs/maths.md's slope 2 - gamma/(alpha^2 (gamma - 1)) at u = 0), else None."""
    if g > 2 and 2 * a * a * (g - 1) > g:
        return math.atan(math.sqrt(max(0.0, 2 * a * a * ((g - 1) / (g - 2)) - g / (g - 2))))
    return None


def d_thetas(a, g, corner):
    ts = set(THETA_D_CORNER if corner else THETA_D)
    if a < 0.3:  # a lobe narrower than the fixed grid: 0.5, 1 and 3 widths
        for k in (0.5, 1.0, 3.0):
            ts.add(math.atan(k * a))
    if a > 1.0:  # a super-rough lobe hugs grazing within ~1/alpha
        for k in (0.5, 2.0):
            ts.add(HALF_PI - k / a)
    tp = peak(a, g)
    if tp is not None:
        ts.add(tp)
    return sorted(ts)


def lambda_thetas(a, g, corner):
    ts = set(THETA_LAMBDA_CORNER if corner else THETA_LAMBDA)
    for k in LAMBDA_A:  # a = cot(theta_o)/alpha = k: Lambda from moderate to a far tail
        ts.add(math.atan(1.0 / (k * a)))
    return sorted(ts)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--quantity", choices=["D", "lambda"], help="write only this quantity, in the existing 4-column form")
    args = ap.parse_args()
    curves = [(a, g, False) for a in ALPHAS for g in GAMMAS] + [(a, g, True) for a, g in CORNERS]
    print("# Generated by student_t_reference_gen.py with mpmath %s at %d digits (D literally; Lambda by quadrature "
          "of its definition, cross-checked against the incomplete-beta closed form)" % (mpmath.__version__, DPS))
    if args.quantity is None:
        print("case_id,curve_json,quantity,theta,value")
    elif args.quantity == "D":
        print("case_id,curve_json,theta,value")
    else:
        print("case_id,curve_json,theta_o,lambda")

    def row(cid, cj, quantity, t, v):
        cell = '"%s"' % cj.replace('"', '""')
        if args.quantity is None:
            print("%s,%s,%s,%s,%s" % (cid, cell, quantity, repr(t), fmt(v)))
        else:
            print("%s,%s,%s,%s" % (cid, cell, repr(t), fmt(v)))
        sys.stdout.flush()

    for i, (a, g, corner) in enumerate(curves):
        cj = json.dumps({"ndf": "student_t", "alpha_std": a, "gamma_std": g}, separators=(",", ":"))
        if args.quantity in (None, "D"):
            for k, t in enumerate(d_thetas(a, g, corner)):
                v = d_literal(a, g, t)
                if v > mpf("1e-300"):
                    assert abs(d_log1p(a, g, t) / v - 1) < CROSS_CHECK_D, (a, g, t)
                row("std-d-%03d-%02d" % (i, k), cj, "D", t, v)
            tp = peak(a, g)
            if tp is not None:  # the peak is a maximum
                for t in (tp * (1 - 1e-6), tp * (1 + 1e-6)):
                    assert d_literal(a, g, t) < d_literal(a, g, tp), (a, g, tp)
        if args.quantity in (None, "lambda"):
            for k, t in enumerate(lambda_thetas(a, g, corner)):
                v = lambda_quad(a, g, t)
                ref = lambda_beta(a, g, t)
                if ref is not None and abs(ref) > mpf("1e-300"):
                    assert abs(v - ref) <= CROSS_CHECK_LAMBDA * abs(ref), (a, g, t, v, ref)
                elif v > mpf("1e-300"):
                    print("# note: %s theta_o=%r: no closed-form cross-check (betainc gave up)" % (cj, t),
                          file=sys.stderr)
                row("std-lambda-%03d-%02d" % (i, k), cj, "lambda", t, v)


if __name__ == "__main__":
    main()
