#!/usr/bin/env python3
"""Fit the polynomials of the batch path's exp and ln_1p (src/ndf/batch.rs) and print their error.

- exp: e^r = 1 + r + r^2 q(r) on |r| <= ln 2 / 2, q of degree 9.
- ln_1p: ln m = 2 atanh s = 2 s + s^3 R(s^2) on s^2 <= (3 - 2 sqrt 2)^2, R of degree 6.

Each q and R is mpmath's Chebyshev fit (chebyfit, 50 digits), rounded to doubles; the script then
measures, in exact arithmetic on those doubles, the largest relative error of the resulting e^r and
ln m over 4001 points, which is what the doc comments in batch.rs quote.

Usage: python3 tests/data/batch_polynomials.py   (needs mpmath >= 1.3)
"""
from mpmath import mp, mpf

mp.dps = 50
ULP_OF_ONE = mpf(2) ** -52


def horner(coefficients, x):
    """coefficients lowest first, as in batch.rs."""
    value = mpf(0)
    for c in reversed(coefficients):
        value = value * x + mpf(c)
    return value


def fit(f, interval, degree):
    highest_first = mp.chebyfit(f, interval, degree + 1)
    return [float(c) for c in reversed(highest_first)]


def exp_fit():
    half_ln2 = mp.log(2) / 2

    def q(r):
        if abs(r) < mpf("1e-12"):
            return mpf(1) / 2 + r / 6 + r * r / 24
        return (mp.exp(r) - 1 - r) / r**2

    coefficients = fit(q, [-half_ln2, half_ln2], 9)
    worst = max(
        abs((1 + r + r * r * horner(coefficients, r)) / mp.exp(r) - 1)
        for r in (-half_ln2 + 2 * half_ln2 * i / 4000 for i in range(4001))
    )
    return coefficients, worst


def ln_fit():
    z_max = (3 - 2 * mp.sqrt(2)) ** 2

    def r_of_z(z):
        if z == 0:
            return mpf(2) / 3
        s = mp.sqrt(z)
        return (2 * mp.atanh(s) - 2 * s) / (s * z)

    coefficients = fit(r_of_z, [0, z_max], 6)
    worst = max(
        abs((2 * s + s**3 * horner(coefficients, s * s)) / (2 * mp.atanh(s)) - 1)
        for s in (mp.sqrt(z_max) * i / 4000 for i in range(1, 4001))
    )
    return coefficients, worst


for name, (coefficients, worst) in [("EXP_POLY", exp_fit()), ("LN_POLY", ln_fit())]:
    print(f"{name} = {[repr(c) for c in coefficients]}")
    print(f"  max relative error {mp.nstr(worst, 3)} = {mp.nstr(worst / ULP_OF_ONE, 3)} ulp of 1")
