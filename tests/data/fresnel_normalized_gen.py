#!/usr/bin/env python3
"""Generate tests/data/fresnel_normalized.csv: the normalized Fresnel curve (F - F0)/(1 - F0) from
theta = 1e-12 to pi/2, computed with mpmath.

Independent of the Rust code: every value is docs/maths.md's normative form
r_s = (c - w)/(c + w), r_p = (eta~^2 c - w)/(eta~^2 c + w), F = (|r_s|^2 + |r_p|^2)/2,
w = sqrt(eta~^2 - 1 + c^2) (principal root), F0 = F at c = 1, and the difference F - F0 taken as it
stands, evaluated at 120 digits from the exact doubles written in the file and printed to 20
significant digits. F - F0 ~ F0 theta^4 near theta = 0 (the theta^2 terms of |r_s|^2 and |r_p|^2
cancel), so at theta = 1e-12 the difference keeps ~120 - 48 digits; 1 - F0 and eta~^2 - 1 lose at
most 10 more. Gulbrandsen's (r, g) goes through docs/maths.md's map; both come from fresnel_near_one_gen.py.

Regimes (the case id's second field):
- dielectric: eta = 0.5, 0.9, 1 - 1e-9, 1 + 1e-9, 1.5, 3, 10 (kappa = 0); for eta < 1 past the
  critical angle asin(eta) the value is 1 (total internal reflection), and points with
  |cos^2 theta / cos^2 theta_c - 1| < 1e-2 are left out (F is ill-conditioned in cos theta there:
  relative condition ~ cos theta / |w|, fresnel_near_one_gen.py);
- conductor: the notebook's Al, Cu, Ag, Fe, Au, and kappa up to 10 (1 + 10i, 0.05 + 10i,
  3 + 10i), and a weakly absorbing 1.5 + 1e-3 i;
- gulbrandsen: (r, g) from r = 1e-12 (eta~ - 1 ~ 1e-6) to r = 0.99;
- training-quirk: the basis training set's row k = 10, eta = -9.999950000513731e-6,
  kappa = 0.9999999999472646 (docs/maths.md step 2; 1 - F0 = 2e-5). The curve model refuses eta < 0;
  the test evaluates this row through the library function directly.
theta: 4 per decade from 1e-12 to 1, then 1.1 ... 1.5, 1.55, 1.57, 1.5707, 1.5707963 and the double
nearest pi/2. Points where the value is ill-conditioned are left out: where |v'(theta)/v| times
min(tan theta, cot theta) exceeds 1e3 (a rounding of the smaller of sin theta and cos theta, from
which any float64 evaluation starts, moves theta by eps min(tan theta, cot theta)), i.e. near the angle
where v returns through 0 on its way from below F0 to 1; the generator prints them to stderr.

Usage: python3 tests/data/fresnel_normalized_gen.py > tests/data/fresnel_normalized.csv   (needs mpmath >= 1.3)
"""
import json
import sys

from mpmath import mp, mpf

from fresnel_near_one_gen import HALF_PI, fmt, fresnel, gulbrandsen  # sets mp.dps = 120

THETAS = [float(mpf(10) ** (mpf(k) / 4)) for k in range(-48, 1)] + \
    [1.1, 1.2, 1.3, 1.4, 1.5, 1.55, 1.57, 1.5707, 1.5707963, HALF_PI]
DIELECTRICS = [0.5, 0.9, 1 - 1e-9, 1 + 1e-9, 1.5, 3.0, 10.0]
CONDUCTORS = [(1.90, 6.79), (0.46, 2.97), (0.15, 3.47), (2.9, 3.0), (0.29, 2.86), (1.0, 10.0),
              (0.05, 10.0), (3.0, 10.0), (1.5, 1e-3)]
GULBRANDSEN = [(1e-12, 0.5), (1e-6, 1.0), (0.04, 0.0), (0.5, 0.5), (0.9, 1.0), (0.99, 0.3)]
QUIRK = (-9.999950000513731e-6, 0.9999999999472646)
CRITICAL_MARGIN = mpf("1e-2")
MAX_CONDITION = 1000


def normalized(n, k, theta):
    if k == 0 and n * n <= 1 - mp.cos(theta) ** 2:
        return mpf(1)
    f0 = fresnel(n, k, 0.0)
    return (fresnel(n, k, theta) - f0) / (1 - f0)


def well_conditioned(n, k, theta):
    if k == 0 and n < 1:
        cos2_critical = 1 - mpf(n) ** 2
        if abs(mp.cos(theta) ** 2 / cos2_critical - 1) < CRITICAL_MARGIN:
            return False
        if mp.sin(theta) >= n:
            return True
    v = normalized(n, k, theta)
    slope = mp.diff(lambda t: normalized(n, k, t), theta)
    return abs(slope / v) * min(mp.tan(theta), mp.cot(theta)) <= MAX_CONDITION


# (regime, label, params for the curve JSON, eta, kappa)
indices = []
for i, n in enumerate(DIELECTRICS):
    indices.append(("dielectric", "%02d" % i, {"eta": n, "kappa": 0.0}, mpf(n), mpf(0)))
for i, (n, k) in enumerate(CONDUCTORS):
    indices.append(("conductor", "%02d" % i, {"eta": n, "kappa": k}, mpf(n), mpf(k)))
for i, (r, g) in enumerate(GULBRANDSEN):
    n, k = gulbrandsen(r, g)
    indices.append(("gulbrandsen", "%02d" % i, {"r": r, "g": g}, n, k))
indices.append(("training-quirk", "00", {"eta": QUIRK[0], "kappa": QUIRK[1]}, mpf(QUIRK[0]), mpf(QUIRK[1])))

left_out = 0
print("case_id,curve_json,theta,value")
for regime, label, params, n, k in indices:
    f0 = fresnel(n, k, 0.0)
    closed = ((abs(n) - 1) ** 2 + k ** 2) / ((abs(n) + 1) ** 2 + k ** 2)
    assert abs(f0 - closed) <= mpf("1e-100") * closed, label
    cj = json.dumps({"fresnel": "normalized", **params}, separators=(",", ":")).replace('"', '""')
    for m, t in enumerate(THETAS):
        theta = mpf(t)
        if not well_conditioned(n, k, theta):
            left_out += 1
            print("left out: %s-%s theta = %r" % (regime, label, t), file=sys.stderr)
            continue
        print('nz-%s-%s-%02d,"%s",%s,%s' % (regime, label, m, cj, repr(t), fmt(normalized(n, k, theta))))
print("left out as ill-conditioned: %d points" % left_out, file=sys.stderr)
