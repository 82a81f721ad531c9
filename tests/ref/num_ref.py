#!/usr/bin/env python3
"""num_ref.py — every printed number of the chapter-1 exercises against its
exact value, computed independently in 50+ digit arithmetic (mpmath) or in
exact rationals (fractions) from the answer's resolved parameters.

    build/mechmat-server --port 0 &          # note the port it prints
    python3 tests/ref/num_ref.py --url http://127.0.0.1:PORT [--draws 200] [--only num-eigen]

The requests are the defaults plus the draws that build/ref/num_draws prints
(the product's own generator, server/mm_draw.h, from a fixed seed), so that
two servers (before and after a change) get the same requests.  A request a
server refuses (400/422) is counted, never dropped silently.

For every number compared:
  relative error  |printed - exact| / |exact|; where the exact value is 0
                  or below 1e-10 of the largest term it comes from (the
                  scale, named per number: |z| for re and im, the integral
                  of |f| for an integral, max |y| for a residual), the
                  absolute error over that scale, marked "(abs/scale)";
  stated accuracy "exact": true must be within 1 ulp of the exact value,
                  "error": e (scalars) or an *_err column (tables) must
                  bound |printed - exact|; a violation is counted and listed.
Numbers that are rounding-level by nature (a residual, f at a root, the
energy residual) have no meaningful relative error: they are checked only
against their stated error and are not in the worst-relative-error column.

What is not compared (and why) is listed with --explain.
"""
import argparse
import json
import math
import subprocess
import sys
import urllib.error
import urllib.parse
import urllib.request
from fractions import Fraction

import mpmath as mp

mp.mp.dps = 60
EXPLAIN = """Not compared:
  num-linear-system  x_matlab, matlab_error, sigma_matlab: MATLAB's double
                     result shown as what it is, with its own error.
  num-eigen          mode shapes (normalisation is a convention), *_matlab.
  num-poly-roots     max_err (an error estimate, not a quantity).
  num-polyfit        std_error (a statistical estimate), c_matlab.
  num-nonlinear-roots iterations.  count: compared with the sign changes of f
                     on a grid 20x finer than n (roots of even multiplicity
                     are not counted by either).
  num-newmark        discrete_difference, observed_order, energy_residual,
                     work_done, energy_dissipated, newton_*: properties of the
                     run, not of the motion; max_error and relative_error only
                     for linear runs (knl = 0; the row 'num-newmark knl=0'
                     sends every draw again with knl = 0), against the exact
                     motion from the state-space transition matrix in 60
                     digits.
  num-plot           the plotted samples themselves (f at the sample points)."""

CHAPTER1 = ["num-complex", "num-linear-system", "num-eigen", "num-poly-roots", "num-polyfit",
            "num-nonlinear-roots", "num-newmark", "num-plot"]


def ulp(x):
    x = abs(float(x))
    if x == 0 or not math.isfinite(x):
        return 5e-324
    return math.ldexp(1.0, math.frexp(x)[1] - 53)


class Tally:
    """The numbers of one answer: name, printed value, exact value, scale."""

    def __init__(self):
        self.items = []

    def add(self, name, printed, exact, scale=None, stated=None, rel=True):
        """stated: None, ('exact',) or ('error', e).  scale: used when exact == 0."""
        if printed is None:
            return
        exact = mp.mpf(exact) if not isinstance(exact, mp.mpc) else exact
        d = abs(mp.mpf(printed) - exact) if not isinstance(exact, mp.mpc) else abs(mp.mpc(*printed) - exact)
        s = mp.mpf(scale) if scale else mp.mpf(0)
        if abs(exact) > 1e-10 * s:
            r, how = d / abs(exact), ""
        else:                           # 0, or cancelled to 0 within 1e-10 of the scale
            r, how = d / (s or 1), " (abs/scale)"
        self.items.append(dict(name=name, printed=printed, exact=exact, abs=d, rel=float(r) if rel else None,
                               how=how, stated=stated))


