"""Reference directional albedos E(mu = 1) of the GGX (Trowbridge-Reitz) microfacet BRDF, F = 1.

E(1) = 2 pi int_0^{pi/4} D(t) G2(0, 2t) cos t sin t dt with D = a^2 / (pi (sin^2 t + a^2 cos^2 t)^2),
Lambda(t) = (sqrt(1 + a^2 tan^2 t) - 1) / 2, G2 height-correlated 1/(1 + Lambda(0) + Lambda(2t)) or
separable G1(0) G1(2t) = 1/(1 + Lambda(2t)) (Lambda(0) = 0, so the two coincide at mu = 1).
mpmath at 40 digits, the interval split at multiples of the lobe width so tanh-sinh resolves narrow
lobes; 20 significant digits printed. Writes albedo_reference.csv beside this script.
"""

import os

import mpmath as mp

mp.mp.dps = 40

ALPHAS = ["0.001", "0.0166493", "0.0625", "0.25", "0.5625", "1", "2", "4"]


def albedo_normal(a):
    a = mp.mpf(a)

    def integrand(t):
        s, c = mp.sin(t), mp.cos(t)
        d = a**2 / (mp.pi * (s**2 + a**2 * c**2) ** 2)
        x = (a * mp.tan(2 * t)) ** 2
        lam = (mp.sqrt(1 + x) - 1) / 2
        return d / (1 + lam) * c * s

    # breakpoints at atan(k a) for k = 1/8 ... 2^20, below pi/4
    points = [mp.mpf(0)]
    k = mp.mpf(1) / 8
    while mp.atan(k * a) < mp.pi / 4:
        points.append(mp.atan(k * a))
        k *= 2
    points.append(mp.pi / 4)
    return 2 * mp.pi * mp.quad(integrand, points)


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    with open(os.path.join(here, "albedo_reference.csv"), "w") as out:
        out.write("alpha,mu,albedo\n")
        for a in ALPHAS:
            out.write(f"{a},1,{mp.nstr(albedo_normal(a), 20)}\n")


if __name__ == "__main__":
    main()
