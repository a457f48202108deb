#!/usr/bin/env python3
"""Generate tests/data/fresnel_near_one.csv: exact Fresnel near the index 1, computed with mpmath.

Independent of the Rust code: every value is docs/maths.md's normative form
r_s = (c - w)/(c + w), r_p = (eta~^2 c - w)/(eta~^2 c + w), F = (|r_s|^2 + |r_p|^2)/2,
w = sqrt(eta~^2 - 1 + c^2) (principal root), evaluated at 120 digits (the raw ratios cancel by up to
|eta~^2 - 1| ~ 1e-12, and Gulbrandsen's kappa^2 by up to g) from the exact doubles written in the file,
and printed to 20 significant digits. Gulbrandsen's (r, g) goes through docs/maths.md's map
n = g (1 - r)/(1 + r) + (1 - g)(1 + sqrt r)/(1 - sqrt r), kappa^2 = (r (1 + n)^2 - (n - 1)^2)/(1 - r)
(0 at g = 0); the generator checks F(0) = r for it and F(0) = ((n - 1)^2 + k^2)/((n + 1)^2 + k^2) for every index.

Regimes (where eta~^2 - 1 is small and float64 loses it if it forms eta~^2 first):
- real eta = 1 +- 1e-6, 1e-9, 1e-12;
- complex eta~ = 1 + small with small kappa (down to 1e-12);
- Gulbrandsen r in {1e-6, 1e-9, 1e-12} with g in {0, 0.25, 0.5, 0.9, 1};
- eta just below 1 near its critical angle theta_c = asin(eta), at cos^2 theta = (1 + t) cos^2 theta_c for
  t in {0.5, 1e-2, 1e-3} (partial reflection) and t in {-1e-3, -0.5} (total internal reflection, F = 1).
  Closer to theta_c, F is ill-conditioned in cos theta itself (relative condition ~ cos theta / |w|, so a
  rounding of cos theta costs ~eps / sqrt(t)); t >= 1e-3 keeps that below 4e-15;
- theta from 0 through 1e-8 and Brewster's angle (pi/4 near the index 1) to the double nearest pi/2;
- and, where sin^2 theta must be known relative to itself rather than from a rounded cos theta, tiny
  indices (|eta~| from 1e-8 to 1e-3) at theta from 1e-9 to 1e-3 (for kappa = 0 away from the critical
  angle asin(eta): |sin theta - eta| > eta / 2).
Also Schlick with F0 from these indices, and the normalized curve (F - F0)/(1 - F0) at the same angles
(F - F0 ~ F0 theta^4 near theta = 0, which the 120 digits keep; fresnel_normalized_gen.py goes down to
theta = 1e-12 for indices away from 1).

Usage: python3 tests/data/fresnel_near_one_gen.py > tests/data/fresnel_near_one.csv   (needs mpmath >= 1.3)
"""
import json

from mpmath import mp, mpf, mpc

mp.dps = 120
HALF_PI = 1.5707963267948966  # the double nearest pi/2 (slightly below it)

THETAS = [0.0, 1e-8, 0.1, 0.5, 0.7853981633974483, 1.0, 1.3, 1.5, 1.57, 1.5707963, HALF_PI]
REAL_ETAS = [1 + 1e-6, 1 - 1e-6, 1 + 1e-9, 1.000000001, 1 - 1e-9, 1 + 1e-12, 1 - 1e-12]
COMPLEX = [(1 + 1e-9, 1e-9), (1 + 1e-9, 1e-6), (1 + 1e-9, 1e-12), (1 - 1e-9, 1e-9), (1.0, 1e-9),
           (1.0, 1e-12), (1 + 1e-12, 1e-12), (1 + 1e-6, 1e-6)]