def stated_of(s):
    if s.get("exact"):
        return ("exact",)
    if "error" in s:
        return ("error", s["error"])
    return None


def scalars(ans):
    return {s["name"]: s for s in ans.get("scalars", [])}


def table(ans, name):
    for t in ans.get("tables", []):
        if t["name"] == name:
            return [dict(zip(t["columns"], row)) for row in t["rows"]]
    return None


def series(ans, name):
    for s in ans.get("series", []):
        if s["name"] == name:
            return s
    return None


def sc(T, S, name, exact, scale=None, rel=True):
    if name in S:
        T.add(name, S[name]["value"], exact, scale, stated_of(S[name]), rel)


def mpf_matrix(rows):
    return mp.matrix([[mp.mpf(v) for v in r] for r in rows])


def frac_solve(A, b):
    """Exact solution of A x = b (lists of Fractions), Gaussian elimination."""
    n = len(A)
    M = [list(A[i]) + [b[i]] for i in range(n)]
    for c in range(n):
        p = next(r for r in range(c, n) if M[r][c] != 0)
        M[c], M[p] = M[p], M[c]
        for r in range(n):
            if r != c and M[r][c] != 0:
                f = M[r][c] / M[c][c]
                M[r] = [M[r][k] - f * M[c][k] for k in range(n + 1)]
    return [M[i][n] / M[i][i] for i in range(n)]


def mpf_of(q):
    return mp.mpf(q.numerator) / q.denominator


def sym_eig(K, M):
    """Eigenvalues of K v = lambda M v, M symmetric positive definite, ascending."""
    L = mp.cholesky(M)
    Li = mp.inverse(L)
    C = Li * K * Li.T
    C = (C + C.T) / 2
    ev = mp.eigsy(C, eigvals_only=True)
    return sorted(ev[i] for i in range(ev.rows))


def svals(A):
    s = mp.svd_r(A, compute_uv=False)
    return sorted((s[i] for i in range(s.rows)), reverse=True)


# ---- the exercises ------------------------------------------------------------------------

def ex_complex(p, ans, T):
    S = scalars(ans)
    a = mp.mpc(p["a_re"], p["a_im"])
    b = mp.mpc(p["b_re"], p["b_im"])
    op, n = p["op"], int(p.get("n", 3))
    if op == "square":
        z = a * a
    elif op == "multiply":
        z = a * b
    elif op == "divide":
        z = a / b
    elif op == "power":
        z = a ** n if n >= 0 else 1 / a ** (-n)
    else:
        z = mp.exp(mp.log(a) / n) if a != 0 else mp.mpc(0)
    # the exact value of a root off an axis is irrational; on an axis its zero part is exactly 0
    if op == "roots" and a != 0:
        zr, zi = mp.re(z), mp.im(z)
        mz = abs(z)
        k4 = mp.arg(a) / n / (mp.pi / 2)         # the root lies on an axis when its angle is k pi/2
        if abs(k4 - mp.nint(k4)) < mp.mpf(10) ** -50:
            if int(mp.nint(k4)) % 2 == 0:
                zi = 0
            else:
                zr = 0
        z = mp.mpc(zr, zi)
    mz = abs(z)
    sc(T, S, "re", mp.re(z), mz)
    sc(T, S, "im", mp.im(z), mz)
    sc(T, S, "modulus", mz, 1)
    sc(T, S, "argument", mp.arg(z) if z != 0 else 0, mp.pi)
    sc(T, S, "a_modulus", abs(a), 1)
    sc(T, S, "a_argument", mp.arg(a) if a != 0 else 0, mp.pi)
    if op == "roots":
        s = series(ans, "roots")
        if s:
            r, th = abs(a) ** (mp.mpf(1) / n), mp.arg(a)
            for k in range(min(n, len(s["x"]))):
                w = r * mp.expj((th + 2 * mp.pi * k) / n)
                T.add("root %d" % k, (s["x"][k], s["y"][k]), mp.mpc(w), r)
    elif op in ("square", "power"):
        s = series(ans, "powers")
        if s:
            step = a if (op == "square" or n >= 0) else 1 / a
            w = mp.mpc(1)
            for j in range(len(s["x"])):
                T.add("power %d" % j, (s["x"][j], s["y"][j]), w, 1)
                w *= step


