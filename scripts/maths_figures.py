#!/usr/bin/env python3
"""Recomputes the figures quoted in docs/maths.md, independently of the C++ code (NumPy only):
  LP-4 a  the most negative S_abs'' and the largest |S_abs'| per order and eps/delta, the
          witness of a non-convex smooth intersection, min dS_max/dy, the convex-envelope gaps;
  LP-4 b  S^c_abs(0) / w per order;
  LP-1    the largest |sum of the grid weights - 1| for cells 0.5 eps to 3 eps wide;
  G-1     the C0 and C1 spline-space dimensions of Kuhn-split grids (ranks of the continuity
          rows), with the gap between kept and dropped singular values.
Usage: /usr/bin/python3 scripts/maths_figures.py [--quick]   (--quick: no 3x3x3 grid; the
full run takes a few minutes on a loaded machine)."""
import itertools
import math
import sys

import numpy as np


# Li & Phillips' smooth unit steps by their recursion (eq. 2-3), vectorised.
def f_n(n, s):
    if n == 0:
        return np.where(s > 0, 1.0, np.where(s < 0, 0.0, 0.5))
    return s / n * f_n(n - 1, s) + (1 - s / n) * f_n(n - 1, s - 1)


def H(n, t):
    return f_n(n, n * (np.asarray(t, float) + 1) / 2)


def mu(n, eps, t):
    return H(n, np.asarray(t) / eps)


def s_abs(t, d, e, n):
    g0 = 1 - mu(n, e, t + d)
    g1 = mu(n, e, t + d) * (1 - mu(n, e, t - d))
    g2 = mu(n, e, t - d)
    return -g0 * t + g1 * (t * t / (2 * d) + d / 2) + g2 * t


def s_max(x, y, d, e, n=3):
    return (x + y + s_abs(x - y, d, e, n)) / 2


def lp4a():
    print("LP-4 a: S_abs'' minimum (x delta) and max |S_abs'| (delta = 1)")
    t = np.linspace(-3, 3, 60001)
    h = t[1] - t[0]
    for n in (2, 3, 4, 6, 8):
        for r in (1.0, 0.5, 0.1):
            s = s_abs(t, 1.0, r, n)
            s2 = (s[2:] - 2 * s[1:-1] + s[:-2]) / h ** 2
            s1 = (s[2:] - s[:-2]) / (2 * h)
            print("  order %d, eps/delta %.1f: min S'' %.4f, max |S'| %.4f" %
                  (n, r, s2.min(), np.abs(s1).max()))

    def zero_y(x):
        lo, hi = -2.0, 2.0
        for _ in range(200):
            m = (lo + hi) / 2
            lo, hi = (lo, m) if s_max(x, m, 1, 1) > 0 else (m, hi)
        return (lo + hi) / 2
    y1, y2 = zero_y(-1.890), zero_y(-0.990)
    print("  witness: zero-set points (-1.890, %.6f), (-0.990, %.7f), midpoint S_max %.4g" %
          (y1, y2, s_max((-1.890 - 0.990) / 2, (y1 + y2) / 2, 1, 1)))
    s1 = np.gradient(s_abs(t, 1, 1, 3), t)
    print("  min dS_max/dy (order 3, eps = delta): %.4f" % ((1 - s1) / 2).min())
    print("  convex-envelope gap / delta at eps/delta = 1, 0.5, 0.2:")
    for n in (2, 3, 4, 6):
        print("    order %d: %s" % (n, ", ".join("%.2g" % hull_gap(n, r) for r in (1, 0.5, 0.2))))


def hull_gap(n, r):
    t = np.linspace(-3, 3, 6001)
    s = s_abs(t, 1.0, r, n)
    hull = []
    for p in zip(t, s):  # lower convex hull (monotone chain)
        while len(hull) >= 2 and ((hull[-1][0] - hull[-2][0]) * (p[1] - hull[-2][1]) -
                                  (hull[-1][1] - hull[-2][1]) * (p[0] - hull[-2][0])) <= 0:
            hull.pop()
        hull.append(p)
    hx, hy = np.array(hull).T
    return (s - np.interp(t, hx, hy)).max()


