"""A user's own discrete MDR spring simulator, scenario A (Lyashenko, Popov & Borysiuk 2023, sec. 4).

Plain numpy, written from the paper's rules; it does not import mdr_events (it stands in for
your simulator). Springs at x_j = (j + 1/2) dx on one half of the contact (sums doubled), profile
g = x²/R, normal stiffness E* dx, tangential stiffness G* dx. Heß's rule: going in, springs attach
while d >= g(x_j) - dl_max(x_j; dγ0); coming out, boundary springs detach while
d < g(x_j) - dl_max(x_j; dγ1), with dl_max(x; dγ) = sqrt(2 π x dγ / E*). A spring's shift starts
at 0 and follows the indenter, clipped to ±ū(a) = ± π a τ0 / (2 G*). SI units throughout.

``variant`` selects the right model or one of three deliberate mistakes (see VARIANTS).
"""
import math

import numpy as np

#: Section 4's parameters (E, ν and v inferred: mdr_events.Parameters.paper()), SI units.
PAPER = dict(E=0.324e6, nu=0.5, R=0.03, tau0=42e3, dgamma0=0.01, dgamma1=0.15, d_max=0.3e-3, v=1e-6)

VARIANTS = {
    "right": "the paper's rules",
    "hess_sqrt2": "Heß threshold off by √2: dl_max = sqrt(π x dγ / E*)",
    "stiffness_E": "tangential springs of stiffness E* dx instead of G* dx",
    "no_hysteresis": "dγ0 also for detaching: no adhesion hysteresis on pull-off",
}


def scenario_a(params, alpha_deg, t):
    """Indenter (x, d) at times t: in at angle α to d_max, then vertically out to -0.2 d_max."""
    d_max, alpha = params["d_max"], math.radians(alpha_deg)
    s, s_in = params["v"] * t, d_max / math.sin(alpha)  # path length travelled; length of the way in
    x = np.where(s < s_in, s * math.cos(alpha), d_max / math.tan(alpha))
    d = np.where(s < s_in, s * math.sin(alpha), d_max - (s - s_in))
    return x, d, s_in + 1.2 * d_max  # ... and the path's total length


def simulate(params, alpha_deg, dx, dt, variant="right"):
    """Run scenario A at angle alpha_deg (degrees); arrays from the first contact to the pull-off."""
    if variant not in VARIANTS:
        raise ValueError(f"variant={variant!r}; allowed: {list(VARIANTS)}")
    E, nu, R, tau0 = params["E"], params["nu"], params["R"], params["tau0"]
    E_star = E / (1 - nu**2)
    G_star = 4 * E / (2 * (1 + nu)) / (2 - nu)
    k_t = (E_star if variant == "stiffness_E" else G_star) * dx  # tangential spring stiffness
    hess = math.pi if variant == "hess_sqrt2" else 2 * math.pi
    dgamma_out = params["dgamma0"] if variant == "no_hysteresis" else params["dgamma1"]

    n = int(2 * math.sqrt(R * params["d_max"]) / dx) + 10  # springs per side, ample
    xj = (np.arange(n) + 0.5) * dx
    g = xj**2 / R
    attach = np.append(g - np.sqrt(hess * xj * params["dgamma0"] / E_star), np.inf)  # d >= attach[j]
    detach = g - np.sqrt(hess * xj * dgamma_out / E_star)  # boundary j detaches if d < detach[j]

    _, _, length = scenario_a(params, alpha_deg, np.zeros(1))
    t = np.arange(int(length / params["v"] / dt) + 1) * dt  # t = 0: the indenter touches the surface
    x_path, d_path = scenario_a(params, alpha_deg, t)[:2]
    u = np.zeros(n)  # shifts of the springs in contact (the first m)
    m = 0
    out = {key: np.zeros(t.size) for key in ("normal_force", "tangential_force", "contact_area",
                                             "sliding_fraction")}
    for k in range(1, t.size):
        d, m_before = d_path[k], m
        if d > d_path[k - 1] and (m > 0 or d >= g[0]):  # going in: the first spring when touched
            while d >= attach[m]:
                m += 1
        elif d < d_path[k - 1]:  # coming out: from the edge inwards
            while m > 0 and d < detach[m - 1]:
                m -= 1
        kept = min(m, m_before)
        u[:kept] += x_path[k] - x_path[k - 1]
        u[kept:] = 0.0  # new springs attach unshifted, detached ones forget their shift
        cap = math.pi * m * dx * tau0 / (2 * G_star)  # ū(a), a = m dx
        np.clip(u[:m], -cap, cap, out=u[:m])
        out["normal_force"][k] = 2 * E_star * dx * np.sum(d - g[:m])
        out["tangential_force"][k] = 2 * k_t * np.sum(u[:m])
        out["contact_area"][k] = math.pi * (m * dx) ** 2
        out["sliding_fraction"][k] = np.count_nonzero(np.abs(u[:m]) >= cap) / m if m else 0.0
        if m_before and not m:  # pulled off: keep this first sample without contact, stop
            break
    return {"time": t[:k + 1], **{key: values[:k + 1] for key, values in out.items()}}


def write_csv(result, path):
    """One column per quantity, SI units, a header row; '#' lines are comments."""
    columns = list(result)
    with open(path, "w", encoding="utf-8") as handle:
        handle.write("# my_simulator.py: scenario A, SI units (s, N, m2)\n")
        np.savetxt(handle, np.column_stack([result[c] for c in columns]), delimiter=",",
                   header=",".join(columns), comments="", fmt="%.17g")