def ex_linear_system(p, ans, T):
    S = scalars(ans)
    A = [[Fraction(v) for v in r] for r in p["A"]]
    b = [Fraction(v) for v in p["b"]]
    n = len(A)
    x = frac_solve(A, b)
    xm = max(abs(v) for v in x)
    sol = table(ans, "solution")
    xhat = []
    for i in range(n):
        nm = "x%d" % (i + 1)
        sc(T, S, nm, mpf_of(x[i]), mpf_of(xm))
        if nm in S:
            xhat.append(S[nm]["value"])
    if sol:
        for i, row in enumerate(sol):
            T.add("solution x[%d]" % (i + 1), row["x"], mpf_of(x[i]), mpf_of(xm), ("error", row["x_err"]))
        if not xhat:
            xhat = [row["x"] for row in sol]
    sv = svals(mpf_matrix(p["A"]))
    sc(T, S, "cond", sv[0] / sv[-1])
    ts = table(ans, "singular_values")
    if ts:
        for i, row in enumerate(ts):
            T.add("sigma%d" % (i + 1), row["sigma"], sv[i], sv[0], ("error", row["sigma_err"]))
    else:
        s = series(ans, "sigma")
        if s:
            for i, v in enumerate(s["y"]):
                T.add("sigma%d" % (i + 1), v, sv[i], sv[0])
    if len(xhat) == n:
        xh = [Fraction(v) for v in xhat]
        r = [b[i] - sum(A[i][j] * xh[j] for j in range(n)) for i in range(n)]
        rn = mp.sqrt(mpf_of(sum(v * v for v in r)))
        mag = mp.sqrt(mpf_of(sum((sum(abs(A[i][j] * xh[j]) for j in range(n)) + abs(b[i])) ** 2
                                  for i in range(n))))
        sc(T, S, "residual", rn, mag, rel=False)
        scale = sv[0] * mp.sqrt(mpf_of(sum(v * v for v in xh))) + mp.sqrt(mpf_of(sum(v * v for v in b)))
        sc(T, S, "backward_error", rn / scale, 1, rel=False)
    c = sv[0] / sv[-1]
    sc(T, S, "digits", min(16, max(0, mp.floor(-mp.log10(c * mp.mpf(2) ** -52)))), 1)


def ex_eigen(p, ans, T):
    S = scalars(ans)
    K, M = mpf_matrix(p["K"]), mpf_matrix(p["M"])
    lam = sym_eig(K, M)
    big = max(abs(v) for v in lam)
    sc(T, S, "lambda_min", lam[0], big)
    sc(T, S, "lambda_max", lam[-1], big)
    sc(T, S, "unstable_modes", sum(1 for v in lam if v < 0), 1)
    mev = mp.eigsy(M, eigvals_only=True)
    mev = [mev[i] for i in range(mev.rows)]
    if min(mev) > 0:
        sc(T, S, "cond_M", max(mev) / min(mev))
    t = table(ans, "eigen")
    if t:
        for i, row in enumerate(t):
            if i >= len(lam):
                break
            st = (lambda c: ("error", row[c + "_err"]) if c + "_err" in row else None)
            T.add("lambda%d" % (i + 1), row["lambda"], lam[i], big, st("lambda"))
            if lam[i] >= 0:
                w = mp.sqrt(lam[i])
                T.add("omega%d" % (i + 1), row["omega"], w, mp.sqrt(big), st("omega"))
                if "f" in row:
                    T.add("f%d" % (i + 1), row["f"], w / (2 * mp.pi), mp.sqrt(big) / (2 * mp.pi), st("f"))


