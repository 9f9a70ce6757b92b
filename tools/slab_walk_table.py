#!/usr/bin/env python3
"""Tabulate the light a random walk carries through a slab of stone (issue 15), for the `marble`
mode's transmission (src/marble/scene/slab_transport.h, shaders/lighting.frag.glsl).

    python3 tools/slab_walk_table.py > src/marble/scene/slab_walk_table.inc     # ~7 minutes, numpy

The walk is the one Blender Cycles 3.4 runs for RANDOM_WALK subsurface scattering, stated from
its source (kernel/integrator/subsurface_random_walk.h, kernel/types.h) and re-derived here as an
analog Monte Carlo walk:
- light enters through the face at z = 0 in a cosine-weighted direction (a Lambertian entry);
- free flights are exponential with the extinction sigma_t; every scattering is isotropic and
  multiplies the weight by the single-scattering albedo alpha (what is not scattered is absorbed);
- the walk ends where it crosses a face: no reflection inside the boundary (Cycles refracts nothing
  there; the surface's own coupling is applied outside the walk);
- a walk that has not left after 256 flights (the entry flight and 255 scatterings) is dropped
  (Cycles' loop `for (bounce = 0; bounce < BSSRDF_MAX_BOUNCES; ...)`, BSSRDF_MAX_BOUNCES = 256). Through
  thick stone this cap, not absorption, rules: for the issue's stone, 20 mm lets through 0.57x
  (red) to 0.30x (blue) of what an uncapped walk does, 40 mm about 1/70 in red.
Cycles guides its walks (Dwivedi sampling, MIS over the channels): that changes the noise, not the
expectation, except through which walks the cap drops; the table below agrees with Cycles' own
slab renders (docs/quality.md, "Transmission from a random walk") within their noise.

In optical units the walk depends on two numbers only: the slab's thickness tau = sigma_t * s and
alpha. The table holds ln(T / R_inf) on a grid of both, where T is the flux that leaves the far
face per unit flux entering, and R_inf what the same stone reflects when it is infinitely thick
(also capped): the transmission relative to the stone's own diffuse albedo, which the renderer
multiplies in later. tau runs over TAU_NODES nodes tau_i = TAU_MAX (i / (TAU_NODES - 1))^2 (dense
where T changes fastest), alpha over the rows u = -log10(1 - alpha). Where fewer than MIN_HITS
walks got through (tau from about 46: the thick body's long chords), T comes instead from the same
capped walk solved without sampling (capped_walk_transmission: the collision densities flight by
flight, through the slab's exponential-integral kernels), and is marked so in the output. Until
session 23 those nodes were continued linearly in ln T from the last two resolved ones (an
exponential tail); the cap makes the true tail fall faster than any exponential (256 flights
spread a walk only about 13 optical units in depth), so that line read up to 15x too much light at
tau 50-64 (docs/quality.md, "Twenty-third session").
"""
import math
import sys

import numpy as np

CAP = 256             # Cycles' BSSRDF_MAX_BOUNCES
TAU_NODES = 40
TAU_MAX = 64.0
# -log10(1 - alpha); dense where stone lies (the stone: 2.1-2.6), where ln T bends most.
U_ROWS = [0.1, 0.5, 1.0, 1.5, 1.75, 2.0, 2.125, 2.25, 2.375, 2.5, 2.625, 2.75, 2.875, 3.0, 3.25, 3.5, 4.0, 4.5, 5.0, 6.0]
PHOTONS = 200000
MIN_HITS = 30
SEED = 15


def walk(alpha, tau, rng, photons=PHOTONS):
    """Fraction of entering flux that leaves the far face (t) and the near face (r), and how many
    walks left through the far face. Units: sigma_t = 1, so the thickness is tau."""
    z = np.zeros(photons)
    mu = np.sqrt(rng.random(photons))  # cosine-weighted into the slab
    w = np.ones(photons)
    t = r = 0.0
    hits = 0
    for _ in range(CAP):  # the entry flight, then up to CAP - 1 scatterings
        z = z + mu * -np.log1p(-rng.random(z.size))
        through, back = z > tau, z < 0.0
        t += w[through].sum()
        r += w[back].sum()
        hits += int(through.sum())
        keep = ~(through | back)
        z, w = z[keep], w[keep] * alpha
        if z.size == 0:
            break
        mu = 2.0 * rng.random(z.size) - 1.0
    return t / photons, r / photons, hits