def lp4b():
    u = np.linspace(-1, 0, 200001)
    print("LP-4 b: S^c_abs(0) / w = 2 int_{-1}^{0} H_n: " + ", ".join(
        "order %d %.6f" % (n, 2 * np.trapz(H(n, u), u)) for n in (1, 2, 3, 4)) +
        " (13/48 = %.6f)" % (13 / 48))


def lp1():
    print("LP-1: largest |sum b - 1| (order 3, eps = 1), cell of width W between cuts 0 and W")
    for w in (3, 2, 1.5, 1, 0.5):
        t = np.linspace(-3, w + 3, 200001)
        total = mu(3, 1, -t) + mu(3, 1, t) * mu(3, 1, w - t) + mu(3, 1, t - w)
        print("  W = %.1f eps: %.2g" % (w, np.abs(total - 1).max()))


# G-1: continuity rows between face-adjacent tetrahedra of a Kuhn-split grid.
def multi(k):
    return [m for m in itertools.product(range(k + 1), repeat=4) if sum(m) == k]


def bary(v, x):
    e = np.column_stack([v[i] - v[3] for i in range(3)])
    t = np.linalg.solve(e, x - v[3])
    return np.append(t, 1 - t.sum())


def bern(j, nu, a):
    c = math.factorial(j)
    for v in nu:
        c //= math.factorial(v)
    return c * np.prod([a[i] ** nu[i] for i in range(4)])


def kuhn(n):
    tets = []
    for c in itertools.product(range(n), repeat=3):
        for perm in itertools.permutations(range(3)):
            v = [np.array(c, float)]
            for axis in perm:
                v.append(v[-1].copy())
                v[-1][axis] += 1
            tets.append(np.array(v))
    return tets


def dimension(n, k, r):
    tets = kuhn(n)
    ms = multi(k)
    index = {m: i for i, m in enumerate(ms)}
    size = len(ms)
    faces = {}
    for t, v in enumerate(tets):
        for o in range(4):
            key = frozenset(tuple(v[i]) for i in range(4) if i != o)
            faces.setdefault(key, []).append((t, o))
    rows = []
    for pair in faces.values():
        if len(pair) < 2:
            continue
        (t, o), (u, q) = pair
        v, w = tets[t], tets[u]
        to_v = {i: [j for j in range(4) if j != o and np.array_equal(w[i], v[j])][0]
                for i in range(4) if i != q}
        alpha = bary(v, w[q])
        for m in ms:
            j = m[q]
            if j > r:
                continue
            lam = [0] * 4
            for i, jj in to_v.items():
                lam[jj] = m[i]
            row = np.zeros(len(tets) * size)
            row[u * size + index[m]] += 1
            for nu in multi(j):
                row[t * size + index[tuple(lam[i] + nu[i] for i in range(4))]] -= bern(j, nu, alpha)
            rows.append(row)
    s = np.linalg.svd(np.array(rows), compute_uv=False)
    kept = s > 1e-8 * s[0]
    return len(tets) * size - int(kept.sum()), s[kept].min(), s[~kept].max() if (~kept).any() else 0


def g1(quick):
    print("G-1: spline-space dimensions (kept / dropped singular values)")
    cases = [(1, 2), (1, 3), (1, 4), (1, 5), (2, 2), (2, 3), (2, 4), (2, 5)]
    if not quick:
        cases += [(3, 2), (3, 3)]
    for n, k in cases:
        out = []
        for r in ((0, 1) if n < 3 else (1,)):
            d, kept, dropped = dimension(n, k, r)
            out.append("C%d %d (%.1e / %.1e)" % (r, d, kept, dropped))
        print("  %dx%dx%d, k = %d: %s; (kn+1)^3 = %d, one polynomial %d" %
              (n, n, n, k, ", ".join(out), (k * n + 1) ** 3, math.comb(k + 3, 3)), flush=True)


if __name__ == "__main__":
    lp4a()
    lp4b()
    lp1()
    g1("--quick" in sys.argv)