def ex_poly_roots(p, ans, T):
    S = scalars(ans)
    c = [mp.mpf(v) for v in p["p"]]
    while c and c[0] == 0:
        c.pop(0)
    nz = 0
    while c and c[-1] == 0:                       # roots at 0, exactly
        c.pop()
        nz += 1
    roots = [mp.mpc(0)] * nz
    if len(c) > 1:
        roots += list(mp.polyroots(c, maxsteps=400, extraprec=400))
    deg = len(roots)
    sc(T, S, "degree", deg, 1)
    big = max([abs(r) for r in roots] + [mp.mpf(1)])
    real = [r for r in roots if abs(mp.im(r)) <= mp.mpf(10) ** -45 * max(abs(r), 1)]
    sc(T, S, "real_roots", len(real), 1)
    t = table(ans, "roots") or []
    used = set()
    for i, row in enumerate(t):
        z = mp.mpc(row["re"], row["im"])
        j = min((k for k in range(len(roots)) if k not in used), key=lambda k: abs(roots[k] - z), default=None)
        if j is None:
            break
        used.add(j)
        r = roots[j]
        if abs(mp.im(r)) <= mp.mpf(10) ** -45 * max(abs(r), 1):
            r = mp.mpc(mp.re(r), 0)
        st = ("error", row["err"]) if "err" in row else None
        T.add("root %d" % (i + 1), (row["re"], row["im"]), r, big, st)
        if "modulus" in row:
            T.add("|root %d|" % (i + 1), row["modulus"], abs(r), big, st)


def ex_polyfit(p, ans, T):
    S = scalars(ans)
    xs = [Fraction(v) for v in p["x"]]
    ys = [Fraction(v) for v in p["y"]]
    d = int(p["degree"])
    m, n = d + 1, len(xs)
    V = [[xi ** (d - k) for k in range(m)] for xi in xs]              # highest power first
    N = [[sum(V[i][a] * V[i][b] for i in range(n)) for b in range(m)] for a in range(m)]
    r = [sum(V[i][a] * ys[i] for i in range(n)) for a in range(m)]
    c = frac_solve(N, r)
    fit = [sum(V[i][k] * c[k] for k in range(m)) for i in range(n)]
    res = [ys[i] - fit[i] for i in range(n)]
    cm = max(abs(v) for v in c)
    for k in range(m):
        sc(T, S, "c%d" % k, mpf_of(c[k]), mpf_of(cm))
    tc = table(ans, "coefficients")
    if tc:
        for row in tc:
            k = d - int(row["power"])
            T.add("coefficient c%d" % k, row["c"], mpf_of(c[k]), mpf_of(cm),
                  ("error", row["c_err"]) if "c_err" in row else None)
    ss = sum(v * v for v in res)
    ym = max(abs(v) for v in ys)
    sc(T, S, "rms_residual", mp.sqrt(mpf_of(ss / n)), mpf_of(ym))
    mu = sum(xs) / n
    spread = max(abs(v - mu) for v in xs) or Fraction(1)
    Vt = mp.matrix([[mpf_of((xi - mu) / spread) ** (d - k) for k in range(m)] for xi in xs])
    sv = svals(Vt)
    if sv[-1] > 0:
        sc(T, S, "cond", sv[0] / sv[-1])
    tr = table(ans, "residuals")
    if tr:
        for i, row in enumerate(tr):
            st = ("error", row["err"]) if "err" in row else None
            T.add("fit(x%d)" % (i + 1), row["fit"], mpf_of(fit[i]), mpf_of(ym), st)
            T.add("residual %d" % (i + 1), row["residual"], mpf_of(res[i]), mpf_of(ym), st)