def exponential_integral(n, x):
    """E_n(x) = int_0^1 mu^(n-2) exp(-x / mu) dmu (Gauss-Legendre in mu; x >= 0, n >= 2)."""
    t, w = np.polynomial.legendre.leggauss(400)
    mu, w = 0.5 * (t + 1.0), 0.5 * w
    x = np.asarray(x, dtype=float)[..., None]
    return (w * mu ** (n - 2) * np.exp(-x / mu)).sum(-1)


def capped_walk_transmission(alpha, tau, cell=0.05):
    """The expectation walk() samples, for one slab, without sampling: the flux through the far
    face per unit entering. The slab is cut into cells of about `cell` optical units; g holds where
    the surviving walks' collisions lie after each flight. From a collision at depth z an isotropic
    direction and an exponential flight get beyond depth z + d (on one side) with probability
    E_2(d) / 2, so a cell m cells away receives (E_2((m - 1/2) h) - E_2((m + 1/2) h)) / 2 of it
    (the collision taken at its cell's centre) and the far face E_2(tau - z) / 2: the kernel of the
    slab's integral transport equation for isotropic scattering (e.g. Case and Zweifel, Linear
    Transport Theory, 1967, ch. 2). The cosine-weighted entry puts its first collision in [a, b]
    with probability 2 (E_3(a) - E_3(b)) and crosses uncollided with 2 E_3(tau). Flight k carries
    the weight alpha^(k - 1); CAP flights in all, as walk(). Against walk() where it resolves
    (tau up to 46, 200 000 walks) ln T agrees within walk()'s noise (0.1 at the deepest nodes);
    halving the cell moves T by under 0.5 %."""
    n = max(int(math.ceil(tau / cell)), 8)
    h = tau / n
    edges = np.linspace(0.0, tau, n + 1)
    centres = 0.5 * (edges[:-1] + edges[1:])
    e3 = exponential_integral(3, edges)
    g = 2.0 * (e3[:-1] - e3[1:])
    t = 2.0 * float(exponential_integral(3, tau))
    e2 = exponential_integral(2, (np.arange(n + 1) + 0.5) * h)
    step = np.empty(n)
    step[0] = 1.0 - e2[0]  # staying in its own cell: out of neither side
    step[1:] = 0.5 * (e2[:-2] - e2[1:-1])
    move = step[np.abs(np.arange(n)[:, None] - np.arange(n)[None, :])]
    escape = 0.5 * exponential_integral(2, tau - centres)
    weight = 1.0
    for _ in range(CAP - 1):  # flights 2 .. CAP, each after one more scattering
        weight *= alpha
        t += weight * float(escape @ g)
        g = move @ g
    return t


def main():
    rng = np.random.default_rng(SEED)
    taus = [TAU_MAX * (i / (TAU_NODES - 1)) ** 2 for i in range(TAU_NODES)]
    rows, notes = [], []
    for u in U_ROWS:
        alpha = 1.0 - 10.0 ** -u
        _, r_inf, _ = walk(alpha, 1e30, rng)
        ln_t, solved = [], 0  # the tail nodes solved without sampling
        for i, tau in enumerate(taus):
            t, _, hits = walk(alpha, tau, rng) if tau > 0 else (1.0, 0.0, PHOTONS)
            if hits >= MIN_HITS:
                ln_t.append(math.log(t / r_inf))
            else:
                ln_t.append(math.log(capped_walk_transmission(alpha, tau) / r_inf))
                solved += 1
        rows.append(ln_t)
        notes.append(f"u {u}: alpha {alpha:.6f}, R_inf {r_inf:.4f}, {solved} tail nodes solved without sampling")
        print(notes[-1], file=sys.stderr)
    print("// Generated by tools/slab_walk_table.py (seed %d, %d walks per cell): do not edit." % (SEED, PHOTONS))
    print("// ln(T / R_inf) of Cycles' capped random walk through a slab (see the script's docstring).")
    for n in notes:
        print("// " + n)
    print("constexpr int kSlabWalkTauNodes = %d;" % TAU_NODES)
    print("constexpr float kSlabWalkTauMax = %.1ff;" % TAU_MAX)
    print("constexpr int kSlabWalkRows = %d;" % len(U_ROWS))
    print("constexpr float kSlabWalkRowU[kSlabWalkRows] = {%s};" % ", ".join("%.2ff" % u for u in U_ROWS))
    print("constexpr float kSlabWalkLnT[kSlabWalkRows][kSlabWalkTauNodes] = {")
    for row in rows:
        print("    {" + ", ".join("%.5ff" % v for v in row) + "},")
    print("};")


if __name__ == "__main__":
    main()