GULBRANDSEN_R = [1e-6, 1e-9, 1e-12]
GULBRANDSEN_G = [0.0, 0.25, 0.5, 0.9, 1.0]
CRITICAL_ETAS = [1 - 1e-6, 1 - 1e-9, 1 - 1e-12]
CRITICAL_T = [0.5, 1e-2, 1e-3, -1e-3, -0.5]
SMALL = [(1e-8, 1e-8), (1e-6, 1e-6), (1e-4, 1e-4), (1e-3, 1e-6), (1e-3, 0.0)]
SMALL_THETAS = [0.0, 1e-9, 1e-7, 3e-7, 1e-6, 1e-5, 1e-4, 5e-4, 1e-3, 0.5, HALF_PI]


def gulbrandsen(r, g):
    r, g = mpf(r), mpf(g)
    sr = mp.sqrt(r)
    n = g * (1 - r) / (1 + r) + (1 - g) * (1 + sr) / (1 - sr)
    k2 = 0 if g <= 0 else (r * (1 + n) ** 2 - (n - 1) ** 2) / (1 - r)
    return n, mp.sqrt(max(k2, 0))


def fresnel(n, k, theta):
    e = mpc(n, k)
    c = mp.cos(mpf(theta))
    if e == 1:
        return mpf(0)
    e2 = e * e
    w = mp.sqrt(e2 - 1 + c * c)
    rs = (c - w) / (c + w)
    rp = (e2 * c - w) / (e2 * c + w)
    return (abs(rs) ** 2 + abs(rp) ** 2) / 2


def f0_closed(n, k):
    return ((n - 1) ** 2 + k ** 2) / ((n + 1) ** 2 + k ** 2)


def fmt(v):
    return mp.nstr(v, 20, min_fixed=-5, max_fixed=5) if v != 0 else "0.0"


def double_theta(cos2):
    """The double nearest arccos(sqrt(cos2))."""
    return float(mp.acos(mp.sqrt(cos2)))


def main():
    # (label, params for the curve JSON, eta, kappa, thetas)
    indices = []
    for i, n in enumerate(REAL_ETAS):
        indices.append(("real-%02d" % i, {"eta": n, "kappa": 0.0}, mpf(n), mpf(0), THETAS))
    for i, (n, k) in enumerate(COMPLEX):
        indices.append(("complex-%02d" % i, {"eta": n, "kappa": k}, mpf(n), mpf(k), THETAS))
    for i, r in enumerate(GULBRANDSEN_R):
        for j, g in enumerate(GULBRANDSEN_G):
            n, k = gulbrandsen(r, g)
            assert abs(f0_closed(n, k) / mpf(r) - 1) < mpf("1e-90"), (r, g)
            indices.append(("gulbrandsen-%d-%d" % (i, j), {"r": r, "g": g}, n, k, THETAS))
    for i, n in enumerate(CRITICAL_ETAS):
        c2 = 1 - mpf(n) ** 2
        ts = [0.0, 0.5, 1.0] + [double_theta((1 + mpf(t)) * c2) for t in CRITICAL_T]
        indices.append(("critical-%d" % i, {"eta": n, "kappa": 0.0}, mpf(n), mpf(0), ts))
    for i, (n, k) in enumerate(SMALL):
        ts = [t for t in SMALL_THETAS if k > 0 or abs(mp.sin(mpf(t)) - n) > n / 2]
        indices.append(("small-%d" % i, {"eta": n, "kappa": k}, mpf(n), mpf(k), ts))

    print("case_id,curve_json,theta,value")
    for label, params, n, k, thetas in indices:
        f0 = fresnel(n, k, 0.0)
        assert abs(f0 - f0_closed(n, k)) <= mpf("1e-100") * f0_closed(n, k), label
        curves = [("exact", thetas, lambda t: fresnel(n, k, t)),
                  ("schlick", thetas, lambda t: f0 + (1 - f0) * (1 - mp.cos(mpf(t))) ** 5),
                  ("normalized", thetas, lambda t: (fresnel(n, k, t) - f0) / (1 - f0))]
        for model, ts, value in curves:
            cj = json.dumps({"fresnel": model, **params}, separators=(",", ":")).replace('"', '""')
            for m, t in enumerate(ts):
                print('fn-%s-%s-%02d,"%s",%s,%s' % (model, label, m, cj, repr(t), fmt(value(t))))


if __name__ == "__main__":
    main()