def mp_function(text):
    """An expression of the exercise (mm_expr / muparser syntax) as an mpmath function of x."""
    env = {k: getattr(mp, k) for k in ("sin", "cos", "tan", "exp", "sqrt", "sinh", "cosh", "tanh", "atan",
                                       "asin", "acos", "pi", "e", "log10", "floor", "ceil")}
    env.update(ln=mp.log, log=mp.log, abs=lambda v: abs(v))
    code = compile(text.replace("^", "**"), "<f>", "eval")
    return lambda x: eval(code, dict(env), {"x": x})


def bisect(f, lo, hi, flo):
    """The root of f in [lo, hi] where f changes sign, to the working precision."""
    for _ in range(mp.mp.prec + 100):
        mid = (lo + hi) / 2
        if mid == lo or mid == hi:
            break
        fm = f(mid)
        if fm == 0:
            return mid
        if (fm < 0) == (flo < 0):
            lo, flo = mid, fm
        else:
            hi = mid
    return (lo + hi) / 2


def ex_nonlinear_roots(p, ans, T):
    S = scalars(ans)
    f = mp_function(p["f"])
    a, b, n = mp.mpf(p["a"]), mp.mpf(p["b"]), int(p["n"])
    # the roots: sign changes on a fine grid, each refined by bisection + secant in 60 digits
    g = 20 * n
    xs = [a + (b - a) * i / g for i in range(g + 1)]
    fs = [f(x) for x in xs]
    exact = []
    for i in range(g):
        if fs[i] == 0:
            exact.append(xs[i])
        elif fs[i] * fs[i + 1] < 0:
            exact.append(bisect(f, xs[i], xs[i + 1], fs[i]))
    if fs[g] == 0:
        exact.append(xs[g])
    sc(T, S, "count", len(exact), 1)
    t = table(ans, "roots") or []
    for i, row in enumerate(t):
        x = row["x"]
        near = mp.findroot(f, mp.mpf(x), solver="secant") if not exact else min(exact, key=lambda r: abs(r - x))
        st = ("error", row["err"]) if "err" in row else None
        T.add("root %d" % (i + 1), x, near, max(abs(a), abs(b)), st)
        if "fx" in row:
            T.add("f(root %d)" % (i + 1), row["fx"], f(mp.mpf(x)), 1,
                  ("error", row["fx_err"]) if "fx_err" in row else None, rel=False)
    if exact:
        sc(T, S, "x1", exact[0], max(abs(a), abs(b)))


def ex_plot(p, ans, T):
    with mp.workdps(34):                          # twice a double's digits: ample, and 1e3-long runs stay quick
        _ex_plot(p, ans, T)


def _ex_plot(p, ans, T):
    S = scalars(ans)
    f = mp_function(p["f"])
    a, b, np_ = mp.mpf(p["a"]), mp.mpf(p["b"]), int(p["points"])
    sc(T, S, "points", np_, 1)
    s = series(ans, "f")
    # extremes: a grid 4x the plot and at most 0.05 apart (the default f's features are ~1 wide),
    # the best local extremes refined by a root of f' in 34 digits; the printed x_max / x_min
    # are one more start (a start can only raise the reference's maximum, never fake it)
    g = max(4 * np_, int(mp.ceil((b - a) / mp.mpf("0.05"))), 1000)
    xs = [a + (b - a) * i / g for i in range(g + 1)]
    fs = [f(x) for x in xs]
    height = max(fs) - min(fs)
    # the scale of the integral: the trapezoid rule on |f| over the grid (a scale needs no digits)
    Iabs = (b - a) / g * (sum(abs(v) for v in fs) - (abs(fs[0]) + abs(fs[-1])) / 2)
    for sign, nv, nx in ((1, "max", "x_max"), (-1, "min", "x_min")):
        cand = [(sign * fs[0], xs[0]), (sign * fs[g], xs[g])]
        loc = [i for i in range(1, g) if sign * fs[i] >= sign * fs[i - 1] and sign * fs[i] >= sign * fs[i + 1]]
        starts = [(xs[i - 1], xs[i + 1]) for i in sorted(loc, key=lambda i: -sign * fs[i])[:6]]
        if nx in S:
            xp, dx = mp.mpf(S[nx]["value"]), (b - a) / g
            starts.append((max(a, xp - dx), min(b, xp + dx)))
        for lo, hi in starts:
            try:
                x = mp.findroot(lambda t: mp.diff(f, t), (lo, hi), solver="anderson")
                if a <= x <= b:
                    cand.append((sign * f(x), x))
            except (ValueError, ZeroDivisionError):
                pass
        v, x = max(cand, key=lambda c: c[0])
        sc(T, S, nv, sign * v, height)
        sc(T, S, nx, x, max(abs(a), abs(b)))
    # the integral by Gauss-Legendre in pieces 4 long at most (f may oscillate), at 24 digits:
    # 1e-20 of the integral of |f|, far below a double's rounding, in a second, not ten
    k = int(mp.ceil((b - a) / 4)) + 1
    with mp.workdps(24):
        I = mp.quad(f, [a + (b - a) * i / k for i in range(k + 1)], method="gauss-legendre")
    sc(T, S, "integral", I, Iabs)
    if s:
        h = (b - a) / (np_ - 1)
        tr = h * (sum(f(mp.mpf(x)) for x in s["x"]) - (f(mp.mpf(s["x"][0])) + f(mp.mpf(s["x"][-1]))) / 2)
        sc(T, S, "integral_plot", tr, Iabs)


