"""Rebuilds the Belcour basis with numpy and compares it with reference/belcour_basis.csv.

Documents the float64 procedure that src/model/fresnel/basis/compute/numpy_f64.rs replicates bit for bit:
the training rows (F - F0)/(1 - F0) of docs/maths.md's normative Fresnel form, evaluated in numpy
complex128 as written in `fresnel` below. Training row k = 10 has 1 - F0 = 2e-5, so each ulp of
F moves the basis by up to ~1e-11; with this exact operation order (w from e2 - (1 - c**2),
np.abs(r)**2, F0 from the same function at c = 1) the basis matches the reference to ~1e-15,
while other algebraically equal orders (e2 - 1 + c**2, r.real**2 + r.imag**2, ...) or an
accurate evaluation land 3e-12 ... 1.7e-11 away. The recovered F of that row was checked by a
first-order inversion of the two SVD steps (the row's values come out as exact doubles).

Not part of the test suite (needs numpy): python3 tests/data/belcour_numpy_training.py
Measured with numpy 2.4 (x86-64, AVX-512): max |error| b0..b3 = 0, 2.2e-16, 6.7e-16, 8.9e-16.
"""

import pathlib

import numpy as np

N = 1000
HERE = pathlib.Path(__file__).parent


def fresnel(c, eta, kappa):
    e2 = complex(eta, kappa) ** 2
    w = np.sqrt(e2 - (1 - c**2))
    r_s = (c - w) / (c + w)
    r_p = (e2 * c - w) / (e2 * c + w)
    return (np.abs(r_s) ** 2 + np.abs(r_p) ** 2) / 2


def rg_to_nk(r, g):
    # The notebook's Gulbrandsen map (only g = 1 is used here).
    n = g * (1.0 - r) / (1.0 + r) + (1.0 - g) * (1.0 + np.sqrt(r)) / (1.0 - np.sqrt(r))
    k2 = (r * (1.0 + n) * (1.0 + n) - (n - 1.0) * (n - 1.0)) / (1.0 - r)
    return n, np.sqrt(k2)


def main():
    c = np.linspace(0.0, 1.0, N)
    eta, kappa = np.linspace(1.1, 3.0, N), np.zeros(N)
    for k in range(1, N):
        r = k / N
        if r <= 0.01:
            r = r / 0.01
            r = r / (1.0 - 1.0e-5) + 1.0e-5
            eta[k], kappa[k] = rg_to_nk(r, 1.0)
        else:
            r = (r - 0.01) / (1.0 - 0.01)
            eta[k], kappa[k] = 1.01 + (3.0 - 1.01) * r, 0.0
    curves = np.empty((N, N))
    for k in range(N):
        f0 = fresnel(np.array([1.0]), eta[k], kappa[k])[0]
        curves[k] = (fresnel(c, eta[k], kappa[k]) - f0) / (1.0 - f0)
    b1 = np.abs(np.linalg.svd(curves)[2][0])
    b1 = b1 / b1.max()
    vh = np.linalg.svd(curves - b1)[2]
    b2, b3 = (v / np.abs(v).max() for v in vh[:2])
    # docs/maths.md's sign convention: the largest-magnitude entry is +1.
    b2, b3 = (b * np.sign(b[np.argmax(np.abs(b))]) for b in (b2, b3))
    basis = np.stack([np.ones(N), b1, b2, b3], axis=1)
    reference = np.loadtxt(HERE / "reference" / "belcour_basis.csv", delimiter=",", skiprows=1)
    print("max |error| b0..b3:", np.abs(basis - reference[:, 3:7]).max(axis=0))


if __name__ == "__main__":
    main()
