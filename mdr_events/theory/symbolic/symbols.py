"""The symbols of section 4, all SI (see :mod:`mdr_events.theory.symbolic` for what each names), and their LaTeX names."""

from __future__ import annotations

import sympy as sp

__all__ = ["SYMBOLS", "LATEX_NAMES"]


# symbols
x = sp.Symbol("x", positive=True)
r = sp.Symbol("r", positive=True)
t = sp.Symbol("t", positive=True)
n = sp.Symbol("n", positive=True)
c = sp.Symbol("c", positive=True)
theta = sp.Symbol("theta", positive=True)
R = sp.Symbol("R", positive=True)
E_star = sp.Symbol("E_star", positive=True)
G_star = sp.Symbol("G_star", positive=True)
tau0 = sp.Symbol("tau0", positive=True)
dgamma = sp.Symbol("dgamma", positive=True)
d = sp.Symbol("d", real=True)
d_max = sp.Symbol("d_max", positive=True)
a = sp.Symbol("a", positive=True)
s = sp.Symbol("s", positive=True)
alpha = sp.Symbol("alpha", positive=True)
tan_alpha = sp.Symbol("tan_alpha", positive=True)
u_bar = sp.Symbol("u_bar", positive=True)
dx = sp.Symbol("Delta_x", positive=True)
n_springs = sp.Symbol("n", positive=True, integer=True)
g = sp.Function("g")
f = sp.Function("f")
u_z = sp.Symbol("u_z", real=True)
dl_max = sp.Symbol("Delta_l_max", positive=True)
F_N = sp.Symbol("F_N", real=True)
tau = sp.Symbol("tau", real=True)
k = sp.Symbol("k", positive=True)
X = sp.Symbol("X", positive=True)
W = sp.Symbol("W", positive=True)
mu = sp.Symbol("mu", positive=True)
u_x = sp.Symbol("u_x", positive=True)
F_x = sp.Symbol("F_x", real=True)

#: Every symbol by its name, for users building their own expressions.
SYMBOLS: dict[str, sp.Symbol] = {
    sym.name: sym
    for sym in (x, r, R, E_star, G_star, tau0, dgamma, d, d_max, a, s, alpha,
                tan_alpha, u_bar, dx, c, n, theta, k, X, W, mu, u_x)
}

#: Pretty LaTeX names (``sympy.latex(..., symbol_names=LATEX_NAMES)``).
LATEX_NAMES: dict[sp.Symbol, str] = {
    E_star: r"E^{*}",
    G_star: r"G^{*}",
    tau0: r"\tau_{0}",
    dgamma: r"\Delta\gamma",
    d_max: r"d_{\max}",
    u_bar: r"\bar{u}",
    dx: r"\Delta x",
    tan_alpha: r"\tan\alpha",
    u_x: r"u_{x}",
    dl_max: r"\Delta l_{\max}",
}