# ---- num-newmark ----------------------------------------------------------------------------

LIMITS = {"average-acceleration": None, "linear-acceleration": mp.sqrt(12), "central-difference": mp.mpf(2),
          "hht-alpha": None}


def exact_motion(M, C, K, F, w, q0, v0, ts):
    """q(t) of M q'' + C q' + K q = F cos(w t), at the times ts: the state-space transition
    matrix for the homogeneous part plus the harmonic particular solution."""
    n = M.rows
    Mi = mp.inverse(M)
    A = mp.zeros(2 * n, 2 * n)
    for i in range(n):
        A[i, n + i] = 1
    MK, MC, MF = -Mi * K, -Mi * C, Mi * F
    for i in range(n):
        for j in range(n):
            A[n + i, j], A[n + i, n + j] = MK[i, j], MC[i, j]
    B = mp.zeros(2 * n, 1)
    for i in range(n):
        B[n + i] = MF[i]
    # x_p = Re(X e^{iwt}), (i w I - A) X = B
    X = mp.lu_solve(mp.mpc(0, w) * mp.eye(2 * n) - A, B)
    x0 = mp.matrix([mp.mpf(v) for v in list(q0) + list(v0)])
    y0 = x0 - mp.matrix([mp.re(X[i]) for i in range(2 * n)])
    out = []
    tprev, E, y = mp.mpf(0), None, y0
    dts = {}
    for t in ts:
        dt = t - tprev
        key = mp.nstr(dt, 40)
        if key not in dts:
            dts[key] = mp.expm(A * dt)
        y = dts[key] * y
        tprev = t
        xp = [mp.re(X[i] * mp.expj(w * t)) for i in range(n)]
        out.append([y[i] + xp[i] for i in range(n)])
    return out


