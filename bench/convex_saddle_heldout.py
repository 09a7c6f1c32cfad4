#!/usr/bin/env python3
# Usage: python3 bench/convex_saddle_heldout.py build/apps/implicitfit 5001,5002,... OUTDIR
# Held-out saddle draws through the command line (independent of the C++ test): points from
# Python's random (not the test's mt19937 draws), fit --model quadric-patch --convex, then RMS
# of f/|grad f| (grad by central differences of `implicitfit eval`), signed cosine, the PCA
# plane's RMS and lambda_min(A)/max|b| from the written control points.
import json, math, random, subprocess, sys
CLI = sys.argv[1]; seeds = [int(s) for s in sys.argv[2].split(",")]; out = sys.argv[3]

def eig3(m):  # eigenvalues of a symmetric 3x3 (trigonometric method), ascending
    p1 = m[0][1]**2 + m[0][2]**2 + m[1][2]**2
    q = (m[0][0] + m[1][1] + m[2][2]) / 3
    p2 = sum((m[i][i] - q)**2 for i in range(3)) + 2 * p1
    p = math.sqrt(p2 / 6)
    if p == 0: return sorted([m[0][0], m[1][1], m[2][2]])
    B = [[(m[i][j] - (q if i == j else 0)) / p for j in range(3)] for i in range(3)]
    det = (B[0][0]*(B[1][1]*B[2][2]-B[1][2]*B[2][1]) - B[0][1]*(B[1][0]*B[2][2]-B[1][2]*B[2][0])
           + B[0][2]*(B[1][0]*B[2][1]-B[1][1]*B[2][0]))
    r = max(-1, min(1, det / 2)); phi = math.acos(r) / 3
    e1 = q + 2 * p * math.cos(phi); e3 = q + 2 * p * math.cos(phi + 2 * math.pi / 3)
    return sorted([e1, 3 * q - e1 - e3, e3])

rows = []
for seed in seeds:
    rng = random.Random(seed)
    P, N = [], []
    for _ in range(5000):
        x, y = rng.uniform(-1, 1), rng.uniform(-1, 1)
        n = (-0.8 * x, 0.8 * y, 1.0); l = math.sqrt(sum(c * c for c in n)); n = tuple(c / l for c in n)
        e = rng.gauss(0, 0.002)
        P.append((x + e * n[0], y + e * n[1], 0.4 * (x * x - y * y) + e * n[2])); N.append(n)
    cloud = f"{out}/s{seed}.xyz"
    with open(cloud, "w") as f:
        for p, n in zip(P, N): f.write("%.17g %.17g %.17g %.17g %.17g %.17g\n" % (p + n))
    model = f"{out}/s{seed}.json"
    r = subprocess.run([CLI, "fit", cloud, "--model", "quadric-patch", "--convex", "--out", model], capture_output=True, text=True)
    if r.returncode != 0:
        rows.append((seed, "exit %d: %s" % (r.returncode, r.stderr.strip()[:200]))); continue
    h = 1e-6; Q = []
    for p in P:
        Q.append(p)
        for k in range(3):
            for s in (1, -1):
                q = list(p); q[k] += s * h; Q.append(tuple(q))
    with open(f"{out}/q.xyz", "w") as f:
        for q in Q: f.write("%.17g %.17g %.17g\n" % q)
    v = [float(t) for t in subprocess.run([CLI, "eval", model, f"{out}/q.xyz"], capture_output=True,
                                          text=True, check=True).stdout.split()]
    ss = cs = 0
    for i, n in enumerate(N):
        f0 = v[7 * i]; g = [(v[7 * i + 1 + 2 * k] - v[7 * i + 2 + 2 * k]) / (2 * h) for k in range(3)]
        gn = math.sqrt(sum(c * c for c in g)); ss += (f0 / gn) ** 2; cs += sum(a * b for a, b in zip(g, n)) / gn
    rms, cos = math.sqrt(ss / len(P)), cs / len(P)
    c = [sum(p[k] for p in P) / len(P) for k in range(3)]
    C = [[sum((p[i] - c[i]) * (p[j] - c[j]) for p in P) for j in range(3)] for i in range(3)]
    plane = math.sqrt(eig3(C)[0] / len(P))
    doc = json.load(open(model)); node = doc["root"]
    b = node["control_points"]
    pair = [[0, 1, 2, 3], [1, 4, 5, 6], [2, 5, 7, 8], [3, 6, 8, 9]]
    A = [[b[pair[i][j]] + b[9] - b[pair[i][3]] - b[pair[j][3]] for j in range(3)] for i in range(3)]
    margin = eig3(A)[0] / max(abs(t) for t in b)
    rows.append((seed, cos, rms, plane, rms / plane, margin))
    print("seed %d: cosine %.4f rms %.4f plane %.4f ratio %.3f margin %.3g" % rows[-1], flush=True)
ok = [r for r in rows if len(r) == 6]
print("held-out: %d of %d fitted; mean cosine %.4f, worst ratio %.3f, smallest margin %.3g" % (
    len(ok), len(rows), sum(r[1] for r in ok) / len(ok), max(r[4] for r in ok), min(r[5] for r in ok)))
for r in rows:
    if len(r) != 6: print("seed", r[0], r[1])