def ex_newmark(p, ans, T):
    S = scalars(ans)
    M, C, K = mpf_matrix(p["M"]), mpf_matrix(p["C"]), mpf_matrix(p["K"])
    n = M.rows
    lam = sym_eig(K, M)
    wmax = mp.sqrt(max(lam[-1], 0))
    h = mp.mpf(p["h"])
    sc(T, S, "n", n, 1)
    sc(T, S, "omega_max", wmax, 1)
    sc(T, S, "omega_max_h", wmax * h, 1)
    lim = LIMITS.get(p.get("method"))
    if lim is not None and wmax > 0:
        sc(T, S, "h_stable", lim / wmax, 1)
    # damped modes: eigenvalues of the state matrix, s = -zeta w +- i w sqrt(1 - zeta^2)
    t = table(ans, "modes")
    if t:
        Mi = mp.inverse(M)
        A = mp.zeros(2 * n, 2 * n)
        for i in range(n):
            A[i, n + i] = 1
        MK, MC = -Mi * K, -Mi * C
        for i in range(n):
            for j in range(n):
                A[n + i, j], A[n + i, n + j] = MK[i, j], MC[i, j]
        ev = mp.eig(A, left=False, right=False)
        ev = [ev[i] for i in range(len(ev))]
        # one per pair: Im >= 0 (or the real ones), sorted by |s|
        modes = sorted([s for s in ev if mp.im(s) > mp.mpf(10) ** -40 * abs(s)], key=abs)
        if len(modes) == n:
            for j, row in enumerate(t):
                s = modes[j]
                wj = abs(s)
                T.add("mode %d omega" % (j + 1), row["omega"], wj, 1)
                T.add("mode %d zeta" % (j + 1), row["zeta"], -mp.re(s) / wj, 1)
                if "omega_d" in row:
                    T.add("mode %d omega_d" % (j + 1), row["omega_d"], mp.im(s), wj)
                if "omega_h" in row:
                    T.add("mode %d omega_h" % (j + 1), row["omega_h"], wj * h, 1)
    if float(p.get("knl", 0)) != 0:
        return
    qs = [series(ans, "q%d" % (i + 1)) for i in range(n)]
    if not all(qs) or "max_error" not in S:
        return
    ts = [mp.mpf(v) for v in qs[0]["x"]]
    F = mp.matrix([mp.mpf(v) for v in p["F"]])
    qx = exact_motion(M, C, K, F, mp.mpf(p["omega"]), p["q0"], p["v0"], ts)
    e1 = max(abs(mp.mpf(qs[i]["y"][k]) - qx[k][i]) for k in range(len(ts)) for i in range(n))
    Aref = max(abs(qx[k][i]) for k in range(len(ts)) for i in range(n))
    sc(T, S, "max_error", e1, Aref)
    sc(T, S, "relative_error", e1 / Aref if Aref else 0, 1)


EXERCISES = {"num-complex": ex_complex, "num-linear-system": ex_linear_system, "num-eigen": ex_eigen,
             "num-poly-roots": ex_poly_roots, "num-polyfit": ex_polyfit,
             "num-nonlinear-roots": ex_nonlinear_roots, "num-newmark": ex_newmark, "num-plot": ex_plot}


# ---- the run ----------------------------------------------------------------------------------

def fetch(url, ex, pairs):
    q = urllib.parse.urlencode(pairs, quote_via=urllib.parse.quote)
    full = "%s/api/exercises/%s/solve%s" % (url, ex, "?" + q if q else "")
    try:
        with urllib.request.urlopen(full, timeout=60) as r:
            return r.status, json.load(r), q
    except urllib.error.HTTPError as e:
        try:
            body = json.load(e)
        except Exception:
            body = {}
        return e.code, body, q


def violation(it):
    st = it["stated"]
    if st is None:
        return None
    if st[0] == "exact":
        x = it["exact"]
        lim = ulp(float(abs(x))) if not isinstance(x, mp.mpc) else ulp(float(abs(x)))
        return it["abs"] > lim * (1 + 1e-9)
    return it["abs"] > mp.mpf(st[1]) * (1 + 1e-9) + mp.mpf(10) ** -320


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--url", required=True)
    ap.add_argument("--draws", type=int, default=200)
    ap.add_argument("--draws-bin", default="build/ref/num_draws")
    ap.add_argument("--only", action="append")
    ap.add_argument("--json", help="write every comparison's worst and every violation here")
    ap.add_argument("--explain", action="store_true")
    ap.add_argument("--verbose", "-v", action="store_true")
    args = ap.parse_args()
    if args.explain:
        print(EXPLAIN)
    want = args.only or CHAPTER1
    lines = subprocess.run([args.draws_bin, "-n", str(args.draws)] + [e for e in want if e in CHAPTER1],
                           check=True, capture_output=True, text=True).stdout.splitlines()
    reqs = {e: [("defaults", [])] for e in want}
    for ln in lines:
        f = ln.split("\t")
        if len(f) > 1 and f[1].startswith("#refused"):
            continue
        reqs[f[0]].append(("draw %d" % len(reqs[f[0]]), [tuple(kv.split("=", 1)) for kv in f[1:]]))
    if "num-newmark" in want:   # the same draws, linear: the exact motion applies
        reqs["num-newmark knl=0"] = [(lab, [(k, "0" if k == "knl" else v) for k, v in pr])
                                     for lab, pr in reqs["num-newmark"]]
    rows, report = [], {}
    for ex, rl in reqs.items():
        fn = EXERCISES[ex.split()[0]]
        print("num_ref: %s, %d requests" % (ex, len(rl)), file=sys.stderr, flush=True)
        n_cmp, worst, refused, viol, unstated, fails = 0, None, {}, [], 0, []
        for lab, pairs in rl:
            status, ans, q = fetch(args.url, ex.split()[0], pairs)
            if status != 200:
                code = (ans.get("error") or {}).get("code", str(status))
                refused.setdefault("%d %s" % (status, code), []).append(q)
                continue
            T = Tally()
            try:
                fn(ans["params"], ans, T)
            except Exception as e:                      # the reference failed: say so, go on
                fails.append((lab, q, repr(e)))
                continue
            for it in T.items:
                n_cmp += 1
                if it["rel"] is not None and (worst is None or it["rel"] > worst[0]):
                    worst = (it["rel"], it["name"] + it["how"], lab, q, it["printed"], mp.nstr(it["exact"], 20))
                v = violation(it)
                if v is None:
                    unstated += 1
                elif v:
                    viol.append((lab, q, it["name"], it["printed"], mp.nstr(it["exact"], 20), float(it["abs"]),
                                 it["stated"]))
            if args.verbose:
                for it in T.items:
                    print(ex, lab, it["name"], it["printed"], mp.nstr(it["exact"], 17), it["rel"], it["stated"])
        rows.append((ex, n_cmp, worst, refused, viol, unstated, fails))
        report[ex] = dict(compared=n_cmp, worst=worst and [worst[0], worst[1], worst[2], worst[3], worst[4],
                                                           worst[5]],
                          refused={k: v for k, v in refused.items()}, violations=viol, unstated=unstated,
                          reference_failures=fails)
    print("| exercise | numbers compared | worst rel. error | which number, which draw | refused draws |"
          " stated-error violations | no accuracy stated |")
    print("|---|---|---|---|---|---|---|")
    for ex, n_cmp, worst, refused, viol, unstated, fails in rows:
        w = "%.2g" % worst[0] if worst else "-"
        which = "%s, %s" % (worst[1], worst[2]) if worst else "-"
        rf = ", ".join("%d x %s" % (len(v), k) for k, v in refused.items()) or "0"
        print("| %s | %d | %s | %s | %s | %d | %d |" % (ex, n_cmp, w, which, rf, len(viol), unstated))
    for ex, n_cmp, worst, refused, viol, unstated, fails in rows:
        if worst:
            print("\n%s worst: %s = %r, exact %s, rel %.3g; request ?%s" % (ex, worst[1], worst[4], worst[5],
                                                                           worst[0], worst[3]))
        for v in viol[:5]:
            print("  violation %s %s: %s printed %r exact %s |diff| %.3g stated %s; ?%s" %
                  (ex, v[0], v[2], v[3], v[4], v[5], v[6], v[1]))
        for k, v in refused.items():
            print("  refused %s %s: e.g. ?%s" % (ex, k, v[0]))
        for f in fails[:3]:
            print("  reference failed %s %s: %s; ?%s" % (ex, f[0], f[2], f[1]))
    if args.json:
        with open(args.json, "w") as fh:
            json.dump(report, fh, indent=1, default=str)


if __name__ == "__main__":
    main()
